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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolvers::isolating::earliestCrossing
(
    const rodPairCrossing& pair,
    const scalar T
) const
{
    const FixedList<scalar, 4> c = pair.tripleProductCubic();

    // Critical points: 3 c3 s^2 + 2 c2 s + c1 = 0
    scalar ends[4] = {0, T, T, T};
    label nEnds = 1;
    {
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
    }

    scalar valueLow = pair.tripleProduct(ends[0]);
    for (label k = 0; k + 1 < nEnds; ++k)
    {
        const scalar valueHigh = pair.tripleProduct(ends[k + 1]);
        if (valueLow*valueHigh < 0)
        {
            const scalar s = bisect(pair, ends[k], ends[k + 1], valueLow);
            if (pair.crossesAt(s))
            {
                return s;
            }
        }
        valueLow = valueHigh;
    }

    return -1;
}

// ************************************************************************* //
