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

#include "rodPairCrossing.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::rodPairCrossing::rodPairCrossing
(
    const vector& xi, const vector& xi1,
    const vector& xj, const vector& xj1,
    const vector& vi, const vector& vi1,
    const vector& vj, const vector& vj1
)
{
    // Element by element, not from initializer lists, which GCC copied
    // through the stack in pieces of other widths than it read them back
    // (failed store forwarding)
    x[0] = xi;
    x[1] = xi1;
    x[2] = xj;
    x[3] = xj1;
    v[0] = vi;
    v[1] = vi1;
    v[2] = vj;
    v[3] = vj1;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::FixedList<Foam::scalar, 4>
Foam::polymer::rodPairCrossing::tripleProductCubic() const
{
    // V(s) = (p + dp s).((b + db s) x (c + dc s))
    const vector p = x[0] - x[2];
    const vector dp = v[0] - v[2];
    const vector b = x[1] - x[0];
    const vector db = v[1] - v[0];
    const vector c = x[3] - x[2];
    const vector dc = v[3] - v[2];

    const vector bc = b ^ c;
    const vector bdc = b ^ dc;
    const vector dbc = db ^ c;
    const vector dbdc = db ^ dc;

    return FixedList<scalar, 4>
    ({
        p & bc,
        (dp & bc) + (p & (dbc + bdc)),
        (dp & (dbc + bdc)) + (p & dbdc),
        dp & dbdc
    });
}


Foam::scalar Foam::polymer::rodPairCrossing::tripleProduct(const scalar s) const
{
    const vector p = (x[0] + s*v[0]) - (x[2] + s*v[2]);
    const vector b = (x[1] + s*v[1]) - (x[0] + s*v[0]);
    const vector c = (x[3] + s*v[3]) - (x[2] + s*v[2]);
    return p & (b ^ c);
}


Foam::scalar Foam::polymer::rodPairCrossing::signKeepingDrift
(
    const scalar T,
    const scalar margin
) const
{
    // The smallest |V| over [0, T]: at the ends and at V's turning points
    // between them (V is monotone between its turning points); none if V
    // changes sign there
    const scalar V0 = tripleProduct(0);
    scalar lowest = mag(V0);
    const auto sameSign = [&](const scalar s)
    {
        const scalar V = tripleProduct(s);
        lowest = min(lowest, mag(V));
        return V != 0 && (V < 0) == (V0 < 0);
    };
    if (V0 == 0 || !sameSign(T))
    {
        return 0;
    }

    // Turning points: the roots of V' = c1 + 2 c2 s + 3 c3 s^2 in (0, T)
    const FixedList<scalar, 4> c = tripleProductCubic();
    const scalar a = 3*c[3], b = 2*c[2];
    FixedList<scalar, 2> turning({-1, -1});
    if (a == 0)
    {
        turning[0] = (b != 0) ? -c[1]/b : -1;
    }
    else
    {
        const scalar discriminant = b*b - 4*a*c[1];
        if (discriminant >= 0)
        {
            // The root of larger magnitude first, the other from their
            // product: no cancellation
            const scalar q =
                -0.5*(b + (b < 0 ? -1 : 1)*std::sqrt(discriminant));
            turning[0] = q/a;
            turning[1] = (q != 0) ? c[1]/q : -1;
        }
    }
    for (const scalar s : turning)
    {
        if (s > 0 && s < T && !sameSign(s))
        {
            return 0;
        }
    }

    // Three quarters of the smallest |V| (a quarter for the turning
    // points' and V's round-off) less the margin is what the paths'
    // departures may change V by. With departures summing to D, the
    // vectors p = x_i - x_j, b and c of V = p.(b x c) change by at most D
    // each, so V by at most D (P + D Q + D^2), P = |b||c| + |p|(|b| + |c|),
    // Q = |p| + |b| + |c| (their largest over [0, T], at an end: each is
    // linear in s). D = allowed/(P + D0 Q + D0^2) with D0 = allowed/P, the
    // larger, keeps that within allowed
    const scalar allowed = 0.75*lowest - margin;
    if (allowed <= 0)
    {
        return 0;
    }
    const auto largest = [&](const label k0, const label k1)
    {
        return max
        (
            mag(x[k1] - x[k0]),
            mag((x[k1] + T*v[k1]) - (x[k0] + T*v[k0]))
        );
    };
    const scalar pMax = largest(2, 0);
    const scalar bMax = largest(0, 1);
    const scalar cMax = largest(2, 3);
    const scalar P = bMax*cMax + pMax*(bMax + cMax);
    const scalar Q = pMax + bMax + cMax;
    const scalar D0 = allowed/P;
    return allowed/(P + D0*Q + D0*D0);
}


bool Foam::polymer::rodPairCrossing::intersection
(
    const scalar s,
    scalar& lambdaI,
    scalar& lambdaJ
) const
{
    const vector xi = x[0] + s*v[0];
    const vector xj = x[2] + s*v[2];
    const vector b = (x[1] + s*v[1]) - xi;
    const vector c = (x[3] + s*v[3]) - xj;
    const vector w = xi - xj;

    // Closest points of the lines xi + lambdaI b and xj + lambdaJ c
    const scalar bb = b & b;
    const scalar bc = b & c;
    const scalar cc = c & c;
    const scalar bw = b & w;
    const scalar cw = c & w;
    const scalar det = bb*cc - bc*bc;

    if (det <= 1e-12*bb*cc)
    {
        return false;
    }

    lambdaI = (bc*cw - cc*bw)/det;
    lambdaJ = (bb*cw - bc*bw)/det;
    return true;
}


bool Foam::polymer::rodPairCrossing::crossesAt(const scalar s) const
{
    scalar lambdaI, lambdaJ;
    return
        intersection(s, lambdaI, lambdaJ)
     && lambdaI >= 0 && lambdaI <= 1
     && lambdaJ >= 0 && lambdaJ <= 1;
}


bool Foam::polymer::rodPairCrossing::parallelContact
(
    const scalar s,
    scalar& lambdaI,
    scalar& lambdaJ,
    vector& n
) const
{
    const vector xi = x[0] + s*v[0];
    const vector xj = x[2] + s*v[2];
    const vector b = (x[1] + s*v[1]) - xi;
    const vector c = (x[3] + s*v[3]) - xj;
    const scalar bb = b & b;
    const scalar cc = c & c;
    if (bb < VSMALL || cc < VSMALL)
    {
        return false;
    }

    // The overlap of rod J's projection on rod I: its middle is the
    // contact on rod I, and its projection on rod J the contact there
    const scalar t0 = ((xj - xi) & b)/bb;
    const scalar t1 = ((xj + c - xi) & b)/bb;
    const scalar low = max(scalar(0), min(t0, t1));
    const scalar high = min(scalar(1), max(t0, t1));
    if (low > high)
    {
        return false;
    }
    lambdaI = 0.5*(low + high);
    const vector contactI = xi + lambdaI*b;
    lambdaJ = min(max(((contactI - xj) & c)/cc, scalar(0)), scalar(1));
    const vector contactJ = xj + lambdaJ*c;

    // The rods' plane, where it is defined to round-off: a crossing the
    // detector found in nearly parallel rods is through that plane.
    // Otherwise normal to rod I: along the rods' separation, or, where
    // they touch, along the contact points' relative velocity
    vector normal = b ^ c;
    if (magSqr(normal) > sqr(1e-12)*bb*cc)
    {
        n = normal/mag(normal);
        return true;
    }
    const vector along = b/std::sqrt(bb);
    normal = contactI - contactJ;
    normal -= (normal & along)*along;
    if (magSqr(normal) <= SMALL*bb)
    {
        normal =
            ((1 - lambdaI)*v[0] + lambdaI*v[1])
          - ((1 - lambdaJ)*v[2] + lambdaJ*v[3]);
        normal -= (normal & along)*along;
    }
    const scalar magNormal = mag(normal);
    if (magNormal < VSMALL)
    {
        return false;
    }
    n = normal/magNormal;
    return true;
}


bool Foam::polymer::rodPairCrossing::contact
(
    const scalar s,
    scalar& lambdaI,
    scalar& lambdaJ,
    vector& n
) const
{
    if (!intersection(s, lambdaI, lambdaJ))
    {
        return parallelContact(s, lambdaI, lambdaJ, n);
    }

    const vector b = (x[1] + s*v[1]) - (x[0] + s*v[0]);
    const vector c = (x[3] + s*v[3]) - (x[2] + s*v[2]);
    const vector normal = b ^ c;
    const scalar magNormal = mag(normal);
    if (magNormal < VSMALL)
    {
        return false;
    }
    n = normal/magNormal;
    return true;
}


bool Foam::polymer::rodPairCrossing::elasticImpulse
(
    const scalar s,
    FixedList<vector, 4>& velocitiesAfter,
    const scalar massI,
    const scalar massJ
) const
{
    scalar lambdaI, lambdaJ;
    vector n;
    if (!contact(s, lambdaI, lambdaJ, n))
    {
        return false;
    }

    const scalar vi = v[0] & n;
    const scalar vi1 = v[1] & n;
    const scalar vj = v[2] & n;
    const scalar vj1 = v[3] & n;

    // Minus the relative normal velocity at the contact point
    const scalar minusU =
        -vi*(1 - lambdaI) - vi1*lambdaI + vj*(1 - lambdaJ) + vj1*lambdaJ;

    if (massI == massJ)
    {
        // The paper's solution of the conservation laws for equal masses
        // (the masses cancel)
        const scalar J =
            minusU/(1 - lambdaI*(1 - lambdaI) - lambdaJ*(1 - lambdaJ));

        velocitiesAfter[0] = v[0] + J*(1 - lambdaI)*n;
        velocitiesAfter[1] = v[1] + J*lambdaI*n;
        velocitiesAfter[2] = v[2] - J*(1 - lambdaJ)*n;
        velocitiesAfter[3] = v[3] - J*lambdaJ*n;
        return true;
    }

    // J = -2u/sum(w_k^2/m_k); bead k's velocity changes by J w_k n/m_k
    const scalar J =
        2*minusU
       /(
            (sqr(1 - lambdaI) + sqr(lambdaI))/massI
          + (sqr(1 - lambdaJ) + sqr(lambdaJ))/massJ
        );

    velocitiesAfter[0] = v[0] + (J*(1 - lambdaI)/massI)*n;
    velocitiesAfter[1] = v[1] + (J*lambdaI/massI)*n;
    velocitiesAfter[2] = v[2] - (J*(1 - lambdaJ)/massJ)*n;
    velocitiesAfter[3] = v[3] - (J*lambdaJ/massJ)*n;

    return true;
}


// ************************************************************************* //
