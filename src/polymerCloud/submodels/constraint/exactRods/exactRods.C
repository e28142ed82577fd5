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

#include "exactRods.H"
#include "checkedInput.H"
#include "makePolymerModel.H"
#include "symmTensor.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(constraintModel, constraintModels, exactRods)


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// sum_k |r_k - c|, the convex function whose minimiser closes a ring
scalar sumOfLengths(const UList<vector>& r, const vector& c)
{
    scalar sum = 0;
    for (const vector& rk : r)
    {
        sum += mag(rk - c);
    }
    return sum;
}


// -sum_k (r_k - c)/|r_k - c|, the gradient of sumOfLengths in c
vector ringGradient(const UList<vector>& r, const vector& c)
{
    vector gradient(Zero);
    for (const vector& rk : r)
    {
        const vector d(rk - c);
        const scalar length = mag(d);
        if (length > VSMALL)
        {
            gradient -= d/length;
        }
    }
    return gradient;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModels::exactRods::exactRods(const dictionary& dict)
:
    newton(typeName, dict),
    descentTolerance_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_, "descentTolerance", 1e-8, "<descent's last step / a>"
        )
    ),
    maxDescentIterations_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_,
            "maxDescentIterations",
            100,
            1,
            "<descent iterations>"
        )
    ),
    exactSolves_(0),
    stoppedDescents_(0),
    target_(),
    step_(),
    trial_(),
    hessian_()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::polymer::constraintModels::exactRods::ringShift
(
    const UList<vector>& r
)
{
    // Newton's method on F(c) = sum |r_k - c|: gradient -sum u_k, Hessian
    // sum (I - u_k u_k)/|r_k - c|, halving the step until F decreases
    vector c(Zero);
    scalar F = sumOfLengths(r, c);
    for (label iter = 0; iter < 100; ++iter)
    {
        vector gradient(Zero);
        symmTensor hessian(Zero);
        scalar scale = 0;
        for (const vector& rk : r)
        {
            const vector d(rk - c);
            const scalar length = mag(d);
            if (length < VSMALL)
            {
                continue;
            }
            const vector u(d/length);
            gradient -= u;
            hessian += (symmTensor::I - sqr(u))/length;
            scale += 1;
        }
        if (mag(gradient) <= 1e-15*scale)
        {
            break;
        }

        const scalar determinant = det(hessian);
        vector dc =
            (mag(determinant) > VSMALL)
          ? -(inv(hessian) & gradient)
          : -gradient;

        // Near the minimum F's decrease is lost in its round-off: the
        // gradient's, which vanishes there, decides then
        bool decreased = false;
        for (label halving = 0; halving < 60; ++halving)
        {
            const scalar trialF = sumOfLengths(r, c + dc);
            if (trialF < F || mag(ringGradient(r, c + dc)) < mag(gradient))
            {
                c += dc;
                F = trialF;
                decreased = true;
                break;
            }
            dc *= 0.5;
        }
        if (!decreased)
        {
            break;
        }
    }
    return c;
}


void Foam::polymer::constraintModels::exactRods::rescaleRods
(
    vector* x,
    const vector* fallback,
    const chainType& type
) const
{
    const label n = type.nBeads();
    const label nRods = type.nRods();
    const scalar a = type.rodLength();

    // The rod vectors, a rod of no length along its fallback's direction
    step_.resize(nRods);
    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1) % n;
        step_[k] = x[j] - x[k];
        if (magSqr(step_[k]) < sqr(SMALL*a))
        {
            step_[k] = fallback[j] - fallback[k];
        }
    }
    if (type.ring())
    {
        const vector c = ringShift(step_);
        for (vector& r : step_)
        {
            r -= c;
        }
    }

    // The chain rebuilt from its first bead, then moved to x's mean
    vector mean(Zero);
    for (label i = 0; i < n; ++i)
    {
        mean += x[i];
    }
    mean /= n;

    vector position(Zero);
    vector rebuiltMean(Zero);
    for (label i = 0; i < n; ++i)
    {
        x[i] = position;
        rebuiltMean += position;
        if (i < n - 1)
        {
            position += (a/mag(step_[i]))*step_[i];
        }
    }
    const vector shift(mean - rebuiltMean/n);
    for (label i = 0; i < n; ++i)
    {
        x[i] += shift;
    }
}


Foam::List<Foam::vector>
Foam::polymer::constraintModels::exactRods::descentDirection
(
    const vector* x,
    const chainType& type
) const
{
    // Newton's step on the constraint set: the Hessian of the Lagrangian,
    // I + L (L the path Laplacian weighted by the rods' multipliers, the
    // same for each coordinate), between tangent projections, solved for
    // the tangent gradient in step_ by conjugate gradients, stopped at a
    // residual of 1% or at negative curvature (then the steps so far, or
    // the gradient)
    const label n = type.nBeads();
    const label nRods = type.nRods();
    const List<scalar> multipliers(rodMultipliers(type));
    const List<vector> gradient(step_);

    auto dot = [n](const UList<vector>& u, const UList<vector>& v)
    {
        scalar sum = 0;
        for (label i = 0; i < n; ++i)
        {
            sum += u[i] & v[i];
        }
        return sum;
    };

    List<vector> d(n, Zero);
    List<vector> r(gradient);
    List<vector> p(gradient);
    List<vector> Hp(n);
    scalar rr = dot(r, r);
    const scalar stop = 1e-4*rr;
    for (label iter = 0; iter < 2*n + 10; ++iter)
    {
        Hp = p;
        for (label k = 0; k < nRods; ++k)
        {
            const label i = k, j = (k + 1) % n;
            const vector pull(multipliers[k]*(p[j] - p[i]));
            Hp[i] -= pull;
            Hp[j] += pull;
        }
        scalar largest;
        if (!projectOnRods(x, type, Hp.data(), largest))
        {
            return gradient;
        }

        const scalar curvature = dot(p, Hp);
        if (curvature <= SMALL*dot(p, p))
        {
            return iter ? d : gradient;
        }
        const scalar alpha = rr/curvature;
        for (label i = 0; i < n; ++i)
        {
            d[i] += alpha*p[i];
            r[i] -= alpha*Hp[i];
        }
        const scalar rrNew = dot(r, r);
        if (rrNew <= stop)
        {
            break;
        }
        const scalar beta = rrNew/rr;
        for (label i = 0; i < n; ++i)
        {
            p[i] = r[i] + beta*p[i];
        }
        rr = rrNew;
    }
    return d;
}


bool Foam::polymer::constraintModels::exactRods::lineSearch
(
    vector* x,
    const UList<vector>& direction,
    const chainType& type,
    scalar& f
) const
{
    // Steps of at most half a rod, halved until the rescaled trial is
    // nearer x*
    const label n = type.nBeads();
    scalar largest = 0;
    for (const vector& d : direction)
    {
        largest = max(largest, mag(d));
    }
    for
    (
        scalar alpha =
            min(scalar(1), 0.5*type.rodLength()/max(largest, VSMALL));
        alpha*largest > 1e-15*type.rodLength();
        alpha *= 0.5
    )
    {
        trial_.resize(n);
        for (label i = 0; i < n; ++i)
        {
            trial_[i] = x[i] + alpha*direction[i];
        }
        rescaleRods(trial_.data(), x, type);

        // The change of the distance summed directly, without the
        // cancellation of two distances: accurate to its own round-off,
        // so the descent goes on near x*'s nearest configuration
        scalar change = 0;
        for (label i = 0; i < n; ++i)
        {
            const vector d(trial_[i] - x[i]);
            change += d & (0.5*d + x[i] - target_[i]);
        }
        if (change < 0)
        {
            for (label i = 0; i < n; ++i)
            {
                x[i] = trial_[i];
            }
            f += change;
            return true;
        }
    }
    return false;
}


Foam::scalar Foam::polymer::constraintModels::exactRods::distance
(
    const vector* x,
    const label n
) const
{
    scalar sum = 0;
    for (label i = 0; i < n; ++i)
    {
        sum += magSqr(x[i] - target_[i]);
    }
    return 0.5*sum;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::constraintModels::exactRods::correctChainLengths
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    scalar& residual
) const
{
    const chainType& type = chains.type(chaini);
    const label first = chains.start(chaini);
    const label n = type.nBeads();
    const scalar a = type.rodLength();

    vector* x = chains.positions().data() + first;
    vector* v = chains.velocities().data() + first;
    const vector* xOld = positionsOld.cdata() + first;

    // The paper's projection along the constraint directions, where it
    // has a solution
    const label newtonIter =
        newton::correctChainLengths
        (
            chains, chaini, positionsOld, deltaT, residual
        );
    if (newtonIter > 0)
    {
        return newtonIter;
    }

    // newton's failed solve left the velocities at v*; the positions
    // return to x*
    target_ = startPositions();
    for (label i = 0; i < n; ++i)
    {
        x[i] = target_[i];
    }
    ++exactSolves_;

    // 1. The feasible start
    rescaleRods(x, xOld, type);
    scalar f = distance(x, n);

    // 2. The feasible descent toward x*
    label iter = 0;
    bool converged = false;
    bool tookRoundOffStep = false;
    while (iter < maxDescentIterations_)
    {
        ++iter;

        step_.resize(n);
        for (label i = 0; i < n; ++i)
        {
            step_[i] = target_[i] - x[i];
        }
        scalar largest;
        if (!projectOnRods(x, type, step_.data(), largest))
        {
            break;
        }
        scalar stepSize = 0;
        for (label i = 0; i < n; ++i)
        {
            stepSize = max(stepSize, mag(step_[i]));
        }
        if (stepSize <= descentTolerance_*a)
        {
            converged = true;
            break;
        }

        // The preconditioned direction, or the gradient where that does
        // not shorten the distance (rescaleRods uses step_ as work space)
        const List<vector> gradient(step_);
        const List<vector> preconditioned(descentDirection(x, type));
        const bool decreased =
            lineSearch(x, preconditioned, type, f)
         || lineSearch(x, gradient, type, f);
        if (decreased)
        {
            tookRoundOffStep = false;
            continue;
        }

        // Close to the nearest configuration the distance changes by less
        // than the round-off of the rebuilt chain, and no step is seen to
        // shorten it: Newton's step then goes as it is, once in a row
        if (tookRoundOffStep || stepSize > std::sqrt(descentTolerance_)*a)
        {
            // Stationary to round-off
            converged = true;
            break;
        }
        for (label i = 0; i < n; ++i)
        {
            x[i] += preconditioned[i];
        }
        rescaleRods(x, target_.cdata(), type);
        f = distance(x, n);
        tookRoundOffStep = true;
    }
    if (!converged)
    {
        ++stoppedDescents_;
    }

    // The positions' correction over the step goes to the velocities
    for (label i = 0; i < n; ++i)
    {
        v[i] += (x[i] - target_[i])/deltaT;
    }

    residual = chains.maxRodLengthError(chaini);
    if (std::isnan(residual))
    {
        // A NaN in the chain (its positions or the drift that made them)
        // is no projection: a failure, reported with the chain and time
        return -1 - iter;
    }
    return iter - newtonIter;
}


void Foam::polymer::constraintModels::exactRods::writeReport
(
    Ostream& os
) const
{
    constraintModel::writeReport(os);
    os  << "    exactRods: chains given exact rods where newton had no"
        << " solution " << returnReduce(exactSolves_, sumOp<label>())
        << ", descents stopped by maxDescentIterations "
        << returnReduce(stoppedDescents_, sumOp<label>()) << nl;
}


void Foam::polymer::constraintModels::exactRods::writeRunTotals
(
    dictionary& dict
) const
{
    constraintModel::writeRunTotals(dict);
    dictionary& totals = dict.subDictOrAdd(modelType());
    runTotals::add
    (
        totals, "exactSolves", returnReduce(exactSolves_, sumOp<label>())
    );
    runTotals::add
    (
        totals, "stoppedDescents",
        returnReduce(stoppedDescents_, sumOp<label>())
    );
}


void Foam::polymer::constraintModels::exactRods::readRunTotals
(
    const dictionary& dict
)
{
    constraintModel::readRunTotals(dict);
    const dictionary* saved = dict.findDict(modelType());
    if (saved)
    {
        runTotals::read(*saved, "exactSolves", exactSolves_);
        runTotals::read(*saved, "stoppedDescents", stoppedDescents_);
    }
}


// ************************************************************************* //
