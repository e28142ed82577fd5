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

#include "polymerSubModel.H"
#include "checkedInput.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

Foam::dictionary coefficients
(
    const Foam::word& modelType,
    const Foam::dictionary& dict,
    const Foam::string& requiredCoeffs
)
{
    const Foam::word keyword(modelType + "Coeffs");
    if (!requiredCoeffs.empty())
    {
        return Foam::polymer::checkedInput::subDict
        (
            dict, keyword, requiredCoeffs
        );
    }

    // Empty when absent, not the parent dictionary (optionalSubDict's
    // answer), whose entries are other models' selections
    return dict.subOrEmptyDict(keyword);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerSubModel::polymerSubModel
(
    const word& modelType,
    const dictionary& dict,
    const string& requiredCoeffs
)
:
    owner_(nullptr),
    modelType_(modelType),
    coeffDict_(coefficients(modelType, dict, requiredCoeffs))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::polymer::polymerCloud& Foam::polymer::polymerSubModel::owner() const
{
    if (!owner_)
    {
        FatalErrorInFunction
            << "The " << modelType_ << " model is not attached to a cloud"
            << exit(FatalError);
    }
    return *owner_;
}


// ************************************************************************* //
