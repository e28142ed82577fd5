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
#include "checkedInput.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::initialisationModel> Foam::initialisationModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType
    (
        checkedInput::modelType
        (
            dict, "initialisation", dictionaryConstructorTablePtr_->sortedToc()
        )
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "initialisation",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<initialisationModel>(cstrIter()(dict, mesh));
}


// ************************************************************************* //
