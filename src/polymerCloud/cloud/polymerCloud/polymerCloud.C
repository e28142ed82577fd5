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
#include "allReduce.H"
#include "writeStatus.H"
#include "OStringStream.H"
#include "Tuple2.H"
#include "checkedInput.H"
#include "IOdictionary.H"
#include "freedMemory.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(polymerCloud, 0);
} // End namespace polymer
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::polymerCloud::removeEscapedChains()
{
    const DynamicList<label>& beads = wall_->escapedBeads();
    if (allReduceAnd(beads.empty()))
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


void Foam::polymer::polymerCloud::rejectChains()
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerCloud::polymerCloud
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


Foam::polymer::polymerCloud::polymerCloud
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
    evolveSeconds_(0),
    pathTimes_(),
    beadSteps_(0),
    firstStepSeconds_(0),
    firstStepBeadSteps_(0),
    firstStepDone_(false)
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

    checkKeywords(subModels);
    selectModels(subModels);

    // In a solved flow, a step's temporary fields (and the cloud's arrays
    // of located beads) reuse the previous step's memory; free chains make
    // no arrays that size each step
    if (solvesFlow())
    {
        freedMemory::keep(mesh_.time());
    }

    const bool restart = startChains(subModels);

    readCloudFunctions();

    // The starting configuration is part of the record (and of the VTK
    // series), and a later run from the start time reads it back: marked
    // complete once written, as a run may be stopped while writing it
    if (!restart)
    {
        const fileName local(cloud::prefix/name());
        writeStatus::mark(mesh_.time(), local, "started");
        write();
        writeStatus::mark(mesh_.time(), local, "complete");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::polymerCloud::nBeadsOutside() const
{
    return returnReduce(flow_->nBeadsOutside(), sumOp<label>());
}


Foam::label Foam::polymer::polymerCloud::nParcels() const
{
    return returnReduce(chains_.nBeads(), sumOp<label>());
}


void Foam::polymer::polymerCloud::injectChains(const scalar time)
{
    const label nChainsBefore = chains_.nChains();
    const label nNew =
        injection_->inject(chains_, solution_.seed(), nextChainId_, time);
    if (nNew)
    {
        distribution_->keepOwn(nChainsBefore, nNew);
        setThermalVelocities(nChainsBefore);
        nInjected_ += chains_.nChains() - nChainsBefore;
    }
}


void Foam::polymer::polymerCloud::stopIfEmpty(const scalar time) const
{
    // The rest of the run would step an empty domain. The time's writeNow,
    // as OpenFOAM's abort function object sets it: the next step is the
    // last, and written. The chains are counted over the processors (a
    // reduction) only once the injection is done
    const Time& runTime = mesh_.time();
    if
    (
        !solution_.stopWhenEmpty()
     || runTime.stopAt() == Time::stopAtControls::saWriteNow
     || !injection_->finished(time)
     || returnReduce(chains_.nChains(), sumOp<label>())
    )
    {
        return;
    }
    Info<< name() << ": no chain left in the domain at time " << time
        << ", and none to inject: the run ends at the next time step,"
        << " written (solution stopWhenEmpty)" << endl;
    runTime.stopAt(Time::stopAtControls::saWriteNow);
}


void Foam::polymer::polymerCloud::evolvePolymerStep
(
    const scalar deltaT,
    const scalar time,
    const bool firstCycle
)
{
    // 1. Unconstrained update in the fluid velocity and forces at x^n
    stepper_->integrate(deltaT);
    pathTimes_.lap(pathTimes::integrate);

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
    pathTimes_.lap(pathTimes::functions);

    // 2. Rod lengths and rod velocities; failed chains are sub-stepped
    stepper_->constrain(deltaT);
    pathTimes_.lap(pathTimes::constrain);

    for (polymerCloudFunction& function : functions_)
    {
        function.postConstrain(deltaT);
    }
    pathTimes_.lap(pathTimes::functions);

    // The momentum the chains exchanged with the solvent (two-way): the
    // friction and noise of each bead's path, the constraint's included;
    // the constraint and collision impulses are internal to the chains,
    // and the walls' to come are not exchanges with the solvent. The
    // sub-cycles of a flow step add theirs up
    if (coupling_->twoWay())
    {
        coupling_->deposit
        (
            chains_,
            stepper_->velocityChange(),
            stepper_->force(),
            deltaT,
            !firstCycle,
            mesh_.time().deltaTValue()
        );
        pathTimes_.lap(pathTimes::couple);
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
    pathTimes_.lap(pathTimes::collide);
    if (contactProjection_)
    {
        contactProjection_->correct
        (
            stepper_->positionsOld(),
            deltaT,
            time,
            wall_.get(),
            collision_()
        );
        pathTimes_.lap(pathTimes::reproject);
    }
    collisionGroups_->checkBoxes();
    rejectChains();
    removeEscapedChains();
    for (polymerSubModel& model : models_)
    {
        model.endStep();
    }
    distribution_->update();
    pathTimes_.lap(pathTimes::bookkeep);

    beadSteps_ += chains_.nBeads();
}


void Foam::polymer::polymerCloud::updateDrift()
{
    stepper_->prepareDrift();
    pathTimes_.lap(pathTimes::interpolate);
    stepper_->updateDrift();
    stepper_->countBeadsOutside();
    pathTimes_.lap(pathTimes::locate);
}


void Foam::polymer::polymerCloud::checkStaticMesh(const scalar time) const
{
    // The cell search, the walls' faces and edges and the beads' kept tets
    // are built from the mesh as it starts; a solver that moves the mesh
    // (pimpleFoam with a dynamicMeshDict's motion) would leave them stale
    if (!mesh_.moving() && !mesh_.topoChanging())
    {
        return;
    }
    const IOdictionary dynamicMeshDict
    (
        IOobject
        (
            "dynamicMeshDict",
            mesh_.time().constant(),
            mesh_,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
    FatalIOErrorInFunction(dynamicMeshDict)
        << "The mesh " << (mesh_.moving() ? "moved" : "changed its cells")
        << " at time " << time << ": the polymer cloud needs a static mesh"
        << " (its cell search, wall faces and the beads' tets are built"
        << " from the mesh as it starts)" << nl
        << "    expected: dynamicFvMesh staticFvMesh; (or no"
        << " constant/dynamicMeshDict)"
        << exit(FatalIOError);
}


void Foam::polymer::polymerCloud::evolve()
{
    if (!solution_.active())
    {
        return;
    }

    pathTimes_.start();

    const Time& runTime = mesh_.time();
    const scalar deltaT = runTime.deltaTValue();
    const scalar time = runTime.value();

    // (not deltaT > 0) also catches a NaN
    if (!(deltaT > 0))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "The time step at time " << time << " is " << deltaT
            << ": the chains' noise and drag need a positive step" << nl
            << "    expected: deltaT <positive time>; (and, with"
            << " adjustTimeStep, maxDeltaT and maxCo positive)"
            << exit(FatalIOError);
    }

    checkStaticMesh(time);

    injectChains(time);
    pathTimes_.lap(pathTimes::inject);
    updateDrift();

    // The flow's step in nCycles polymer steps (solution's
    // maxNeighbourDisplacement), each from the fluid velocity and forces
    // at its own start
    const label nCycles = stepper_->subCycles(deltaT);
    for (label cycle = 0; cycle < nCycles; ++cycle)
    {
        if (cycle)
        {
            updateDrift();
        }
        stepper_->setSubCycle(nCycles, cycle);
        evolvePolymerStep
        (
            deltaT/nCycles,
            time - deltaT*(nCycles - 1 - cycle)/nCycles,
            cycle == 0
        );
    }
    stepper_->setSubCycle(1, 0);

    // The step's paths up to its bookkeeping, the cloud functions' laps
    // within the step included
    evolveSeconds_ += pathTimes_.stop();
    if (!firstStepDone_)
    {
        firstStepSeconds_ = evolveSeconds_;
        firstStepBeadSteps_ = beadSteps_;
        firstStepDone_ = true;
    }

    for (polymerCloudFunction& function : functions_)
    {
        function.postEvolve();
    }
    pathTimes_.lap(pathTimes::functions);

    stopIfEmpty(time);
}


void Foam::polymer::polymerCloud::predictCoupling()
{
    const scalar deltaT = mesh_.time().deltaTValue();

    // Steps 1 and 2 in the flow of the step's start, with the same noise
    // as the step proper (keyed by the time index), so the predictor
    // differs from it by the flow only; the chains then return to x^n
    stepper_->updateDrift();
    flow_->storePredictor();
    stepper_->integrate(deltaT);
    stepper_->constrainUncounted(deltaT);

    coupling_->deposit
    (
        chains_,
        stepper_->velocityChange(),
        stepper_->force(),
        deltaT,
        false,
        deltaT
    );

    stepper_->restoreStart();
}


void Foam::polymer::polymerCloud::resetIntervalCounters() const
{
    for (const polymerSubModel& model : models_)
    {
        model.resetInterval();
    }
}


// ************************************************************************* //
