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

#include "polymerCloudSource.H"
#include "fvMatrices.H"
#include "field.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(polymerCloudSource, 0);
    addToRunTimeSelectionTable(option, polymerCloudSource, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::polymerCloudSource::polymerCloudSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    polymers_("polymerCloud", mesh),
    source_(polymers_)
{
    fieldNames_ = coeffs_.getOrDefault<wordList>("fields", wordList(1, "U"));
    if (fieldNames_.size() != 1)
    {
        FatalIOErrorInFunction(coeffs_)
            << "Keyword 'fields' of fvOption " << name << " in "
            << coeffs_.name() << " is " << fieldNames_ << nl
            << "    expected: fields (<the momentum equation's velocity>);"
            << exit(FatalIOError);
    }
    // The source acts on the velocity the chains sample: on another field
    // it would never be applied, and the chains would never move
    const auto* field =
        isA<polymer::flowModels::field>(polymers_.flow());
    if (field && fieldNames_[0] != field->UName())
    {
        FatalIOErrorInFunction(coeffs_)
            << "Keyword 'fields' of fvOption " << name << " in "
            << coeffs_.name() << " is " << fieldNames_ << ", but the chains"
            << " sample " << field->UName() << " (fieldCoeffs U)" << nl
            << "    expected: fields (" << field->UName() << ");"
            << exit(FatalIOError);
    }
    applied_.setSize(fieldNames_.size(), false);

    // The predictor-corrector solves the flow before the chains' step,
    // which only polymerPimpleFoam does
    if (polymers_.predictsCoupling())
    {
        const dictionary& subModels =
            polymers_.properties().subDict("subModels");
        FatalIOErrorInFunction(subModels)
            << "Keyword 'predictorCorrector' of fieldCoeffs in "
            << subModels.name() << " is true: the predictor-corrector"
            << " solves the flow twice a step, which only polymerPimpleFoam"
            << " does, not the fvOption " << name << nl
            << "    expected: predictorCorrector false; (or run"
            << " polymerPimpleFoam)" << exit(FatalIOError);
    }
    if (!polymers_.solvesFlow())
    {
        WarningInFunction
            << "The chains of fvOption " << name << " do not sample the"
            << " solver's flow (flow model " << polymers_.flow().type()
            << "): they move as in polymerPimpleFoam without flow"
            << " equations" << endl;
    }

    Info<< nl;
    polymers_.writeSummary(Info);
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fv::polymerCloudSource::~polymerCloudSource()
{
    Info<< nl;
    polymers_.writeReport(Info);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fv::polymerCloudSource::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    source_.addSup(eqn);
}


bool Foam::fv::polymerCloudSource::read(const dictionary& dict)
{
    return option::read(dict);
}


// ************************************************************************* //
