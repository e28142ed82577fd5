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

#include "collisionModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(collisionModel, 0);
    defineRunTimeSelectionTable(collisionModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::collisionModel::collisionModel
(
    const word& type,
    const dictionary& dict
)
:
    coeffDict_(dict.optionalSubDict(type + "Coeffs")),
    counters_()
{}


// ************************************************************************* //
