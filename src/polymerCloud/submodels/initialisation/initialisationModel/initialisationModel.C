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

#include "initialisationModel.H"
#include "makePolymerModel.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(initialisationModel)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::initialisationModel::initialisationModel
(
    const word& type,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    polymerSubModel
    (
        type,
        dict,
        "the " + type + " initialisation's settings"
    ),
    mesh_(mesh)
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::initialisationModel::lookupType
(
    const PtrList<chainType>& types,
    const dictionary& dict,
    const word& keyword
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << keyword << "' in " << dict.name() << nl
            << "    expected: " << keyword << " <name of an entry of"
            << " chainTypes>;"
            << exit(FatalIOError);
    }

    return findType(types, dict.get<word>(keyword), dict, keyword);
}


Foam::label Foam::polymer::initialisationModel::findType
(
    const PtrList<chainType>& types,
    const word& typeName,
    const dictionary& dict,
    const word& keyword
)
{
    wordList names(types.size());
    forAll(types, typei)
    {
        if (types[typei].name() == typeName)
        {
            return typei;
        }
        names[typei] = types[typei].name();
    }

    FatalIOErrorInFunction(dict)
        << "Unknown chain type '" << typeName << "' for keyword '"
        << keyword << "' in " << dict.name() << nl
        << "    expected one of the chainTypes: " << names
        << exit(FatalIOError);

    return -1;
}


// ************************************************************************* //
