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

#include "SHAKE.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(constraintModel, constraintModels, SHAKE)

const Foam::Enum<Foam::polymer::constraintModels::SHAKE::directionType>
Foam::polymer::constraintModels::SHAKE::directionTypeNames
({
    { directionType::start, "start" },
    { directionType::end, "end" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModels::SHAKE::SHAKE(const dictionary& dict)
:
    SHAKE(typeName, dict)
{}


Foam::polymer::constraintModels::SHAKE::SHAKE
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
    maxIterations_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxIterations", 10000, 1, "<iteration cap>"
        )
    ),
    directions_
    (
        checkedInput::enumOrDefault
        (
            coeffDict_, "directions", directionTypeNames,
            directionType::start
        )
    ),
    reference_()
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

const Foam::vector* Foam::polymer::constraintModels::SHAKE::directionSource
(
    const polymerChains& chains,
    const label chaini,
    const UList<vector>& positionsOld
) const
{
    if (directions_ == directionType::end)
    {
        reference_ = SubList<vector>
        (
            chains.positions(),
            chains.size(chaini),
            chains.start(chaini)
        );
        return reference_.cdata();
    }

    return positionsOld.cdata() + chains.start(chaini);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::constraintModels::SHAKE::correctChainLengths
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    scalar& residual
) const
{
    const chainType& type = chains.type(chaini);
    const label first = chains.start(chaini);
    const label n = type.nBeads();
    const label nRods = type.nRods();
    const scalar a2 = sqr(type.rodLength());

    vector* x = chains.positions().data() + first;
    vector* v = chains.velocities().data() + first;
    const vector* rc = directionSource(chains, chaini, positionsOld);

    // |s.s - a^2|/(2 a^2) is the relative length error to first order
    const scalar squaredTolerance = 2*a2*tolerance_;
    const scalar oneByDeltaT = 1/deltaT;

    for (label iter = 1; iter <= maxIterations_; ++iter)
    {
        bool converged = true;

        for (label k = 0; k < nRods; ++k)
        {
            const label j = (k + 1 < n) ? k + 1 : 0;
            const vector s = x[j] - x[k];
            const scalar excess = a2 - (s & s);

            // (not <=: a NaN is not converged)
            if (!(mag(excess) <= squaredTolerance))
            {
                converged = false;

                const vector direction = rc[j] - rc[k];
                const scalar alignment = s & direction;

                if (alignment <= SMALL*a2)
                {
                    residual = mag(excess)/(2*a2);
                    return -iter;
                }

                const vector shift = (excess/(4*alignment))*direction;
                x[k] -= shift;
                x[j] += shift;
                v[k] -= oneByDeltaT*shift;
                v[j] += oneByDeltaT*shift;
            }
        }

        if (converged)
        {
            residual = 0;
            return iter;
        }
    }

    residual = chains.maxRodLengthError(chaini);
    return -maxIterations_;
}


// ************************************************************************* //
