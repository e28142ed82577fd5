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

#include "crossingRootSolver.H"
#include "makePolymerModel.H"
#include "polymerSubModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(crossingRootSolver)


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

bool Foam::polymer::crossingRootSolver::signChange
(
    const rodPairCrossing& pair,
    const scalar T,
    scalar& valueStart,
    scalar& valueEnd
)
{
    valueStart = pair.tripleProduct(0);
    valueEnd = pair.tripleProduct(T);
    return valueStart*valueEnd < 0;
}


bool Foam::polymer::crossingRootSolver::narrow
(
    const rodPairCrossing& pair,
    scalar& a,
    scalar& b,
    scalar& valueA,
    const label maxSteps
)
{
    for (label step = 0; step < maxSteps; ++step)
    {
        const scalar middle = 0.5*(a + b);
        if (middle <= a || middle >= b)
        {
            return false;
        }
        const scalar valueMiddle = pair.tripleProduct(middle);
        if ((valueMiddle < 0) == (valueA < 0))
        {
            a = middle;
            valueA = valueMiddle;
        }
        else
        {
            b = middle;
        }
    }
    return true;
}


Foam::scalar Foam::polymer::crossingRootSolver::bisect
(
    const rodPairCrossing& pair,
    scalar a,
    scalar b,
    scalar valueA
)
{
    // To the last representable midpoint. The end before the sign change
    // is returned: the state there is not yet crossed.
    narrow(pair, a, b, valueA, 200);
    return a;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolver::deferredCrossing
(
    const rodPairCrossing& pair,
    const scalar T,
    bracket& next
) const
{
    next.interval = -1;
    return earliestCrossing(pair, T);
}


Foam::scalar Foam::polymer::crossingRootSolver::continueCrossing
(
    const rodPairCrossing& pair,
    const scalar T,
    bracket& next
) const
{
    // Not reached where deferredCrossing does not defer: the whole search
    return deferredCrossing(pair, T, next);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::polymer::crossingRootSolver>
Foam::polymer::crossingRootSolver::New
(
    const word& solverType,
    const dictionary& dict
)
{
    return polymerSubModel::selectNamed<crossingRootSolver>
    (
        solverType, dict, "rootSolver"
    );
}


// ************************************************************************* //
