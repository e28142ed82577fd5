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

// The transform is bound by the latency of each deviate's chain of
// operations (a division, a square root, three polynomials), not by the
// arithmetic: the processor overlaps only as many iterations as its
// floating-point scheduler holds. GCC's first scheduling pass (off by
// default on x86-64) interleaves the independent chains of a vectorised
// iteration, so more of them are ready at once. It moves instructions, not
// roundings: the results are the same bits.
#pragma GCC optimize ("schedule-insns", "sched-pressure")

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

// Bit copies between a double and its 64-bit pattern (memcpy: no aliasing
// issue, and the compiler turns it into a register move)
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


// ln u for a positive normal u: fdlibm's e_log.c without its branches
// (no special values to handle for uniforms in (0, 1))
static inline double logPositive(const double u)
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
    const uint64_t bits = bitsOf(u);
    const uint64_t sqrtHalfBits = 0x3fe6a09e667f3bcdULL;
    const uint64_t offset = uint64_t(1024) << 52;
    const uint64_t shifted = bits - sqrtHalfBits + offset;
    const uint64_t exponentField = shifted >> 52;
    const double m =
        fromBits(bits - (exponentField << 52) + offset);
    const double twoPower52 = 4503599627370496.0;
    const double k =
        fromBits(exponentField | bitsOf(twoPower52)) - (twoPower52 + 1024);

    const double f = m - 1;
    const double s = f/(2 + f);
    const double z = s*s;
    const double w = z*z;
    const double t1 = w*(Lg2 + w*(Lg4 + w*Lg6));
    const double t2 = z*(Lg1 + w*(Lg3 + w*(Lg5 + w*Lg7)));
    const double R = t2 + t1;
    const double hfsq = 0.5*f*f;

    return k*ln2Hi - ((hfsq - (s*(hfsq + R) + k*ln2Lo)) - f);
}


// sin t and cos t for |t| <= pi/4: fdlibm's k_sin.c and k_cos.c
static inline void sinCosKernel(const double t, double& s, double& c)
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

    const double z = t*t;

    const double rs = S2 + z*(S3 + z*(S4 + z*(S5 + z*S6)));
    s = t + z*t*(S1 + z*rs);

    const double rc = z*(C1 + z*(C2 + z*(C3 + z*(C4 + z*(C5 + z*C6)))));
    const double hz = 0.5*z;
    const double w = 1 - hz;
    c = w + (((1 - w) - hz) + z*rc);
}


// sin and cos of 2 pi u for u in [0, 1)
static inline void sinCosTurn(const double u, double& s, double& c)
{
    // 2 pi u = q pi/2 + t: quarter turns x = 4 u, q = round(x) by adding
    // 1.5 2^52 (a tie goes to even, |t| <= pi/4 either way), after which
    // the low bits of the sum are those of q; x - q is exact
    const double x = 4*u;
    const double round = 6755399441055744.0;
    const uint64_t qBits = bitsOf(x + round);
    const double t = 1.57079632679489661923*(x - (fromBits(qBits) - round));

    double sinT, cosT;
    sinCosKernel(t, sinT, cosT);

    // Quadrants 1 and 3 swap sine and cosine; sine is negative in
    // quadrants 2 and 3, cosine in 1 and 2. All on the bits, without
    // comparisons or branches, which would stop the loop's vectorisation.
    const uint64_t sinBits = bitsOf(sinT);
    const uint64_t cosBits = bitsOf(cosT);
    const uint64_t swap = (sinBits ^ cosBits) & (0 - (qBits & 1));
    s = fromBits((sinBits ^ swap) ^ ((qBits & 2) << 62));
    c = fromBits((cosBits ^ swap) ^ (((qBits + 1) & 2) << 62));
}

} // End namespace polymer
} // End namespace Foam


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

BOX_MULLER_TARGETS
void Foam::polymer::boxMuller::transform(const label nPairs, scalar* u)
{
    // One pair after another, with no dependence between them: the
    // compiler vectorises the loop (-O3; -fno-math-errno for sqrt)
    for (label p = 0; p < nPairs; ++p)
    {
        const double radius = std::sqrt(-2*logPositive(u[2*p]));

        double s, c;
        sinCosTurn(u[2*p + 1], s, c);

        u[2*p] = radius*c;
        u[2*p + 1] = radius*s;
    }
}


// ************************************************************************* //
