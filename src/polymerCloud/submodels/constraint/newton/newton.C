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
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace constraintModels
{
    defineTypeNameAndDebug(newton, 0);
    addToRunTimeSelectionTable(constraintModel, newton, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constraintModels::newton::newton(const dictionary& dict)
:
    constraintModel(typeName, dict),
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
        SHAKE::directionTypeNames.getOrDefault
        (
            "directions", coeffDict_, SHAKE::directionType::start
        )
    ),
    reference_(),
    velocityStart_(),
    system_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::constraintModels::newton::correctChainLengths
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

    // x* itself: the end directions, and the state to retry from
    reference_ = SubList<vector>(chains.positions(), n, first);
    velocityStart_ = SubList<vector>(chains.velocities(), n, first);

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
    SubList<vector>(chains.velocities(), n, first) = velocityStart_;
    const label retry =
        iterate(chains, chaini, reference_.cdata(), deltaT, residual);

    return (retry > 0) ? retry - iter : retry + iter;
}


Foam::label Foam::constraintModels::newton::iterate
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
    const label nRods = type.nRods();
    const bool ring = type.ring();
    const scalar a2 = sqr(type.rodLength());

    vector* x = chains.positions().data() + first;
    vector* v = chains.velocities().data() + first;

    system_.resize(nRods);
    UList<scalar>& lower = system_.lower();
    UList<scalar>& diagonal = system_.diagonal();
    UList<scalar>& upper = system_.upper();
    UList<scalar>& step = system_.source();

    const scalar oneByDeltaT = 1/deltaT;

    // Move the beads by alpha times the Newton step along the directions
    auto shiftBy = [&](const scalar alpha)
    {
        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const vector shift = alpha*step[k]*(rc[j] - rc[k]);
            x[k] -= shift;
            x[j] += shift;
            v[k] -= oneByDeltaT*shift;
            v[j] += oneByDeltaT*shift;
        }
    };

    // Largest relative length error at the current positions
    auto lengthResidual = [&]()
    {
        scalar largest = 0;
        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            largest = max(largest, mag(magSqr(x[j] - x[k]) - a2));
        }
        return largest/(2*a2);
    };

    // Newton's iteration converges quadratically near the solution; far
    // from it (large errors, as rod-rod collisions can leave) the step is
    // halved until the residual falls. A residual that still grows three
    // times running means there is no solution near.
    scalar lastResidual = GREAT;
    label nGrowing = 0;

    for (label iter = 0; iter <= maxIterations_; ++iter)
    {
        // Residuals and the Jacobian at the current positions
        residual = 0;
        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const label before = (k > 0) ? k - 1 : nRods - 1;
            const label after = (k + 1 < nRods) ? k + 1 : 0;

            const vector s = x[j] - x[k];
            const scalar sigma = (s & s) - a2;
            residual = max(residual, mag(sigma));

            diagonal[k] = 4*(s & (rc[j] - rc[k]));
            lower[k] = -2*(s & (rc[k] - rc[before]));
            upper[k] = -2*(s & (rc[(after + 1) % n] - rc[after]));
            step[k] = -sigma;
        }
        residual /= 2*a2;

        if (residual <= tolerance_)
        {
            return max(iter, 1);
        }
        nGrowing = (residual > lastResidual) ? nGrowing + 1 : 0;
        lastResidual = residual;
        if (nGrowing == 3 || iter == maxIterations_ || !system_.solve(ring))
        {
            return -max(iter, 1);
        }

        scalar alpha = 1;
        shiftBy(alpha);
        for (int halving = 0; halving < 8; ++halving)
        {
            if (lengthResidual() < residual)
            {
                break;
            }
            shiftBy(-0.5*alpha);
            alpha *= 0.5;
        }
    }

    return -maxIterations_;
}


Foam::label Foam::constraintModels::newton::correctChainVelocities
(
    polymerChains& chains,
    const label chaini,
    scalar& residual
) const
{
    const chainType& type = chains.type(chaini);
    const label first = chains.start(chaini);
    const label n = type.nBeads();
    const label nRods = type.nRods();

    const vector* x = chains.positions().cdata() + first;
    vector* v = chains.velocities().data() + first;

    system_.resize(nRods);
    UList<scalar>& lower = system_.lower();
    UList<scalar>& diagonal = system_.diagonal();
    UList<scalar>& upper = system_.upper();
    UList<scalar>& kick = system_.source();

    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        const label previous = (k > 0) ? k - 1 : nRods - 1;
        const label next = (k + 1 < nRods) ? k + 1 : 0;

        const vector r = x[j] - x[k];
        diagonal[k] = 2*(r & r);
        lower[k] = -(r & (x[k] - x[previous]));
        upper[k] = -(r & (x[(next + 1) % n] - x[next]));
        kick[k] = r & (v[j] - v[k]);
    }

    const bool solved = system_.solve(type.ring());

    if (solved)
    {
        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const vector dv = kick[k]*(x[j] - x[k]);
            v[k] += dv;
            v[j] -= dv;
        }
    }

    residual = 0;
    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        residual = max(residual, mag((x[j] - x[k]) & (v[j] - v[k])));
    }
    residual /= velocityScale(type, v, n, velocityTolerance_);

    return (solved && residual <= velocityTolerance_) ? 1 : -1;
}


// ************************************************************************* //
