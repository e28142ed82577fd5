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

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::collisionModels::elasticRods::edgePair
(
    const label rod,
    const label edgei
)
{
    const labelPair key(rod, edgei);
    const auto found = edgePairIndex_.cfind(key);
    if (found.found())
    {
        return found.val();
    }
    const label index = edgePairs_.size();
    edgePairs_.append(key);
    edgePairIndex_.insert(key, index);
    return index;
}


void Foam::polymer::collisionModels::elasticRods::predictEdges
(
    const label rod,
    const scalar t,
    const scalar dt
)
{
    const wallEdges& edges = wall_->edges();
    const label a0 = rods_[rod].first();
    const label a1 = rods_[rod].second();
    const point p0 = positionAt(a0, t);
    const point p1 = positionAt(a1, t);
    const scalar rest = dt - t;

    // The rod at its image inside the mesh, where the edges are
    const vector shift = wall_->imageShift(0.5*(p0 + p1));

    // A rod whose path stays farther from every edge meets none, and
    // needs no look-up in the edges' tree: a point of the rod strays from
    // the rod's clearance by at most its beads' larger motion over the
    // rest
    const scalar clearance =
        wall_->rodEdgeClearance(p0, p1, shift)
      - rest*max(mag(velocity_[a0]), mag(velocity_[a1]));
    if (clearance > 0)
    {
        edgeBudget_[rod] = clearance + rodDrift(rod);
        edgeDistanceBudget_[rod] = edgeBudget_[rod];
        return;
    }
    // Else the edges near the path (its swept box, formed only here: most
    // rods are cleared above), looked up in a box wider than the path's
    // by a margin: the edges beyond it are farther than that. The
    // rod keeps a budget while every edge has one: the margin, the
    // clearance of an edge it stays apart from, the drift that keeps V's
    // sign with an edge found uncrossed; none with an edge it meets
    const boundBox box(sweep(rod, t, dt));
    const scalar margin = growMargin(rod, t, dt);
    const vector fat(vector::uniform(margin));
    scalar budget = margin;
    bool distance = true;

    // The rod and each edge in turn, filled element by element (as in
    // predict: not from initializer lists, whose copies stalled the reads)
    FixedList<point, 4> x;
    x[0] = p0 + shift;
    x[1] = p1 + shift;
    FixedList<vector, 4> moved;
    moved[0] = rest*velocity_[a0];
    moved[1] = rest*velocity_[a1];
    moved[2] = Zero;
    moved[3] = Zero;
    for
    (
        const label edgei
      : edges.near(boundBox(box.min() + shift - fat, box.max() + shift + fat))
    )
    {
        // An edge is a rod that does not move: one the rod stays apart
        // from needs no crossing-time solve
        x[2] = edges.start(edgei);
        x[3] = edges.end(edgei);
        scalar clearance;
        if (sweptApart(x, moved, clearance))
        {
            budget = min(budget, clearance);
            continue;
        }

        const rodPairCrossing pair
        (
            x[0], x[1], x[2], x[3], velocity_[a0], velocity_[a1], Zero, Zero
        );
        const label pairi = edgePair(rod, edgei);
        label side = 0;
        bool atContact = false;
        const scalar s = edgeContacts_.earliestCrossing
        (
            pairi, pair, *rootSolver_, dt - t, side, atContact
        );
        ++counters_.pairChecks;
        if (s < 0)
        {
            budget = min
            (
                budget,
                pair.signKeepingDrift(rest, pairContacts::bandMargin(pair))
            );
            distance = false;
            continue;
        }
        budget = 0;

        event e;
        e.time = t + s;
        e.pair = pairi;
        e.from = t;
        e.offset = s;
        e.normal = shift;   // the rod's image translation
        e.patch = edges.patch(edgei);
        e.side = side;
        e.atContact = atContact;
        e.edge = true;
        e.beads = FixedList<label, 4>({a0, a1, -1, -1});
        queue_.push(e);
    }
    edgeBudget_[rod] = (budget > 0) ? budget + rodDrift(rod) : -GREAT;
    edgeDistanceBudget_[rod] = distance ? edgeBudget_[rod] : -GREAT;
}


bool Foam::polymer::collisionModels::elasticRods::resolveEdge
(
    const event& e,
    const polymerChains& chains,
    UList<vector>& velocitiesDagger
)
{
    const label b0 = e.beads[0];
    const label b1 = e.beads[1];
    for (const label bead : {b0, b1})
    {
        position_[bead] =
            positionAt(bead, e.from) + e.offset*velocity_[bead];
        beadTime_[bead] = e.time;
    }

    // The rod at its image (e.normal holds its translation) and the edge
    const wallEdges& edges = wall_->edges();
    const label edgei = edgePairs_[e.pair].second();
    const vector& shift = e.normal;
    const rodPairCrossing pair
    (
        position_[b0] + shift, position_[b1] + shift,
        edges.start(edgei), edges.end(edgei),
        velocity_[b0], velocity_[b1], Zero, Zero
    );
    scalar lambda, mu;
    vector n;
    if (!pair.contact(0, lambda, mu, n))
    {
        return false;
    }

    // The contact's normal velocity reverses (the edge does not move),
    // through the chain's rods or on the rod's two beads alone
    edgeContacts_.record(e.pair, e.side, e.atContact);
    if
    (
        impulse_ == impulseType::constrained
     && reverseThroughChain
        (
            chains, labelList({b0, b1}), scalarList({1 - lambda, lambda}),
            n, e.time, velocitiesDagger
        )
    )
    {
        return true;
    }

    const scalar u = ((1 - lambda)*velocity_[b0] + lambda*velocity_[b1]) & n;
    const scalar uDagger =
        ((1 - lambda)*velocitiesDagger[b0] + lambda*velocitiesDagger[b1]) & n;
    const scalar mass = chains.type(chains.chainOf(b0)).beadMass();
    const scalar perUnit = (sqr(1 - lambda) + sqr(lambda))/mass;
    const scalar J = -2*u/perUnit;
    const scalar JDagger = velocityImpulse(J, u, uDagger, perUnit);
    changedBeads_.clear();
    for (const label bead : {b0, b1})
    {
        const scalar weight = (bead == b0) ? 1 - lambda : lambda;
        setVelocity(bead, velocity_[bead] + (J*weight/mass)*n);
        velocitiesDagger[bead] += (JDagger*weight/mass)*n;
        changedBeads_.append(bead);
    }
    return true;
}


// ************************************************************************* //
