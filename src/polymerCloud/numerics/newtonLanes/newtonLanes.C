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
#include <cmath>

#pragma GCC diagnostic ignored "-Wpsabi"

// * * * * * * * * * * * * * * * * Dispatch  * * * * * * * * * * * * * * * //

// As boxMuller: each kernel compiled for AVX-512, AVX2 and the x86-64
// baseline, without fused multiply-adds, so all give the scalar path's
// bits. The AVX-512 version (four lanes still, in EVEX instructions) is
// for the processors boxMuller's AVX-512 transform runs on: there the
// integration around the lanes ran faster with it than with the lanes
// in AVX2 (the chainThroughput README, 2026-12-05)
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

typedef newtonLanes::lane lane;

//- Lane masks: all bits set where a lane comparison holds
typedef long laneMask __attribute__
((
    vector_size(sizeof(lane)),
    aligned(sizeof(lane))
));


//- The dot product of 3-vectors held component-wise, in Vector's order.
//  Always inlined: no lane passes by value between functions compiled for
//  different instruction sets, whose calling conventions for it differ
//  (the kernels take lanes by pointer), and GCC's -Wpsabi notes on this
//  file, which it gives at the end of the file, do not apply.
__attribute__((always_inline))
static inline lane dot(const lane* s, const lane* d)
{
    return s[0]*d[0] + s[1]*d[1] + s[2]*d[2];
}


// newton::linearise, lane by lane. x: 3 per bead; d: 3 per padded rod;
// source: padded; largest: each lane's largest |sigma|. (Lanes pass by
// pointer: by value their calling convention would differ between the
// AVX2 and the baseline version.)
LANE_TARGETS
void linearise
(
    const label nRods,
    const lane* x,
    const lane* d,
    lane* lower,
    lane* diagonal,
    lane* upper,
    lane* source,
    const double a2,
    lane* largestSigma
)
{
    const laneMask magnitudeBits = laneMask{} + 0x7fffffffffffffffL;

    lane largest = {};
    laneMask notNumber = {};
    for (label k = 0; k < nRods; ++k)
    {
        const lane* xk = x + 3*k;
        const lane s[3] = {xk[3] - xk[0], xk[4] - xk[1], xk[5] - xk[2]};
        const lane sigma = dot(s, s) - a2;
        const lane magSigma = __builtin_bit_cast
        (
            lane, __builtin_bit_cast(laneMask, sigma) & magnitudeBits
        );

        // A NaN is kept (maxOrNaN) without an ordered comparison, which
        // would raise the invalid-operation trap that OpenFOAM sets
        const laneMask isNumber = (magSigma == magSigma);
        notNumber |= ~isNumber;
        const lane number = isNumber ? magSigma : lane{};
        largest = number > largest ? number : largest;

        const lane* dk = d + 3*(k + 1);
        lower[k] = -2*dot(s, dk - 3);
        diagonal[k] = 4*dot(s, dk);
        upper[k] = -2*dot(s, dk + 3);
        source[k + 1] = -sigma;
    }
    *largestSigma = notNumber ? lane{} + NAN : largest;
}


// tridiagonalSystem::eliminate and backSubstitute, lane by lane, on the
// right-hand side x. A zero pivot is replaced by 1 (no division by zero)
// and its lane set in zeroPivot: its solution is not to be used.
LANE_TARGETS
void solveTridiagonal
(
    const label n,
    const lane* l,
    const lane* d,
    const lane* u,
    lane* reciprocal,
    lane* x,
    laneMask* zeroPivot
)
{
    const label m = n/2;
    const lane unit = lane{} + 1;

    laneMask zero = (d[0] == 0) | (d[n - 1] == 0);

    lane down = unit/(zero ? unit : d[0]);
    lane up = unit/(zero ? unit : d[n - 1]);
    lane xDown = x[0];
    lane xUp = x[n - 1];
    reciprocal[0] = down;
    reciprocal[n - 1] = up;
    for (label k = 1; k < m; ++k)
    {
        const lane pivot = d[k] - (l[k]*u[k - 1])*down;
        xDown = x[k] - (l[k]*down)*xDown;
        x[k] = xDown;
        const laneMask isZero = (pivot == 0);
        zero |= isZero;
        down = unit/(isZero ? unit : pivot);
        reciprocal[k] = down;

        const label j = n - 1 - k;
        if (j > m)
        {
            const lane pivot = d[j] - (u[j]*l[j + 1])*up;
            xUp = x[j] - (u[j]*up)*xUp;
            x[j] = xUp;
            const laneMask isZero = (pivot == 0);
            zero |= isZero;
            up = unit/(isZero ? unit : pivot);
            reciprocal[j] = up;
        }
    }

    lane pivot = d[m];
    lane xm = x[m];
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
    const laneMask isZero = (pivot == 0);
    zero |= isZero;
    reciprocal[m] = unit/(isZero ? unit : pivot);
    x[m] = xm*reciprocal[m];

    lane xUpward = x[m];
    lane xDownward = x[m];
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
LANE_TARGETS
void shift(const label nRods, lane* x, const lane* d, const lane* g)
{
    for (label k = 0; k < nRods; ++k)
    {
        const lane* dk = d + 3*(k + 1);
        const lane gk = g[k + 1];
        lane* xk = x + 3*k;
        for (int c = 0; c < 3; ++c)
        {
            const lane dx = gk*dk[c];
            xk[c] -= dx;
            xk[c + 3] += dx;
        }
    }
}

// rodVelocityProjection::project's system, lane by lane: rods r of the
// positions x (padded with a zero rod at each end, as d), the velocities w
// (3 per bead); source padded
LANE_TARGETS
void velocitySystem
(
    const label nRods,
    const lane* x,
    const lane* w,
    lane* r,
    lane* lower,
    lane* diagonal,
    lane* upper,
    lane* source
)
{
    for (label k = 0; k < nRods; ++k)
    {
        const lane* xk = x + 3*k;
        lane* rk = r + 3*(k + 1);
        for (int c = 0; c < 3; ++c)
        {
            rk[c] = xk[c + 3] - xk[c];
        }
    }
    for (label k = 0; k < nRods; ++k)
    {
        const lane* rk = r + 3*(k + 1);
        const lane* wk = w + 3*k;
        const lane dw[3] = {wk[3] - wk[0], wk[4] - wk[1], wk[5] - wk[2]};
        lower[k] = -dot(rk, rk - 3);
        diagonal[k] = 2*dot(rk, rk);
        upper[k] = -dot(rk, rk + 3);
        source[k + 1] = dot(rk, dw);
    }
}


// rodVelocityProjection::kick, lane by lane: w changes by the multipliers
// m (padded) along the rods r (padded); largest: each lane's largest
// |r_k.(w_{k+1} - w_k)| after it (a NaN kept, as in linearise)
LANE_TARGETS
void kick
(
    const label nBeads,
    const lane* r,
    const lane* m,
    lane* w,
    lane* largestVelocity
)
{
    const laneMask magnitudeBits = laneMask{} + 0x7fffffffffffffffL;

    for (int c = 0; c < 3; ++c)
    {
        w[c] += m[1]*r[3 + c] - m[0]*r[c];
    }

    lane largest = {};
    laneMask notNumber = {};
    for (label k = 0; k + 1 < nBeads; ++k)
    {
        const lane* rk = r + 3*(k + 1);
        lane* wk = w + 3*k;
        for (int c = 0; c < 3; ++c)
        {
            wk[c + 3] += m[k + 2]*rk[c + 3] - m[k + 1]*rk[c];
        }
        const lane dw[3] = {wk[3] - wk[0], wk[4] - wk[1], wk[5] - wk[2]};
        const lane relative = dot(rk, dw);
        const lane magRelative = __builtin_bit_cast
        (
            lane, __builtin_bit_cast(laneMask, relative) & magnitudeBits
        );
        const laneMask isNumber = (magRelative == magRelative);
        notNumber |= ~isNumber;
        const lane number = isNumber ? magRelative : lane{};
        largest = number > largest ? number : largest;
    }
    *largestVelocity = notNumber ? lane{} + NAN : largest;
}

// converged = positions in the lanes of keep (all bits set), unchanged in
// the others; n lanes each. On the bits, so that the baseline version too
// is whole-register logic (a lane-wise ?: there became a branch per
// element, whose stores and wide reloads stalled).
LANE_TARGETS
void keepConverged
(
    const label n,
    const laneMask* keep,
    const lane* positions,
    lane* converged
)
{
    const laneMask taken = *keep;
    for (label i = 0; i < n; ++i)
    {
        converged[i] = __builtin_bit_cast
        (
            lane,
            (__builtin_bit_cast(laneMask, positions[i]) & taken)
          | (__builtin_bit_cast(laneMask, converged[i]) & ~taken)
        );
    }
}

} // End namespace newtonLaneKernels
} // End namespace polymer
} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::newtonLanes::newtonLanes()
:
    nBeads_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::newtonLanes::linearise
(
    const scalar rodLength,
    lane& residual
)
{
    const scalar a2 = rodLength*rodLength;
    lane largest;
    newtonLaneKernels::linearise
    (
        nBeads_ - 1,
        lanes(positions_),
        lanes(rods_),
        lanes(lower_),
        lanes(diagonal_),
        lanes(upper_),
        lanes(solution_),
        a2,
        &largest
    );
    residual = largest/(2*a2);
}


void Foam::polymer::newtonLanes::solveSystem(bool solved[nLanes])
{
    newtonLaneKernels::laneMask zero;
    newtonLaneKernels::solveTridiagonal
    (
        nBeads_ - 1,
        lanes(lower_),
        lanes(diagonal_),
        lanes(upper_),
        lanes(reciprocal_),
        lanes(solution_) + 1,
        &zero
    );

    for (label lanei = 0; lanei < nLanes; ++lanei)
    {
        solved[lanei] = !zero[lanei];
    }
}


void Foam::polymer::newtonLanes::shift()
{
    newtonLaneKernels::shift
    (
        nBeads_ - 1, lanes(positions_), lanes(rods_), lanes(solution_)
    );
}


void Foam::polymer::newtonLanes::freeze(const bool active[nLanes])
{
    const label nRods = nBeads_ - 1;
    for (label lanei = 0; lanei < nLanes; ++lanei)
    {
        if (active[lanei])
        {
            continue;
        }
        for (label k = 0; k < nRods; ++k)
        {
            lower_[k].value[lanei] = 0;
            diagonal_[k].value[lanei] = 1;
            upper_[k].value[lanei] = 0;
            solution_[k + 1].value[lanei] = 0;
        }
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
    const laneElement zero{};

    positions_.resize(3*nBeads);
    converged_.resize(3*nBeads);
    velocities_.resize(3*nBeads);
    rods_.assign(3*(nRods + 2), zero);
    lower_.resize(nRods);
    diagonal_.resize(nRods);
    upper_.resize(nRods);
    reciprocal_.resize(nRods);
    solution_.assign(nRods + 2, zero);
}


void Foam::polymer::newtonLanes::interleave
(
    const vector* const values[nLanes],
    laneArray& lanesOf
) const
{
    for (label i = 0; i < nBeads_; ++i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            lane value;
            for (label lanei = 0; lanei < nLanes; ++lanei)
            {
                value[lanei] = values[lanei][i][c];
            }
            lanesOf[3*i + c].value = value;
        }
    }
}


void Foam::polymer::newtonLanes::load
(
    const vector* const x[nLanes],
    const vector* const rodStart[nLanes]
)
{
    interleave(x, positions_);
    for (label k = 0; k + 1 < nBeads_; ++k)
    {
        for (direction c = 0; c < 3; ++c)
        {
            lane value;
            for (label lanei = 0; lanei < nLanes; ++lanei)
            {
                const vector* r = rodStart[lanei];
                value[lanei] = r[k + 1][c] - r[k][c];
            }
            rods_[3*(k + 1) + c].value = value;
        }
    }
}


void Foam::polymer::newtonLanes::solve
(
    const scalar rodLength,
    const scalar tolerance,
    const label maxIterations,
    label iterations[nLanes]
)
{
    // newton::solveLengths on its usual path: a full step whose residual
    // falls, until it is within the tolerance
    bool active[nLanes];
    scalar lastResidual[nLanes];
    std::fill(lastResidual, lastResidual + nLanes, GREAT);
    for (label lanei = 0; lanei < nLanes; ++lanei)
    {
        active[lanei] = true;
        iterations[lanei] = 0;
    }

    lane residual;
    linearise(rodLength, residual);
    for (label iter = 0; iter <= maxIterations; ++iter)
    {
        bool anyActive = false;
        bool anyConverged = false;
        newtonLaneKernels::laneMask converging = {};
        for (label lanei = 0; lanei < nLanes; ++lanei)
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
                3*nBeads_, &converging, lanes(positions_), lanes(converged_)
            );
        }
        if (!anyActive)
        {
            return;
        }

        freeze(active);
        bool solved[nLanes];
        solveSystem(solved);
        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            if (active[lanei] && !solved[lanei])
            {
                active[lanei] = false;
                for (label k = 1; k < nBeads_; ++k)
                {
                    solution_[k].value[lanei] = 0;
                }
            }
        }

        shift();
        linearise(rodLength, residual);
        for (label lanei = 0; lanei < nLanes; ++lanei)
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


void Foam::polymer::newtonLanes::loadVelocities
(
    const vector* const v[nLanes]
)
{
    interleave(v, velocities_);
}


void Foam::polymer::newtonLanes::projectVelocities
(
    bool solved[nLanes],
    scalar largest[nLanes]
)
{
    const label nRods = nBeads_ - 1;
    newtonLaneKernels::velocitySystem
    (
        nRods,
        lanes(converged_),
        lanes(velocities_),
        lanes(rods_),
        lanes(lower_),
        lanes(diagonal_),
        lanes(upper_),
        lanes(solution_)
    );
    solveSystem(solved);

    lane largestVelocity;
    newtonLaneKernels::kick
    (
        nBeads_,
        lanes(rods_),
        lanes(solution_),
        lanes(velocities_),
        &largestVelocity
    );
    for (label lanei = 0; lanei < nLanes; ++lanei)
    {
        largest[lanei] = largestVelocity[lanei];
    }
}


void Foam::polymer::newtonLanes::storeVelocities
(
    const label lanei,
    vector* v
) const
{
    for (label i = 0; i < nBeads_; ++i)
    {
        for (direction c = 0; c < 3; ++c)
        {
            v[i][c] = velocities_[3*i + c].value[lanei];
        }
    }
}


void Foam::polymer::newtonLanes::store
(
    const label lanei,
    vector* x,
    vector* v,
    const scalar oneByDeltaT
) const
{
    // As newton::iterate: v += (x - x*)/deltaT, x* being x before
    for (label i = 0; i < nBeads_; ++i)
    {
        const vector solved
        (
            converged_[3*i].value[lanei],
            converged_[3*i + 1].value[lanei],
            converged_[3*i + 2].value[lanei]
        );
        v[i] += oneByDeltaT*(solved - x[i]);
        x[i] = solved;
    }
}


// ************************************************************************* //
