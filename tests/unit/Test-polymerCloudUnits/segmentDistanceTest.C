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
    segmentDistanceSqr, the segments' distance that elasticRods' apartness
    tests take, against a reference of its own: the distance of a point
    moving along the first segment from the second is convex in its
    parameter, so a ternary search in long double finds its least value.
    - 20000 random pairs of segments of lengths 1e-3 to 3, some crossing:
      the distance within 1e-12 of the reference, as OpenFOAM's
      linePointRef::nearestDist is; half of them with their middles within
      0.05 of each other;
    - 20000 nearly parallel pairs (angles 1e-5 to 1e-11): within 1e-6 of
      the first segment's length of the reference (the Description's
      bound where the segments are taken as parallel), and within 1e-12
      above 1e-6;
    - points, crossing and collinear segments: the exact distances.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "segmentDistance.H"
#include "linePointRef.H"

#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::polymer;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

typedef long double real;

//- The distance of x from the segment q0-q1, in long double
real pointSegment(const real x[3], const point& q0, const point& q1)
{
    real d[3], w[3];
    real dd = 0, dw = 0;
    for (label i = 0; i < 3; ++i)
    {
        d[i] = real(q1[i]) - real(q0[i]);
        w[i] = x[i] - real(q0[i]);
        dd += d[i]*d[i];
        dw += d[i]*w[i];
    }
    const real t = dd > 0 ? std::min(std::max(dw/dd, real(0)), real(1)) : 0;
    real s = 0;
    for (label i = 0; i < 3; ++i)
    {
        const real r = w[i] - t*d[i];
        s += r*r;
    }
    return std::sqrt(s);
}


//- The segments' distance by a ternary search along the first
real referenceDistance
(
    const point& p0,
    const point& p1,
    const point& q0,
    const point& q1
)
{
    const auto along = [&](const real s)
    {
        real x[3];
        for (label i = 0; i < 3; ++i)
        {
            x[i] = real(p0[i]) + s*(real(p1[i]) - real(p0[i]));
        }
        return pointSegment(x, q0, q1);
    };
    real lo = 0, hi = 1;
    for (label iter = 0; iter < 200; ++iter)
    {
        const real m1 = lo + (hi - lo)/3, m2 = hi - (hi - lo)/3;
        if (along(m1) < along(m2))
        {
            hi = m2;
        }
        else
        {
            lo = m1;
        }
    }
    return std::min({along(0.5L*(lo + hi)), along(0), along(1)});
}


vector randomUnit(std::mt19937_64& rng)
{
    std::normal_distribution<scalar> normal;
    vector u;
    do
    {
        u = vector(normal(rng), normal(rng), normal(rng));
    } while (mag(u) < 1e-3);
    return u/mag(u);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(segmentDistance, RandomPairsWithinRoundOffOfTheReference)
{
    std::mt19937_64 rng(20261128);
    std::uniform_real_distribution<scalar> unit(0, 1);
    label crossing = 0;
    scalar worst = 0, worstFoam = 0;
    for (label pairi = 0; pairi < 20000; ++pairi)
    {
        // Every other pair's middles within 0.05 of each other
        const point p0(unit(rng), unit(rng), unit(rng));
        const point p1(p0 + std::pow(10, 3*unit(rng) - 3)*3*randomUnit(rng));
        const vector q(std::pow(10, 3*unit(rng) - 3)*3*randomUnit(rng));
        const point q0
        (
            pairi % 2
          ? point(unit(rng), unit(rng), unit(rng))
          : 0.5*(p0 + p1) + 0.05*unit(rng)*randomUnit(rng) - 0.5*q
        );
        const point q1(q0 + q);

        const scalar distance = std::sqrt(segmentDistanceSqr(p0, p1, q0, q1));
        const scalar reference = referenceDistance(p0, p1, q0, q1);
        point onA, onB;
        const scalar foam =
            linePointRef(p0, p1).nearestDist(linePointRef(q0, q1), onA, onB);
        worst = max(worst, mag(distance - reference));
        worstFoam = max(worstFoam, mag(foam - reference));
        crossing += (reference < 0.01);
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(worstFoam, 1e-12);
    EXPECT_GT(crossing, 1000);
    Info<< "    random pairs: largest difference " << worst
        << " (OpenFOAM's nearestDist " << worstFoam << "), "
        << crossing << " pairs closer than 0.01" << endl;
}


TEST(segmentDistance, NearlyParallelPairsWithinTheStatedBound)
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<scalar> unit(0, 1);
    scalar worstParallel = 0, worstOther = 0;
    label parallel = 0;
    for (label pairi = 0; pairi < 20000; ++pairi)
    {
        const vector axis(randomUnit(rng));
        vector side(axis ^ randomUnit(rng));
        side /= mag(side);
        const vector third(axis ^ side);
        const scalar angle = std::pow(10, -5 - 6*unit(rng));
        const scalar length = 0.5 + unit(rng);

        const point p0(unit(rng), unit(rng), unit(rng));
        const point p1(p0 + length*axis);
        // The second rod: shifted along and off the first, turned by angle
        const point q0
        (
            p0 + (2*unit(rng) - 1)*length*axis
          + 0.1*unit(rng)*side + 0.1*unit(rng)*third
        );
        const point q1
        (
            q0 + (0.5 + unit(rng))*(std::cos(angle)*axis + std::sin(angle)*side)
        );

        const scalar distance = std::sqrt(segmentDistanceSqr(p0, p1, q0, q1));
        const scalar reference = referenceDistance(p0, p1, q0, q1);
        const scalar error = mag(distance - reference);
        if (angle < 1e-6)
        {
            worstParallel = max(worstParallel, error/length);
            ++parallel;
        }
        else
        {
            worstOther = max(worstOther, error);
        }
    }
    EXPECT_LT(worstParallel, 1e-6);
    EXPECT_LT(worstOther, 1e-12);
    EXPECT_GT(parallel, 5000);
    Info<< "    nearly parallel pairs: largest error " << worstParallel
        << " of the length below 1e-6 rad, " << worstOther
        << " above" << endl;
}


TEST(segmentDistance, PointsCrossingAndCollinearSegments)
{
    const point o(Zero);
    const vector x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);

    // Two points, a point and a segment (either way round)
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, o, z, z), 1);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, o, z - x, z + x), 1);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(z - x, z + x, o, o), 1);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, o, 2*x, 3*x), 4);

    // Crossing, and passing at 0.5 above each other
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(-x, x, -y, y), 0);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(-x, x, 0.5*z - y, 0.5*z + y), 0.25);

    // The lines' closest points beyond an end of one or both
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 2*x - y, 2*x + y), 1);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 2*x + y, 2*x + 3*y), 2);

    // Collinear: overlapping, apart; parallel: offset
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, 2*x, x, 3*x), 0);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 3*x, 4*x), 4);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 4*x, 3*x), 4);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 0.5*x + y, 2*x + y), 1);
    EXPECT_DOUBLE_EQ(segmentDistanceSqr(o, x, 2*x + y, 3*x + y), 2);
}


// ************************************************************************* //
