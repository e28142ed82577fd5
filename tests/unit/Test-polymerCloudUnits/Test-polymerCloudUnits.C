/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    Test-polymerCloudUnits

Description
    GoogleTest unit tests of the polymerCloud kernels that need no mesh:
    exactOU moments, trefoil initialisation, SHAKE/RATTLE/newton
    projections, the tridiagonal solver and the Philox noise.
    OpenFOAM's fatal errors throw, so a FatalError fails one test instead of
    ending the run.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "error.H"

int main(int argc, char* argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    Foam::FatalError.throwExceptions(true);
    Foam::FatalIOError.throwExceptions(true);

    return RUN_ALL_TESTS();
}

// ************************************************************************* //
