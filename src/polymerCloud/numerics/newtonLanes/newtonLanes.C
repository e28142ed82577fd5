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

#include "newtonLanes.H"

#include <algorithm>
#include <cmath>
#include <type_traits>

#pragma GCC diagnostic ignored "-Wpsabi"

// * * * * * * * * * * * * * * * * Dispatch  * * * * * * * * * * * * * * * //

// As boxMuller: each kernel, for four lanes and for eight, compiled for
// AVX-512, AVX2 and the x86-64 baseline, without fused multiply-adds, so
// all give the scalar path's bits. Eight lanes run only where the loader
// picks the AVX-512 version (registerLanes), one register each; four
// elsewhere, one AVX2 register each (the chainThroughput README,
// 2026-12-05)
#if defined(__x86_64__) && defined(__has_attribute)
    #if __has_attribute(target_clones)
        #define LANE_TARGETS \
            __attribute__((target_clones("avx512f", "avx2", "default")))
    #endif
#endif

#ifndef LANE_TARGETS
    #define LANE_TARGETS
#endif


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
namespace newtonLaneKernels
{

//- Eight lanes' values and four lanes' (GCC's vector extension:
//  element-wise arithmetic, one instruction for the eight with AVX-512,
//  for the four with AVX2). Aligned explicitly: compiled for the
//  baseline, GCC gives a vector type only SSE2's 16 bytes.
typedef double eightLanes __attribute__
((
    vector_size(8*sizeof(double)),
    aligned(8*sizeof(double))
));

typedef double fourLanes __attribute__
((
    vector_size(4*sizeof(double)),
    aligned(4*sizeof(double))
));

//- Lane masks: all bits set where a lane comparison holds
template<class Lanes>
using laneMask = decltype(Lanes{} < Lanes{});


//- The dot product of 3-vectors held component-wise, in Vector's order.
//  Always inlined: no vector of lanes passes by value between functions
//  compiled for different instruction sets, whose calling conventions for
//  it differ (the kernels take lanes by pointer), and GCC's -Wpsabi notes
//  on this file, which it gives at the end of the file, do not apply.
template<class Lanes>
__attribute__((always_inline))
static inline Lanes dot(const Lanes* s, const Lanes* d)
{
    return s[0]*d[0] + s[1]*d[1] + s[2]*d[2];
}


// newton::linearise, lane by lane. x: 3 per bead; d: 3 per padded rod;
// source: padded; largest: each lane's largest |sigma|. (Lanes pass by
// pointer: by value their calling convention would differ between the
// AVX2 and the baseline version.)
template<class Lanes>
LANE_TARGETS
void linearise
(
    const label nRods,
    const Lanes* x,
    const Lanes* d,
    Lanes* lower,
    Lanes* diagonal,
    Lanes* upper,
    Lanes* source,
    const double a2,
    Lanes* largestSigma
)
{
    typedef laneMask<Lanes> mask;
    const mask magnitudeBits = mask{} + 0x7fffffffffffffffL;

    Lanes largest = {};
    mask notNumber = {};
    for (label k = 0; k < nRods; ++k)
    {
        const Lanes* xk = x + 3*k;
        const Lanes s[3] = {xk[3] - xk[0], xk[4] - xk[1], xk[5] - xk[2]};
        const Lanes sigma = dot(s, s) - a2;
        const Lanes magSigma = __builtin_bit_cast
        (
            Lanes, __builtin_bit_cast(mask, sigma) & magnitudeBits
        );

        // A NaN is kept (maxOrNaN) without an ordered comparison, which
        // would raise the invalid-operation trap that OpenFOAM sets
        const mask isNumber = (magSigma == magSigma);
        notNumber |= ~isNumber;
        const Lanes number = isNumber ? magSigma : Lanes{};
        largest = number > largest ? number : largest;

        const Lanes* dk = d + 3*(k + 1);
        lower[k] = -2*dot(s, dk - 3);
        diagonal[k] = 4*dot(s, dk);
        upper[k] = -2*dot(s, dk + 3);
        source[k + 1] = -sigma;
    }
    *largestSigma = notNumber ? Lanes{} + NAN : largest;
}


// tridiagonalSystem::eliminate and backSubstitute, lane by lane, on the
// right-hand side x. A zero pivot is replaced by 1 (no division by zero)
// and its lane set in zeroPivot: its solution is not to be used.
template<class Lanes>
LANE_TARGETS
void solveTridiagonal
(
    const label n,
    const Lanes* l,
    const Lanes* d,
    const Lanes* u,
    Lanes* reciprocal,
    Lanes* x,
    laneMask<Lanes>* zeroPivot
)
{
    const label m = n/2;
    const Lanes unit = Lanes{} + 1;

    typedef laneMask<Lanes> mask;
    mask zero = (d[0] == 0) | (d[n - 1] == 0);

    Lanes down = unit/(zero ? unit : d[0]);
    Lanes up = unit/(zero ? unit : d[n - 1]);
    Lanes xDown = x[0];
    Lanes xUp = x[n - 1];
    reciprocal[0] = down;
    reciprocal[n - 1] = up;
    for (label k = 1; k < m; ++k)
    {
        const Lanes pivot = d[k] - (l[k]*u[k - 1])*down;
        xDown = x[k] - (l[k]*down)*xDown;
        x[k] = xDown;
        const mask isZero = (pivot == 0);
        zero |= isZero;
        down = unit/(isZero ? unit : pivot);
        reciprocal[k] = down;

        const label j = n - 1 - k;
        if (j > m)
        {
            const Lanes pivot = d[j] - (u[j]*l[j + 1])*up;
            xUp = x[j] - (u[j]*up)*xUp;
            x[j] = xUp;
            const mask isZero = (pivot == 0);
            zero |= isZero;
            up = unit/(isZero ? unit : pivot);
            reciprocal[j] = up;
        }
    }

    Lanes pivot = d[m];
    Lanes xm = x[m];
    if (m > 0)
    {
        pivot -= (l[m]*u[m - 1])*down;
        xm -= (l[m]*down)*xDown;
    }
    if (m + 1 < n)
    {
        pivot -= (u[m]*l[m + 1])*up;
        xm -= (u[m]*up)*xUp;
    }
    const mask isZero = (pivot == 0);
    zero |= isZero;
    reciprocal[m] = unit/(isZero ? unit : pivot);
    x[m] = xm*reciprocal[m];

    Lanes xUpward = x[m];
    Lanes xDownward = x[m];
    for (label k = 1; k <= m; ++k)
    {
        const label i = m - k;
        const label j = m + k;
        xUpward = (x[i] - u[i]*xUpward)*reciprocal[i];
        x[i] = xUpward;
        if (j < n)
        {
            xDownward = (x[j] - l[j]*xDownward)*reciprocal[j];
            x[j] = xDownward;
        }
    }

    *zeroPivot = zero;
}


// newton::shift with alpha = 1 (whose product alpha*g is g): the beads of
// rod k move by -g_k d_k and +g_k d_k, in rod order. g: padded.
template<class Lanes>
LANE_TARGETS
void shift(const label nRods, Lanes* x, const Lanes* d, const Lanes* g)
{
    for (label k = 0; k < nRods; ++k)
    {
        const Lanes* dk = d + 3*(k + 1);
        const Lanes gk = g[k + 1];
        Lanes* xk = x + 3*k;
        for (int c = 0; c < 3; ++c)
        {
            const Lanes dx = gk*dk[c];
            xk[c] -= dx;
            xk[c + 3] += dx;
        }
    }
}

// rodVelocityProjection::project's system, lane by lane: rods r of the
// positions x (padded with a zero rod at each end, as d), the velocities w
// (3 per bead); source padded
template<class Lanes>
LANE_TARGETS
void velocitySystem
(
    const label nRods,
    const Lanes* x,
    const Lanes* w,
    Lanes* r,
    Lanes* lower,
    Lanes* diagonal,
    Lanes* upper,
    Lanes* source
)
{
    for (label k = 0; k < nRods; ++k)
    {
        const Lanes* xk = x + 3*k;
        Lanes* rk = r + 3*(k + 1);
        for (int c = 0; c < 3; ++c)
        {
            rk[c] = xk[c + 3] - xk[c];
        }
    }
    for (label k = 0; k < nRods; ++k)
    {
        const Lanes* rk = r + 3*(k + 1);
        const Lanes* wk = w + 3*k;
        const Lanes dw[3] = {wk[3] - wk[0], wk[4] - wk[1], wk[5] - wk[2]};
        lower[k] = -dot(rk, rk - 3);
        diagonal[k] = 2*dot(rk, rk);
        upper[k] = -dot(rk, rk + 3);
        source[k + 1] = dot(rk, dw);
    }
}


// rodVelocityProjection::kick, lane by lane: w changes by the multipliers
// m (padded) along the rods r (padded); largest: each lane's largest
// |r_k.(w_{k+1} - w_k)| after it (a NaN kept, as in linearise)
template<class Lanes>
LANE_TARGETS
void kick
(
    const label nBeads,
    const Lanes* r,
    const Lanes* m,
    Lanes* w,
    Lanes* largestVelocity
)
{
    typedef laneMask<Lanes> mask;
    const mask magnitudeBits = mask{} + 0x7fffffffffffffffL;

    for (int c = 0; c < 3; ++c)
    {
        w[c] += m[1]*r[3 + c] - m[0]*r[c];
    }

    Lanes largest = {};
    mask notNumber = {};
    for (label k = 0; k + 1 < nBeads; ++k)
    {
        const Lanes* rk = r + 3*(k + 1);
        Lanes* wk = w + 3*k;
        for (int c = 0; c < 3; ++c)
        {
            wk[c + 3] += m[k + 2]*rk[c + 3] - m[k + 1]*rk[c];
        }
        const Lanes dw[3] = {wk[3] - wk[0], wk[4] - wk[1], wk[5] - wk[2]};
        const Lanes relative = dot(rk, dw);
        const Lanes magRelative = __builtin_bit_cast
        (
            Lanes, __builtin_bit_cast(mask, relative) & magnitudeBits
        );
        const mask isNumber = (magRelative == magRelative);
        notNumber |= ~isNumber;
        const Lanes number = isNumber ? magRelative : Lanes{};
        largest = number > largest ? number : largest;
    }
    *largestVelocity = notNumber ? Lanes{} + NAN : largest;
}

// converged = positions in the lanes of keep (all bits set), unchanged in
// the others; n lanes each. On the bits, so that the baseline version too
// is whole-register logic (a lane-wise ?: there became a branch per
// element, whose stores and wide reloads stalled).
template<class Lanes>
LANE_TARGETS
void keepConverged
(
    const label n,
    const laneMask<Lanes>* keep,
    const Lanes* positions,
    Lanes* converged
)
{
    typedef laneMask<Lanes> mask;
    const mask taken = *keep;
    for (label i = 0; i < n; ++i)
    {
        converged[i] = __builtin_bit_cast
        (
            Lanes,
            (__builtin_bit_cast(mask, positions[i]) & taken)
          | (__builtin_bit_cast(mask, converged[i]) & ~taken)
        );
    }
}

} // End namespace newtonLaneKernels

// The lanes' layout, with the lane count N a constant: interleaving the
// chains' values in and taking a lane's out in loops the compiler unrolls
// (with N a run-time count it kept a loop a value). value(lanei, i, c):
// component c of the i-th of n vectors of lane lanei's chain
template<label N, class Value>
static void interleaveLanes(const label n, const Value& value, double* out)
{
    for (label i = 0; i < n; ++i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            for (label lanei = 0; lanei < N; ++lanei)
            {
                out[lanei] = value(lanei, i, c);
            }
            out += N;
        }
    }
}


// Vector i of a lane (its first value at lane)
template<label N>
static inline vector laneVector(const double* lane, const label i)
{
    return vector(lane[3*i*N], lane[(3*i + 1)*N], lane[(3*i + 2)*N]);
}


// As newton::iterate: v += (x - x*)/deltaT, x* being x before
template<label N>
static void storeLane
(
    const label nBeads,
    const double* lane,
    vector* x,
    vector* v,
    const scalar oneByDeltaT
)
{
    for (label i = 0; i < nBeads; ++i)
    {
        const vector solved = laneVector<N>(lane, i);
        v[i] += oneByDeltaT*(solved - x[i]);
        x[i] = solved;
    }
}


template<label N>
static void laneVectors(const label nVectors, const double* lane, vector* v)
{
    for (label i = 0; i < nVectors; ++i)
    {
        v[i] = laneVector<N>(lane, i);
    }
}


// The vector of lanes of N lanes
template<label N>
struct lanesOfWidth;

template<>
struct lanesOfWidth<4>
{
    typedef newtonLaneKernels::fourLanes type;
};

template<>
struct lanesOfWidth<8>
{
    typedef newtonLaneKernels::eightLanes type;
};


// action(width), the lane count nLanes as a constant
// (decltype(width)::value): the one place the run-time count becomes a
// compile-time one
template<class Action>
static inline void atWidth(const label nLanes, const Action& action)
{
    if (nLanes == 8)
    {
        action(std::integral_constant<label, 8>());
    }
    else
    {
        action(std::integral_constant<label, 4>());
    }
}

} // End namespace polymer
} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::newtonLanes::newtonLanes(const label nLanes)
:
    nLanes_(nLanes),
    nBeads_(0)
{
    if (nLanes != 4 && !(nLanes == 8 && registerLanes() == 8))
    {
        FatalErrorInFunction
            << nLanes << " lanes: 4, or 8 on a processor with AVX-512"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::label Foam::polymer::newtonLanes::registerLanes()
{
    // The processors the kernels' AVX-512 version runs on (the loader's
    // choice, from the same test)
    #if defined(__x86_64__) && defined(__GNUC__)
    if (__builtin_cpu_supports("avx512f"))
    {
        return 8;
    }
    #endif
    return 4;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::newtonLanes::resize
(
    laneArray& array,
    const label n
) const
{
    array.resize((n*nLanes_ + maxLanes - 1)/maxLanes);
}


void Foam::polymer::newtonLanes::interleave
(
    const vector* const chainValues[],
    laneArray& lanesOf
) const
{
    const auto value = [chainValues]
    (
        const label lanei,
        const label i,
        const direction c
    )
    {
        return chainValues[lanei][i][c];
    };

    atWidth(nLanes_, [&](auto width)
    {
        constexpr label N = decltype(width)::value;
        interleaveLanes<N>(nBeads_, value, values(lanesOf));
    });
}


void Foam::polymer::newtonLanes::freeze(const bool active[])
{
    const label nRods = nBeads_ - 1;
    double* lower = values(lower_);
    double* diagonal = values(diagonal_);
    double* upper = values(upper_);
    double* solution = values(solution_) + nLanes_;
    for (label lanei = 0; lanei < nLanes_; ++lanei)
    {
        if (active[lanei])
        {
            continue;
        }
        for (label k = 0; k < nRods; ++k)
        {
            const label at = k*nLanes_ + lanei;
            lower[at] = 0;
            diagonal[at] = 1;
            upper[at] = 0;
            solution[at] = 0;
        }
    }
}


template<class Lanes>
void Foam::polymer::newtonLanes::linearise
(
    const scalar rodLength,
    Lanes& residual
)
{
    const scalar a2 = rodLength*rodLength;
    Lanes largest;
    newtonLaneKernels::linearise
    (
        nBeads_ - 1,
        lanes<Lanes>(positions_),
        lanes<Lanes>(rods_),
        lanes<Lanes>(lower_),
        lanes<Lanes>(diagonal_),
        lanes<Lanes>(upper_),
        lanes<Lanes>(solution_),
        a2,
        &largest
    );
    residual = largest/(2*a2);
}


template<class Lanes>
void Foam::polymer::newtonLanes::solveSystem(bool solved[])
{
    newtonLaneKernels::laneMask<Lanes> zero;
    newtonLaneKernels::solveTridiagonal
    (
        nBeads_ - 1,
        lanes<Lanes>(lower_),
        lanes<Lanes>(diagonal_),
        lanes<Lanes>(upper_),
        lanes<Lanes>(reciprocal_),
        lanes<Lanes>(solution_) + 1,
        &zero
    );

    for (label lanei = 0; lanei < nLanes_; ++lanei)
    {
        solved[lanei] = !zero[lanei];
    }
}


template<class Lanes>
void Foam::polymer::newtonLanes::shift()
{
    newtonLaneKernels::shift
    (
        nBeads_ - 1,
        lanes<Lanes>(positions_),
        lanes<Lanes>(rods_),
        lanes<Lanes>(solution_)
    );
}


template<class Lanes>
void Foam::polymer::newtonLanes::solveLanes
(
    const scalar rodLength,
    const scalar tolerance,
    const label maxIterations,
    label iterations[]
)
{
    // newton::solveLengths on its usual path: a full step whose residual
    // falls, until it is within the tolerance
    bool active[maxLanes];
    scalar lastResidual[maxLanes];
    for (label lanei = 0; lanei < nLanes_; ++lanei)
    {
        active[lanei] = true;
        lastResidual[lanei] = GREAT;
        iterations[lanei] = 0;
    }

    Lanes residual;
    linearise(rodLength, residual);
    for (label iter = 0; iter <= maxIterations; ++iter)
    {
        bool anyActive = false;
        bool anyConverged = false;
        newtonLaneKernels::laneMask<Lanes> converging = {};
        for (label lanei = 0; lanei < nLanes_; ++lanei)
        {
            if (!active[lanei])
            {
                continue;
            }
            if (std::isnan(residual[lanei]))
            {
                // The scalar path reports it
                active[lanei] = false;
            }
            else if (residual[lanei] <= tolerance)
            {
                iterations[lanei] = max(iter, 1);
                converging[lanei] = -1;
                anyConverged = true;
                active[lanei] = false;
            }
            else if (iter == maxIterations)
            {
                active[lanei] = false;
            }
            else
            {
                lastResidual[lanei] = residual[lanei];
                anyActive = true;
            }
        }
        if (anyConverged)
        {
            newtonLaneKernels::keepConverged
            (
                3*nBeads_,
                &converging,
                lanes<Lanes>(positions_),
                lanes<Lanes>(converged_)
            );
        }
        if (!anyActive)
        {
            return;
        }

        freeze(active);
        bool solved[maxLanes];
        solveSystem<Lanes>(solved);
        for (label lanei = 0; lanei < nLanes_; ++lanei)
        {
            if (active[lanei] && !solved[lanei])
            {
                active[lanei] = false;
                for (label k = 1; k < nBeads_; ++k)
                {
                    values(solution_)[k*nLanes_ + lanei] = 0;
                }
            }
        }

        shift<Lanes>();
        linearise(rodLength, residual);
        for (label lanei = 0; lanei < nLanes_; ++lanei)
        {
            if
            (
                active[lanei]
             && (
                    std::isnan(residual[lanei])
                 || residual[lanei] >= lastResidual[lanei]
                )
            )
            {
                // The scalar path would halve the step
                active[lanei] = false;
            }
        }
    }
}


template<class Lanes>
void Foam::polymer::newtonLanes::projectLanes
(
    bool solved[],
    scalar largest[]
)
{
    newtonLaneKernels::velocitySystem
    (
        nBeads_ - 1,
        lanes<Lanes>(converged_),
        lanes<Lanes>(velocities_),
        lanes<Lanes>(rods_),
        lanes<Lanes>(lower_),
        lanes<Lanes>(diagonal_),
        lanes<Lanes>(upper_),
        lanes<Lanes>(solution_)
    );
    solveSystem<Lanes>(solved);

    Lanes largestVelocity;
    newtonLaneKernels::kick
    (
        nBeads_,
        lanes<Lanes>(rods_),
        lanes<Lanes>(solution_),
        lanes<Lanes>(velocities_),
        &largestVelocity
    );
    for (label lanei = 0; lanei < nLanes_; ++lanei)
    {
        largest[lanei] = largestVelocity[lanei];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::newtonLanes::resize(const label nBeads)
{
    if (nBeads == nBeads_)
    {
        return;
    }

    // The padding rods and solutions stay zero: load and the solves write
    // only the chain's own
    nBeads_ = nBeads;
    const label nRods = nBeads - 1;

    resize(positions_, 3*nBeads);
    resize(converged_, 3*nBeads);
    resize(velocities_, 3*nBeads);
    resize(rods_, 3*(nRods + 2));
    resize(lower_, nRods);
    resize(diagonal_, nRods);
    resize(upper_, nRods);
    resize(reciprocal_, nRods);
    resize(solution_, nRods + 2);
    std::fill(rods_.begin(), rods_.end(), laneChunk{});
    std::fill(solution_.begin(), solution_.end(), laneChunk{});
}


void Foam::polymer::newtonLanes::load
(
    const vector* const x[],
    const vector* const rodStart[]
)
{
    interleave(x, positions_);

    // Rod k at 3 (k + 1): the first is padding
    const auto rod = [rodStart]
    (
        const label lanei,
        const label k,
        const direction c
    )
    {
        return rodStart[lanei][k + 1][c] - rodStart[lanei][k][c];
    };

    double* rods = values(rods_) + 3*nLanes_;
    atWidth(nLanes_, [&](auto width)
    {
        interleaveLanes<decltype(width)::value>(nBeads_ - 1, rod, rods);
    });
}


void Foam::polymer::newtonLanes::solve
(
    const scalar rodLength,
    const scalar tolerance,
    const label maxIterations,
    label iterations[]
)
{
    atWidth(nLanes_, [&](auto width)
    {
        typedef typename lanesOfWidth<decltype(width)::value>::type Lanes;
        this->template solveLanes<Lanes>
        (
            rodLength, tolerance, maxIterations, iterations
        );
    });
}


void Foam::polymer::newtonLanes::loadVelocities(const vector* const v[])
{
    interleave(v, velocities_);
}


void Foam::polymer::newtonLanes::projectVelocities
(
    bool solved[],
    scalar largest[]
)
{
    atWidth(nLanes_, [&](auto width)
    {
        typedef typename lanesOfWidth<decltype(width)::value>::type Lanes;
        this->template projectLanes<Lanes>(solved, largest);
    });
}


void Foam::polymer::newtonLanes::storeVelocities
(
    const label lanei,
    vector* v
) const
{
    const double* lane = values(velocities_) + lanei;
    atWidth(nLanes_, [&](auto width)
    {
        laneVectors<decltype(width)::value>(nBeads_, lane, v);
    });
}


void Foam::polymer::newtonLanes::store
(
    const label lanei,
    vector* x,
    vector* v,
    const scalar oneByDeltaT
) const
{
    const double* lane = values(converged_) + lanei;
    atWidth(nLanes_, [&](auto width)
    {
        constexpr label N = decltype(width)::value;
        storeLane<N>(nBeads_, lane, x, v, oneByDeltaT);
    });
}


// ************************************************************************* //
