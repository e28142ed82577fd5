/*---------------------------------------------------------------------------*\
Description
    chainNoise (Philox4x64-10 + Box-Muller): a deviate depends only on
    (seed, chain, time index, bead, stream,
    sub-step key), bit for bit; over 10^6 normal
    deviates mean 0, variance 1, fourth moment 3 and no correlation between
    the four outputs of a call; uniforms in (0, 1) with mean 1/2 and
    variance 1/12. Tolerances 5 SE for n samples: mean 1/sqrt(n), variance
    sqrt(2/(n-1)), fourth moment sqrt(96/n) (Var x^4 = 105 - 9), correlation
    1/sqrt(n), uniform mean sqrt(1/(12 n)), uniform variance
    sqrt((1/80 - 1/144)/n).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "chainNoise.H"
#include <cmath>

using namespace Foam;
using namespace Foam::polymer;


// Same inputs give identical outputs; changing any input changes them.
TEST(chainNoise, Deterministic)
{
    const chainNoise a(7, 42), b(7, 42), otherSeed(8, 42), otherChain(7, 43);
    scalar x[4], y[4], z[4];

    a.normals(100, 5, chainNoise::stepStream0, 0, x);
    b.normals(100, 5, chainNoise::stepStream0, 0, y);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(x[k], y[k]);

    a.normals(100, 5, chainNoise::stepStream0, 0, y);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(x[k], y[k]);

    auto differs = [&x](const scalar* z)
    {
        for (int k = 0; k < 4; ++k) if (x[k] != z[k]) return true;
        return false;
    };

    otherSeed.normals(100, 5, chainNoise::stepStream0, 0, z);  EXPECT_TRUE(differs(z));
    otherChain.normals(100, 5, chainNoise::stepStream0, 0, z); EXPECT_TRUE(differs(z));
    a.normals(101, 5, chainNoise::stepStream0, 0, z);          EXPECT_TRUE(differs(z));
    a.normals(100, 6, chainNoise::stepStream0, 0, z);          EXPECT_TRUE(differs(z));
    a.normals(100, 5, chainNoise::stepStream1, 0, z);          EXPECT_TRUE(differs(z));
    a.normals(100, 5, chainNoise::stepStream0, 1, z);          EXPECT_TRUE(differs(z));
}


// 10^6 standard normals: mean, variance, fourth moment, correlation (5 SE).
TEST(chainNoise, NormalMoments)
{
    const chainNoise noise(3, 1);
    long double s1 = 0, s2 = 0, s4 = 0, s01 = 0, s23 = 0, s03 = 0;
    const label nCalls = 250000;
    for (label i = 0; i < nCalls; ++i)
    {
        scalar xi[4];
        noise.normals(i/100 + 1, i%100, chainNoise::stepStream0, 0, xi);
        for (int k = 0; k < 4; ++k)
        {
            ASSERT_TRUE(std::isfinite(xi[k]));
            s1 += xi[k]; s2 += xi[k]*xi[k]; s4 += std::pow(xi[k], 4);
        }
        s01 += xi[0]*xi[1]; s23 += xi[2]*xi[3]; s03 += xi[0]*xi[3];
    }
    const double n = 4.0*nCalls;
    const double mean = s1/n;
    const double var = (s2 - s1*s1/n)/(n - 1);

    EXPECT_NEAR(mean, 0, 5/std::sqrt(n));
    EXPECT_NEAR(var, 1, 5*std::sqrt(2/(n - 1)));
    EXPECT_NEAR(double(s4/n), 3, 5*std::sqrt(96/n));
    for (const long double s : {s01, s23, s03})
    {
        EXPECT_NEAR(double(s/nCalls), 0, 5/std::sqrt(double(nCalls)));
    }
}


// 10^6 uniforms: all in (0, 1), mean 1/2, variance 1/12 (5 SE).
TEST(chainNoise, UniformMoments)
{
    const chainNoise noise(5, 9);
    long double s1 = 0, s2 = 0;
    const label nCalls = 250000;
    for (label i = 0; i < nCalls; ++i)
    {
        scalar u[4];
        noise.uniforms(0, i, chainNoise::setUpStream, 0, u);
        for (int k = 0; k < 4; ++k)
        {
            ASSERT_GT(u[k], 0);
            ASSERT_LT(u[k], 1);
            s1 += u[k]; s2 += u[k]*u[k];
        }
    }
    const double n = 4.0*nCalls;
    const double mean = s1/n;
    const double var = (s2 - s1*s1/n)/(n - 1);
    EXPECT_NEAR(mean, 0.5, 5*std::sqrt(1/(12*n)));
    EXPECT_NEAR(var, 1.0/12, 5*std::sqrt((1.0/80 - 1.0/144)/n));
}

// ************************************************************************* //
