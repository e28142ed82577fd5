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

#include "modelKeywords.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::HashTable<Foam::wordList>& Foam::polymer::modelKeywords::table()
{
    static const HashTable<wordList> keywords
    ({
        #include "modelKeywordsTable.H"
    });
    return keywords;
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::polymer::modelKeywords::check
(
    const word& family,
    const word& modelType,
    const dictionary& dict
)
{
    const auto iter = table().cfind(family + "::" + modelType);
    if (!iter.found())
    {
        return;
    }
    const wordList& known = *iter;

    for (const entry& e : dict)
    {
        if (e.keyword().isPattern() || known.found(e.keyword()))
        {
            continue;
        }
        string expected("no entries (" + modelType + " has none)");
        if (!known.empty())
        {
            expected = "one of";
            for (const word& keyword : known)
            {
                expected += " " + keyword;
            }
        }
        FatalIOErrorInFunction(dict)
            << "Keyword '" << e.keyword() << "' in " << dict.name()
            << " is not a keyword of " << modelType << " (" << family
            << "): misspelt, or meant for another model" << nl
            << "    expected: " << expected.c_str()
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
