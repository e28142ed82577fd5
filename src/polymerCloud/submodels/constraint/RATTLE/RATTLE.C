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

#include "RATTLE.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace constraintModels
{
    defineTypeNameAndDebug(RATTLE, 0);
    addToRunTimeSelectionTable(constraintModel, RATTLE, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constraintModels::RATTLE::RATTLE(const dictionary& dict)
:
    SHAKE(typeName, dict),
    velocityTolerance_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_,
            "velocityTolerance",
            1e-10,
            "<relative rod velocity r.v/(a sqrt(kT/m))>"
        )
    )
{}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::label Foam::constraintModels::RATTLE::correctChainVelocities
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

    const scalar scale =
        type.rodLength()*std::sqrt(type.kT()/type.beadMass());
    const scalar absoluteTolerance = velocityTolerance_*scale;

    for (label iter = 1; iter <= maxIterations_; ++iter)
    {
        scalar largest = 0;

        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const vector r = x[j] - x[k];
            const scalar alongRod = r & (v[j] - v[k]);

            largest = max(largest, mag(alongRod));

            if (mag(alongRod) > absoluteTolerance)
            {
                const vector kick = (alongRod/(2*(r & r)))*r;
                v[k] += kick;
                v[j] -= kick;
            }
        }

        if (largest <= absoluteTolerance)
        {
            residual = largest/scale;
            return iter;
        }
    }

    residual = 0;
    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        residual = max(residual, mag((x[j] - x[k]) & (v[j] - v[k])));
    }
    residual /= scale;

    return -maxIterations_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::constraintModels::RATTLE::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time
) const
{
    SHAKE::correct(chains, positionsOld, deltaT, time);
    correctVelocities(chains, time);
}


void Foam::constraintModels::RATTLE::correctVelocities
(
    polymerChains& chains,
    const scalar time
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        scalar residual = 0;
        const label iter = correctChainVelocities(chains, c, residual);

        counters_.add(mag(iter), iter > 0);

        if (iter < 0)
        {
            reportFailure(chains, c, "Rod-velocity", time, residual, -iter);
        }
    }
}


// ************************************************************************* //
