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

#include "newton.H"
#include "maxOrNaN.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(constraintModel, constraintModels, newton)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModels::newton::newton(const dictionary& dict)
:
    newton(typeName, dict)
{}


Foam::polymer::constraintModels::newton::newton
(
    const word& type,
    const dictionary& dict
)
:
    constraintModel(type, dict),
    tolerance_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_, "tolerance", 1e-10, "<relative rod-length error>"
        )
    ),
    velocityTolerance_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_,
            "velocityTolerance",
            1e-10,
            "<relative rod velocity r.v/(a sqrt(kT/m))>"
        )
    ),
    maxIterations_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxIterations", 50, 1, "<iteration cap>"
        )
    ),
    directions_
    (
        checkedInput::enumOrDefault
        (
            coeffDict_, "directions", SHAKE::directionTypeNames,
            SHAKE::directionType::start
        )
    ),
    reference_(),
    rods_(),
    system_(),
    solution_(),
    velocityProjection_(),
    lanes_(),
    fourLanes_(4)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::polymer::constraintModels::newton::linearise
(
    const vector* x,
    const chainType& type
) const
{
    const label n = type.nBeads();
    const label nRods = type.nRods();
    const scalar a2 = sqr(type.rodLength());

    // d[k] is the direction of rod k, d[k - 1] and d[k + 1] its neighbours'
    const vector* d = rods_.cdata() + 1;
    scalar* lower = system_.lower().data();
    scalar* diagonal = system_.diagonal().data();
    scalar* upper = system_.upper().data();
    scalar* source = system_.source().data();

    scalar largest = 0;
    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        const vector s = x[j] - x[k];
        const scalar sigma = (s & s) - a2;
        largest = maxOrNaN(largest, mag(sigma));

        lower[k] = -2*(s & d[k - 1]);
        diagonal[k] = 4*(s & d[k]);
        upper[k] = -2*(s & d[k + 1]);
        source[k] = -sigma;
    }

    return largest/(2*a2);
}


void Foam::polymer::constraintModels::newton::shift
(
    vector* x,
    const chainType& type,
    const scalar alpha
) const
{
    const label n = type.nBeads();
    const label nRods = type.nRods();

    // d[k] is the direction of rod k and g[k] its step
    const vector* d = rods_.cdata() + 1;
    const scalar* g = solution_.cdata() + 1;

    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        const vector dx = (alpha*g[k])*d[k];
        x[k] -= dx;
        x[j] += dx;
    }
}


Foam::scalar Foam::polymer::constraintModels::newton::lineSearch
(
    vector* x,
    const chainType& type,
    const scalar lastResidual
) const
{
    // The system is rebuilt at once: its residual tests the step, and in
    // the usual case (a full step) it is the next iteration's system
    rodVelocityProjection::padSolution(system_.source(), type, solution_);

    scalar alpha = 1;
    shift(x, type, alpha);
    scalar residual = linearise(x, type);

    for (int halving = 0; halving < 8 && residual >= lastResidual; ++halving)
    {
        shift(x, type, -0.5*alpha);
        alpha *= 0.5;
        residual = linearise(x, type);
    }

    return residual;
}


Foam::label Foam::polymer::constraintModels::newton::solveLengths
(
    vector* x,
    const chainType& type,
    scalar& residual
) const
{
    // Newton's iteration converges quadratically near the solution; far
    // from it (large errors, as rod-rod collisions can leave) the step is
    // halved until the residual falls. A residual that still grows three
    // times running means there is no solution near.
    scalar lastResidual = GREAT;
    label nGrowing = 0;

    residual = linearise(x, type);
    for (label iter = 0; iter <= maxIterations_; ++iter)
    {
        if (residual <= tolerance_)
        {
            return max(iter, 1);
        }
        nGrowing = (residual > lastResidual) ? nGrowing + 1 : 0;
        lastResidual = residual;
        if
        (
            nGrowing == 3
         || iter == maxIterations_
         || !system_.solve(type.ring())
        )
        {
            return -max(iter, 1);
        }

        residual = lineSearch(x, type, lastResidual);
    }

    return -maxIterations_;
}


Foam::label Foam::polymer::constraintModels::newton::iterate
(
    polymerChains& chains,
    const label chaini,
    const vector* rc,
    const scalar deltaT,
    scalar& residual
) const
{
    const chainType& type = chains.type(chaini);
    const label first = chains.start(chaini);
    const label n = type.nBeads();

    vector* x = chains.positions().data() + first;

    system_.resize(type.nRods());
    rodVelocityProjection::padRods(rc, type, rods_);

    const label result = solveLengths(x, type, residual);
    if (result < 0)
    {
        return result;
    }

    // The velocities move with the beads, from x* (as the retry in
    // correctChainLengths, every solve starts there)
    const vector* xStar = reference_.cdata();
    vector* v = chains.velocities().data() + first;
    const scalar oneByDeltaT = 1/deltaT;
    for (label i = 0; i < n; ++i)
    {
        v[i] += oneByDeltaT*(x[i] - xStar[i]);
    }

    return result;
}


bool Foam::polymer::constraintModels::newton::inLanes
(
    const polymerChains& chains,
    const label chaini
)
{
    return !chains.type(chaini).ring() && chains.type(chaini).nRods() >= 1;
}


void Foam::polymer::constraintModels::newton::correctInLanes
(
    polymerChains& chains,
    const laneGroup& group,
    const label nGroup,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time,
    DynamicList<label>& failedChains
) const
{
    const chainType& type = chains.type(group[0]);
    const label n = type.nBeads();
    const bool alongStart = (directions_ == SHAKE::directionType::start);

    // A group of fewer chains than lanes repeats its last chain; one of at
    // most four takes four lanes, the same arithmetic in fewer
    newtonLanes& lanes =
        (nGroup <= fourLanes_.nLanes()) ? fourLanes_ : lanes_;
    lanes.resize(n);
    const vector* x[newtonLanes::maxLanes];
    const vector* rodStart[newtonLanes::maxLanes];
    vector* v[newtonLanes::maxLanes];
    for (label lanei = 0; lanei < lanes.nLanes(); ++lanei)
    {
        const label first = chains.start(group[min(lanei, nGroup - 1)]);
        x[lanei] = chains.positions().cdata() + first;
        rodStart[lanei] =
            (alongStart ? positionsOld.cdata() : chains.positions().cdata())
          + first;
        v[lanei] = chains.velocities().data() + first;
    }
    lanes.load(x, rodStart);

    label iterations[newtonLanes::maxLanes];
    lanes.solve(type.rodLength(), tolerance_, maxIterations_, iterations);

    // The converged chains take their positions, and their velocities the
    // beads' moves from x* (as iterate), for the velocity solve in lanes
    const scalar oneByDeltaT = 1/deltaT;
    for (label lanei = 0; lanei < nGroup; ++lanei)
    {
        if (iterations[lanei])
        {
            lanes.store
            (
                lanei,
                chains.positions().data() + chains.start(group[lanei]),
                v[lanei],
                oneByDeltaT
            );
        }
    }
    lanes.loadVelocities(v);

    bool velocitiesSolved[newtonLanes::maxLanes];
    scalar largestVelocity[newtonLanes::maxLanes];
    lanes.projectVelocities(velocitiesSolved, largestVelocity);

    // In the group's order, as one at a time: counts, reports and failures
    for (label lanei = 0; lanei < nGroup; ++lanei)
    {
        const label c = group[lanei];
        if (!iterations[lanei])
        {
            if (!correctChain(chains, c, positionsOld, deltaT, time))
            {
                failedChains.append(c);
            }
            continue;
        }

        countSolve(chains, c, "Rod-length", iterations[lanei], 0, time);

        scalar residual = 0;
        label iter = 0;
        if (velocitiesSolved[lanei])
        {
            // As correctChainVelocities
            lanes.storeVelocities(lanei, v[lanei]);
            residual =
                largestVelocity[lanei]
               /velocityScale(type, v[lanei], n, velocityTolerance_);
            iter = (residual <= velocityTolerance_) ? 1 : -1;
        }
        else
        {
            iter = correctChainVelocities(chains, c, residual);
        }
        countSolve(chains, c, "Rod-velocity", iter, residual, time);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::constraintModels::newton::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time,
    DynamicList<label>& failedChains
) const
{
    // The open chains of each type gathered into lanes in the chains'
    // order, a group solved when full and the rest at the end: the chains
    // are kept in the order of their cells, which interleaves the types
    // of a mixed scene. A chain comes out of a lane with the bits of one
    // at a time, so the grouping changes no result; the failures are
    // listed in the chains' order, as one at a time
    const label nFailedBefore = failedChains.size();
    const label nTypes = chains.types().size();
    List<laneGroup> groups(nTypes);
    labelList nGrouped(nTypes, 0);
    const auto solve = [&](const label typei)
    {
        if (nGrouped[typei] >= 2)
        {
            correctInLanes
            (
                chains, groups[typei], nGrouped[typei],
                positionsOld, deltaT, time, failedChains
            );
        }
        else if
        (
            nGrouped[typei] == 1
         && !correctChain(chains, groups[typei][0], positionsOld, deltaT, time)
        )
        {
            failedChains.append(groups[typei][0]);
        }
        nGrouped[typei] = 0;
    };

    for (label c = 0; c < chains.nChains(); ++c)
    {
        if (!inLanes(chains, c))
        {
            if (!correctChain(chains, c, positionsOld, deltaT, time))
            {
                failedChains.append(c);
            }
            continue;
        }
        const label typei = chains.typeIndex(c);
        groups[typei][nGrouped[typei]++] = c;
        if (nGrouped[typei] == lanes_.nLanes())
        {
            solve(typei);
        }
    }
    for (label typei = 0; typei < nTypes; ++typei)
    {
        solve(typei);
    }
    std::sort(failedChains.begin() + nFailedBefore, failedChains.end());
}


Foam::label Foam::polymer::constraintModels::newton::correctChainLengths
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    scalar& residual
) const
{
    const label first = chains.start(chaini);
    const label n = chains.size(chaini);

    // x* itself: the end directions, and the state to retry from (a
    // failed solve leaves the velocities at v*)
    reference_ = SubList<vector>(chains.positions(), n, first);

    if (directions_ == SHAKE::directionType::end)
    {
        return iterate(chains, chaini, reference_.cdata(), deltaT, residual);
    }

    const label iter = iterate
    (
        chains, chaini, positionsOld.cdata() + first, deltaT, residual
    );
    if (iter > 0)
    {
        return iter;
    }

    // The rods of x^n can be too far from those of x* for their directions
    // to reach the lengths (a rod-rod collision in the last step can have
    // bent them): retry along the rods of x*
    SubList<vector>(chains.positions(), n, first) = reference_;
    const label retry =
        iterate(chains, chaini, reference_.cdata(), deltaT, residual);

    return (retry > 0) ? retry - iter : retry + iter;
}


bool Foam::polymer::constraintModels::newton::projectOnRods
(
    const vector* x,
    const chainType& type,
    vector* w,
    scalar& largest
) const
{
    return velocityProjection_.project(x, type, w, largest);
}


Foam::label Foam::polymer::constraintModels::newton::correctChainVelocities
(
    polymerChains& chains,
    const label chaini,
    scalar& residual
) const
{
    const chainType& type = chains.type(chaini);
    const label first = chains.start(chaini);
    const label n = type.nBeads();

    const vector* x = chains.positions().cdata() + first;
    vector* v = chains.velocities().data() + first;

    const bool solved = projectOnRods(x, type, v, residual);
    residual /= velocityScale(type, v, n, velocityTolerance_);

    return (solved && residual <= velocityTolerance_) ? 1 : -1;
}


// ************************************************************************* //
