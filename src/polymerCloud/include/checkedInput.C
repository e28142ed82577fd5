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

#include "checkedInput.H"

#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

//- Within two single-character edits (insertions, deletions or
//  substitutions, any case) of each other: a misspelling
bool nearlyEqual(const Foam::word& a, const Foam::word& b)
{
    // Levenshtein's distance, one row at a time
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t above = row[j];
            const bool same =
                std::tolower(a[i - 1]) == std::tolower(b[j - 1]);
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + !same});
            diagonal = above;
        }
    }
    return row[b.size()] <= 2;
}

//- Stop for a keyword that is not one of the known ones, saying why
void notAKeyword
(
    const Foam::dictionary& dict,
    const Foam::word& keyword,
    const Foam::wordList& known,
    const Foam::string& owner,
    const Foam::string& why
)
{
    using namespace Foam;
    FatalIOErrorInFunction(dict)
        << "Keyword '" << keyword << "' in " << dict.name()
        << " is not a keyword of " << owner.c_str() << ": " << why.c_str()
        << nl << "    expected: one of";
    for (const word& other : known)
    {
        FatalIOError << ' ' << other;
    }
    FatalIOError << exit(FatalIOError);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

void Foam::polymer::checkedInput::missing
(
    const dictionary& dict,
    const word& keyword,
    const string& meaning
)
{
    FatalIOErrorInFunction(dict)
        << "Missing keyword '" << keyword << "' in " << dict.name() << nl
        << "    expected: " << keyword << ' ' << meaning.c_str() << ';'
        << exit(FatalIOError);
}


Foam::scalar Foam::polymer::checkedInput::positiveScalar
(
    const dictionary& dict,
    const word& keyword,
    const string& meaning
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        checkedInput::missing(dict, keyword, meaning);
    }

    const scalar value = dict.get<scalar>(keyword, keyType::LITERAL);

    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' in " << dict.name()
            << " is " << value << nl
            << "    expected: " << keyword << ' ' << meaning.c_str()
            << "; a number > 0"
            << exit(FatalIOError);
    }

    return value;
}


Foam::scalar Foam::polymer::checkedInput::positiveScalarOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt,
    const string& meaning
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        return deflt;
    }

    return positiveScalar(dict, keyword, meaning);
}


Foam::label Foam::polymer::checkedInput::labelAtLeast
(
    const dictionary& dict,
    const word& keyword,
    const label minValue,
    const string& meaning
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        checkedInput::missing(dict, keyword, meaning);
    }

    const label value = dict.get<label>(keyword, keyType::LITERAL);

    if (value < minValue)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << keyword << "' in " << dict.name()
            << " is " << value << nl
            << "    expected: " << keyword << ' ' << meaning.c_str()
            << "; an integer >= " << minValue
            << exit(FatalIOError);
    }

    return value;
}


Foam::label Foam::polymer::checkedInput::labelAtLeastOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const label deflt,
    const label minValue,
    const string& meaning
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        return deflt;
    }

    return labelAtLeast(dict, keyword, minValue, meaning);
}


void Foam::polymer::checkedInput::onlyKeywords
(
    const dictionary& dict,
    const wordList& known,
    const string& owner
)
{
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            notAKeyword
            (
                dict, e.keyword(), known, owner,
                "misspelt, or meant for another dictionary"
            );
        }
    }
}


void Foam::polymer::checkedInput::noMisspeltKeywords
(
    const dictionary& dict,
    const wordList& known,
    const string& owner
)
{
    for (const entry& e : dict)
    {
        if (known.found(e.keyword()))
        {
            continue;
        }
        for (const word& keyword : known)
        {
            if (nearlyEqual(e.keyword(), keyword))
            {
                notAKeyword
                (
                    dict, e.keyword(), known, owner,
                    "misspelt '" + keyword + "'?"
                );
            }
        }
    }
}


bool Foam::polymer::checkedInput::firstOfTwo
(
    const dictionary& dict,
    const string& owner,
    const word& first,
    const word& second,
    const string& expected
)
{
    const bool hasFirst = dict.found(first, keyType::LITERAL);
    if (hasFirst == dict.found(second, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << owner.c_str() << " in " << dict.name()
            << " needs exactly one of the keywords '" << first << "' or '"
            << second << "'" << nl
            << "    expected: " << expected.c_str()
            << exit(FatalIOError);
    }
    return hasFirst;
}


Foam::word Foam::polymer::checkedInput::modelType
(
    const dictionary& dict,
    const word& keyword,
    const wordList& validNames
)
{
    if (!dict.found(keyword, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << keyword << "' in " << dict.name() << nl
            << "    expected: " << keyword << " <model>; with <model> one of "
            << validNames
            << exit(FatalIOError);
    }

    return dict.get<word>(keyword, keyType::LITERAL);
}


const Foam::dictionary& Foam::polymer::checkedInput::subDict
(
    const dictionary& dict,
    const word& keyword,
    const string& meaning
)
{
    if (!dict.isDict(keyword, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary '" << keyword << "' in "
            << dict.name() << nl
            << "    expected: " << keyword << " { " << meaning.c_str() << " }"
            << exit(FatalIOError);
    }

    return dict.subDict(keyword);
}


// ************************************************************************* //
