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

#include "noConstraint.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
namespace constraintModels
{
    defineTypeNameAndDebug(noConstraint, 0);
    addToRunTimeSelectionTable(constraintModel, noConstraint, dictionary);
}
} // End namespace polymer
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModels::noConstraint::noConstraint
(
    const dictionary& dict
)
:
    constraintModel(typeName, dict)
{}


// ************************************************************************* //
