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

#include "polymerPimpleSolver.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymerPimpleSolver::createFlow()
{
    Time& runTime = runTime_;
    fvMesh& mesh = mesh_;

    pimple_.reset(new pimpleControl(mesh));

    bool& adjustTimeStep = adjustTimeStep_;
    scalar& maxCo = maxCo_;
    scalar& maxDeltaT = maxDeltaT_;
    #include "readTimeControls.H"

    cumulativeContErr_.reset
    (
        new uniformDimensionedScalarField
        (
            IOobject
            (
                "cumulativeContErr",
                runTime.timeName(),
                "uniform",
                mesh,
                IOobject::READ_IF_PRESENT,
                IOobject::AUTO_WRITE
            ),
            dimensionedScalar(dimless, Zero)
        )
    );

    auto field = [&](const word& name)
    {
        return IOobject
        (
            name, runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::AUTO_WRITE
        );
    };

    Info<< "Reading field p\n" << endl;
    p_.reset(new volScalarField(field("p"), mesh));

    Info<< "Reading field U\n" << endl;
    U_.reset(new volVectorField(field("U"), mesh));

    Info<< "Reading/calculating face flux field phi\n" << endl;
    IOobject phiIO(field("phi"));
    phiIO.readOpt() = IOobject::READ_IF_PRESENT;
    phi_.reset(new surfaceScalarField(phiIO, fvc::flux(U_())));

    setRefCell(p_(), pimple_->dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_->name());

    laminarTransport_.reset(new singlePhaseTransportModel(U_(), phi_()));
    turbulence_ = incompressible::turbulenceModel::New
    (
        U_(), phi_(), laminarTransport_()
    );

    MRF_.reset(new IOMRFZoneList(mesh));
    fvOptions_ = &fv::options::New(mesh);
    if (!fvOptions_->optionList::size())
    {
        Info<< "No finite volume options present" << endl;
    }

    MRF_->correctBoundaryVelocity(U_());
}


Foam::scalar Foam::polymerPimpleSolver::courantNumber() const
{
    const Time& runTime = runTime_;
    const fvMesh& mesh = mesh_;
    const surfaceScalarField& phi = phi_();

    #include "CourantNo.H"

    return CoNum;
}


void Foam::polymerPimpleSolver::solveFlow()
{
    pimpleControl& pimple = pimple_();

    while (pimple.loop())
    {
        tmp<fvVectorMatrix> tUEqn(momentumPredictor());

        while (pimple.correct())
        {
            pressureCorrector(tUEqn);
        }

        if (pimple.turbCorr())
        {
            laminarTransport_->correct();
            turbulence_->correct();
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymerPimpleSolver::polymerPimpleSolver(Time& runTime, fvMesh& mesh)
:
    runTime_(runTime),
    mesh_(mesh),
    polymers_("polymerCloud", mesh),
    polymerSource_(polymers_),
    progress_(runTime),
    pRefCell_(0),
    pRefValue_(0),
    fvOptions_(nullptr),
    adjustTimeStep_(false),
    maxCo_(1),
    maxDeltaT_(GREAT)
{
    Info<< nl;
    polymers_.writeSummary(Info);
    Info<< endl;

    if (!polymers_.solvesFlow())
    {
        return;
    }

    createFlow();

    // The first time step from the Courant number, only if that reduces
    // it
    const scalar CoNum = courantNumber();
    const bool adjustTimeStep = adjustTimeStep_;
    const scalar maxCo = maxCo_;
    const scalar maxDeltaT = maxDeltaT_;
    #include "setInitialDeltaT.H"

    turbulence_->validate();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymerPimpleSolver::preSolve()
{
    if (!solvesFlow())
    {
        return;
    }

    // A reduction of the step is immediate, an increase damped
    Time& runTime = runTime_;
    bool& adjustTimeStep = adjustTimeStep_;
    scalar& maxCo = maxCo_;
    scalar& maxDeltaT = maxDeltaT_;
    #include "readTimeControls.H"

    const scalar CoNum = courantNumber();
    #include "setDeltaT.H"
}


void Foam::polymerPimpleSolver::evolve()
{
    if (!solvesFlow())
    {
        polymerSource_.evolve();
        return;
    }

    Info<< "Time = " << runTime_.timeName() << nl << endl;

    // Predictor-corrector coupling: a first flow solve with the momentum
    // of a step in the flow of its start
    if (polymers_.predictsCoupling())
    {
        polymerSource_.predict();
        solveFlow();
    }

    polymerSource_.evolve();

    solveFlow();
}


Foam::tmp<Foam::fvVectorMatrix> Foam::polymerPimpleSolver::momentumPredictor()
{
    // The names of pimpleFoam's equations
    volScalarField& p = p_();
    volVectorField& U = U_();
    surfaceScalarField& phi = phi_();
    const IOMRFZoneList& MRF = MRF_();
    fv::options& fvOptions = *fvOptions_;
    incompressible::turbulenceModel* turbulence = turbulence_.get();
    const pimpleControl& pimple = pimple_();
    polymer::polymerMomentumSource& polymerSource = polymerSource_;

    #include "UEqn.H"

    return tUEqn;
}


void Foam::polymerPimpleSolver::pressureCorrector
(
    tmp<fvVectorMatrix>& tUEqn
)
{
    // The names of pimpleFoam's equations
    const Time& runTime = runTime_;
    const fvMesh& mesh = mesh_;
    volScalarField& p = p_();
    volVectorField& U = U_();
    surfaceScalarField& phi = phi_();
    const IOMRFZoneList& MRF = MRF_();
    fv::options& fvOptions = *fvOptions_;
    pimpleControl& pimple = pimple_();
    const label pRefCell = pRefCell_;
    const scalar pRefValue = pRefValue_;
    scalar& cumulativeContErr = cumulativeContErr_->value();
    fvVectorMatrix& UEqn = tUEqn.ref();

    #include "pEqn.H"
}


void Foam::polymerPimpleSolver::postSolve() const
{
    if (solvesFlow())
    {
        runTime_.printExecutionTime(Info);
        progress_.report(runTime_);
    }
    else if (runTime_.writeTime())
    {
        Info<< "Time = " << runTime_.timeName() << nl;
        progress_.report(runTime_);
    }
}


void Foam::polymerPimpleSolver::writeReport(OSstream& os) const
{
    os  << nl;
    polymers_.writeReport(os);
    runTime_.printExecutionTime(os);
}


// ************************************************************************* //
