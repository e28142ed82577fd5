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

#include "elasticRods.H"
#include "checkedInput.H"
#include "rodCrossingAudit.H"
#include "makePolymerModel.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(collisionModel, collisionModels, elasticRods)

const Foam::Enum
<
    Foam::polymer::collisionModels::elasticRods::impulseType
>
Foam::polymer::collisionModels::elasticRods::impulseTypeNames
({
    { impulseType::dumbbell, "dumbbell" },
    { impulseType::constrained, "constrained" },
});

const Foam::Enum
<
    Foam::polymer::collisionModels::elasticRods::velocityImpulseType
>
Foam::polymer::collisionModels::elasticRods::velocityImpulseTypeNames
({
    { velocityImpulseType::pathChange, "pathChange" },
    { velocityImpulseType::elastic, "elastic" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::collisionModels::elasticRods::elasticRods(const dictionary& dict)
:
    collisionModel(typeName, dict),
    rootSolver_
    (
        crossingRootSolver::New
        (
            coeffDict_.getOrDefault<word>("rootSolver", "isolating"),
            coeffDict_
        )
    ),
    maxEvents_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxEvents", 100000, 1, "<events per time step>"
        )
    ),
    stallTime_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_, "stallTime", 1e-9, "<event spacing / deltaT>"
        )
    ),
    stallEvents_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "stallEvents", 100, 1, "<successive short events>"
        )
    ),
    audit_(coeffDict_.getOrDefault<bool>("audit", false)),
    impulse_
    (
        checkedInput::enumOrDefault
        (
            coeffDict_, "impulse", impulseTypeNames, impulseType::constrained
        )
    ),
    velocityImpulse_
    (
        checkedInput::enumOrDefault
        (
            coeffDict_, "velocityImpulse", velocityImpulseTypeNames,
            impulse_ == impulseType::constrained
          ? velocityImpulseType::elastic
          : velocityImpulseType::pathChange
        )
    ),
    wallEdges_(coeffDict_.getOrDefault<bool>("wallEdges", true)),
    rods_(),
    position_(),
    velocity_(),
    beadTime_(),
    deltaT_(0),
    drift_(),
    pairBudget_(),
    rodLimit_(),
    rodClosePairs_(),
    pairListed_(),
    pairStamp_(),
    wallBudget_(),
    grid_(),
    queue_(),
    deferredPairs_(),
    deferredBrackets_(),
    contacts_(),
    edgePairs_(),
    edgePairIndex_(),
    edgeContacts_(),
    snapshots_(),
    wall_(nullptr),
    projection_(),
    changedBeads_(),
    rodStamp_(),
    repredictions_(0),
    rodsToPredict_(),
    rodsBeyondLimit_(),
    frozenChains_(),
    heldChains_()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boundBox Foam::polymer::collisionModels::elasticRods::sweep
(
    const label rod,
    const scalar t,
    const scalar dt
) const
{
    boundBox box(positionAt(rods_[rod].first(), t));
    box.add(positionAt(rods_[rod].second(), t));
    box.add(positionAt(rods_[rod].first(), dt));
    box.add(positionAt(rods_[rod].second(), dt));
    return box;
}


Foam::scalar Foam::polymer::collisionModels::elasticRods::growMargin
(
    const label rod,
    const scalar t,
    const scalar dt
) const
{
    // Half the rod's motion over the rest of the step: an event on its
    // chain changes its path by a part of that
    const scalar rest = dt - t;
    return 0.5*rest*max
    (
        mag(velocity_[rods_[rod].first()]),
        mag(velocity_[rods_[rod].second()])
    );
}


bool Foam::polymer::collisionModels::elasticRods::sweptApart
(
    const FixedList<point, 4>& x,
    const FixedList<vector, 4>& moved,
    scalar& clearance
)
{
    const scalar margin = 1e-4*(mag(x[1] - x[0]) + mag(x[3] - x[2]));

    // Swept boxes apart: the extent of rod k's (beads 2k, 2k+1) paths
    const auto extent = [&](const label k, const direction d)
    {
        const scalar p0 = x[2*k][d], p1 = x[2*k + 1][d];
        const scalar q0 = p0 + moved[2*k][d], q1 = p1 + moved[2*k + 1][d];
        return std::make_pair
        (
            min(min(p0, p1), min(q0, q1)), max(max(p0, p1), max(q0, q1))
        );
    };
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const std::pair<scalar, scalar> a = extent(0, d);
        const std::pair<scalar, scalar> b = extent(1, d);
        if (a.first > b.second + margin || b.first > a.second + margin)
        {
            clearance = max(a.first - b.second, b.first - a.second) - margin;
            return true;
        }
    }

    // Or the rods' distance now more than they can close: a point of a rod
    // moves by a weighted mean of its beads' motions, so two points close
    // by at most the largest relative motion of a bead of each
    scalar closing = 0;
    for (label i = 0; i < 2; ++i)
    {
        for (label j = 2; j < 4; ++j)
        {
            closing = max(closing, magSqr(moved[i] - moved[j]));
        }
    }
    point onA, onB;
    const scalar distance =
        linePointRef(x[0], x[1]).nearestDist(linePointRef(x[2], x[3]), onA, onB);
    const scalar reach = std::sqrt(closing);
    clearance = distance - (reach + margin);
    if (clearance > 0)
    {
        return true;
    }

    // Or the distance at the middles of pieces of the rest more than the
    // rods can close over half a piece: rods close in on each other over
    // a step, but seldom meet
    scalar lowest = GREAT;
    for (label k = 0; k < nApartPieces; ++k)
    {
        const scalar s = (k + 0.5)/nApartPieces;
        lowest = min
        (
            lowest,
            linePointRef(x[0] + s*moved[0], x[1] + s*moved[1]).nearestDist
            (
                linePointRef(x[2] + s*moved[2], x[3] + s*moved[3]), onA, onB
            )
        );
        clearance = lowest - (0.5*reach/nApartPieces + margin);
        if (clearance <= 0)
        {
            return false;
        }
    }
    return true;
}


void Foam::polymer::collisionModels::elasticRods::predict
(
    const label pairi,
    const scalar t,
    const scalar dt
)
{
    const labelPair& rodPair = grid_.pairs()[pairi];
    const label a0 = rods_[rodPair.first()].first();
    const label a1 = rods_[rodPair.first()].second();
    const label b0 = rods_[rodPair.second()].first();
    const label b1 = rods_[rodPair.second()].second();
    const vector& shift = grid_.pairShift(pairi);

    const FixedList<point, 4> x
    ({
        positionAt(a0, t), positionAt(a1, t),
        positionAt(b0, t) + shift, positionAt(b1, t) + shift
    });
    const FixedList<vector, 4> v
    ({
        velocity_[a0], velocity_[a1], velocity_[b0], velocity_[b1]
    });

    // A crossing is a point of both rods at one time: rods that stay
    // apart need no crossing-time solve. The margin is far beyond the
    // round-off of the lines' distance at a crossing the root solvers
    // place (they accept one with the rods' closest points inside both
    // rods, at an angle of at least 1e-6)
    const scalar rest = dt - t;
    sizePairData();
    scalar clearance = 0;
    if
    (
        sweptApart
        (
            x, {rest*v[0], rest*v[1], rest*v[2], rest*v[3]}, clearance
        )
    )
    {
        pairBudget_[pairi] = clearance + pairDrift(pairi);
        limitDrift(pairi);
        return;
    }
    pairBudget_[pairi] = -GREAT;
    listClosePair(pairi);

    const rodPairCrossing pair
    (
        x[0], x[1], x[2], x[3], v[0], v[1], v[2], v[3]
    );

    label side = 0;
    bool atContact = false;
    crossingRootSolver::bracket next;
    const scalar s = contacts_.earliestCrossing
    (
        pairi, pair, *rootSolver_, dt - t, side, atContact, next
    );
    ++counters_.pairChecks;

    if (debug > 1 && s >= 0 && next.interval < 0)
    {
        const FixedList<scalar, 4> c = pair.tripleProductCubic();
        scalar li, lj;
        pair.intersection(s, li, lj);
        Pout<< "    predict pair " << rods_[rodPair.first()] << ' '
            << rods_[rodPair.second()] << " from " << t << ": s " << s
            << " V " << c << " lambda " << li << ' ' << lj << endl;
    }

    if (s >= 0)
    {
        event e;
        e.time = t + s;
        e.pair = pairi;
        e.from = t;
        e.offset = s;
        e.normal = Zero;
        e.patch = -1;
        e.side = side;
        e.atContact = atContact;
        e.beads = FixedList<label, 4>({a0, a1, b0, b1});
        if (next.interval >= 0)
        {
            e.deferred = deferredPairs_.size();
            deferredPairs_.push_back(pair);
            deferredBrackets_.push_back(next);
        }
        queue_.push(e);
    }
}


void Foam::polymer::collisionModels::elasticRods::continuePrediction
(
    const event& e,
    const scalar dt
)
{
    // The search from the same paths and rest of the step as predicted:
    // the same crossing as a search that was not deferred
    crossingRootSolver::bracket& next = deferredBrackets_[e.deferred];
    label side = e.side;
    const scalar s = pairContacts::continueCrossing
    (
        deferredPairs_[e.deferred], *rootSolver_, dt - e.from, side, next
    );
    if (s >= 0)
    {
        event found(e);
        found.time = e.from + s;
        found.offset = s;
        found.side = side;
        if (next.interval < 0)
        {
            found.deferred = -1;
        }
        queue_.push(found);
    }
}


void Foam::polymer::collisionModels::elasticRods::predictWall
(
    const label bead,
    const scalar t,
    const scalar dt
)
{
    // A path shorter than the walls' clearance meets none (as predict
    // finds), nor does a path that drifts from it by less than the rest
    const point x(positionAt(bead, t));
    const scalar path = (dt - t)*mag(velocity_[bead]);
    const scalar clearance = wall_->clearance(x);
    if (path < clearance)
    {
        wallBudget_[bead] = clearance - path + drift_[bead];
        return;
    }
    wallBudget_[bead] = -GREAT;

    wallModel::impact hit;
    if (wall_->predict(x, velocity_[bead], dt - t, hit))
    {
        event e;
        e.time = t + hit.time;
        e.pair = -1 - bead;
        e.from = t;
        e.offset = hit.time;
        e.normal = hit.normal;
        e.patch = hit.patch;
        e.side = 0;
        e.atContact = false;
        e.beads = FixedList<label, 4>({bead, -1, -1, -1});
        queue_.push(e);
    }
}


void Foam::polymer::collisionModels::elasticRods::repredict
(
    const labelUList& beads,
    const scalar t,
    const scalar dt
)
{
    rodStamp_.resize(rods_.size(), 0);
    if (++repredictions_ == labelMax)
    {
        std::fill(rodStamp_.begin(), rodStamp_.end(), 0);
        std::fill(pairStamp_.begin(), pairStamp_.end(), 0);
        repredictions_ = 1;
    }
    rodsToPredict_.clear();
    for (const label bead : beads)
    {
        for (const label rod : rods_.beadRods(bead))
        {
            if (rod >= 0 && rodStamp_[rod] != repredictions_)
            {
                rodStamp_[rod] = repredictions_;
                rodsToPredict_.append(rod);
            }
        }
    }

    // Grow the broad phase where the new paths leave the rods' boxes. A
    // rod with new candidate pairs, or drifted beyond its limit, has its
    // pairs looked at; the others keep the stamp of no re-prediction
    const bool edges = wall_ && wallEdges_ && wall_->edges().size();
    rodsBeyondLimit_.clear();
    for (const label rod : rodsToPredict_)
    {
        const boundBox box(sweep(rod, t, dt));
        const bool grown = grid_.grow(rod, box, growMargin(rod, t, dt));
        if (edges)
        {
            predictEdges(rod, box, t, dt);
        }
        if (grown || !(rodDrift(rod) < rodLimit_[rod]))
        {
            rodsBeyondLimit_.append(rod);
        }
        else
        {
            rodStamp_[rod] = 0;
        }
    }

    sizePairData();

    // A pair of two such rods from its first rod only. Each rod's limit
    // anew from its pairs' budgets, the partners' lowered to match
    for (const label rod : rodsBeyondLimit_)
    {
        scalar limit = GREAT;
        for (const label pairi : grid_.rodPairs(rod))
        {
            const labelPair& pair = grid_.pairs()[pairi];
            if
            (
                (
                    pair.first() == rod
                 || rodStamp_[pair.first()] != repredictions_
                )
             && pairStamp_[pairi] != repredictions_
             && !stillApart(pairi)
            )
            {
                pairStamp_[pairi] = repredictions_;
                predict(pairi, t, dt);
            }
            limit = min(limit, limitDrift(pairi, rod));
        }
        rodLimit_[rod] = limit;
    }

    // The close pairs of the others
    for (const label rod : rodsToPredict_)
    {
        if (rodStamp_[rod] != repredictions_)
        {
            predictClosePairs(rod, t, dt);
        }
    }

    if (wall_)
    {
        for (const label bead : beads)
        {
            if (!(drift_[bead] < wallBudget_[bead]))
            {
                predictWall(bead, t, dt);
            }
        }
    }
}


void Foam::polymer::collisionModels::elasticRods::listClosePair
(
    const label pairi
)
{
    const labelPair& pair = grid_.pairs()[pairi];
    if (!(pairListed_[pairi] & 1))
    {
        rodClosePairs_[pair.first()].push_back(pairi);
    }
    if (!(pairListed_[pairi] & 2))
    {
        rodClosePairs_[pair.second()].push_back(pairi);
    }
    pairListed_[pairi] = 3;
}


void Foam::polymer::collisionModels::elasticRods::predictClosePairs
(
    const label rod,
    const scalar t,
    const scalar dt
)
{
    std::vector<label>& close = rodClosePairs_[rod];
    for (size_t k = 0; k < close.size(); )
    {
        const label pairi = close[k];
        if (pairBudget_[pairi] != -GREAT)
        {
            pairListed_[pairi] &= (grid_.pairs()[pairi].first() == rod) ? 2 : 1;
            close[k] = close.back();
            close.pop_back();
            continue;
        }
        if (pairStamp_[pairi] != repredictions_)
        {
            pairStamp_[pairi] = repredictions_;
            predict(pairi, t, dt);
        }
        ++k;
    }
}


void Foam::polymer::collisionModels::elasticRods::resolveWall
(
    const event& e,
    const polymerChains& chains,
    UList<vector>& velocitiesDagger
)
{
    const label bead = -1 - e.pair;

    position_[bead] = positionAt(bead, e.from) + e.offset*velocity_[bead];
    beadTime_[bead] = e.time;

    if
    (
        impulse_ == impulseType::constrained
     && wall_->interaction(e.patch) == wallModel::interactionType::rebound
     && reboundConstrained(e, chains, velocitiesDagger)
    )
    {
        return;
    }

    // A bead that escapes, sticks or is rejected stops: its chain takes
    // no impulse through its rods for the rest of the step
    if (wall_->interaction(e.patch) != wallModel::interactionType::rebound)
    {
        frozenChains_.append(chains.chainOf(bead));
    }
    changedBeads_.clear();
    changedBeads_.append(bead);
    vector v(velocity_[bead]);
    wall_->interact
    (
        bead,
        wallModel::impact{e.offset, e.normal, e.patch},
        v,
        velocitiesDagger[bead]
    );
    setVelocity(bead, v);
}


void Foam::polymer::collisionModels::elasticRods::snapshot(const scalar t)
{
    List<point> positions(position_.size());
    forAll(positions, i)
    {
        positions[i] = positionAt(i, t);
    }
    snapshots_.append(std::move(positions));
}


Foam::label Foam::polymer::collisionModels::elasticRods::auditStep
(
    const scalar time
)
{
    const List<rodCrossingAudit::crossing> found =
        rodCrossingAudit(rods_.rods(), lattice_).check(snapshots_);

    for (const rodCrossingAudit::crossing& c : found)
    {
        WarningInFunction
            << "Audit: rods (beads " << c.rodA << ") and (" << c.rodB
            << (c.shift == vector::zero ? ")" : ") translated by ")
            << (c.shift == vector::zero ? "" : Foam::name(c.shift))
            << " crossed in the step to time " << time
            << ", after event " << c.piece << " of the step" << endl;
    }
    const label nFound = found.size();

    snapshots_.clear();
    return nFound;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::collisionModels::elasticRods::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time,
    const wallModel* wall
)
{
    wall_ = (wall && wall->active()) ? wall : nullptr;
    frozenChains_.clear();
    heldChains_.clear();

    const label nBeads = chains.nBeads();
    List<vector>& x = chains.positions();
    List<vector>& vDagger = chains.velocities();

    rods_.update(chains);

    // Straight paths over the step (paper eq. 1), in step time [0, dt]
    position_ = positionsOld;
    velocity_.resize(nBeads);
    for (label i = 0; i < nBeads; ++i)
    {
        velocity_[i] = (x[i] - positionsOld[i])/deltaT;
    }
    beadTime_.resize(nBeads);
    beadTime_ = 0;
    deltaT_ = deltaT;
    drift_.resize(nBeads);
    drift_ = 0;
    wallBudget_.resize(nBeads);
    wallBudget_ = -GREAT;

    // Broad phase: rods whose swept boxes, with the margin that an event
    // on their chains grows them by, overlap. Most rods of a crowded
    // scene take an impulse through their chain within the step: grown
    // at once, their boxes need not be inserted a second time then
    List<boundBox> boxes(rods_.size());
    forAll(boxes, rod)
    {
        const boundBox swept(sweep(rod, 0, deltaT));
        const vector fat(vector::uniform(growMargin(rod, 0, deltaT)));
        boxes[rod] = boundBox(swept.min() - fat, swept.max() + fat);
    }
    grid_.build(rods_, std::move(boxes), lattice_);
    pairBudget_.assign(grid_.pairs().size(), -GREAT);
    pairListed_.assign(grid_.pairs().size(), 0);
    pairStamp_.assign(grid_.pairs().size(), 0);
    rodLimit_.assign(rods_.size(), GREAT);
    rodClosePairs_.resize(rods_.size());
    for (std::vector<label>& close : rodClosePairs_)
    {
        close.clear();
    }

    queue_.reset(nBeads);
    deferredPairs_.clear();
    deferredBrackets_.clear();
    contacts_.clear();
    edgeContacts_.clear();
    edgePairs_.clear();
    edgePairIndex_.clear();
    forAll(grid_.pairs(), pairi)
    {
        predict(pairi, 0, deltaT);
    }
    if (wall_)
    {
        for (label bead = 0; bead < nBeads; ++bead)
        {
            predictWall(bead, 0, deltaT);
        }
        if (wallEdges_ && wall_->edges().size())
        {
            forAll(rods_.rods(), rod)
            {
                predictEdges(rod, sweep(rod, 0, deltaT), 0, deltaT);
            }
        }
    }

    if (audit_)
    {
        snapshots_.clear();
        snapshot(0);
    }

    // Multi-collision loop: earliest event first
    label nEvents = 0;
    label nWallEvents = 0;
    label nShort = 0;
    scalar now = 0;
    bool runaway = false;

    event e;
    while (queue_.next(e))
    {
        if (e.deferred >= 0)
        {
            continuePrediction(e, deltaT);
            continue;
        }

        const bool wallEvent = (e.pair < 0);

        nShort = (e.time - now < stallTime_*deltaT) ? nShort + 1 : 0;
        now = e.time;

        runaway = (nEvents + nWallEvents >= maxEvents_);
        const pairContacts& followed = e.edge ? edgeContacts_ : contacts_;
        if
        (
            runaway
         || nShort >= stallEvents_
         || (!wallEvent && followed.contactStreak(e.pair) >= stallEvents_)
        )
        {
            reportStall
            (
                chains, e, time - deltaT + now, nEvents + nWallEvents
            );
            ++counters_.stalls;
            if (runaway)
            {
                break;
            }
            holdStalled(chains, e, deltaT);
            nShort = 0;
            continue;
        }

        if (audit_)
        {
            snapshot(now);
        }

        if (e.edge)
        {
            ++nWallEvents;
            if (resolveEdge(e, chains, vDagger))
            {
                ++counters_.edgeContacts;
                repredict(changedBeads_, now, deltaT);
            }
            else
            {
                ++counters_.unresolved;
            }
            continue;
        }

        if (wallEvent)
        {
            ++nWallEvents;
            resolveWall(e, chains, vDagger);
            repredict(changedBeads_, now, deltaT);
            continue;
        }

        if (!resolve(e, chains, vDagger))
        {
            // No contact to push along: the rods will pass through each
            // other unless a later event turns them
            if (!totalCounters_.unresolved && !counters_.unresolved)
            {
                WarningInFunction
                    << "A rod-rod event at time " << time - deltaT + now
                    << " (beads " << e.beads << ") has no contact normal"
                    << " (rods parallel without overlap): not resolved;"
                    << " such events are counted in the final report"
                    << endl;
            }
            ++counters_.unresolved;
            continue;
        }
        ++nEvents;

        const labelPair& pair = grid_.pairs()[e.pair];
        if (debug)
        {
            Pout<< "elasticRods: event " << nEvents << " at " << now
                << " rods " << rods_[pair.first()] << ' '
                << rods_[pair.second()] << " snapshot "
                << snapshots_.size() - 1 << endl;
        }

        // Re-predict every event of the beads whose course changed
        repredict(changedBeads_, now, deltaT);
    }

    // x^{n+1}: the end of the paths (held chains stay where they were
    // held), or the last uncrossed state of a runaway loop
    const scalar end = runaway ? now : deltaT;
    for (label i = 0; i < nBeads; ++i)
    {
        x[i] = positionAt(i, end);
    }

    if (audit_)
    {
        snapshot(end);
        counters_.auditCrossings += auditStep(time);
    }

    ++counters_.steps;
    counters_.events += nEvents;
    counters_.maxEventsPerStep = max(counters_.maxEventsPerStep, nEvents);
}


// ************************************************************************* //
