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
#include "modelKeywords.H"

#include <type_traits>

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class Model, class... Args>
Foam::autoPtr<Model> Foam::polymer::polymerSubModel::select
(
    const dictionary& dict,
    const word& keyword,
    Args&&... args
)
{
    const word modelType
    (
        checkedInput::modelType
        (
            dict, keyword, Model::dictionaryConstructorTablePtr_->sortedToc()
        )
    );

    return selectNamed<Model>
    (
        modelType, dict, keyword, std::forward<Args>(args)...
    );
}


template<class Model, class... Args>
Foam::autoPtr<Model> Foam::polymer::polymerSubModel::selectNamed
(
    const word& modelType,
    const dictionary& dict,
    const word& keyword,
    Args&&... args
)
{
    auto cstrIter = Model::dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Unknown " << keyword << " type " << modelType
            << " (keyword '" << keyword << "' in " << dict.name() << ")"
            << nl << "    expected: " << keyword << " <";
        const wordList names
        (
            Model::dictionaryConstructorTablePtr_->sortedToc()
        );
        forAll(names, i)
        {
            FatalIOError << (i ? " | " : "") << names[i];
        }
        FatalIOError << ">;" << exit(FatalIOError);
    }

    autoPtr<Model> model(cstrIter()(std::forward<Args>(args)...));

    // A misspelt coefficient would be ignored and its default used
    if constexpr (std::is_base_of<polymerSubModel, Model>::value)
    {
        modelKeywords::check(Model::typeName, modelType, model->coeffDict());
    }
    return model;
}


// ************************************************************************* //
