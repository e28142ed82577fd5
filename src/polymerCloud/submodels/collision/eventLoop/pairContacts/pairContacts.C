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

bool Foam::polymer::pairContacts::leaveBand
(
    const rodPairCrossing& pair,
    const label side,
    const scalar lower,
    const scalar upper,
    const scalar T,
    scalar& inside,
    scalar& outside
)
{
    const auto W = [&](const scalar s) { return side*pair.tripleProduct(s); };
    const auto out = [&](const scalar s)
    {
        const scalar w = W(s);
        return w > upper || w < lower;
    };

    // The smallest s = T 2^-k outside the band, from 2^-52 up
    inside = 0;
    outside = -1;
    for (int k = 52; k >= 0; --k)
    {
        const scalar s = std::ldexp(T, -k);
        if (out(s))
        {
            outside = s;
            break;
        }
        inside = s;
    }
    if (outside < 0)
    {
        return false;
    }

    for (int iter = 0; iter < 60 && outside - inside > SMALL*outside; ++iter)
    {
        const scalar mid = 0.5*(inside + outside);
        (out(mid) ? outside : inside) = mid;
    }
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::pairContacts::sideBefore
(
    const rodPairCrossing& pair,
    const scalar s,
    const label fallback
)
{
    if (s < 0)
    {
        return fallback;
    }
    const FixedList<scalar, 4> c = pair.tripleProductCubic();
    const scalar slope = c[1] + s*(2*c[2] + 3*s*c[3]);
    return (slope > 0) ? -1 : (slope < 0) ? 1 : fallback;
}



void Foam::polymer::pairContacts::clear()
{
    for (const label pairi : resolved_)
    {
        sides_[pairi] = 0;
        streaks_[pairi] = 0;
    }
    resolved_.clear();
}


void Foam::polymer::pairContacts::record
(
    const label pairi,
    const label side,
    const bool atContact
)
{
    if (pairi >= sides_.size())
    {
        const label oldSize = sides_.size();
        sides_.resize(pairi + 1);
        streaks_.resize(pairi + 1);
        for (label i = oldSize; i < sides_.size(); ++i)
        {
            sides_[i] = 0;
            streaks_[i] = 0;
        }
    }
    if (!sides_[pairi])
    {
        resolved_.append(pairi);
    }
    sides_[pairi] = (side < 0) ? -1 : 1;
    streaks_[pairi] = atContact ? streaks_[pairi] + 1 : 0;
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


Foam::scalar Foam::polymer::pairContacts::followContact
(
    const rodPairCrossing& pair,
    const crossingRootSolver& rootSolver,
    const scalar T,
    const scalar W0,
    const scalar tol,
    label& side,
    bool& atContact
)
{
    // Followed until W leaves [min(-2 tol, W(0) - tol), tol]
    const scalar lower = min(-2*tol, W0 - tol);
    scalar inside, outside;
    if (!leaveBand(pair, side, lower, tol, T, inside, outside))
    {
        return -1;
    }
    if (side*pair.tripleProduct(outside) < 0)
    {
        // Toward the crossed side: a crossing where the lines meet within
        // both rods, at the band's edge (the next prediction, from there,
        // is at contact again); else the lines met beyond the rods, and the
        // pair's side is V's
        if (pair.crossesAt(inside))
        {
            atContact = true;
            return inside;
        }
        side = -side;
    }

    const scalar s =
        rootSolver.earliestCrossing(advanced(pair, outside), T - outside);
    if (s < 0)
    {
        return -1;
    }
    side = sideBefore(pair, outside + s, side);
    return outside + s;
}


Foam::scalar Foam::polymer::pairContacts::earliestCrossing
(
    const label pairi,
    const rodPairCrossing& pair,
    const crossingRootSolver& rootSolver,
    const scalar T,
    label& side,
    bool& atContact,
    crossingRootSolver::bracket& next
) const
{
    atContact = false;
    next.interval = -1;

    // W = side V: positive on the pair's own side. A resolved pair at
    // contact is followed by W; one well on its side, or crossed beyond
    // round-off (the lines met beyond the rods earlier in the step), and
    // every unresolved pair (most: no round-off computed for them) is the
    // root solver's
    const scalar V0 = pair.tripleProduct(0);
    side = this->side(pairi);
    if (side)
    {
        const scalar tol = tolerance(pair);
        const scalar W0 = side*V0;
        if (W0 <= tol && W0 >= -1000*tol)
        {
            return followContact
            (
                pair, rootSolver, T, W0, tol, side, atContact
            );
        }
    }

    const scalar s = rootSolver.deferredCrossing(pair, T, next);
    side = (V0 < 0) ? -1 : 1;
    if (next.interval < 0)
    {
        side = sideBefore(pair, s, side);
    }
    return s;
}


Foam::scalar Foam::polymer::pairContacts::earliestCrossing
(
    const label pairi,
    const rodPairCrossing& pair,
    const crossingRootSolver& rootSolver,
    const scalar T,
    label& side,
    bool& atContact
) const
{
    crossingRootSolver::bracket next;
    scalar s = earliestCrossing
    (
        pairi, pair, rootSolver, T, side, atContact, next
    );
    while (next.interval >= 0)
    {
        s = continueCrossing(pair, rootSolver, T, side, next);
    }
    return s;
}


Foam::scalar Foam::polymer::pairContacts::continueCrossing
(
    const rodPairCrossing& pair,
    const crossingRootSolver& rootSolver,
    const scalar T,
    label& side,
    crossingRootSolver::bracket& next
)
{
    const scalar s = rootSolver.continueCrossing(pair, T, next);
    if (next.interval < 0)
    {
        side = sideBefore(pair, s, (pair.tripleProduct(0) < 0) ? -1 : 1);
    }
    return s;
}


// ************************************************************************* //
