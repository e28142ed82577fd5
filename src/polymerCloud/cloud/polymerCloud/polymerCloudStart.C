/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    The polymerCloud's start: the chain types, the sub-models and the
    cloud's parts, the chains read from a saved cloud or created, with
    their checks (rod lengths, beads in the mesh) and thermal velocities.

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"
#include "IFstream.H"
#include "initialisationModel.H"
#include "newton.H"
#include "chainNoise.H"
#include "checkedInput.H"
#include "pointOwners.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::polymerCloud::readChainTypes()
{
    const dictionary& typesDict = checkedInput::subDict
    (
        properties_,
        "chainTypes",
        "<name> { nBeads <N>; rodLength <a>; beadMass <m>; friction <zeta>;"
        " kT <kT>; } ..."
    );

    for (const entry& e : typesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(typesDict)
                << "Entry '" << e.keyword() << "' in " << typesDict.name()
                << " is not a dictionary" << nl
                << "    expected: " << e.keyword() << " { nBeads <N>;"
                << " rodLength <a>; beadMass <m>; friction <zeta>; kT <kT>; }"
                << exit(FatalIOError);
        }
        types_.append(new chainType(e.keyword(), e.dict()));
    }

    if (types_.empty())
    {
        FatalIOErrorInFunction(typesDict)
            << "No chain types in " << typesDict.name() << nl
            << "    expected: <name> { nBeads <N>; rodLength <a>; ... }"
            << exit(FatalIOError);
    }
}


void Foam::polymer::polymerCloud::readCloudFunctions()
{
    const dictionary* dictPtr =
        properties_.findDict("cloudFunctions", keyType::LITERAL);

    if (!dictPtr)
    {
        return;
    }

    for (const entry& e : *dictPtr)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*dictPtr)
                << "Entry '" << e.keyword() << "' in " << dictPtr->name()
                << " is not a dictionary" << nl
                << "    expected: " << e.keyword() << " { type <function>; }"
                << exit(FatalIOError);
        }
        functions_.append
        (
            polymerCloudFunction::New(e.keyword(), e.dict(), *this)
        );
    }
}


void Foam::polymer::polymerCloud::readForces(const dictionary& subModels)
{
    const wordList names
    (
        subModels.getOrDefault<wordList>("forces", wordList())
    );

    for (const word& name : names)
    {
        forces_.append(forceModel::New(name, subModels, mesh_));
    }
}


Foam::label Foam::polymer::polymerCloud::initialise()
{
    const dictionary& subModels = properties_.subDict("subModels");

    autoPtr<initialisationModel> initialisation
    (
        initialisationModel::New(subModels, mesh_)
    );

    // The chains are drawn from counter-based noise, so every processor
    // draws the same: each creates those it may own (randomWalk) or all,
    // and keeps those it owns once their velocities are set
    const label nCreated = initialisation->create(chains_, solution_.seed());

    checkRods(properties_.dictionary::name()/"subModels"/"initialisation");
    if
    (
        (flow_->solvesFlow() || wall_->active())
     && !initialisation->placesInsideMesh()
    )
    {
        checkInsideMesh(properties_.dictionary::name()/"subModels");
    }
    setThermalVelocities(0);
    return nCreated;
}


void Foam::polymer::polymerCloud::setThermalVelocities(const label firstChain)
{
    List<vector>& v = chains_.velocities();

    // A direct solve of the rod velocities, whatever the dynamics' method:
    // the iterative ones converge slowly on smooth starting shapes such as
    // the trefoil
    const constraintModels::newton projection(dictionary::null);

    label nFailed = 0;
    for (label c = firstChain; c < chains_.nChains(); ++c)
    {
        const chainType& type = chains_.type(c);
        const scalar thermalSpeed = std::sqrt(type.kT()/type.beadMass());
        const chainNoise noise(solution_.seed(), chains_.globalId(c));

        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            scalar xi[4];
            noise.normals
            (
                0,
                i - chains_.start(c),
                chainNoise::setUpStream + 1,
                0,
                xi
            );
            v[i] = thermalSpeed*vector(xi[0], xi[1], xi[2]);
        }

        scalar residual = 0;
        if
        (
            constraint_->constrainsVelocities()
         && projection.correctChainVelocities(chains_, c, residual) < 0
         && nFailed++ == 0
        )
        {
            WarningInFunction
                << "The starting velocities of chain " << chains_.globalId(c)
                << " (" << type.name() << ") at time "
                << mesh_.time().timeName() << " are off its rods by "
                << residual << " (relative), above the projection's"
                << " tolerance" << endl;
        }
    }
    if (nFailed > 1)
    {
        WarningInFunction
            << nFailed << " chains' starting velocities at time "
            << mesh_.time().timeName() << " are off their rods above the"
            << " projection's tolerance" << endl;
    }
}


void Foam::polymer::polymerCloud::checkRods(const fileName& origin) const
{
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const scalar error = chains_.maxRodLengthError(c);

        if (!(error <= solution_.rodLengthCheck()))
        {
            FatalIOErrorInFunction(properties_)
                << "Chain " << chains_.globalId(c) << " ("
                << chains_.type(c).name() << ") from " << origin.c_str()
                << " has a rod whose length differs from rodLength "
                << chains_.type(c).rodLength() << " by a relative " << error
                << nl << "    expected: every rod of length rodLength to a"
                << " relative " << solution_.rodLengthCheck()
                << " (solution { rodLengthCheck <tolerance>; })"
                << exit(FatalIOError);
        }
    }
}


void Foam::polymer::polymerCloud::checkInsideMesh(const fileName& origin) const
{
    // Every processor holds every new chain: each searches only the beads
    // in its part of the mesh (collective)
    const List<vector>& x = chains_.positions();
    pointField images(x.size());
    forAll(x, i)
    {
        images[i] = periodic_.wrap(x[i]);
    }
    const label i = replicatedPointOwners(mesh_, images).find(-1);
    if (i >= 0)
    {
        const label c = chains_.chainOf(i);
        FatalIOErrorInFunction(properties_)
            << "Chain " << chains_.globalId(c) << " ("
            << chains_.type(c).name() << ") from " << origin.c_str()
            << "/initialisation has bead " << i - chains_.start(c)
            << " at " << x[i] << ", outside the mesh" << nl
            << "    expected: every bead in the mesh when the flow is"
            << " solved or walls are modelled"
            << exit(FatalIOError);
    }
}


void Foam::polymer::polymerCloud::attachModels()
{
    models_.clear();
    models_.append(flow_.get());
    for (forceModel& model : forces_)
    {
        models_.append(&model);
    }
    models_.append(integration_.get());
    models_.append(constraint_.get());
    models_.append(collision_.get());
    models_.append(wall_.get());
    models_.append(injection_.get());

    for (polymerSubModel& model : models_)
    {
        model.attach(*this);
    }
}


void Foam::polymer::polymerCloud::checkKeywords
(
    const dictionary& subModels
) const
{
    // Other top-level entries may be variables for $-expansion
    checkedInput::noMisspeltKeywords
    (
        properties_,
        {"FoamFile", "solution", "chainTypes", "subModels", "cloudFunctions"},
        "the cloud's properties"
    );

    wordList known
    ({
        "integration", "constraint", "collision", "wall", "flow",
        "forces", "initialisation", "injection"
    });
    for
    (
        const wordList& models
      : {
            integrationModel::dictionaryConstructorTablePtr_->sortedToc(),
            constraintModel::dictionaryConstructorTablePtr_->sortedToc(),
            collisionModel::dictionaryConstructorTablePtr_->sortedToc(),
            wallModel::dictionaryConstructorTablePtr_->sortedToc(),
            flowModel::dictionaryConstructorTablePtr_->sortedToc(),
            forceModel::dictionaryConstructorTablePtr_->sortedToc(),
            initialisationModel::dictionaryConstructorTablePtr_->sortedToc(),
            injectionModel::dictionaryConstructorTablePtr_->sortedToc()
        }
    )
    {
        for (const word& model : models)
        {
            // Several families have a model 'none'
            if (!known.found(model + "Coeffs"))
            {
                known.append(model + "Coeffs");
            }
        }
    }
    checkedInput::onlyKeywords(subModels, known, "the cloud's subModels");
}


void Foam::polymer::polymerCloud::selectModels(const dictionary& subModels)
{
    flow_ = flowModel::New(subModels, mesh_);
    readForces(subModels);
    integration_ = integrationModel::New(subModels);
    constraint_ = constraintModel::New(subModels);
    collision_ = collisionModel::New(subModels);
    collision_->setLattice(periodic_.lattice());
    wall_ = wallModel::New(subModels, mesh_);
    injection_ = injectionModel::New(subModels, mesh_);
    injection_->checkTypes(types_);
    attachModels();
    coupling_.reset(new polymerCoupling(mesh_, flow_()));
    stepper_.reset
    (
        new chainStepper
        (
            mesh_.time(),
            solution_,
            chains_,
            flow_(),
            coupling_(),
            forces_,
            integration_(),
            constraint_()
        )
    );
    // Without collisions and walls no contact leaves a rod off: a chain
    // the constraint leaves off is its own (sub-stepped on failure)
    if
    (
        solution_.reproject()
     && (collision_->type() != "none" || wall_->active())
    )
    {
        contactProjection_.reset
        (
            new contactProjection
            (
                chains_,
                constraint_(),
                collision_->uncrossable(),
                periodic_.lattice(),
                collision_->meetsWallEdges(),
                solution_.maxContactRounds()
            )
        );
    }
    distribution_.reset
    (
        new chainDistribution
        (
            mesh_,
            periodic_,
            chains_,
            flow_->solvesFlow() || wall_->active()
        )
    );
    if (const beadSampler* sampler = flow_->beadLocations())
    {
        distribution_->useKeptTets(*sampler);
    }
    collisionGroups_.reset
    (
        new collisionGroups
        (
            periodic_,
            chains_,
            distribution_(),
            collision_->type() != "none"
        )
    );

    if (wall_->rejects() && collision_->type() != "none")
    {
        FatalIOErrorInFunction(subModels)
            << "A patch of " << subModels.name() << " rejects steps"
            << " (patchInteraction reject) while collision is "
            << collision_->type() << nl
            << "    expected: collision none; with reject patches (a"
            << " rejected chain returning to x^n could cross chains that"
            << " moved)"
            << exit(FatalIOError);
    }

    // The predictor takes the flow step as one polymer step, with the
    // noise of a whole step: not the sub-cycles' step it predicts
    if
    (
        coupling_->predictorCorrector()
     && solution_.maxNeighbourDisplacement() > 0
    )
    {
        FatalIOErrorInFunction(properties_)
            << "solution maxNeighbourDisplacement in " << properties_.name()
            << " sub-cycles the polymer step, while the field flow's"
            << " predictorCorrector is true" << nl
            << "    expected: one of them (the predictor-corrector coupling"
            << " predicts a whole flow step as one polymer step)"
            << exit(FatalIOError);
    }

    checkParallelSupport(subModels);
}


void
Foam::polymer::polymerCloud::checkParallelSupport(const dictionary& subModels)
{
    if (!Pstream::parRun())
    {
        return;
    }

    if (wall_->active() && !wall_->runsInParallel())
    {
        FatalIOErrorInFunction(subModels)
            << "wall " << wall_->type() << " in " << subModels.name()
            << " runs serially in this version: its distance field is not"
            << " exchanged between processors" << nl
            << "    expected: a serial run, or in parallel wall meshFaces"
            << " (or none)"
            << exit(FatalIOError);
    }

    // A bead of a chain is at most a contour length from the chain's
    // reference bead, which is in its owner's mesh at the step's start,
    // and moves less than a rod length in a step: the walls of other
    // processors within that reach; twice that with collisions, whose
    // groups bring a neighbour's chains into a processor's loop
    if (wall_->active())
    {
        scalar reach = 0;
        for (const chainType& type : types_)
        {
            reach = max(reach, type.nBeads()*type.rodLength());
        }
        if (collision_->type() != "none")
        {
            reach *= 2;
        }
        wall_->setReach(reach);
        Info<< name() << ": wall " << wall_->type() << " sees "
            << returnReduce(wall_->faces().nHaloFaces(), sumOp<label>())
            << " boundary faces of other processors (within "
            << reach << " of each processor's mesh)" << endl;
    }
}


bool Foam::polymer::polymerCloud::startChains(const dictionary& subModels)
{
    // Every processor of a parallel run restarts, or none does; a parallel
    // run may continue a serial one from the undecomposed case's chains
    // (decomposePar carries no chains), every processor keeping its own
    const bool restart = savedCloudIsComplete();
    const bool fromUndecomposed =
        !restart && Pstream::parRun()
     && returnReduce
        (
            savedCloudExists(undecomposedCloudDir()), andOp<bool>()
        );

    if (restart)
    {
        Info<< name() << ": reading the chains saved in "
            << mesh_.time().timeName()/cloud::prefix/name() << endl;
        if (savedCloudExists(savedCloudDir()))
        {
            readChains(savedCloudDir());
        }
    }
    else if (fromUndecomposed)
    {
        Info<< name() << ": reading the chains saved in the undecomposed"
            << " case's " << mesh_.time().timeName()/cloud::prefix/name()
            << endl;
        readChains(undecomposedCloudDir());
        distribution_->keepOwn();

        // The noise is keyed by the time index: continue the serial run's
        // (decomposePar gives a case without fields no uniform/time, and
        // the run would count from 0)
        IFstream is(undecomposedCloudDir()/".."/".."/"uniform"/"time");
        if (is.good())
        {
            const dictionary timeDict(is);
            Time& runTime = const_cast<Time&>(mesh_.time());
            runTime.setTime(runTime.value(), timeDict.get<label>("index"));
        }
    }
    else
    {
        const label nCreated = initialise();
        distribution_->keepOwn(0, nCreated);
        Info<< name() << ": created "
            << returnReduce(chains_.nChains(), sumOp<label>())
            << " chains with the "
            << subModels.get<word>("initialisation") << " initialisation"
            << endl;
    }

    distribution_->sort();

    // The next chain id: the saved one (a chain that left before the
    // write may have had the largest id), at least past every chain held
    label largestId = -1;
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        largestId = max(largestId, chains_.globalId(c));
    }
    const dictionary outputProperties
    (
        restart ? readOutputProperties(mesh_.time().timePath())
      : fromUndecomposed
      ? readOutputProperties
        (
            mesh_.time().globalPath()/mesh_.time().timeName()
        )
      : dictionary()
    );
    const label savedNext = readNextChainId(outputProperties);
    readRunTotals(outputProperties);
    nextChainId_ = max
    (
        returnReduce(largestId, maxOp<label>()) + 1,
        returnReduce(savedNext, maxOp<label>())
    );

    return restart || fromUndecomposed;
}


// ************************************************************************* //
