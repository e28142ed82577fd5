/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

    The coefficients are fdlibm's (e_log.c, k_sin.c, k_cos.c):
    Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
    Developed at SunPro, a Sun Microsystems, Inc. business.
    Permission to use, copy, modify, and distribute this software is freely
    granted, provided that this notice is preserved.

\*---------------------------------------------------------------------------*/

#include "boxMuller.H"

#include <cmath>
#include <cstdint>
#include <cstring>

// * * * * * * * * * * * * * * * * Dispatch  * * * * * * * * * * * * * * * //

// On x86-64 the transform is compiled three times, for the baseline
// (SSE2), for AVX2 (twice the lanes) and for AVX-512 (four times), and the
// loader picks the one the processor runs (function multiversioning, GCC 6
// and Clang 14 on). Not FMA: fused multiply-adds would change the
// rounding (and -ffp-contract=off forbids them), where these three give
// the same bits, so results do not depend on the processor.
#if defined(__x86_64__) && defined(__has_attribute)
    #if __has_attribute(target_clones)
        #define BOX_MULLER_TARGETS \
            __attribute__((target_clones("avx512f", "avx2", "default")))
    #endif
#endif

#ifndef BOX_MULLER_TARGETS
    #define BOX_MULLER_TARGETS
#endif


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{

//- A block of pairs' values, one per pair (GCC's vector extension:
//  element-wise arithmetic, four 256-bit registers with AVX2, two 512-bit
//  with AVX-512, eight 128-bit with SSE2). The transform is bound by the
//  latency of each deviate's chain of operations (a division, a square
//  root, three polynomials), not by the arithmetic: the processor overlaps
//  only as many chains as its floating-point scheduler holds. A block's
//  statements hold several registers' independent chains side by side,
//  and Make/options compiles this file with GCC's first scheduling pass
//  (off by default on x86-64), which interleaves them further.
static constexpr int blockSize = 16;

typedef double block __attribute__
((
    vector_size(blockSize*sizeof(double)),
    aligned(blockSize*sizeof(double))
));

typedef uint64_t blockBits __attribute__
((
    vector_size(blockSize*sizeof(uint64_t)),
    aligned(blockSize*sizeof(uint64_t))
));


// Bit copies between a double and its 64-bit pattern (memcpy: no aliasing
// issue, and the compiler turns it into a register move), and between
// blocks of them
static inline uint64_t bitsOf(const double x)
{
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    return bits;
}


static inline double fromBits(const uint64_t bits)
{
    double x;
    std::memcpy(&x, &bits, sizeof(x));
    return x;
}


__attribute__((always_inline))
static inline blockBits bitsOf(const block& x)
{
    return __builtin_bit_cast(blockBits, x);
}


__attribute__((always_inline))
static inline block fromBits(const blockBits& bits)
{
    return __builtin_bit_cast(block, bits);
}


//- The square root of each element (one instruction per register)
__attribute__((always_inline))
static inline double squareRoot(const double x)
{
    return std::sqrt(x);
}


__attribute__((always_inline))
static inline block squareRoot(const block& x)
{
    block root;
    for (int j = 0; j < blockSize; ++j)
    {
        root[j] = std::sqrt(x[j]);
    }
    return root;
}


// ln u for a positive normal u: fdlibm's e_log.c without its branches
// (no special values to handle for uniforms in (0, 1)); of a double or
// of each element of a block, with the same operations
template<class Real>
__attribute__((always_inline))
static inline Real logPositive(const Real& u)
{
    const double ln2Hi = 6.93147180369123816490e-01;    // 3fe62e42 fee00000
    const double ln2Lo = 1.90821492927058770002e-10;    // 3dea39ef 35793c76
    const double Lg1 = 6.666666666666735130e-01;
    const double Lg2 = 3.999999999940941908e-01;
    const double Lg3 = 2.857142874366239149e-01;
    const double Lg4 = 2.222219843214978396e-01;
    const double Lg5 = 1.818357216161805012e-01;
    const double Lg6 = 1.531383769920937332e-01;
    const double Lg7 = 1.479819860511658591e-01;

    // u = 2^k m with m in [sqrt(1/2), sqrt(2)), where f = m - 1 is
    // exact, in integer arithmetic on the bits of u (ARM's optimized-
    // routines): the offset keeps the difference positive, and k becomes
    // a double through the mantissa of 2^52 (64-bit integer to double
    // conversions do not vectorise before AVX-512)
    const auto bits = bitsOf(u);
    const uint64_t sqrtHalfBits = 0x3fe6a09e667f3bcdULL;
    const uint64_t offset = uint64_t(1024) << 52;
    const auto shifted = bits - sqrtHalfBits + offset;
    const auto exponentField = shifted >> 52;
    const Real m = fromBits(bits - (exponentField << 52) + offset);
    const double twoPower52 = 4503599627370496.0;
    const Real k =
        fromBits(exponentField | bitsOf(twoPower52)) - (twoPower52 + 1024);

    const Real f = m - 1;
    const Real s = f/(2 + f);
    const Real z = s*s;
    const Real w = z*z;
    const Real t1 = w*(Lg2 + w*(Lg4 + w*Lg6));
    const Real t2 = z*(Lg1 + w*(Lg3 + w*(Lg5 + w*Lg7)));
    const Real R = t2 + t1;
    const Real hfsq = 0.5*f*f;

    return k*ln2Hi - ((hfsq - (s*(hfsq + R) + k*ln2Lo)) - f);
}


// sin t and cos t for |t| <= pi/4: fdlibm's k_sin.c and k_cos.c
template<class Real>
__attribute__((always_inline))
static inline void sinCosKernel(const Real& t, Real& s, Real& c)
{
    const double S1 = -1.66666666666666324348e-01;
    const double S2 = 8.33333333332248946124e-03;
    const double S3 = -1.98412698298579493134e-04;
    const double S4 = 2.75573137070700676789e-06;
    const double S5 = -2.50507602534068634195e-08;
    const double S6 = 1.58969099521155010221e-10;

    const double C1 = 4.16666666666666019037e-02;
    const double C2 = -1.38888888888741095749e-03;
    const double C3 = 2.48015872894767294178e-05;
    const double C4 = -2.75573143513906633035e-07;
    const double C5 = 2.08757232129817482790e-09;
    const double C6 = -1.13596475577881948265e-11;

    const Real z = t*t;

    const Real rs = S2 + z*(S3 + z*(S4 + z*(S5 + z*S6)));
    s = t + z*t*(S1 + z*rs);

    const Real rc = z*(C1 + z*(C2 + z*(C3 + z*(C4 + z*(C5 + z*C6)))));
    const Real hz = 0.5*z;
    const Real w = 1 - hz;
    c = w + (((1 - w) - hz) + z*rc);
}


// sin and cos of 2 pi u for u in [0, 1)
template<class Real>
__attribute__((always_inline))
static inline void sinCosTurn(const Real& u, Real& s, Real& c)
{
    // 2 pi u = q pi/2 + t: quarter turns x = 4 u, q = round(x) by adding
    // 1.5 2^52 (a tie goes to even, |t| <= pi/4 either way), after which
    // the low bits of the sum are those of q; x - q is exact
    const Real x = 4*u;
    const double round = 6755399441055744.0;
    const auto qBits = bitsOf(x + round);
    const Real t = 1.57079632679489661923*(x - (fromBits(qBits) - round));

    Real sinT, cosT;
    sinCosKernel(t, sinT, cosT);

    // Quadrants 1 and 3 swap sine and cosine; sine is negative in
    // quadrants 2 and 3, cosine in 1 and 2. All on the bits, without
    // comparisons or branches, which would stop the loop's vectorisation.
    const auto sinBits = bitsOf(sinT);
    const auto cosBits = bitsOf(cosT);
    const auto swap = (sinBits ^ cosBits) & (0 - (qBits & 1));
    s = fromBits((sinBits ^ swap) ^ ((qBits & 2) << 62));
    c = fromBits((cosBits ^ swap) ^ (((qBits + 1) & 2) << 62));
}

// The transform of one pair of uniforms (or of a block of pairs)
template<class Real>
__attribute__((always_inline))
static inline void normalPair
(
    const Real& u1,
    const Real& u2,
    Real& x,
    Real& y
)
{
    const Real radius = squareRoot(-2*logPositive(u1));
    Real s, c;
    sinCosTurn(u2, s, c);
    x = radius*c;
    y = radius*s;
}


// The uniform (w + 1/2) 2^-32 in (0, 1) of each 32-bit word w (held in a
// 64-bit integer): 2^52 + w is a double's bits, and subtracting 2^52 - 1/2
// leaves w + 1/2; every operation is exact, so these are the bits of
// (double(w) + 0.5)*2^-32, in integer and vector arithmetic throughout
// (a 32-bit integer's conversion to double does not vectorise without
// AVX-512)
template<class Bits>
__attribute__((always_inline))
static inline auto uniformOfWord(const Bits& word)
{
    const uint64_t twoPower52Bits = 0x4330000000000000ULL;
    const double twoPower52LessHalf = 4503599627370495.5;
    const double toUnit = 1.0/4294967296.0;
    return (fromBits(word | twoPower52Bits) - twoPower52LessHalf)*toUnit;
}


// The pairs p = first, ..., first + n - 1 of u, with Real a double
// (n = 1) or a block (n = blockSize)
template<class Real>
__attribute__((always_inline))
static inline void transformPairs(const label first, scalar* u)
{
    constexpr int n = sizeof(Real)/sizeof(double);
    Real u1, u2;
    for (int j = 0; j < n; ++j)
    {
        reinterpret_cast<double*>(&u1)[j] = u[2*(first + j)];
        reinterpret_cast<double*>(&u2)[j] = u[2*(first + j) + 1];
    }

    Real x, y;
    normalPair(u1, u2, x, y);

    for (int j = 0; j < n; ++j)
    {
        u[2*(first + j)] = reinterpret_cast<const double*>(&x)[j];
        u[2*(first + j) + 1] = reinterpret_cast<const double*>(&y)[j];
    }
}


// The block of pairs p = first, ..., first + blockSize - 1 of words in
// u's second half: pair p's uniforms are those of the low and the high 32
// bits of the word in u[nPairs + p], its deviates go to u[2 p] and
// u[2 p + 1]. The words are copied out (memcpy: their storage is
// doubles') before any deviate is written, and the deviates stop short
// of the words of the pairs after these (2 (first + blockSize) <= nPairs
// + first + blockSize while first + blockSize <= nPairs).
__attribute__((always_inline))
static inline void transformWordBlock
(
    const label nPairs,
    const label first,
    scalar* u
)
{
    blockBits word;
    std::memcpy(&word, u + nPairs + first, sizeof(word));

    const uint64_t low32 = 0xffffffffULL;
    block x, y;
    normalPair
    (
        block(uniformOfWord(word & low32)),
        block(uniformOfWord(word >> 32)),
        x,
        y
    );

    for (int j = 0; j < blockSize; ++j)
    {
        u[2*(first + j)] = reinterpret_cast<const double*>(&x)[j];
        u[2*(first + j) + 1] = reinterpret_cast<const double*>(&y)[j];
    }
}

} // End namespace polymer
} // End namespace Foam


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

BOX_MULLER_TARGETS
void Foam::polymer::boxMuller::transform(const label nPairs, scalar* u)
{
    // Whole blocks, then the pairs left one at a time: the same operations
    // on each pair, so the same bits
    label p = 0;
    for (; p + blockSize <= nPairs; p += blockSize)
    {
        transformPairs<block>(p, u);
    }
    for (; p < nPairs; ++p)
    {
        transformPairs<double>(p, u);
    }
}


BOX_MULLER_TARGETS
void Foam::polymer::boxMuller::transformWords(const label nPairs, scalar* u)
{
    label p = 0;
    for (; p + blockSize <= nPairs; p += blockSize)
    {
        transformWordBlock(nPairs, p, u);
    }

    // The pairs left as one more block, filled with copies of the last
    // word, in a block of its own (words in its second half): a pair's
    // deviates are its own lane's operations, the same bits as one pair at
    // a time, where the pairs left of a chain of 10 beads (14 of 30) one
    // at a time took longer than its whole blocks
    const label nLeft = nPairs - p;
    if (nLeft > 0)
    {
        alignas(sizeof(block)) scalar tail[2*blockSize];
        for (label j = 0; j < blockSize; ++j)
        {
            const label word = nPairs + p + min(j, nLeft - 1);
            std::memcpy(tail + blockSize + j, u + word, sizeof(scalar));
        }
        transformWordBlock(blockSize, 0, tail);
        for (label j = 0; j < 2*nLeft; ++j)
        {
            u[2*p + j] = tail[j];
        }
    }
}


// ************************************************************************* //
