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

void Foam::polymer::flowModels::noFlow::update(const polymerChains& chains)
{
    // The velocities stay zero: only a change of bead count costs anything
    if (beadVelocity_.size() != chains.nBeads())
    {
        beadVelocity_.setSize(chains.nBeads());
        beadVelocity_ = Zero;
    }
}


// ************************************************************************* //
