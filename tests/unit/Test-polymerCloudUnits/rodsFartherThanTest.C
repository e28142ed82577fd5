/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    The lower bound of two rods' distance (rodsFartherThan) by which the
    crossing audit passes over distant pairs:
    - of 200000 random pairs of unit rods (near each other, at any angle,
      and nearly parallel ones), none is said farther apart than a random
      distance that their exact distance (closest points of the segments,
      in long double) does not exceed;
    - rods whose midpoints are more than the distance plus a rod length
      apart are always said farther apart (the midpoints' bound alone);
    - rods that cross, or touch at an end, are never farther apart than
      zero.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "rodsFartherThan.H"

#include <random>

using namespace Foam;
using namespace Foam::polymer;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

typedef long double real;

real dotL(const vector& a, const vector& b)
{
    return real(a.x())*b.x() + real(a.y())*b.y() + real(a.z())*b.z();
}

real clamp01(const real x)
{
    return x < 0 ? 0 : (x > 1 ? 1 : x);
}

// The segments' distance from their closest points (Ericson, Real-Time
// Collision Detection, 5.1.9), in long double
real segmentDistance
(
    const point& p0,
    const point& p1,
    const point& q0,
    const point& q1
)
{
    const vector d1(p1 - p0), d2(q1 - q0), r(p0 - q0);
    const real a = dotL(d1, d1), e = dotL(d2, d2), f = dotL(d2, r);
    const real c = dotL(d1, r), b = dotL(d1, d2);
    const real denominator = a*e - b*b;
    real s = denominator > 0 ? clamp01((b*f - c*e)/denominator) : 0;
    real t = (b*s + f)/e;
    if (t < 0)
    {
        t = 0;
        s = clamp01(-c/a);
    }
    else if (t > 1)
    {
        t = 1;
        s = clamp01((b - c)/a);
    }
    real sum = 0;
    for (direction k = 0; k < 3; ++k)
    {
        const real x =
            (p0[k] + s*real(d1[k])) - (q0[k] + t*real(d2[k]));
        sum += x*x;
    }
    return std::sqrt(sum);
}

vector randomUnit(std::mt19937_64& engine)
{
    std::normal_distribution<scalar> g(0, 1);
    const vector v(g(engine), g(engine), g(engine));
    return v/mag(v);
}

} // End anonymous namespace


TEST(rodsFartherThan, NeverBeyondTheExactDistance)
{
    std::mt19937_64 engine(20261127);
    std::uniform_real_distribution<scalar> u(0, 1);
    label nFarther = 0;
    for (label k = 0; k < 200000; ++k)
    {
        const point p0(3*u(engine), 3*u(engine), 3*u(engine));
        const point p1(p0 + randomUnit(engine));
        const point q0(3*u(engine), 3*u(engine), 3*u(engine));

        // One pair in four nearly parallel (the lines' bound is not used
        // there)
        vector b(randomUnit(engine));
        if (k % 4 == 0)
        {
            b = (p1 - p0) + 1e-4*u(engine)*randomUnit(engine);
            b /= mag(b);
        }
        const point q1(q0 + b);
        const scalar distance = 1.5*u(engine);
        if (rodsFartherThan(p0, p1, q0, q1, distance))
        {
            ++nFarther;
            ASSERT_GT(segmentDistance(p0, p1, q0, q1), distance)
                << "pair " << k;
        }
    }

    // The bound passes over a fair share of them
    EXPECT_GT(nFarther, 20000);
}


TEST(rodsFartherThan, MidpointsFartherThanARodLength)
{
    std::mt19937_64 engine(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    for (label k = 0; k < 10000; ++k)
    {
        const scalar distance = u(engine);
        const point p0(10*u(engine), 10*u(engine), 10*u(engine));
        const point p1(p0 + randomUnit(engine));
        const point midpoint(0.5*(p0 + p1));
        const vector b(randomUnit(engine));
        const point q0
        (
            midpoint + (distance + 1.001)*randomUnit(engine) - 0.5*b
        );
        EXPECT_TRUE(rodsFartherThan(p0, p1, q0, q0 + b, distance));
    }
}


TEST(rodsFartherThan, CrossingOrTouchingRodsAreNot)
{
    std::mt19937_64 engine(11);
    std::uniform_real_distribution<scalar> u(0, 1);
    for (label k = 0; k < 10000; ++k)
    {
        const point p0(u(engine), u(engine), u(engine));
        const point p1(p0 + randomUnit(engine));

        // A rod through a point of the other, and one from its end
        const point on(p0 + u(engine)*(p1 - p0));
        const vector b(randomUnit(engine));
        const scalar s = u(engine);
        EXPECT_FALSE(rodsFartherThan(p0, p1, on - s*b, on + (1 - s)*b, 0));
        EXPECT_FALSE(rodsFartherThan(p0, p1, p1, p1 + b, 0));
    }
}


// ************************************************************************* //
