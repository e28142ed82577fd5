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

#include "polymerCloudFunction.H"
#include "modelKeywords.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(polymerCloudFunction)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerCloudFunction::polymerCloudFunction
(
    const word& name,
    const polymerCloud& cloud
)
:
    name_(name),
    cloud_(cloud)
{}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::polymer::polymerCloudFunction>
Foam::polymer::polymerCloudFunction::New
(
    const word& name,
    const dictionary& dict,
    const polymerCloud& cloud
)
{
    if (!dict.found("type", keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword 'type' in " << dict.name() << nl
            << "    expected: type <"
            << dictionaryConstructorTablePtr_->sortedToc() << ">;"
            << exit(FatalIOError);
    }

    const word functionType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(functionType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "cloud function",
            functionType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    modelKeywords::check(typeName, functionType, dict);
    return autoPtr<polymerCloudFunction>(cstrIter()(name, dict, cloud));
}


// ************************************************************************* //
