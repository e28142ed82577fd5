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

#include "cubic.H"
#include "mathematicalConstants.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(crossingRootSolver, crossingRootSolvers, cubic)


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolvers::cubic::earliestCrossing
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

    const FixedList<scalar, 4> c = pair.tripleProductCubic();
    scalar roots[3];
    label nRoots = 0;

    if (mag(c[3]) > VSMALL)
    {
        // Depressed cubic t^3 + p t + q with s = t - c2/(3 c3)
        const scalar a = c[2]/c[3];
        const scalar b = c[1]/c[3];
        const scalar d = c[0]/c[3];
        const scalar p = b - a*a/3;
        const scalar q = 2*a*a*a/27 - a*b/3 + d;
        const scalar discriminant = q*q/4 + p*p*p/27;

        if (discriminant > 0)
        {
            const scalar r = std::sqrt(discriminant);
            roots[nRoots++] = std::cbrt(-q/2 + r) + std::cbrt(-q/2 - r) - a/3;
        }
        else
        {
            const scalar m = 2*std::sqrt(max(-p/3, scalar(0)));
            const scalar argument =
                (m > 0) ? max(min(3*q/(p*m), scalar(1)), scalar(-1)) : 0;
            const scalar theta = std::acos(argument)/3;
            for (int k = 0; k < 3; ++k)
            {
                roots[nRoots++] =
                    m*std::cos(theta - 2*constant::mathematical::pi*k/3)
                  - a/3;
            }
        }
    }
    else if (mag(c[2]) > VSMALL)
    {
        const scalar discriminant = c[1]*c[1] - 4*c[2]*c[0];
        if (discriminant >= 0)
        {
            const scalar r = std::sqrt(discriminant);
            roots[nRoots++] = (-c[1] - r)/(2*c[2]);
            roots[nRoots++] = (-c[1] + r)/(2*c[2]);
        }
    }
    else if (mag(c[1]) > VSMALL)
    {
        roots[nRoots++] = -c[0]/c[1];
    }

    scalar earliest = -1;
    for (label k = 0; k < nRoots; ++k)
    {
        if
        (
            roots[k] >= 0 && roots[k] <= T
         && (earliest < 0 || roots[k] < earliest)
         && pair.crossesAt(roots[k])
        )
        {
            earliest = roots[k];
        }
    }
    return earliest;
}

// ************************************************************************* //
