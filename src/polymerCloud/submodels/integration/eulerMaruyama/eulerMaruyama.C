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

#include "eulerMaruyama.H"
#include "chainNoise.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(integrationModel, integrationModels, eulerMaruyama)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::integrationModels::eulerMaruyama::eulerMaruyama
(
    const dictionary& dict
)
:
    integrationModel(typeName, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::integrationModels::eulerMaruyama::integrateChain
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& driftVelocity,
    const scalar deltaT,
    const label timeIndex,
    const label seed,
    const label subStepKey
) const
{
    const chainType& type = chains.type(chaini);
    const scalar gammaDt = deltaT/type.inertialTime();
    const scalar sigma = std::sqrt(2*gammaDt*type.kT()/type.beadMass());

    const chainNoise noise(seed, chains.globalId(chaini));
    const label first = chains.start(chaini);

    vector* x = chains.positions().data();
    vector* v = chains.velocities().data();
    const vector* u = driftVelocity.empty() ? nullptr : driftVelocity.cdata();

    for (label i = first; i < chains.end(chaini); ++i)
    {
        scalar a[4];
        noise.normals
        (
            timeIndex, i - first, chainNoise::stepStream0, subStepKey, a
        );

        x[i] += v[i]*deltaT;
        const vector relative = u ? v[i] - u[i] : v[i];
        v[i] += -gammaDt*relative + sigma*vector(a[0], a[1], a[2]);
    }
}


// ************************************************************************* //
