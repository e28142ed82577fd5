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

#include "pairContacts.H"
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
using namespace Foam::polymer;

//- The pair with its beads advanced by s along their paths
rodPairCrossing advanced(const rodPairCrossing& pair, const scalar s)
{
    return rodPairCrossing
    (
        pair.x[0] + s*pair.v[0], pair.x[1] + s*pair.v[1],
        pair.x[2] + s*pair.v[2], pair.x[3] + s*pair.v[3],
        pair.v[0], pair.v[1], pair.v[2], pair.v[3]
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::polymer::pairContacts::leaveRoundOff
(
    const rodPairCrossing& pair,
    const scalar tolerance,
    const scalar T
)
{
    if (mag(pair.tripleProduct(0)) > tolerance)
    {
        return 0;
    }

    // The smallest s = T 2^-k outside the band, from 2^-52 up
    scalar inside = 0;
    scalar outside = -1;
    for (int k = 52; k >= 0; --k)
    {
        const scalar s = std::ldexp(T, -k);
        if (mag(pair.tripleProduct(s)) > tolerance)
        {
            outside = s;
            break;
        }
        inside = s;
    }
    if (outside < 0)
    {
        return -1;
    }

    for (int iter = 0; iter < 60 && outside - inside > SMALL*outside; ++iter)
    {
        const scalar mid = 0.5*(inside + outside);
        (mag(pair.tripleProduct(mid)) > tolerance ? outside : inside) = mid;
    }
    return outside;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::pairContacts::clear()
{
    for (const label pairi : resolved_)
    {
        sides_[pairi] = 0;
    }
    resolved_.clear();
}


void Foam::polymer::pairContacts::record(const label pairi, const label side)
{
    if (pairi >= sides_.size())
    {
        const label oldSize = sides_.size();
        sides_.resize(pairi + 1);
        for (label i = oldSize; i < sides_.size(); ++i)
        {
            sides_[i] = 0;
        }
    }
    if (!sides_[pairi])
    {
        resolved_.append(pairi);
    }
    sides_[pairi] = (side < 0) ? -1 : 1;
}


Foam::scalar Foam::polymer::pairContacts::tolerance
(
    const rodPairCrossing& pair
)
{
    scalar X = 0;
    for (const vector& x : pair.x)
    {
        X = max(X, cmptMax(cmptMag(x)));
    }
    const scalar b = mag(pair.x[1] - pair.x[0]);
    const scalar c = mag(pair.x[3] - pair.x[2]);
    return 32*std::numeric_limits<scalar>::epsilon()*(X + b + c)*b*c;
}


Foam::scalar Foam::polymer::pairContacts::earliestCrossing
(
    const label pairi,
    const rodPairCrossing& pair,
    const crossingRootSolver& rootSolver,
    const scalar T,
    label& side
) const
{
    const scalar V0 = pair.tripleProduct(0);
    const scalar tol = tolerance(pair);
    side = this->side(pairi);

    if (!side || mag(V0) > 2*tol)
    {
        side = (V0 < 0) ? -1 : 1;
        return rootSolver.earliestCrossing(pair, T);
    }

    // At contact on a known side: followed by V until it leaves round-off
    const scalar sExit = leaveRoundOff(pair, tol, T);
    if (sExit < 0)
    {
        return -1;
    }
    if (side*pair.tripleProduct(sExit) < 0)
    {
        if (pair.crossesAt(sExit))
        {
            return sExit;
        }
        side = -side;
    }

    const scalar s =
        rootSolver.earliestCrossing(advanced(pair, sExit), T - sExit);
    return (s < 0) ? -1 : sExit + s;
}


// ************************************************************************* //
