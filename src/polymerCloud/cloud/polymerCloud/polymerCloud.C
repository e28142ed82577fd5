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

#include "polymerCloud.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "Tuple2.H"
#include "initialisationModel.H"
#include "newton.H"
#include "chainNoise.H"
#include "checkedInput.H"
#include "cpuTime.H"
#include "HashTable.H"
#include "pointOwners.H"
#include "cellLocator.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(polymerCloud, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymerCloud::readChainTypes()
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


void Foam::polymerCloud::readCloudFunctions()
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


void Foam::polymerCloud::readForces(const dictionary& subModels)
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


void Foam::polymerCloud::initialise()
{
    const dictionary& subModels = properties_.subDict("subModels");

    autoPtr<initialisationModel> initialisation
    (
        initialisationModel::New(subModels, mesh_)
    );

    // Every processor creates the same chains (the initialisations draw
    // counter-based noise and test beads against the whole mesh); each
    // keeps those it owns once their velocities are set
    initialisation->create(chains_, solution_.seed());

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
}


void Foam::polymerCloud::setThermalVelocities(const label firstChain)
{
    List<vector>& v = chains_.velocities();

    // A direct solve of the rod velocities, whatever the dynamics' method:
    // the iterative ones converge slowly on smooth starting shapes such as
    // the trefoil
    const constraintModels::newton projection(dictionary::null);

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

        if (constraint_->constrainsVelocities())
        {
            scalar residual;
            projection.correctChainVelocities(chains_, c, residual);
        }
    }
}


void Foam::polymerCloud::checkRods(const fileName& origin) const
{
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const scalar error = chains_.maxRodLengthError(c);

        if (error > solution_.rodLengthCheck())
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


void Foam::polymerCloud::checkInsideMesh(const fileName& origin) const
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


void Foam::polymerCloud::attachModels()
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


void Foam::polymerCloud::removeEscapedChains()
{
    const DynamicList<label>& beads = wall_->escapedBeads();
    if (returnReduce(beads.empty(), andOp<bool>()))
    {
        return;
    }

    DynamicList<label> leaving;
    for (const label bead : beads)
    {
        const label c = chains_.chainOf(bead);
        if (!leaving.found(c))
        {
            leaving.append(c);
        }
    }

    // One log line per chain, from every processor, in chain id order
    label nBeads = 0;
    List<List<Tuple2<label, string>>> departures(Pstream::nProcs());
    List<Tuple2<label, string>>& mine = departures[Pstream::myProcNo()];
    mine.setSize(leaving.size());
    forAll(leaving, k)
    {
        const label c = leaving[k];
        nBeads += chains_.size(c);
        OStringStream os;
        os  << name() << ": chain " << chains_.globalId(c) << " ("
            << chains_.type(c).name() << ", " << chains_.size(c)
            << " beads) left the domain at time " << mesh_.time().value();
        mine[k] = Tuple2<label, string>(chains_.globalId(c), os.str());
    }
    Pstream::gatherList(departures);
    if (Pstream::master())
    {
        List<Tuple2<label, string>> all;
        for (const auto& list : departures)
        {
            all.append(list);
        }
        Foam::sort(all);
        for (const Tuple2<label, string>& departure : all)
        {
            Info<< departure.second().c_str() << endl;
        }
    }

    wall_->countEscaped(leaving.size(), nBeads);
    chains_.remove(leaving);
    wall_->clearEscaped();
}


void Foam::polymerCloud::rejectChains()
{
    const DynamicList<label>& beads = wall_->rejectedBeads();
    if (beads.empty())
    {
        return;
    }

    DynamicList<label> rejected;
    for (const label bead : beads)
    {
        const label c = chains_.chainOf(bead);
        if (!rejected.found(c))
        {
            rejected.append(c);
        }
    }

    List<vector>& x = chains_.positions();
    List<vector>& v = chains_.velocities();
    const UList<vector>& positionsOld = stepper_->positionsOld();
    const UList<vector>& velocitiesOld = stepper_->velocitiesOld();
    for (const label c : rejected)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            x[i] = positionsOld[i];
            v[i] = -velocitiesOld[i];
        }
    }

    wall_->clearRejected(rejected.size());
}


void Foam::polymerCloud::wrapChains()
{
    if (!periodic_.active())
    {
        return;
    }

    List<vector>& x = chains_.positions();
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const label first = chains_.start(c);
        const vector shift = periodic_.shift(x[chains_.referenceBead(c)]);
        if (shift == vector::zero)
        {
            continue;
        }
        for (label i = first; i < chains_.end(c); ++i)
        {
            x[i] += shift;
        }
        ++periodicCrossings_;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymerCloud::polymerCloud
(
    const word& cloudName,
    const fvMesh& mesh
)
:
    polymerCloud
    (
        cloudName,
        mesh,
        IOdictionary
        (
            IOobject
            (
                cloudName + "Properties",
                mesh.time().constant(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        )
    )
{}


Foam::polymerCloud::polymerCloud
(
    const word& cloudName,
    const fvMesh& mesh,
    const dictionary& properties
)
:
    cloud(mesh, cloudName),
    mesh_(mesh),
    properties_
    (
        IOobject
        (
            cloudName + "Properties",
            mesh.time().constant(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        properties
    ),
    periodic_(periodicImages::New(mesh)),
    solution_(properties_),
    types_(),
    chains_(types_),
    flow_(),
    forces_(),
    integration_(),
    constraint_(),
    collision_(),
    wall_(),
    injection_(),
    nextChainId_(0),
    nInjected_(0),
    functions_(),
    periodicCrossings_(0),
    evolveSeconds_(0),
    beadSteps_(0),
    maxBeadsOutside_(0),
    beadStepsOutside_(0)
{
    // Keep the file's name for messages when given a dictionary read from it
    if (!properties.name().empty())
    {
        properties_.dictionary::name() = properties.name();
    }

    // Locating points builds the mesh's tet base points on first use, a
    // collective operation: build them on every processor now, since only
    // some processors hold chains
    mesh_.tetBasePtIs();

    readChainTypes();

    const dictionary& subModels = checkedInput::subDict
    (
        properties_,
        "subModels",
        "integration <model>; constraint <model>; collision <model>;"
        " wall <model>; flow <model>; initialisation <model>; ..."
    );

    flow_ = flowModel::New(subModels, mesh_);
    readForces(subModels);
    integration_ = integrationModel::New(subModels);
    constraint_ = constraintModel::New(subModels);
    collision_ = collisionModel::New(subModels);
    collision_->setLattice(periodic_.lattice());
    wall_ = wallModel::New(subModels, mesh_);
    injection_ = injectionModel::New(subModels, mesh_);
    attachModels();
    stepper_.reset
    (
        new chainStepper
        (
            mesh_.time(),
            solution_.seed(),
            chains_,
            flow_(),
            forces_,
            integration_(),
            constraint_()
        )
    );
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

    checkParallelSupport(subModels);

    // Every processor of a parallel run restarts, or none does; a parallel
    // run may continue a serial one from the undecomposed case's chains
    // (decomposePar carries no chains), every processor keeping its own
    const bool restart =
        returnReduce(savedCloudExists(savedCloudDir()), orOp<bool>());
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
        initialise();
        distribution_->keepOwn();
        Info<< name() << ": created "
            << returnReduce(chains_.nChains(), sumOp<label>())
            << " chains with the "
            << subModels.get<word>("initialisation") << " initialisation"
            << endl;
    }

    distribution_->sort();

    label largestId = -1;
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        largestId = max(largestId, chains_.globalId(c));
    }
    nextChainId_ = returnReduce(largestId, maxOp<label>()) + 1;

    readCloudFunctions();

    // The starting configuration is part of the record (and of the VTK
    // series), and a later run from the start time reads it back
    if (!restart && !fromUndecomposed)
    {
        write();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymerCloud::nBeadsOutside() const
{
    return returnReduce(flow_->nBeadsOutside(), sumOp<label>());
}


Foam::label Foam::polymerCloud::nParcels() const
{
    return returnReduce(chains_.nBeads(), sumOp<label>());
}


void Foam::polymerCloud::evolve()
{
    if (!solution_.active())
    {
        return;
    }

    cpuTime timer;

    const Time& runTime = mesh_.time();
    const scalar deltaT = runTime.deltaTValue();
    const scalar time = runTime.value();

    // New chains fed in, with thermal velocities
    const label nChainsBefore = chains_.nChains();
    if (injection_->inject(chains_, solution_.seed(), nextChainId_, time))
    {
        distribution_->keepOwn(nChainsBefore);
        setThermalVelocities(nChainsBefore);
        nInjected_ += chains_.nChains() - nChainsBefore;
    }

    stepper_->start();

    // 1. Unconstrained update in the fluid velocity and forces at x^n
    stepper_->updateDrift();
    maxBeadsOutside_ = max(maxBeadsOutside_, flow_->nBeadsOutside());
    beadStepsOutside_ += flow_->nBeadsOutside();
    stepper_->integrate(deltaT);

    for (polymerCloudFunction& function : functions_)
    {
        function.postIntegrate
        (
            stepper_->positionsOld(),
            stepper_->velocitiesOld(),
            stepper_->force(),
            deltaT
        );
    }

    // 2. Rod lengths and rod velocities; failed chains are sub-stepped
    stepper_->constrain(deltaT);

    for (polymerCloudFunction& function : functions_)
    {
        function.postConstrain(deltaT);
    }

    // The momentum the chains exchanged with the solvent (two-way): the
    // friction and noise of each bead's path, the constraint's included;
    // the constraint and collision impulses are internal to the chains,
    // and the walls' to come are not exchanges with the solvent
    if (flow_->twoWay())
    {
        flow_->depositMomentum
        (
            chains_,
            stepper_->velocityChange(),
            stepper_->force(),
            deltaT
        );
    }

    // 3. Rod-rod collisions and bead-wall impacts, chains of different
    // processors that can meet in one loop
    collisionGroups_->group
    (
        stepper_->positionsOld(),
        stepper_->velocitiesOld()
    );
    collision_->correct
    (
        chains_, stepper_->positionsOld(), deltaT, time, wall_.get()
    );
    collisionGroups_->checkBoxes();
    rejectChains();
    removeEscapedChains();
    for (polymerSubModel& model : models_)
    {
        model.endStep();
    }
    wrapChains();
    distribution_->locateReferenceBeads();
    distribution_->distribute();
    distribution_->sort();

    evolveSeconds_ += timer.cpuTimeIncrement();
    beadSteps_ += chains_.nBeads();

    for (polymerCloudFunction& function : functions_)
    {
        function.postEvolve();
    }
}


void Foam::polymerCloud::predictCoupling()
{
    const scalar deltaT = mesh_.time().deltaTValue();

    // Steps 1 and 2 in the flow of the step's start, with the same noise
    // as the step proper (keyed by the time index), so the predictor
    // differs from it by the flow only; the chains then return to x^n
    stepper_->start();
    stepper_->updateDrift();
    flow_->storePredictor();
    stepper_->integrate(deltaT);
    stepper_->constrainUncounted(deltaT);

    flow_->depositMomentum
    (
        chains_,
        stepper_->velocityChange(),
        stepper_->force(),
        deltaT
    );

    stepper_->restoreStart();
}


void Foam::polymerCloud::resetIntervalCounters() const
{
    for (const polymerSubModel& model : models_)
    {
        model.resetInterval();
    }
}


void Foam::polymerCloud::writeSummary(Ostream& os) const
{
    // Chains per type, over all processors
    labelList nChainsOfType(types_.size(), Zero);
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        ++nChainsOfType[chains_.typeIndex(c)];
    }
    Pstream::listCombineGather(nChainsOfType, plusEqOp<label>());

    os  << name() << ':';
    label nListed = 0;
    forAll(types_, typei)
    {
        if (nChainsOfType[typei])
        {
            os  << (nListed++ ? " +" : "") << ' ' << nChainsOfType[typei]
                << (types_[typei].ring() ? " ring" : " chain")
                << (nChainsOfType[typei] > 1 ? "s" : "") << " x "
                << types_[typei].nBeads() << " beads";
        }
    }
    if (!nListed)
    {
        os  << " no chains";
    }

    os  << "; integration " << integration_->type()
        << "; constraint " << constraint_->type()
        << "; collision " << collision_->type()
        << "; wall " << wall_->type()
        << "; flow " << flow_->type();
    if (forces_.size())
    {
        os  << "; forces";
        for (const forceModel& model : forces_)
        {
            os  << ' ' << model.type();
        }
    }
    os  << (solution_.active() ? "" : " (inactive)") << nl;

    forAll(types_, typei)
    {
        os  << "    ";
        types_[typei].writeSummary(os);
        os  << nl;
    }
}


void Foam::polymerCloud::writeReport(Ostream& os) const
{
    const scalar seconds = returnReduce(evolveSeconds_, maxOp<scalar>());
    const scalar beadSteps = returnReduce(beadSteps_, sumOp<scalar>());

    os  << name() << ": " << beadSteps << " bead-steps in " << seconds
        << " s of cloud evolution";
    if (seconds > 0)
    {
        os  << ", " << beadSteps/seconds << " bead-steps/s";
    }
    os  << nl;
    for (const polymerSubModel& model : models_)
    {
        model.writeReport(os);
    }
    os
        << "    chains injected " << returnReduce(nInjected_, sumOp<label>())
        << ", chains carried across cyclic patches "
        << returnReduce(periodicCrossings_, sumOp<label>())
        << ", chains moved between processors "
        << returnReduce(distribution_->nMoved(), sumOp<label>()) << nl;
    if (Pstream::parRun())
    {
        collisionGroups_->writeReport(os);
        os  << "    parallel exchanges (wall clock, slowest processor):"
            << " moving chains "
            << returnReduce(distribution_->seconds(), maxOp<scalar>())
            << " s, beads' flow and momentum "
            << returnReduce(flow_->exchangeSeconds(), maxOp<scalar>())
            << " s" << nl;
        writeProcessorLoads(os);
    }
    os
        << "    beads " << nParcels() << ", outside the mesh "
        << nBeadsOutside() << " (checked every step: at most "
        << returnReduce(maxBeadsOutside_, maxOp<label>()) << " in a step, "
        << returnReduce(beadStepsOutside_, sumOp<scalar>())
        << " bead-steps in all)" << nl;
}


// ************************************************************************* //
