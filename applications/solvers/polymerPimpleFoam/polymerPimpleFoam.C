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
    are advanced. With 'field' the flow is solved and the chains move in it
    (one-way coupling).

    \heading Required fields (flow 'field' only)
    \plaintable
        U       | Velocity [m/s]
        p       | Kinematic pressure, p/rho [m2/s2]
    \endplaintable

    constant/polymerCloudProperties sets the chains and their models.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "polymerCloud.H"
#include "progressReport.H"

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
    #include "createTime.H"
    #include "createMesh.H"

    polymerCloud polymers("polymerCloud", mesh);

    Info<< nl;
    polymers.writeSummary(Info);
    Info<< endl;

    const progressReport progress(runTime);

    if (polymers.solvesFlow())
    {
        #include "flowLoop.H"
    }
    else
    {
        #include "polymerLoop.H"
    }

    Info<< nl;
    polymers.writeReport(Info);
    runTime.printExecutionTime(Info);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
