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

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(integrationModel, 0);
    defineRunTimeSelectionTable(integrationModel, dictionary);
} // End namespace polymer
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::integrationModel::integrationModel
(
    const word& type,
    const dictionary& dict
)
:
    polymerSubModel(type, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::integrationModel::integrate
(
    polymerChains& chains,
    const UList<vector>& driftVelocity,
    const scalar deltaT,
    const label timeIndex,
    const label seed
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        integrateChain(chains, c, driftVelocity, deltaT, timeIndex, seed, 0);
    }
}


// ************************************************************************* //
