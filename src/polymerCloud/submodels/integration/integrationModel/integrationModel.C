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

#include "integrationModel.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(integrationModel)


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::integrationModel::integrate
(
    polymerChains& chains,
    const UList<vector>& driftVelocity,
    const scalar deltaT,
    const label timeIndex,
    const label seed,
    const label subStepKey
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        integrateChain
        (
            chains, c, driftVelocity, deltaT, timeIndex, seed, subStepKey
        );
    }
}


// ************************************************************************* //
