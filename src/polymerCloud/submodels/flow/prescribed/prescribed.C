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

#include "prescribed.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(flowModel, flowModels, prescribed)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::flowModels::prescribed::prescribed
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    flowModel(typeName, dict, mesh),
    U0_(coeffDict_.getOrDefault<vector>("U0", Zero)),
    velocityGradient_
    (
        coeffDict_.getOrDefault<tensor>("velocityGradient", Zero)
    ),
    origin_(coeffDict_.getOrDefault<point>("origin", Zero))
{
    const scalar divergence = tr(velocityGradient_);
    if (mag(divergence) > 1e-12*(mag(velocityGradient_) + VSMALL))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'velocityGradient' in " << coeffDict_.name()
            << " has trace " << divergence << ": the solvent is"
            << " incompressible" << nl
            << "    expected: velocityGradient <tensor with zero trace>;"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::flowModels::prescribed::update(const polymerChains& chains)
{
    const List<vector>& x = chains.positions();
    beadVelocity_.setSize(x.size());

    forAll(x, i)
    {
        beadVelocity_[i] = velocity(x[i]);
    }
}


// ************************************************************************* //
