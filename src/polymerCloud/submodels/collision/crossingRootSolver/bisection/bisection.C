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

#include "bisection.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(crossingRootSolver, crossingRootSolvers, bisection)


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolvers::bisection::earliestCrossing
(
    const rodPairCrossing& pair,
    const scalar T
) const
{
    scalar start, end;
    if (!signChange(pair, T, start, end))
    {
        return -1;
    }

    const scalar s = bisect(pair, 0, T, start);
    return pair.crossesAt(s) ? s : -1;
}

// ************************************************************************* //
