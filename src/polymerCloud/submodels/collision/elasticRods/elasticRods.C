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
    boxSlack_(),
    slackRoundOff_(0),
    rodClosePairs_(),
    pairListed_(),
    pairStamp_(),
    pairLazyBudget_(),
    pairLazyTime_(),
    pairSerial_(),
    pairLazyQueued_(),
    wallBudget_(),
    edgeBudget_(),
    edgeDistanceBudget_(),
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
    edgeBudget_.resize(rods_.size());
    edgeBudget_ = -GREAT;
    edgeDistanceBudget_.resize(rods_.size());
    edgeDistanceBudget_ = -GREAT;

    // Broad phase: rods whose swept boxes, with the margin that an event
    // on their chains grows them by, overlap. Most rods of a crowded
    // scene take an impulse through their chain within the step: grown
    // at once, their boxes need not be inserted a second time then
    List<boundBox> boxes(rods_.size());
    boxSlack_.resize(rods_.size());
    boundBox bounds;
    forAll(boxes, rod)
    {
        const boundBox swept(sweep(rod, 0, deltaT));
        boxSlack_[rod] = growMargin(rod, 0, deltaT);
        const vector fat(vector::uniform(boxSlack_[rod]));
        boxes[rod] = boundBox(swept.min() - fat, swept.max() + fat);
        bounds.add(boxes[rod]);
    }
    // The paths' points are computed again at each event (positionAt):
    // a few roundings of the coordinates, far below a relative 1e-12
    slackRoundOff_ =
        1e-12
       *(cmptMax(cmptMag(bounds.min())) + cmptMax(cmptMag(bounds.max())));
    grid_.build(rods_, std::move(boxes), lattice_);
    resetPredictions(nBeads);
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
                predictEdges(rod, 0, deltaT);
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
        if (e.revalidate >= 0)
        {
            // Unless predicted since
            if (e.revalidate == pairSerial_[e.pair])
            {
                predict(e.pair, e.time, deltaT);
            }
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
    counters_.collidingPairs += contacts_.nResolved();
}


// ************************************************************************* //
