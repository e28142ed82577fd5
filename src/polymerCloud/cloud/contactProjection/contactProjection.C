/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

\*---------------------------------------------------------------------------*/

#include "contactProjection.H"
#include "packedReduction.H"
#include "rodCrossingAudit.H"
#include "rodPairCrossing.H"
#include "cpuTimeCxx.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::contactProjection::contactProjection
(
    polymerChains& chains,
    const constraintModel& constraint,
    const bool uncrossable,
    const UList<vector>& lattice,
    const bool wallEdges,
    const label maxContactRounds
)
:
    chains_(chains),
    constraint_(constraint),
    uncrossable_(uncrossable),
    lattice_(lattice),
    wallEdges_(wallEdges),
    edgeRootSolver_
    (
        wallEdges ? crossingRootSolver::New("isolating", dictionary::null)
      : autoPtr<crossingRootSolver>()
    ),
    rods_(),
    maxContactRounds_(maxContactRounds),
    contactSolver_(constraint.lengthTolerance(), 50),
    contacts_(),
    contactGroups_(),
    zones_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::polymer::contactProjection::reprojectChain
(
    const label c,
    const UList<point>& directions,
    const scalar deltaT,
    const scalar time
)
{
    // The length projection adds its correction over deltaT to the
    // velocities, as a constraint force over the step would; here it
    // corrects positions the impulses left, so the velocities stay
    SubList<vector> v(chains_.velocities(), chains_.size(c), chains_.start(c));
    const List<vector> velocities(v);

    scalar residual = 0;
    const label iter = constraint_.correctChainLengths
    (
        chains_, c, directions, deltaT, residual
    );
    v = velocities;
    if (iter < 0)
    {
        if (!counts_.notConverged)
        {
            WarningInFunction
                << "The re-projection of chain " << chains_.globalId(c)
                << " after its contacts at time " << time
                << " did not converge (residual " << residual
                << "): it moves in a rigid impact zone instead; such"
                << " chains are counted in the final report (constraint"
                << " exactRods always converges)" << endl;
        }
        ++counts_.notConverged;
        return false;
    }
    constraint_.correctChainVelocities(chains_, c, residual);
    return true;
}


Foam::List<Foam::polymer::contactProjection::edgeMeeting>
Foam::polymer::contactProjection::edgeMeetings
(
    const wallModel& wall,
    const labelUList& chainList,
    const UList<point>& from,
    const scalarField& clearances
) const
{
    const wallEdges& edges = wall.edges();
    const List<point>& x = chains_.positions();
    DynamicList<edgeMeeting> meetings;
    for (const label c : chainList)
    {
        const label start = chains_.start(c);
        const label end = chains_.end(c);
        const bool ring = chains_.type(c).ring();
        for (label i = start; i < (ring ? end : end - 1); ++i)
        {
            const label j = (i + 1 < end) ? i + 1 : start;

            // A rod whose path stays farther from every edge than its
            // beads move (no point of it moves more) meets none: no
            // look-up in the edges' tree (most rods of a device), nor in
            // the voxels where its clearance is known
            const scalar moves = max(mag(x[i] - from[i]), mag(x[j] - from[j]));
            if (clearances.size() && moves < clearances[rods_.beadRods(i)[1]])
            {
                continue;
            }

            // The rod's path at its image inside the mesh
            const vector shift = wall.imageShift(0.5*(from[i] + from[j]));
            if (wall.rodEdgeClearance(from[i], from[j], shift) > moves)
            {
                continue;
            }
            boundBox box(from[i]);
            box.add(from[j]);
            box.add(x[i]);
            box.add(x[j]);
            for
            (
                const label edgei
              : edges.near(boundBox(box.min() + shift, box.max() + shift))
            )
            {
                const rodPairCrossing pair
                (
                    from[i] + shift, from[j] + shift,
                    edges.start(edgei), edges.end(edgei),
                    x[i] - from[i], x[j] - from[j], Zero, Zero
                );
                const scalar s = edgeRootSolver_->earliestCrossing(pair, 1);
                if (s >= 0)
                {
                    meetings.append({labelPair(i, j), edgei, shift, s});
                }
            }
        }
    }
    return List<edgeMeeting>(std::move(meetings));
}


Foam::scalar Foam::polymer::contactProjection::firstEdgeMeeting
(
    const wallModel& wall,
    const labelUList& chainList,
    const UList<point>& from
) const
{
    scalar first = GREAT;
    for (const edgeMeeting& meeting : edgeMeetings(wall, chainList, from))
    {
        first = min(first, meeting.time);
    }
    return first;
}


Foam::scalar Foam::polymer::contactProjection::firstWallMeeting
(
    const wallModel& wall,
    const labelUList& chainList,
    const UList<point>& from
) const
{
    const List<point>& x = chains_.positions();
    scalar first =
        (wallEdges_ && wall.edges().size())
      ? firstEdgeMeeting(wall, chainList, from)
      : GREAT;
    wallModel::impact hit;
    for (const label c : chainList)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            if (wall.predict(from[i], x[i] - from[i], 1, hit))
            {
                first = min(first, hit.time);
            }
        }
    }
    return first;
}


void Foam::polymer::contactProjection::addWallZones
(
    const wallModel* wall,
    const boolList& moved,
    const UList<point>& positionsAfter
)
{
    // A projected chain whose path meets a wall becomes a zone (which
    // placeZones keeps in the fluid); projected chains move no further, so
    // this is checked once
    if (!wall || !wall->active())
    {
        return;
    }
    forAll(moved, c)
    {
        if
        (
            moved[c]
         && !zones_.inZone(c)
         && firstWallMeeting(*wall, labelList(1, c), positionsAfter) <= 1
        )
        {
            zones_.add(c);
        }
    }
}


Foam::boolList Foam::polymer::contactProjection::rodsToAudit
(
    List<point>& positionsAudited
) const
{
    // The other rods' pairs are on the paths the last audit checked
    const List<point>& x = chains_.positions();
    boolList rodsToCheck;
    if (positionsAudited.size())
    {
        const List<labelPair>& rods = rods_.rods();
        rodsToCheck.setSize(rods.size());
        forAll(rods, rodi)
        {
            const label i = rods[rodi].first(), j = rods[rodi].second();
            rodsToCheck[rodi] =
                x[i] != positionsAudited[i] || x[j] != positionsAudited[j];
        }
    }
    positionsAudited = x;
    return rodsToCheck;
}


bool Foam::polymer::contactProjection::mergeCrossing
(
    const rodCrossingAudit::crossing& crossing,
    const boolList& moved,
    const scalar time
)
{
    // Rods that would cross join one zone; a zone's own rods cannot cross,
    // since it moves rigidly from the step's start
    const label a = chains_.chainOf(crossing.rodA.first());
    const label b = chains_.chainOf(crossing.rodB.first());
    const bool sameZone = zones_.sameZone(a, b);
    if
    (
        !sameZone
     && !moved[a] && !moved[b] && !zones_.inZone(a) && !zones_.inZone(b)
    )
    {
        WarningInFunction
            << "Audit: rods (beads " << crossing.rodA << ") and ("
            << crossing.rodB << ") cross at time " << time
            << " on paths the re-projection did not move" << endl;
        ++counts_.crossingsLeft;
        return false;
    }
    if (!zones_.merge(a, b, crossing.shift))
    {
        // A zone is rigid with one image of each of its chains only: a
        // zone that meets another image of its own chain (it wraps around
        // the period) is held at the step's start, where its chains'
        // images do not move relative to each other
        if (!zones_.held(a))
        {
            zones_.hold(a);
            return true;
        }
        return false;
    }
    return !sameZone;
}


bool Foam::polymer::contactProjection::checkPaths
(
    const rodCrossingAudit& audit,
    const boolList& moved,
    const UList<point>& positionsAfter,
    List<point>& positionsAudited,
    const scalar time
)
{
    if (!uncrossable_)
    {
        return false;
    }

    // A pass checks only the rods the zones placed since the last pass
    const boolList rodsToCheck(rodsToAudit(positionsAudited));
    bool changed = false;
    for
    (
        const rodCrossingAudit::crossing& crossing
      : audit.check(positionsAfter, chains_.positions(), rodsToCheck)
    )
    {
        changed = mergeCrossing(crossing, moved, time) || changed;
    }
    return changed;
}


void Foam::polymer::contactProjection::restoreZones
(
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter
)
{
    for (const labelList& zone : placed_)
    {
        for (const label c : zone)
        {
            for (label i = chains_.start(c); i < chains_.end(c); ++i)
            {
                chains_.positions()[i] = positionsAfter[i];
                chains_.velocities()[i] = velocitiesAfter[i];
            }
            ++counts_.leftOff;
        }
    }
}


void Foam::polymer::contactProjection::countZones
(
    const UList<vector>& velocitiesAfter
)
{
    const List<vector>& v = chains_.velocities();
    forAll(placed_, z)
    {
        const bool wrapped = zones_.held(placed_[z][0]);
        ++counts_.zonesFormed;
        for (const label c : placed_[z])
        {
            ++counts_.zoneChainSteps;
            counts_.stoppedChainSteps += (fractions_[z] < 1 && !wrapped);
            counts_.heldChainSteps += (fractions_[z] == 0);
            counts_.wrappedChainSteps += wrapped;
            const scalar m = chains_.type(c).beadMass();
            for (label i = chains_.start(c); i < chains_.end(c); ++i)
            {
                counts_.energyRemoved +=
                    0.5*m*(magSqr(velocitiesAfter[i]) - magSqr(v[i]));
            }
        }
    }
}


Foam::scalar Foam::polymer::contactProjection::placeZone
(
    const labelList& zone,
    const UList<vector>& offsets,
    const wallModel* wall,
    const UList<point>& positionsStart,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter
)
{
    scalar fraction = zones_.held(zone[0]) ? 0 : 1;
    for (label attempt = 0; attempt <= 5; ++attempt)
    {
        if (attempt == 5)
        {
            fraction = 0;
        }
        rigidImpactZones::place
        (
            chains_, zone, fraction,
            positionsStart, positionsAfter, velocitiesAfter, offsets
        );
        if (!fraction || !wall || !wall->active())
        {
            break;
        }

        // The first meeting of a bead's path from x^n with the walls
        const scalar first = firstWallMeeting(*wall, zone, positionsStart);
        if (first > 1)
        {
            break;
        }
        fraction *= 0.9*first;
    }
    return fraction;
}


void Foam::polymer::contactProjection::placeZones
(
    const wallModel* wall,
    const UList<point>& positionsStart,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter
)
{
    placed_ = zones_.zones(chains_);
    placedOffsets_.setSize(placed_.size());
    fractions_.setSize(placed_.size());
    forAll(placed_, z)
    {
        // Translations relative to the zone's first chain by global id,
        // whichever chain the sets' tree has at its root
        List<vector>& offsets = placedOffsets_[z];
        offsets.clear();
        if (lattice_.size())
        {
            const labelList& zone = placed_[z];
            offsets.setSize(zone.size());
            forAll(zone, k)
            {
                offsets[k] = zones_.offset(zone[k]) - zones_.offset(zone[0]);
            }
        }
        fractions_[z] = placeZone
        (
            placed_[z], offsets, wall,
            positionsStart, positionsAfter, velocitiesAfter
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::contactProjection::chainsOff
(
    boolList& moved
) const
{
    moved.setSize(chains_.nChains());
    moved = false;
    const scalar tolerance = constraint_.lengthTolerance();
    if (tolerance >= GREAT)
    {
        return 0;
    }
    label nOff = 0;
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        if (!(chains_.maxRodLengthError(c) <= tolerance))
        {
            moved[c] = true;
            ++nOff;
        }
    }
    return nOff;
}


void Foam::polymer::contactProjection::project
(
    const UList<point>& positionsStart,
    const scalar deltaT,
    const scalar time,
    const wallModel* wall,
    const rodBoxPairs& candidates,
    boolList& moved
)
{
    // The contacts' state; the projection's directions are its rods
    const List<point> positionsAfter(chains_.positions());
    const List<vector> velocitiesAfter(chains_.velocities());
    zones_.reset(chains_.nChains());
    placed_.clear();
    fractions_.clear();
    forAll(moved, c)
    {
        if (moved[c] && !reprojectChain(c, positionsAfter, deltaT, time))
        {
            zones_.add(c);
        }
    }

    const bool contactRounds =
        maxContactRounds_ > 0 && (uncrossable_ || (wall && wall->active()));
    if (!contactRounds)
    {
        addWallZones(wall, moved, positionsAfter);
    }

    rods_.update(chains_);
    if (edgeClearances_.size() != rods_.size())
    {
        edgeClearances_.clear();
    }
    const rodCrossingAudit audit(rods_.rods(), lattice_, candidates);
    List<point> positionsAudited;
    if (contactRounds)
    {
        // Zones so far (failed projections, wall paths) placed first: the
        // contact rounds' audits see them where the zones put them
        placeZones(wall, positionsStart, positionsAfter, velocitiesAfter);
        resolveContacts
        (
            audit, moved, wall, positionsAfter, velocitiesAfter,
            positionsAudited, time
        );
    }

    const label maxPasses = 3*chains_.nChains() + 2;
    for (label pass = 0; pass < maxPasses; ++pass)
    {
        cpuTimeCxx zoneTimer;
        placeZones(wall, positionsStart, positionsAfter, velocitiesAfter);
        counts_.zoneSeconds += zoneTimer.cpuTimeIncrement();
        const bool changed =
            checkPaths(audit, moved, positionsAfter, positionsAudited, time);
        counts_.auditSeconds += zoneTimer.cpuTimeIncrement();
        if (!changed)
        {
            countZones(velocitiesAfter);
            return;
        }
    }

    WarningInFunction
        << "The rigid impact zones at time " << time << " did not settle in "
        << maxPasses << " passes: " << zones_.nChainsInZones()
        << " chains stay as the contacts left them (rods off)" << endl;
    restoreZones(positionsAfter, velocitiesAfter);
}


void Foam::polymer::contactProjection::correct
(
    const UList<point>& positionsStart,
    const scalar deltaT,
    const scalar time,
    const wallModel* wall,
    const collisionModel& collision
)
{
    // Most steps of a dilute scene have no chain off: no clock read (a
    // system call) for them
    boolList moved;
    const label nOff = chainsOff(moved);
    if (!nOff)
    {
        return;
    }
    counts_.reprojected += nOff;

    // What the collisions know, asked for only on a step with chains to
    // project; the beads' clearances only where they are these chains'
    tmp<scalarField> wallClearances(collision.wallClearances());
    wallClearances_.transfer(wallClearances.ref());
    if (wallClearances_.size() != chains_.nBeads())
    {
        wallClearances_.clear();
    }
    tmp<scalarField> edgeClearances(collision.edgeClearances());
    edgeClearances_.transfer(edgeClearances.ref());

    cpuTimeCxx timer;
    project
    (
        positionsStart, deltaT, time, wall, collision.candidatePairs(), moved
    );
    counts_.seconds += timer.cpuTimeIncrement();
}


Foam::polymer::contactProjection::runCounts
Foam::polymer::contactProjection::runCounts::reduced() const
{
    runCounts all(*this);
    packedReduction reduction;
    reduction.sum(all.reprojected);
    reduction.sum(all.notConverged);
    reduction.sum(all.zoneChainSteps);
    reduction.sum(all.stoppedChainSteps);
    reduction.sum(all.heldChainSteps);
    reduction.sum(all.wrappedChainSteps);
    reduction.sum(all.leftOff);
    reduction.sum(all.zonesFormed);
    reduction.sum(all.energyRemoved);
    reduction.sum(all.seconds);
    reduction.sum(all.zoneSeconds);
    reduction.sum(all.auditSeconds);
    reduction.sum(all.crossingsLeft);
    reduction.sum(all.contactGroups);
    reduction.sum(all.contactChainSteps);
    reduction.sum(all.contactsHeld);
    reduction.sum(all.wallContactsHeld);
    reduction.sum(all.groupSolves);
    reduction.sum(all.groupFailures);
    reduction.sum(all.contactSeconds);
    reduction.reduce();
    return all;
}


void Foam::polymer::contactProjection::writeReport(Ostream& os) const
{
    const runCounts all(counts_.reduced());
    os  << "    re-projection after contacts: chain-steps "
        << scalar(all.reprojected)
        << ", not converged " << scalar(all.notConverged)
        << "; rigid impact zones " << scalar(all.zonesFormed)
        << " of " << scalar(all.zoneChainSteps)
        << " chain-steps, stopped short by a wall "
        << scalar(all.stoppedChainSteps)
        << ", held at the step's start " << scalar(all.heldChainSteps)
        << ", kinetic energy removed " << all.energyRemoved
        << "; chain-steps left off " << scalar(all.leftOff)
        << ", crossings left " << scalar(all.crossingsLeft)
        << "; chain-steps held for a zone wrapping around the period "
        << scalar(all.wrappedChainSteps)
        << "; CPU " << all.seconds
        << " s (placing zones " << all.zoneSeconds
        << " s, auditing the paths " << all.auditSeconds << " s)" << nl
        << "    contact constraints before the zones: groups "
        << scalar(all.contactGroups) << " of " << scalar(all.contactChainSteps)
        << " chain-steps held apart by " << scalar(all.contactsHeld)
        << " contacts (" << scalar(all.wallContactsHeld)
        << " of them with a wall: a bead's, or a rod's with an edge);"
        << " group solves " << scalar(all.groupSolves)
        << ", failed (made zones) " << scalar(all.groupFailures)
        << "; CPU " << all.contactSeconds << " s" << nl;
}


void Foam::polymer::contactProjection::writeRunTotals(dictionary& dict) const
{
    const runCounts all(counts_.reduced());
    dictionary& totals = dict.subDictOrAdd("reprojection");
    runTotals::add(totals, "reprojected", all.reprojected);
    runTotals::add(totals, "notConverged", all.notConverged);
    runTotals::add(totals, "zoneChainSteps", all.zoneChainSteps);
    runTotals::add(totals, "stoppedChainSteps", all.stoppedChainSteps);
    runTotals::add(totals, "heldChainSteps", all.heldChainSteps);
    runTotals::add(totals, "wrappedChainSteps", all.wrappedChainSteps);
    runTotals::add(totals, "leftOff", all.leftOff);
    runTotals::add(totals, "zonesFormed", all.zonesFormed);
    runTotals::add(totals, "crossingsLeft", all.crossingsLeft);
    runTotals::add(totals, "energyRemoved", all.energyRemoved);
    runTotals::add(totals, "contactGroups", all.contactGroups);
    runTotals::add(totals, "contactChainSteps", all.contactChainSteps);
    runTotals::add(totals, "contactsHeld", all.contactsHeld);
    runTotals::add(totals, "wallContactsHeld", all.wallContactsHeld);
    runTotals::add(totals, "groupSolves", all.groupSolves);
    runTotals::add(totals, "groupFailures", all.groupFailures);
}


void Foam::polymer::contactProjection::readRunTotals(const dictionary& dict)
{
    const dictionary* saved = dict.findDict("reprojection");
    if (!saved)
    {
        return;
    }
    runTotals::read(*saved, "reprojected", counts_.reprojected);
    runTotals::read(*saved, "notConverged", counts_.notConverged);
    runTotals::read(*saved, "zoneChainSteps", counts_.zoneChainSteps);
    runTotals::read(*saved, "stoppedChainSteps", counts_.stoppedChainSteps);
    runTotals::read(*saved, "heldChainSteps", counts_.heldChainSteps);
    runTotals::read(*saved, "wrappedChainSteps", counts_.wrappedChainSteps);
    runTotals::read(*saved, "leftOff", counts_.leftOff);
    runTotals::read(*saved, "zonesFormed", counts_.zonesFormed);
    runTotals::read(*saved, "crossingsLeft", counts_.crossingsLeft);
    runTotals::read(*saved, "energyRemoved", counts_.energyRemoved);
    runTotals::read(*saved, "contactGroups", counts_.contactGroups);
    runTotals::read(*saved, "contactChainSteps", counts_.contactChainSteps);
    runTotals::read(*saved, "contactsHeld", counts_.contactsHeld);
    runTotals::read(*saved, "wallContactsHeld", counts_.wallContactsHeld);
    runTotals::read(*saved, "groupSolves", counts_.groupSolves);
    runTotals::read(*saved, "groupFailures", counts_.groupFailures);
}


// ************************************************************************* //
