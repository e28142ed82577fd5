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

#include "contactConstraints.H"
#include "linePointRef.H"
#include "maxOrNaN.H"
#include "HashSet.H"
#include "Tuple2.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The bead's position along rod k of a chain of n beads (ring: modulo n)
inline label rodEnd(const label k, const label n)
{
    return (k + 1 < n) ? k + 1 : 0;
}

//- The rods of a chain that hold its bead l, as the rod's second bead
//  (rod l - 1) and as its first (rod l); -1 where there is none
inline void rodsOfBead
(
    const label l,
    const label n,
    const bool ring,
    label& asSecond,
    label& asFirst
)
{
    asSecond = (l > 0) ? l - 1 : (ring ? n - 1 : -1);
    asFirst = (ring || l < n - 1) ? l : -1;
}

//- The parameter in [0, 1] of a point on the segment p0-p1
inline scalar alongSegment(const point& p, const point& p0, const point& p1)
{
    return min(max(((p - p0) & (p1 - p0))/magSqr(p1 - p0), scalar(0)), scalar(1));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::contactConstraints::contactConstraints
(
    const scalar tolerance,
    const label maxIterations
)
:
    tolerance_(tolerance),
    maxIterations_(maxIterations),
    system_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::contactConstraints::setPositions
(
    polymerChains& chains,
    const labelUList& group,
    const labelUList& firstRod,
    const UList<contact>& contacts,
    const UList<point>& start,
    const UList<scalar>& rodMultipliers,
    const UList<scalar>& contactMultipliers
)
{
    List<point>& x = chains.positions();
    forAll(group, gi)
    {
        const label c = group[gi];
        const label s0 = chains.start(c);
        const label n = chains.size(c);
        for (label i = s0; i < s0 + n; ++i)
        {
            x[i] = start[i];
        }
        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            const label i = s0 + k, j = s0 + rodEnd(k, n);
            const vector move = rodMultipliers[firstRod[gi] + k]*(start[j] - start[i]);
            x[i] -= move;
            x[j] += move;
        }
    }
    forAll(contacts, q)
    {
        const contact& cq = contacts[q];
        const FixedList<label, 4> beads(cq.beads());
        forAll(beads, b)
        {
            x[beads[b]] +=
                contactMultipliers[q]*cq.weights[b]*cq.inverseMasses[b]
               *cq.normal;
        }
    }
}


Foam::scalar Foam::polymer::contactConstraints::residual
(
    const polymerChains& chains,
    const labelUList& group,
    const UList<contact>& contacts
)
{
    const List<point>& x = chains.positions();
    scalar r = 0;
    for (const label c : group)
    {
        r = maxOrNaN(r, chains.maxRodLengthError(c));
    }
    for (const contact& cq : contacts)
    {
        const scalar rodLength =
            chains.type(chains.chainOf(cq.rodA.first())).rodLength();
        r = maxOrNaN(r, mag(presentGap(cq, x) - cq.gap)/rodLength);
    }
    return r;
}


void Foam::polymer::contactConstraints::rodResiduals
(
    const polymerChains& chains,
    const labelUList& group,
    const labelUList& firstRod,
    scalarField& sigma
)
{
    const List<point>& x = chains.positions();
    forAll(group, gi)
    {
        const label c = group[gi];
        const label s0 = chains.start(c);
        const label n = chains.size(c);
        const scalar a = chains.type(c).rodLength();
        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            sigma[firstRod[gi] + k] =
                magSqr(x[s0 + rodEnd(k, n)] - x[s0 + k]) - a*a;
        }
    }
}


bool Foam::polymer::contactConstraints::solveBlock
(
    const polymerChains& chains,
    const label chaini,
    const UList<point>& start,
    UList<scalar>& source
)
{
    // Newton's Jacobian of one chain's sigma in its rods' multipliers (as
    // constraint newton): 4 s_k.d_k, -2 s_k.d_(k-1), -2 s_k.d_(k+1)
    const List<point>& x = chains.positions();
    const label s0 = chains.start(chaini);
    const label n = chains.size(chaini);
    const label nRods = chains.type(chaini).nRods();
    const bool ring = chains.type(chaini).ring();

    const auto direction = [&](const label k)
    {
        return start[s0 + rodEnd(k, n)] - start[s0 + k];
    };

    system_.resize(nRods);
    for (label k = 0; k < nRods; ++k)
    {
        const vector s = x[s0 + rodEnd(k, n)] - x[s0 + k];
        system_.diagonal()[k] = 4*(s & direction(k));
        const label before = (k > 0) ? k - 1 : nRods - 1;
        const label after = (k + 1 < nRods) ? k + 1 : 0;
        system_.lower()[k] =
            (k > 0 || ring) ? -2*(s & direction(before)) : 0;
        system_.upper()[k] =
            (k + 1 < nRods || ring) ? -2*(s & direction(after)) : 0;
        system_.source()[k] = source[k];
    }
    if (!system_.solve(ring))
    {
        return false;
    }
    for (label k = 0; k < nRods; ++k)
    {
        source[k] = system_.source()[k];
    }
    return true;
}


Foam::scalar Foam::polymer::contactConstraints::presentGap
(
    const contact& c,
    const UList<point>& x
)
{
    const FixedList<label, 4> beads(c.beads());
    vector separation(c.shift);
    forAll(beads, b)
    {
        separation += c.weights[b]*x[beads[b]];
    }
    return c.normal & separation;
}


void Foam::polymer::contactConstraints::couple
(
    const polymerChains& chains,
    const labelUList& firstRod,
    const Map<label>& groupIndex,
    const contact& c,
    const UList<point>& start,
    UList<scalar>& column,
    DynamicList<Tuple2<label, scalar>>& row
)
{
    // A bead's move along the normal changes the sigma of its two rods
    // (column of B), and the rods' multipliers move it along their
    // directions (row of C): rod l - 1 holds bead l as its second bead,
    // rod l as its first
    const List<point>& x = chains.positions();
    const FixedList<label, 4> beads(c.beads());
    forAll(beads, b)
    {
        const label chaini = chains.chainOf(beads[b]);
        const label first = firstRod[groupIndex[chaini]];
        const label s0 = chains.start(chaini);
        const label n = chains.size(chaini);
        const vector move = c.weights[b]*c.inverseMasses[b]*c.normal;
        label asSecond, asFirst;
        rodsOfBead
        (
            beads[b] - s0, n, chains.type(chaini).ring(), asSecond, asFirst
        );
        for (const label k : {asSecond, asFirst})
        {
            if (k < 0)
            {
                continue;
            }
            const scalar sign = (k == asSecond) ? 1 : -1;
            const label i = s0 + k, j = s0 + rodEnd(k, n);
            column[first + k] += sign*2*((x[j] - x[i]) & move);
            row.append
            ({
                first + k,
                sign*c.weights[b]*(c.normal & (start[j] - start[i]))
            });
        }
    }
}


bool Foam::polymer::contactConstraints::newtonStep
(
    const polymerChains& chains,
    const labelUList& group,
    const labelUList& firstRod,
    const Map<label>& groupIndex,
    const UList<contact>& contacts,
    const UList<point>& start,
    scalarField& rodStep,
    scalarField& contactStep
)
{
    const label nRodsAll = rodStep.size();
    const label m = contacts.size();

    // The chains' blocks on -sigma
    rodResiduals(chains, group, firstRod, rodStep);
    rodStep.negate();
    forAll(group, gi)
    {
        SubList<scalar> block
        (
            rodStep, chains.type(group[gi]).nRods(), firstRod[gi]
        );
        if (!solveBlock(chains, group[gi], start, block))
        {
            return false;
        }
    }

    // Each contact's column of B through the blocks, T^-1 B, and its row
    // of C
    List<scalarField> columns(m, scalarField(nRodsAll, Zero));
    List<DynamicList<Tuple2<label, scalar>>> rows(m);
    forAll(contacts, q)
    {
        couple
        (
            chains, firstRod, groupIndex, contacts[q], start, columns[q],
            rows[q]
        );
        labelHashSet chainsOfContact;
        for (const label bead : contacts[q].beads())
        {
            chainsOfContact.insert(chains.chainOf(bead));
        }
        for (const label c : chainsOfContact)
        {
            SubList<scalar> block
            (
                columns[q], chains.type(c).nRods(), firstRod[groupIndex[c]]
            );
            if (!solveBlock(chains, c, start, block))
            {
                return false;
            }
        }
    }

    // The Schur complement D - C T^-1 B, and -h - C T^-1 (-sigma)
    Eigen::MatrixXd schur(m, m);
    Eigen::VectorXd rhs(m);
    forAll(contacts, p)
    {
        const contact& cp = contacts[p];
        rhs(p) = cp.gap - presentGap(cp, chains.positions());
        for (const Tuple2<label, scalar>& entry : rows[p])
        {
            rhs(p) -= entry.second()*rodStep[entry.first()];
        }
        forAll(contacts, q)
        {
            schur(p, q) = contactCoupling(cp, contacts[q]);
            for (const Tuple2<label, scalar>& entry : rows[p])
            {
                schur(p, q) -= entry.second()*columns[q][entry.first()];
            }
        }
    }

    // Contacts may repeat each other (two rods meeting a third at their
    // common bead): the least-norm solution of a rank-deficient system;
    // contacts that contradict each other leave a residual, and the solve
    // fails
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(schur);
    const Eigen::VectorXd contactSolution = cod.solve(rhs);
    if (!contactSolution.allFinite())
    {
        return false;
    }
    forAll(contacts, q)
    {
        contactStep[q] = contactSolution(q);
        for (label r = 0; r < nRodsAll; ++r)
        {
            rodStep[r] -= columns[q][r]*contactStep[q];
        }
    }
    return true;
}


Foam::scalar Foam::polymer::contactConstraints::contactCoupling
(
    const contact& p,
    const contact& q
)
{
    // The change of p's gap per unit impulse of q: their shared beads'
    // weights over the beads' masses
    const FixedList<label, 4> beadsP(p.beads());
    const FixedList<label, 4> beadsQ(q.beads());
    scalar d = 0;
    forAll(beadsP, b)
    {
        forAll(beadsQ, bq)
        {
            if (beadsP[b] == beadsQ[bq])
            {
                d += p.weights[b]*q.weights[bq]*q.inverseMasses[bq]
                    *(p.normal & q.normal);
            }
        }
    }
    return d;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::contactConstraints::setContact
(
    const labelPair& rodA,
    const labelPair& rodB,
    const vector& shift,
    const FixedList<scalar, 4>& weights,
    const vector& normal,
    const polymerChains& chains,
    const UList<point>& x,
    contact& result
)
{
    result.rodA = rodA;
    result.rodB = rodB;
    result.shift = shift;
    result.weights = weights;
    result.normal = normal;
    const FixedList<label, 4> beads(result.beads());
    forAll(beads, b)
    {
        result.inverseMasses[b] =
            1/chains.type(chains.chainOf(beads[b])).beadMass();
    }
    result.gap = presentGap(result, x);
}


bool Foam::polymer::contactConstraints::makeContact
(
    const labelPair& rodA,
    const labelPair& rodB,
    const vector& shift,
    const polymerChains& chains,
    const UList<point>& x,
    contact& result
)
{
    const point& a0 = x[rodA.first()];
    const point& a1 = x[rodA.second()];
    const point b0 = x[rodB.first()] + shift;
    const point b1 = x[rodB.second()] + shift;

    point onA, onB;
    linePointRef(a0, a1).nearestDist(linePointRef(b0, b1), onA, onB);
    const vector separation = onB - onA;
    const scalar distance = mag(separation);
    const scalar rodLength =
        chains.type(chains.chainOf(rodA.first())).rodLength();
    if (!(distance > 1e-10*rodLength))
    {
        return false;
    }

    const scalar s = alongSegment(onA, a0, a1);
    const scalar u = alongSegment(onB, b0, b1);
    setContact
    (
        rodA, rodB, shift, {-(1 - s), -s, 1 - u, u}, separation/distance,
        chains, x, result
    );
    return true;
}


bool Foam::polymer::contactConstraints::makeCrossingContact
(
    const labelPair& rodA,
    const labelPair& rodB,
    const vector& shift,
    const polymerChains& chains,
    const UList<point>& from,
    const UList<point>& to,
    const scalar fraction,
    contact& result
)
{
    const auto at = [&](const label i, const vector& translation)
    {
        return from[i] + fraction*(to[i] - from[i]) + translation;
    };
    const point a0 = at(rodA.first(), Zero), a1 = at(rodA.second(), Zero);
    const point b0 = at(rodB.first(), shift), b1 = at(rodB.second(), shift);

    point onA, onB;
    linePointRef(a0, a1).nearestDist(linePointRef(b0, b1), onA, onB);
    const scalar s = alongSegment(onA, a0, a1);
    const scalar u = alongSegment(onB, b0, b1);

    vector normal = (a1 - a0) ^ (b1 - b0);
    const scalar rodLength =
        chains.type(chains.chainOf(rodA.first())).rodLength();
    if (!(mag(normal) > 1e-6*sqr(rodLength)))
    {
        return false;
    }
    normal /= mag(normal);

    // The normal turned from A to B at the start
    setContact
    (
        rodA, rodB, shift, {-(1 - s), -s, 1 - u, u}, normal, chains, from,
        result
    );
    if (result.gap < 0)
    {
        result.normal = -normal;
        result.gap = -result.gap;
    }
    return result.gap > 1e-10*rodLength;
}


bool Foam::polymer::contactConstraints::makeWallContact
(
    const label bead,
    const point& hit,
    const vector& normal,
    const polymerChains& chains,
    const UList<point>& from,
    contact& result
)
{
    setContact
    (
        labelPair(bead, bead), labelPair(bead, bead), -hit, {0, 0, 1, 0},
        normal, chains, from, result
    );
    return
        result.gap > 1e-10*chains.type(chains.chainOf(bead)).rodLength();
}


bool Foam::polymer::contactConstraints::makeEdgeContact
(
    const labelPair& rod,
    const point& edgeStart,
    const point& edgeEnd,
    const polymerChains& chains,
    const UList<point>& from,
    contact& result
)
{
    const point& b0 = from[rod.first()];
    const point& b1 = from[rod.second()];
    point onEdge, onRod;
    linePointRef(edgeStart, edgeEnd).nearestDist
    (
        linePointRef(b0, b1), onEdge, onRod
    );
    const vector separation = onRod - onEdge;
    const scalar distance = mag(separation);
    if
    (
        !(distance > 1e-10*chains.type(chains.chainOf(rod.first())).rodLength())
    )
    {
        return false;
    }
    const scalar u = alongSegment(onRod, b0, b1);
    setContact
    (
        rod, rod, -onEdge, {0, 0, 1 - u, u}, separation/distance, chains,
        from, result
    );
    return true;
}


Foam::label Foam::polymer::contactConstraints::project
(
    polymerChains& chains,
    const labelUList& group,
    const UList<contact>& contacts,
    const UList<point>& start
)
{
    labelList firstRod(group.size());
    Map<label> groupIndex(2*group.size());
    label nRodsAll = 0;
    forAll(group, gi)
    {
        firstRod[gi] = nRodsAll;
        nRodsAll += chains.type(group[gi]).nRods();
        groupIndex.insert(group[gi], gi);
    }

    scalarField rodMultipliers(nRodsAll, Zero);
    scalarField contactMultipliers(contacts.size(), Zero);
    scalarField rodStep(nRodsAll);
    scalarField contactStep(contacts.size());

    setPositions
    (
        chains, group, firstRod, contacts, start,
        rodMultipliers, contactMultipliers
    );
    scalar r = residual(chains, group, contacts);
    for (label iter = 0; ; ++iter)
    {
        if (r <= tolerance_)
        {
            return iter;
        }
        if
        (
            iter == maxIterations_
         || !newtonStep
            (
                chains, group, firstRod, groupIndex, contacts, start,
                rodStep, contactStep
            )
        )
        {
            break;
        }

        // The step, halved until the residual falls
        bool fell = false;
        for (scalar length = 1; length > 1e-3 && !fell; length *= 0.5)
        {
            const scalarField rodTrial(rodMultipliers + length*rodStep);
            const scalarField contactTrial
            (
                contactMultipliers + length*contactStep
            );
            setPositions
            (
                chains, group, firstRod, contacts, start,
                rodTrial, contactTrial
            );
            const scalar trial = residual(chains, group, contacts);
            if (trial < r)
            {
                rodMultipliers = rodTrial;
                contactMultipliers = contactTrial;
                r = trial;
                fell = true;
            }
        }
        if (!fell)
        {
            break;
        }
    }

    setPositions
    (
        chains, group, firstRod, contacts, start,
        scalarField(nRodsAll, Zero), scalarField(contacts.size(), Zero)
    );
    return -1;
}


// ************************************************************************* //
