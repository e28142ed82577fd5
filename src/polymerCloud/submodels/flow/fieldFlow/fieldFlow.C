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

#include "fieldFlow.H"
#include "volFields.H"
#include "interpolation.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace flowModels
{
    defineTypeNameAndDebug(fieldFlow, 0);
    addToRunTimeSelectionTable(flowModel, fieldFlow, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flowModels::fieldFlow::fieldFlow
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    flowModel(typeName, dict, mesh),
    UName_(coeffDict_.getOrDefault<word>("U", "U")),
    interpolationScheme_
    (
        coeffDict_.getOrDefault<word>("interpolation", "cellPoint")
    ),
    search_(mesh),
    hostCell_(),
    nOutside_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::flowModels::fieldFlow::update(const polymerChains& chains)
{
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);

    autoPtr<interpolation<vector>> interpolator
    (
        interpolation<vector>::New(interpolationScheme_, U)
    );

    const List<vector>& x = chains.positions();

    if (hostCell_.size() != x.size())
    {
        hostCell_.setSize(x.size());
        hostCell_ = -1;
    }
    beadVelocity_.setSize(x.size());

    nOutside_ = 0;
    forAll(x, i)
    {
        // Walk from the previous cell; a tree search when there is none
        hostCell_[i] = search_.findCell(x[i], hostCell_[i]);

        if (hostCell_[i] < 0)
        {
            beadVelocity_[i] = Zero;
            ++nOutside_;
        }
        else
        {
            beadVelocity_[i] = interpolator->interpolate(x[i], hostCell_[i]);
        }
    }
}


// ************************************************************************* //
