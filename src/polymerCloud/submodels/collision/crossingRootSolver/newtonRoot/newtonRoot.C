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

#include "newtonRoot.H"
#include "makePolymerModel.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(crossingRootSolver, crossingRootSolvers, newtonRoot)


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::crossingRootSolvers::newtonRoot::earliestCrossing
(
    const rodPairCrossing& pair,
    const scalar T
) const
{
    scalar low = 0;
    scalar high = T;
    scalar valueLow, valueHigh;
    if (!signChange(pair, T, valueLow, valueHigh))
    {
        return -1;
    }
    const bool startNegative = valueLow < 0;

    const FixedList<scalar, 4> c = pair.tripleProductCubic();
    scalar s = valueLow/(valueLow - valueHigh)*T;

    for (int iter = 0; iter < 100; ++iter)
    {
        const scalar value = pair.tripleProduct(s);
        if (value == 0)
        {
            break;
        }
        if ((value < 0) == (valueLow < 0))
        {
            low = s;
            valueLow = value;
        }
        else
        {
            high = s;
        }

        const scalar slope = c[1] + s*(2*c[2] + 3*s*c[3]);
        scalar next = (slope != 0) ? s - value/slope : 0.5*(low + high);
        if (!(next > low && next < high))
        {
            next = 0.5*(low + high);
        }
        if (next == s || high - low <= 4*SMALL*T)
        {
            break;
        }
        s = next;
    }

    // The converged time, moved back to the not-yet-crossed side of the
    // root (a few representable times at most), else the bracket's end
    for (int k = 0; k < 64; ++k)
    {
        const scalar value = pair.tripleProduct(s);
        if (value != 0 && (value < 0) == startNegative)
        {
            break;
        }
        s = std::nextafter(s, scalar(0));
        if (k == 63 || s <= low)
        {
            s = low;
        }
    }
    return pair.crossesAt(s) ? s : -1;
}

// ************************************************************************* //
