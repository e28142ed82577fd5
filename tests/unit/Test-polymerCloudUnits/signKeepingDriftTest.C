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
    The drift a rod pair's beads may take from their straight paths without
    changing the sign of V (rodPairCrossing::signKeepingDrift), the budget
    by which the event loop passes over a close pair that its last
    prediction found uncrossed:
    - for 20000 random pairs of unit rods near each other with random
      velocities, the beads moved off their paths by departures summing to
      the drift, in the directions that change V fastest toward zero
      (against its gradient in each bead, at each time) and in random
      directions with a kink in time, keep V's sign, with |V| above the
      margin, at 201 times of [0, T]; a fair share of the pairs have a
      drift (the test is not vacuous);
    - a pair whose V changes sign on [0, T] (rods crossing, lines passing
      beyond the rods, or V dipping through zero and back between ends of
      one sign) has none, nor a pair whose smallest |V|, at a turning
      point inside [0, T], is within the margin of it (by the quarter
      kept for round-off).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "rodPairCrossing.H"

#include <random>

using namespace Foam;
using namespace Foam::polymer;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- V of the four beads at s with each bead moved off its path by offset
scalar perturbedV
(
    const rodPairCrossing& pair,
    const scalar s,
    const FixedList<vector, 4>& offset
)
{
    FixedList<vector, 4> x;
    for (label k = 0; k < 4; ++k)
    {
        x[k] = pair.x[k] + s*pair.v[k] + offset[k];
    }
    return (x[0] - x[2]) & ((x[1] - x[0]) ^ (x[3] - x[2]));
}


//- The gradient of V in each bead's position at s
FixedList<vector, 4> gradientV(const rodPairCrossing& pair, const scalar s)
{
    FixedList<vector, 4> x;
    for (label k = 0; k < 4; ++k)
    {
        x[k] = pair.x[k] + s*pair.v[k];
    }
    const vector p = x[0] - x[2], b = x[1] - x[0], c = x[3] - x[2];
    return FixedList<vector, 4>
    ({
        (b ^ c) - (c ^ p),
        c ^ p,
        -(b ^ c) - (p ^ b),
        p ^ b
    });
}


vector unitOrZero(const vector& v)
{
    const scalar m = mag(v);
    return m > 0 ? v/m : vector::zero;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests * * * * * * * * * * * * * * * * //

TEST(rodPairCrossing, SignKeepingDriftKeepsTheSide)
{
    std::mt19937_64 generator(20261128);
    std::uniform_real_distribution<scalar> uniform(-1, 1);
    const auto randomVector = [&]()
    {
        return vector(uniform(generator), uniform(generator), uniform(generator));
    };
    const auto unitVector = [&]()
    {
        for (;;)
        {
            const vector v(randomVector());
            if (magSqr(v) > 1e-4 && magSqr(v) <= 1)
            {
                return v/mag(v);
            }
        }
    };

    const scalar T = 0.05;
    const scalar margin = 1e-12;
    const label nTimes = 200;
    label withDrift = 0, failures = 0;
    const label nPairs = 20000;
    for (label n = 0; n < nPairs; ++n)
    {
        // Rod I from the origin, rod J's first bead within 1.5 of it;
        // beads at thermal speeds (about 1)
        const vector xi(Zero), xj(1.5*randomVector());
        const rodPairCrossing pair
        (
            xi, xi + unitVector(), xj, xj + unitVector(),
            randomVector(), randomVector(), randomVector(), randomVector()
        );
        const scalar drift = pair.signKeepingDrift(T, margin);
        ASSERT_GE(drift, 0);
        if (drift == 0)
        {
            continue;
        }
        ++withDrift;
        const int side = pair.tripleProduct(0) < 0 ? -1 : 1;

        // Random departures, each bead a quarter of the drift at most,
        // turning half-way through the step
        FixedList<vector, 4> first, second;
        for (label k = 0; k < 4; ++k)
        {
            first[k] = 0.25*drift*unitVector();
            second[k] = 0.25*drift*unitVector();
        }
        for (label m = 0; m <= nTimes; ++m)
        {
            const scalar s = T*m/nTimes;
            const scalar w = min(1, 2*s/T);
            FixedList<vector, 4> toward, random;
            const FixedList<vector, 4> g = gradientV(pair, s);
            for (label k = 0; k < 4; ++k)
            {
                toward[k] = -side*0.25*drift*unitOrZero(g[k]);
                random[k] = (1 - w)*first[k] + w*second[k];
            }
            for (const FixedList<vector, 4>& offset : {toward, random})
            {
                const scalar V = perturbedV(pair, s, offset);
                if (!(side*V > margin))
                {
                    ++failures;
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
    // Most random nearby pairs keep a side over a short step
    EXPECT_GT(withDrift, nPairs/2) << withDrift << " of " << nPairs;
}


TEST(rodPairCrossing, NoSignKeepingDriftNearZero)
{
    const scalar T = 0.05;

    // Rod J passes through rod I at s = T/2: V changes sign
    const rodPairCrossing crossing
    (
        vector(-0.5, 0, 0), vector(0.5, 0, 0),
        vector(0, -0.5, 0.01), vector(0, 0.5, 0.01),
        Zero, Zero, vector(0, 0, -0.4), vector(0, 0, -0.4)
    );
    EXPECT_EQ(crossing.signKeepingDrift(T, 0), 0);

    // The lines pass each other beyond rod I's end: no crossing, but V
    // changes sign, and a small drift could make it one
    const rodPairCrossing passing
    (
        vector(-0.5, 0, 0), vector(0.5, 0, 0),
        vector(0.8, -0.5, 0.01), vector(0.8, 0.5, 0.01),
        Zero, Zero, vector(0, 0, -0.4), vector(0, 0, -0.4)
    );
    EXPECT_EQ(passing.signKeepingDrift(T, 0), 0);

    // V with a turning point inside [0, T]: rod J slides along y and
    // tilts, V(s) = s^2 - s/2 - h (h its height below rod I), the same at
    // both ends, smallest in |V| at s = 1/4
    const auto dipping = [](const scalar h)
    {
        return rodPairCrossing
        (
            vector(-0.5, 0, 0), vector(0.5, 0, 0),
            vector(0, -0.5, h), vector(0, 0.5, h),
            Zero, Zero, vector(0, 1, 0), vector(0, 1, 1)
        );
    };
    // h = -0.05: V is 0.05 at both ends but -0.0125 at s = 1/4: two sign
    // changes between ends of one sign
    EXPECT_EQ(dipping(-0.05).signKeepingDrift(0.5, 0), 0);
    // h = -0.07: V is 0.07 at the ends, 0.0075 at s = 1/4, which sets the
    // drift: none once three quarters of it is within the margin
    const rodPairCrossing dip(dipping(-0.07));
    EXPECT_NEAR(dip.tripleProduct(0.25), 0.0075, 1e-15);
    EXPECT_GT(dip.signKeepingDrift(0.5, 0.005), 0);
    EXPECT_EQ(dip.signKeepingDrift(0.5, 0.006), 0);
    EXPECT_LT(dip.signKeepingDrift(0.5, 0), 0.0075);
}


// ************************************************************************* //
