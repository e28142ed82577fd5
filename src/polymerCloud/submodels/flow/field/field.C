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

#include "field.H"
#include "PstreamBuffers.H"
#include "clockTime.H"
#include "volFields.H"
#include "interpolation.H"
#include "fvmSup.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(flowModel, flowModels, field)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::flowModels::field::field
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    flowModel(typeName, dict, mesh),
    UName_(coeffDict_.getOrDefault<word>("U", "U")),
    interpolationScheme_
    (
        coeffDict_.getOrDefault<word>("interpolation", "cellPoint")
    ),
    sampler_(mesh),
    velocityStart_()
{
    if
    (
        !interpolation<vector>::dictionaryConstructorTablePtr_->found
        (
            interpolationScheme_
        )
    )
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'interpolation' in " << coeffDict_.name() << " is "
            << interpolationScheme_ << nl
            << "    expected: interpolation <"
            << interpolation<vector>::dictionaryConstructorTablePtr_
               ->sortedToc()
            << ">; (default cellPoint)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::flowModels::field::prepare(const polymerChains& chains)
{
    if (chains.positions().empty() && !Pstream::parRun())
    {
        // No interpolation to set up (cellPoint interpolates U to the
        // points): a scene without chains pays nothing
        return;
    }

    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'U' in " << coeffDict_.name() << " names "
            << UName_ << ", which is no velocity field of the solver" << nl
            << "    expected: U <the velocity field's name>; (default U)"
            << exit(FatalIOError);
    }
    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    if (interpolationScheme_ == "cellPoint")
    {
        pointVelocity_ = beadSampler::pointValues(U);
    }
    else
    {
        interpolator_ = interpolation<vector>::New(interpolationScheme_, U);
    }
}


void Foam::polymer::flowModels::field::update(const polymerChains& chains)
{
    if (chains.positions().empty() && !Pstream::parRun())
    {
        beadVelocity_.clear();
        velocityStart_.clear();
        return;
    }

    // The interpolation of this step's flow, built now if prepare was not
    // called since the last update
    if (!interpolator_.valid() && !pointVelocity_.valid())
    {
        prepare(chains);
    }
    sampler_.locate(chains);
    beadVelocity_.setSize(chains.nBeads());
    if (pointVelocity_.valid())
    {
        sampler_.sample
        (
            mesh_.lookupObject<volVectorField>(UName_),
            pointVelocity_(),
            beadVelocity_
        );
        pointVelocity_.clear();
    }
    else
    {
        sampler_.sample(interpolator_(), beadVelocity_);
        interpolator_.clear();
    }

    // The corrector's flow: the mean of the step's start and the predicted
    // end (beads injected since have no start value)
    const label nStart = min(velocityStart_.size(), beadVelocity_.size());
    for (label i = 0; i < nStart; ++i)
    {
        beadVelocity_[i] = 0.5*(velocityStart_[i] + beadVelocity_[i]);
    }
    velocityStart_.clear();
}


void Foam::polymer::flowModels::field::storePredictor()
{
    velocityStart_ = beadVelocity_;
}


// ************************************************************************* //
