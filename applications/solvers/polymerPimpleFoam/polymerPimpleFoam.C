/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Application
    polymerPimpleFoam

Group
    grpIncompressibleSolvers grpLagrangianSolvers

Description
    Transient solver for incompressible flow (pimpleFoam's PIMPLE algorithm
    on a static mesh) carrying a polymerCloud: Kramers bead-rod chains in
    the solvent, the mesoscale polymer model of Miller & Trebotich (2007).

    With the cloud's flow model 'none' (quiescent solvent) or 'prescribed'
    (a given homogeneous flow) no flow equations are solved: only the chains
    are advanced, and the log reports the write times. With 'field' the
    flow is solved by PIMPLE each time step (adjustable by maxCo) and the
    chains move in it. The coupling is set by the field model's coupling
    entry: oneWay (the default), the chains feel the flow and the momentum
    equation is pimpleFoam's; twoWay, the momentum the beads exchange with
    the solvent over the step enters the momentum equation as a source
    (polymerCloud::SU), so the chains' stress acts on the flow; with
    predictorCorrector (two-way) the flow is solved twice a step, before
    and after the chains' step.

    \heading Required fields (flow 'field' only)
    \plaintable
        U       | Velocity [m/s]
        p       | Kinematic pressure, p/rho [m2/s2]
    \endplaintable

    constant/polymerCloudProperties sets the chains and their models; with
    flow 'field' the case also needs constant/transportProperties and
    constant/turbulenceProperties, as pimpleFoam's. The solver is the class
    polymerPimpleSolver (the fields, the PIMPLE control and the cloud as
    members; preSolve, evolve, momentumPredictor, pressureCorrector,
    postSolve).

    Each time directory written is marked complete once all its files are
    (polymer::writeStatus); a restart from latestTime continues from the
    last complete time, moving aside a directory left incomplete by a run
    stopped while writing it (system/controlDict incompleteTimes skip, the
    default; or stop).

\*---------------------------------------------------------------------------*/

#include "polymerPimpleSolver.H"
#include "writeStatus.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for incompressible flow carrying Kramers bead-rod"
        " polymer chains (Miller & Trebotich 2007)."
    );

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    // A restart never reads half a state: incomplete latest times are
    // moved aside (or stop the run) before the Time selects its start
    polymer::writeStatus::selectComplete(args);
    #include "createTime.H"
    polymer::writeStatus writes(runTime);
    #include "createMesh.H"

    polymerPimpleSolver solver(runTime, mesh);

    Info<< "\nStarting time loop"
        << (solver.solvesFlow() ? "" : " (no flow equations to solve)")
        << nl << endl;

    while (writes.run())
    {
        solver.preSolve();
        ++runTime;
        solver.evolve();
        writes.write();
        solver.postSolve();
    }

    solver.writeReport(Info);
    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
