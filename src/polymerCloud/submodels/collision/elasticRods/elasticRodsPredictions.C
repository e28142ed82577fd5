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
#include "segmentDistance.H"

#include <cmath>

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
    const scalar reach = std::sqrt(closing);
    clearance =
        std::sqrt(segmentDistanceSqr(x[0], x[1], x[2], x[3]))
      - (reach + margin);
    if (clearance > 0)
    {
        return true;
    }

    // Or the distance at the middles of pieces of the rest more than the
    // rods can close over half a piece: rods close in on each other over
    // a step, but seldom meet
    const scalar pieceReach = 0.5*reach/nApartPieces + margin;
    scalar lowestSqr = GREAT;
    for (label k = 0; k < nApartPieces; ++k)
    {
        const scalar s = (k + 0.5)/nApartPieces;
        lowestSqr = min
        (
            lowestSqr,
            segmentDistanceSqr
            (
                x[0] + s*moved[0], x[1] + s*moved[1],
                x[2] + s*moved[2], x[3] + s*moved[3]
            )
        );
        if (!(lowestSqr > sqr(pieceReach)))
        {
            clearance = std::sqrt(lowestSqr) - pieceReach;
            return false;
        }
    }
    clearance = std::sqrt(lowestSqr) - pieceReach;
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

    // Filled element by element, not from initializer lists (and the
    // velocities not copied at all): GCC copied those through the stack in
    // pieces of other widths than it then read, and each read waited for
    // the stores (failed store forwarding)
    FixedList<point, 4> x;
    x[0] = positionAt(a0, t);
    x[1] = positionAt(a1, t);
    x[2] = positionAt(b0, t) + shift;
    x[3] = positionAt(b1, t) + shift;
    const vector& va0 = velocity_[a0];
    const vector& va1 = velocity_[a1];
    const vector& vb0 = velocity_[b0];
    const vector& vb1 = velocity_[b1];

    // A crossing is a point of both rods at one time: rods that stay
    // apart need no crossing-time solve. The margin is far beyond the
    // round-off of the lines' distance at a crossing the root solvers
    // place (they accept one with the rods' closest points inside both
    // rods, at an angle of at least 1e-6)
    const scalar rest = dt - t;
    FixedList<vector, 4> moved;
    moved[0] = rest*va0;
    moved[1] = rest*va1;
    moved[2] = rest*vb0;
    moved[3] = rest*vb1;
    sizePairData();
    ++pairSerial_[pairi];
    pairLazyBudget_[pairi] = -GREAT;
    pairLazyQueued_[pairi] = 0;
    scalar clearance = 0;
    if (sweptApart(x, moved, clearance))
    {
        pairBudget_[pairi] = clearance + pairDrift(pairi);
        limitDrift(pairi);
        return;
    }
    pairBudget_[pairi] = -GREAT;
    listClosePair(pairi);

    const rodPairCrossing pair
    (
        x[0], x[1], x[2], x[3], va0, va1, vb0, vb1
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

        // No crossing before half the time to it while the beads' paths
        // drift less than V's distance from zero over that half allows:
        // a change of course within that is predicted then, not now
        const scalar lazy = 0.5*s;
        const scalar keep =
            lazy > 0
          ? pair.signKeepingDrift(lazy, pairContacts::bandMargin(pair))
          : 0;
        if (keep > 0)
        {
            pairLazyBudget_[pairi] = keep + pairDrift(pairi);
            pairLazyTime_[pairi] = t + lazy;
        }
    }
    else
    {
        // No crossing over the rest: none either while the beads' paths
        // drift less than V's distance from zero allows (a budget as an
        // apart pair's), kept clear of the contacts' band of V
        const scalar keep =
            pair.signKeepingDrift(rest, pairContacts::bandMargin(pair));
        if (keep > 0)
        {
            pairBudget_[pairi] = keep + pairDrift(pairi);
            limitDrift(pairi);
        }
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
    // A path shorter than the walls' clearance (the voxels' far from the
    // walls) meets none (as predict finds), nor does a path that drifts
    // from it by less than the rest
    const point x(positionAt(bead, t));
    const scalar path = (dt - t)*mag(velocity_[bead]);
    const scalar clearance = wall_->clearance(x, 0);
    if (path < clearance)
    {
        wallBudget_[bead] = clearance - path + drift_[bead];
        return;
    }

    // Near a wall, the faces' clearance from the path itself, sought up
    // to the path's length: a bead held against a wall by its chain is
    // predicted again at every impulse on the chain, and one search of
    // the faces' bounds clears a path that stays off the wall; only the
    // others are cast as rays
    const scalar keep =
        wall_->pathClearance(x, velocity_[bead], dt - t, path);
    if (keep > 0)
    {
        wallBudget_[bead] = keep + drift_[bead];
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


void Foam::polymer::collisionModels::elasticRods::resetPredictions
(
    const label nBeads
)
{
    const label nPairs = grid_.pairs().size();
    pairBudget_.assign(nPairs, -GREAT);
    pairListed_.assign(nPairs, 0);
    pairStamp_.assign(nPairs, 0);
    pairLazyBudget_.assign(nPairs, -GREAT);
    pairLazyTime_.assign(nPairs, 0);
    pairSerial_.assign(nPairs, 0);
    pairLazyQueued_.assign(nPairs, 0);
    rodLimit_.assign(rods_.size(), GREAT);
    rodClosePairs_.resize(rods_.size());
    for (std::vector<label>& close : rodClosePairs_)
    {
        close.clear();
    }

    queue_.reset(nBeads);
    deferredPairs_.clear();
    deferredBrackets_.clear();
}


void Foam::polymer::collisionModels::elasticRods::stampRods
(
    const labelUList& beads
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
}


bool Foam::polymer::collisionModels::elasticRods::growBox
(
    const label rod,
    const scalar t,
    const scalar dt
)
{
    // A point of the rod's path strays from the path its box was formed
    // round by at most the rod's drift since then: within the box's gap
    // from that path, the box holds it (no sweep). Else swept: a box that
    // holds the new path (its gap from it not negative) keeps the larger
    // of the two slacks; one that does not grows round it, by the margin
    const scalar drift = rodDrift(rod);
    if (drift + slackRoundOff_ < boxSlack_[rod])
    {
        return false;
    }
    const boundBox box(sweep(rod, t, dt));
    const boundBox& held = grid_.boxes()[rod];
    const scalar gap = min
    (
        cmptMin(box.min() - held.min()),
        cmptMin(held.max() - box.max())
    );
    if (gap >= 0)
    {
        boxSlack_[rod] = max(boxSlack_[rod], drift + gap);
        return false;
    }
    // The margin (two square roots) only for a box that grows
    const scalar margin = growMargin(rod, t, dt);
    boxSlack_[rod] = drift + margin;
    return grid_.grow(rod, box, margin);
}


void Foam::polymer::collisionModels::elasticRods::growBoxes
(
    const scalar t,
    const scalar dt
)
{
    // A rod with new candidate pairs, or drifted beyond its limit, has
    // its pairs looked at; the others lose the re-prediction's stamp
    const bool edges = wall_ && wallEdges_ && wall_->edges().size();
    rodsBeyondLimit_.clear();
    for (const label rod : rodsToPredict_)
    {
        const bool grown = growBox(rod, t, dt);
        if (edges && !(rodDrift(rod) < edgeBudget_[rod]))
        {
            predictEdges(rod, t, dt);
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
}


void Foam::polymer::collisionModels::elasticRods::lookAtPairs
(
    const label rod,
    const scalar t,
    const scalar dt
)
{
    // A pair of two such rods from its first rod only. The rod's limit
    // anew from its pairs' budgets, the partners' lowered to match
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
            if (!predictLater(pairi, t))
            {
                predict(pairi, t, dt);
            }
        }
        limit = min(limit, limitDrift(pairi, rod));
    }
    rodLimit_[rod] = limit;
}


void Foam::polymer::collisionModels::elasticRods::repredict
(
    const labelUList& beads,
    const scalar t,
    const scalar dt
)
{
    stampRods(beads);

    // Grow the broad phase where the new paths leave the rods' boxes
    growBoxes(t, dt);

    for (const label rod : rodsBeyondLimit_)
    {
        lookAtPairs(rod, t, dt);
    }
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


Foam::tmp<Foam::scalarField>
Foam::polymer::collisionModels::elasticRods::wallClearances() const
{
    tmp<scalarField> tclearances(new scalarField(wallBudget_.size()));
    scalarField& clearances = tclearances.ref();
    forAll(clearances, bead)
    {
        clearances[bead] = max(wallBudget_[bead] - drift_[bead], 0);
    }
    return tclearances;
}


Foam::tmp<Foam::scalarField>
Foam::polymer::collisionModels::elasticRods::edgeClearances() const
{
    // None on a periodic mesh: a rod meets the edges at one image, its
    // middle's, which its path may change
    if (lattice_.size())
    {
        return tmp<scalarField>::New();
    }
    tmp<scalarField> tclearances(new scalarField(edgeDistanceBudget_.size()));
    scalarField& clearances = tclearances.ref();
    forAll(clearances, rod)
    {
        clearances[rod] = max(edgeDistanceBudget_[rod] - rodDrift(rod), 0);
    }
    return tclearances;
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


bool Foam::polymer::collisionModels::elasticRods::predictLater
(
    const label pairi,
    const scalar t
)
{
    if
    (
        !(pairDrift(pairi) < pairLazyBudget_[pairi])
     || !(t < pairLazyTime_[pairi])
    )
    {
        return false;
    }
    if (!pairLazyQueued_[pairi])
    {
        pairLazyQueued_[pairi] = 1;
        event e;
        e.time = pairLazyTime_[pairi];
        e.pair = pairi;
        e.from = t;
        e.offset = e.time - t;
        e.normal = Zero;
        e.patch = -1;
        e.side = 0;
        e.atContact = false;
        e.revalidate = pairSerial_[pairi];
        e.beads = FixedList<label, 4>({-1, -1, -1, -1});
        queue_.push(e);
    }
    return true;
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
            if (!predictLater(pairi, t))
            {
                predict(pairi, t, dt);
            }
        }
        ++k;
    }
}


// ************************************************************************* //
