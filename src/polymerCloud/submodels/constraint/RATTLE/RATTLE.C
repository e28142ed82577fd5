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
#include "maxOrNaN.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(constraintModel, constraintModels, RATTLE)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModels::RATTLE::RATTLE(const dictionary& dict)
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::constraintModels::RATTLE::correctChainVelocities
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

    const scalar scale = velocityScale(type, v, n, velocityTolerance_);
    const scalar absoluteTolerance = velocityTolerance_*scale;

    for (label iter = 1; iter <= maxIterations_; ++iter)
    {
        scalar largest = 0;

        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const vector r = x[j] - x[k];
            const scalar alongRod = r & (v[j] - v[k]);

            largest = maxOrNaN(largest, mag(alongRod));

            // (not <=: a NaN is not converged)
            if (!(mag(alongRod) <= absoluteTolerance))
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
        residual = maxOrNaN(residual, mag((x[j] - x[k]) & (v[j] - v[k])));
    }
    residual /= scale;

    return -maxIterations_;
}


// ************************************************************************* //
