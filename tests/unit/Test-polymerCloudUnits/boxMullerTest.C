/*---------------------------------------------------------------------------*\
Description
    boxMuller: each deviate against the exact transform of its uniforms,
    evaluated in long double (64-bit mantissa), over 2^20 random pairs of
    32-bit uniforms (as chainNoise makes them) and the extreme ones (words
    0 and 2^32 - 1, and those at the quadrant boundaries of the angle):
    error at most 1e-15 of the radius sqrt(-2 ln u1) (about 4 units in the
    last place; fdlibm's kernels and the exact reduction give about 1.5).
    transformWords: the same bits as transform of the words' uniforms.

    chainNoise::sixNormals: a bead's deviates depend on its counter only,
    not on the chain's length, bit for bit; over 1.2 10^6 deviates mean 0,
    variance 1, fourth moment 3 and no correlation between the six of a
    bead. Tolerances 5 SE for n samples, as in chainNoiseTest.C.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "boxMuller.H"
#include "chainNoise.H"
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace Foam;
using namespace Foam::polymer;

namespace
{

//- The uniform of a 32-bit word, as chainNoise makes it
double uniformOf(const uint32_t word)
{
    return (double(word) + 0.5)/4294967296.0;
}

} // End anonymous namespace


// Every deviate within 1e-15 of its radius of the long double transform.
TEST(boxMuller, MatchesExactTransform)
{
    std::vector<uint32_t> words;
    for (uint32_t k = 0; k < 16; ++k)
    {
        // Extreme radii, paired with angles at and around the quadrant
        // boundaries (multiples of 2^30) and at the ends of the turn
        for (const uint32_t radial : {k, 0xffffffffu - k})
        {
            words.push_back(radial);
            words.push_back((k % 4)*0x40000000u + (k/4) - 2);
        }
    }
    std::mt19937_64 gen(5);
    for (label p = 0; p < (1 << 20); ++p)
    {
        words.push_back(uint32_t(gen()));
        words.push_back(uint32_t(gen()));
    }

    std::vector<double> xi(words.size());
    for (size_t i = 0; i < words.size(); ++i)
    {
        xi[i] = uniformOf(words[i]);
    }
    boxMuller::transform(xi.size()/2, xi.data());

    const long double twoPi = 6.283185307179586476925286766559L;
    double largest = 0;
    for (size_t p = 0; p < xi.size()/2; ++p)
    {
        const long double u1 = uniformOf(words[2*p]);
        const long double u2 = uniformOf(words[2*p + 1]);
        const long double radius = std::sqrt(-2*std::log(u1));
        const long double angle = twoPi*u2;

        ASSERT_TRUE(std::isfinite(xi[2*p]) && std::isfinite(xi[2*p + 1]));
        largest = std::max
        (
            largest,
            double
            (
                std::max
                (
                    std::fabs(xi[2*p] - radius*std::cos(angle)),
                    std::fabs(xi[2*p + 1] - radius*std::sin(angle))
                )/radius
            )
        );
    }
    EXPECT_LE(largest, 1e-15);
}


// transformWords from words in u's second half: the bits transform gives
// for the words' uniforms, for whole blocks and the pairs after them.
TEST(boxMuller, WordsGiveTheUniformsDeviates)
{
    std::mt19937_64 gen(11);
    for (const label nPairs : {1, 15, 16, 51, 1200})
    {
        std::vector<uint64_t> words(nPairs);
        words[0] = 0xffffffff00000000ULL;   // the extreme uniforms
        for (label p = 1; p < nPairs; ++p)
        {
            words[p] = gen();
        }

        std::vector<double> expected(2*nPairs), xi(2*nPairs);
        for (label p = 0; p < nPairs; ++p)
        {
            expected[2*p] = uniformOf(uint32_t(words[p]));
            expected[2*p + 1] = uniformOf(uint32_t(words[p] >> 32));
        }
        boxMuller::transform(nPairs, expected.data());

        std::memcpy(xi.data() + nPairs, words.data(), nPairs*sizeof(uint64_t));
        boxMuller::transformWords(nPairs, xi.data());
        for (label k = 0; k < 2*nPairs; ++k)
        {
            ASSERT_EQ(xi[k], expected[k]) << "pairs " << nPairs << ", " << k;
        }
    }
}


// A bead's six deviates do not depend on how many beads the chain has.
TEST(chainNoise, SixNormalsPerBead)
{
    const chainNoise noise(7, 42);
    std::vector<scalar> chain(6*50), prefix(6*17);
    noise.sixNormals(100, chainNoise::stepStream0, 0, 50, chain.data());
    noise.sixNormals(100, chainNoise::stepStream0, 0, 17, prefix.data());
    for (size_t k = 0; k < prefix.size(); ++k)
    {
        EXPECT_EQ(prefix[k], chain[k]);
    }

    std::vector<scalar> other(6*50);
    noise.sixNormals(100, chainNoise::stepStream0, 1, 50, other.data());
    EXPECT_NE(other[0], chain[0]);
}


// 1.2 10^6 deviates: mean, variance, fourth moment, correlation (5 SE).
TEST(chainNoise, SixNormalsMoments)
{
    const chainNoise noise(3, 1);
    const label nBeads = 1000, nSteps = 200;
    std::vector<scalar> xi(6*nBeads);

    long double s1 = 0, s2 = 0, s4 = 0;
    long double sPair = 0, sAcross = 0, sNext = 0;
    for (label step = 1; step <= nSteps; ++step)
    {
        noise.sixNormals
        (
            step, chainNoise::stepStream0, 0, nBeads, xi.data()
        );
        for (label i = 0; i < nBeads; ++i)
        {
            const scalar* x = &xi[6*i];
            for (int k = 0; k < 6; ++k)
            {
                ASSERT_TRUE(std::isfinite(x[k]));
                s1 += x[k]; s2 += x[k]*x[k]; s4 += std::pow(x[k], 4);
            }
            sPair += x[0]*x[1];     // one Box-Muller pair
            sAcross += x[1]*x[2];   // neighbouring pairs
            sNext += x[5]*x[2];     // the bead's two vectors
        }
    }

    const double n = 6.0*nBeads*nSteps;
    const double nBeadSteps = double(nBeads)*nSteps;
    const double mean = s1/n;
    const double var = (s2 - s1*s1/n)/(n - 1);
    EXPECT_NEAR(mean, 0, 5/std::sqrt(n));
    EXPECT_NEAR(var, 1, 5*std::sqrt(2/(n - 1)));
    EXPECT_NEAR(double(s4/n), 3, 5*std::sqrt(96/n));
    for (const long double s : {sPair, sAcross, sNext})
    {
        EXPECT_NEAR(double(s/nBeadSteps), 0, 5/std::sqrt(nBeadSteps));
    }
}


// ************************************************************************* //
