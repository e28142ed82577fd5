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

#include "isolating.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(crossingRootSolver, crossingRootSolvers, isolating)


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::crossingRootSolvers::isolating::monotoneEnds
(
    const rodPairCrossing& pair,
    const scalar T,
    scalar ends[4]
)
{
    const FixedList<scalar, 4> c = pair.tripleProductCubic();

    // Critical points: 3 c3 s^2 + 2 c2 s + c1 = 0
    ends[0] = 0;
    label nEnds = 1;
    const scalar A = 3*c[3];
    const scalar B = 2*c[2];
    const scalar C = c[1];
    scalar critical[2];
    label nCritical = 0;
    if (mag(A) > VSMALL)
    {
        const scalar discriminant = B*B - 4*A*C;
        if (discriminant > 0)
        {
            const scalar r = std::sqrt(discriminant);
            const scalar q = -0.5*(B + (B < 0 ? -r : r));
            critical[nCritical++] = q/A;
            if (q != 0)
            {
                critical[nCritical++] = C/q;
            }
        }
    }
    else if (mag(B) > VSMALL)
    {
        critical[nCritical++] = -C/B;
    }
    if (nCritical == 2 && critical[0] > critical[1])
    {
        std::swap(critical[0], critical[1]);
    }
    for (label k = 0; k < nCritical; ++k)
    {
        if (critical[k] > 0 && critical[k] < T)
        {
            ends[nEnds++] = critical[k];
        }
    }
    ends[nEnds++] = T;
    return nEnds;
}


Foam::scalar Foam::polymer::crossingRootSolvers::isolating::firstBracket
(
    const rodPairCrossing& pair,
    const scalar T,
    const label first,
    bracket& next
)
{
    scalar ends[4];
    const label nEnds = monotoneEnds(pair, T, ends);

    scalar valueLow = pair.tripleProduct(ends[first]);
    for (label k = first; k + 1 < nEnds; ++k)
    {
        const scalar valueHigh = pair.tripleProduct(ends[k + 1]);
        if (valueLow*valueHigh < 0)
        {
            next.interval = k;
            next.a = ends[k];
            next.b = ends[k + 1];
            next.valueA = valueLow;
            narrow(pair, next.a, next.b, next.valueA, nNarrowSteps);
            return next.a;
        }
        valueLow = valueHigh;
    }
    next.interval = -1;
    return -1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolvers::isolating::earliestCrossing
(
    const rodPairCrossing& pair,
    const scalar T
) const
{
    bracket next;
    scalar s = deferredCrossing(pair, T, next);
    while (next.interval >= 0)
    {
        s = continueCrossing(pair, T, next);
    }
    return s;
}


Foam::scalar Foam::polymer::crossingRootSolvers::isolating::deferredCrossing
(
    const rodPairCrossing& pair,
    const scalar T,
    bracket& next
) const
{
    return firstBracket(pair, T, 0, next);
}


Foam::scalar Foam::polymer::crossingRootSolvers::isolating::continueCrossing
(
    const rodPairCrossing& pair,
    const scalar T,
    bracket& next
) const
{
    const scalar s = bisect(pair, next.a, next.b, next.valueA);
    if (pair.crossesAt(s))
    {
        next.interval = -1;
        return s;
    }
    return firstBracket(pair, T, next.interval + 1, next);
}


// ************************************************************************* //
