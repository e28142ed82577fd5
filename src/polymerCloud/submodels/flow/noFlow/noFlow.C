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

#include "noFlow.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(flowModel, flowModels, noFlow)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::flowModels::noFlow::noFlow
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    flowModel(typeName, dict, mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::flowModels::noFlow::update(const polymerChains&)
{
    // No velocities kept: the bead velocities stay an empty list, which
    // its users read as a solvent at rest (24 bytes a bead saved)
}


// ************************************************************************* //
