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

#include "chainStepper.H"
#include "packedReduction.H"
#include "allReduce.H"
#include "Time.H"
#include "isFinite.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::chainStepper::chainStepper
(
    const Time& time,
    const polymerCloudSolution& solution,
    polymerChains& chains,
    flowModel& flow,
    const polymerCoupling& coupling,
    const PtrList<forceModel>& forces,
    const integrationModel& integration,
    const constraintModel& constraint
)
:
    time_(time),
    seed_(solution.seed()),
    chains_(chains),
    flow_(flow),
    coupling_(coupling),
    forces_(forces),
    integration_(integration),
    constraint_(constraint),
    positionsOld_(),
    velocitiesOld_(),
    positionsStar_(),
    velocityChange_(),
    force_(),
    drift_(),
    displacementReported_(false),
    maxNeighbourDisplacement_(solution.maxNeighbourDisplacement()),
    maxSubCycles_(solution.maxSubCycles()),
    cycleKey_(0),
    flowSteps_(0),
    subCycledSteps_(0),
    subCycleSteps_(0),
    largestSubCycles_(1),
    cappedSteps_(0),
    maxBeadsOutside_(0),
    beadStepsOutside_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::chainStepper::writeNeighbourDisplacement() const
{
    // delta = |r*_k - r^n_k|/a over the rods: how far the step moves
    // neighbouring beads apart, the scale that sets the projections'
    // failures and bias
    scalar sumSqr = 0, largest = 0, nRods = 0;
    const List<vector>& x = chains_.positions();
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const chainType& type = chains_.type(c);
        const label first = chains_.start(c);
        const label n = type.nBeads();
        for (label k = 0; k < type.nRods(); ++k)
        {
            const label i = first + k;
            const label j = first + (k + 1) % n;
            const scalar delta =
                mag((x[j] - x[i]) - (positionsOld_[j] - positionsOld_[i]))
               /type.rodLength();
            sumSqr += sqr(delta);
            largest = max(largest, delta);
            nRods += 1;
        }
    }
    reduce(sumSqr, sumOp<scalar>());
    reduce(largest, maxOp<scalar>());
    reduce(nRods, sumOp<scalar>());

    if (nRods > 0)
    {
        Info<< "polymerCloud: the first step moves neighbouring beads apart"
            << " by delta/a = " << std::sqrt(sumSqr/nRods) << " (rms), "
            << largest << " (largest)" << endl;
    }
}


void Foam::polymer::chainStepper::checkFinite
(
    const UList<vector>& values,
    const char* what,
    const char* when
) const
{
    if (allFinite(values))
    {
        return;
    }
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            const vector& value = values[i];
            if (isFinite(value))
            {
                continue;
            }
            FatalErrorInFunction
                << "The " << what << " of chain " << chains_.globalId(c)
                << " (type " << chains_.type(c).name() << "), bead "
                << i - chains_.start(c) << ", is " << value
                << " " << when << " " << time_.timeName()
                << " (time index " << time_.timeIndex() << ")" << nl
                << "    expected: finite values; a NaN or inf made by the"
                << " step's arithmetic (with FOAM_SIGFPE off), or by"
                << " the flow or forces at the bead"
                << exit(FatalError);
        }
    }
}


void Foam::polymer::chainStepper::checkFinite(const char* when) const
{
    checkFinite(chains_.positions(), "position", when);
    checkFinite(chains_.velocities(), "velocity", when);
}


void Foam::polymer::chainStepper::startChain(const label c)
{
    const label first = chains_.start(c);
    const label n = chains_.size(c);
    if
    (
        !copyAllFinite
        (
            SubList<vector>(chains_.positions(), n, first),
            positionsOld_.data() + first
        )
     || !copyAllFinite
        (
            SubList<vector>(chains_.velocities(), n, first),
            velocitiesOld_.data() + first
        )
    )
    {
        checkFinite("at the start of the step to time");
    }
}


void Foam::polymer::chainStepper::recordUnconstrained(const label c)
{
    const List<vector>& x = chains_.positions();
    const List<vector>& v = chains_.velocities();
    for (label i = chains_.start(c); i < chains_.end(c); ++i)
    {
        velocityChange_[i] = v[i] - velocitiesOld_[i];
        positionsStar_[i] = x[i];
    }
}


void Foam::polymer::chainStepper::recordVelocityChange()
{
    if (!coupling_.twoWay())
    {
        return;
    }

    // The friction over the step is zeta (u dt - (x - x^n)) on the path
    // the bead took: the constraint's displacement adds -zeta (x-dagger -
    // x*) to that of the unconstrained update
    const List<vector>& x = chains_.positions();
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const scalar gamma = 1/chains_.type(c).inertialTime();
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            velocityChange_[i] -= gamma*(x[i] - positionsStar_[i]);
        }
    }
}


void Foam::polymer::chainStepper::subStepChain
(
    const label chaini,
    const scalar deltaT
)
{
    const Time& runTime = time_;
    const label first = chains_.start(chaini);
    const label n = chains_.size(chaini);

    SubList<vector> x(chains_.positions(), n, first);
    SubList<vector> v(chains_.velocities(), n, first);
    SubList<vector> subStepStart(positionsOld_, n, first);
    SubList<vector> change
    (
        velocityChange_, coupling_.twoWay() ? n : 0, first
    );
    const List<vector> xStart(SubList<vector>(positionsOld_, n, first));
    const List<vector> vStart(SubList<vector>(velocitiesOld_, n, first));

    constraint_.countSubStepped();

    const scalar gamma = 1/chains_.type(chaini).inertialTime();

    for (label nSub = 2; nSub <= constraint_.maxSubSteps(); nSub *= 2)
    {
        x = xStart;
        v = vStart;
        change = Zero;

        bool converged = true;
        for (label s = 0; s < nSub && converged; ++s)
        {
            // The fluid velocity stays that at x^n; each sub-step has its
            // own noise, keyed by (nSub, s) under the step's own key
            subStepStart = x;
            const List<vector> vSubStart(v);
            integration_.integrateChain
            (
                chains_,
                chaini,
                drift(),
                deltaT/nSub,
                runTime.timeIndex(),
                seed_,
                (cycleKey_ ? cycleKey_ : 1)*nSub + s
            );
            const List<vector> xSubStar(x);
            const List<vector> vSubStar(v);
            converged = constraint_.correctChain
            (
                chains_, chaini, positionsOld_, deltaT/nSub, runTime.value()
            );

            // The friction and noise part, as recordVelocityChange
            forAll(change, k)
            {
                change[k] +=
                    vSubStar[k] - vSubStart[k] - gamma*(x[k] - xSubStar[k]);
            }
        }

        if (converged)
        {
            subStepStart = xStart;
            return;
        }
    }

    FatalErrorInFunction
        << "The constraint solve of chain " << chains_.globalId(chaini)
        << " (" << chains_.type(chaini).name() << ") at time "
        << runTime.value() << " did not converge in "
        << constraint_.maxSubSteps() << " sub-steps of the time step "
        << deltaT << " (constraint " << constraint_.type() << ")" << nl
        << constraint_.roundOffHint(chains_, chaini).c_str()
        << "    The chain's state at the step's start may be too distorted"
        << " (rod-rod collisions or wall rebounds in strong flow leave rod"
        << " errors): reduce deltaT (maxCo), or raise maxSubSteps or"
        << " maxIterations"
        << (constraint_.type() == "newton" ? "" : ", or use newton")
        << exit(FatalError);
}


Foam::scalar Foam::polymer::chainStepper::predictedDisplacement
(
    const chainType& type,
    const scalar deltaU,
    const scalar dt
)
{
    return std::sqrt
    (
        type.neighbourDisplacementSqr(dt) + sqr(deltaU*dt/type.rodLength())
    );
}


Foam::scalar Foam::polymer::chainStepper::driftDifference(const label c) const
{
    const UList<vector>& u = drift();
    if (u.size() != chains_.nBeads())
    {
        return 0;           // no flow: the beads relax to rest
    }

    const label first = chains_.start(c);
    const label n = chains_.size(c);
    scalar largest = 0;
    for (label k = 0; k < chains_.type(c).nRods(); ++k)
    {
        largest = max
        (
            largest, magSqr(u[first + (k + 1) % n] - u[first + k])
        );
    }
    return std::sqrt(largest);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::chainStepper::subCycles(const scalar deltaT)
{
    if (maxNeighbourDisplacement_ <= 0)
    {
        return 1;
    }

    // The least K with every chain's delta(deltaT/K) within the bound:
    // delta falls with K, so K only grows over the chains
    label nCycles = 1;
    scalar largest = 0;
    bool capped = false;
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const chainType& type = chains_.type(c);
        if (!type.nRods())
        {
            continue;
        }
        const scalar deltaU = driftDifference(c);
        largest = max(largest, predictedDisplacement(type, deltaU, deltaT));
        while
        (
            predictedDisplacement(type, deltaU, deltaT/nCycles)
          > maxNeighbourDisplacement_
        )
        {
            if (nCycles == maxSubCycles_)
            {
                capped = true;
                break;
            }
            ++nCycles;
        }
    }
    nCycles = allReduceMax(nCycles);
    largest = allReduceMax(largest);
    capped = allReduceOr(capped);

    if (!flowSteps_)
    {
        Info<< "polymerCloud: predicted delta/a over the flow's step "
            << largest << " (maxNeighbourDisplacement "
            << maxNeighbourDisplacement_ << "): " << nCycles
            << " polymer step(s) per flow step" << endl;
    }
    if (capped && !cappedSteps_)
    {
        WarningInFunction
            << "At time " << time_.value() << " the polymer step needs more"
            << " than maxSubCycles " << maxSubCycles_ << " sub-cycles of"
            << " the flow's step " << deltaT << " to keep the predicted"
            << " delta/a within maxNeighbourDisplacement "
            << maxNeighbourDisplacement_ << " (largest " << largest
            << " over the flow's step): taking " << maxSubCycles_
            << "; such steps are counted in the final report" << endl;
    }

    ++flowSteps_;
    if (nCycles > 1)
    {
        ++subCycledSteps_;
        subCycleSteps_ += nCycles;
        largestSubCycles_ = max(largestSubCycles_, nCycles);
    }
    if (capped)
    {
        ++cappedSteps_;
    }
    return nCycles;
}


void Foam::polymer::chainStepper::writeSubCycleReport(Ostream& os) const
{
    if (maxNeighbourDisplacement_ <= 0)
    {
        return;
    }

    os  << "    sub-cycles (maxNeighbourDisplacement "
        << maxNeighbourDisplacement_ << "): " << subCycledSteps_ << " of "
        << flowSteps_ << " flow steps in sub-cycles, "
        << subCycleSteps_ << " polymer steps in them, at most "
        << largestSubCycles_ << " in a flow step; " << cappedSteps_
        << " flow steps needed more than maxSubCycles " << maxSubCycles_
        << nl;
}


void Foam::polymer::chainStepper::prepareDrift()
{
    flow_.prepare(chains_);
}


void Foam::polymer::chainStepper::updateDrift()
{
    flow_.update(chains_);

    if (forces_.empty())
    {
        if (!flow_.quiescent())
        {
            checkFinite(flow_.beadVelocity(), "fluid velocity", "at time");
        }
        return;
    }

    force_.resize(chains_.nBeads());
    force_ = Zero;
    for (const forceModel& model : forces_)
    {
        model.addForce(chains_, force_);
    }

    if (flow_.quiescent())
    {
        drift_.resize(chains_.nBeads());
        drift_ = Zero;
    }
    else
    {
        drift_ = flow_.beadVelocity();
    }
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const scalar mobility = 1/chains_.type(c).friction();
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            drift_[i] += mobility*force_[i];
        }
    }
    checkFinite
    (
        drift_, "drift velocity (fluid velocity + force/friction)", "at time"
    );
}


void Foam::polymer::chainStepper::countBeadsOutside()
{
    maxBeadsOutside_ = max(maxBeadsOutside_, flow_.nBeadsOutside());
    beadStepsOutside_ += flow_.nBeadsOutside();
}


void Foam::polymer::chainStepper::integrate(const scalar deltaT)
{
    // A chain's start copied, its update and its record while its beads
    // are in the cache: separate passes over all beads would read them
    // from memory three times
    const label nBeads = chains_.nBeads();
    positionsOld_.resize(nBeads);
    velocitiesOld_.resize(nBeads);
    const bool twoWay = coupling_.twoWay();
    if (twoWay)
    {
        velocityChange_.resize(nBeads);
        positionsStar_.resize(nBeads);
    }
    const UList<vector>& driftVelocity = drift();
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        startChain(c);
        integration_.integrateChain
        (
            chains_,
            c,
            driftVelocity,
            deltaT,
            time_.timeIndex(),
            seed_,
            cycleKey_
        );
        if (twoWay)
        {
            recordUnconstrained(c);
        }
    }

    if (!displacementReported_)
    {
        writeNeighbourDisplacement();
        displacementReported_ = true;
    }
}


void Foam::polymer::chainStepper::constrain(const scalar deltaT)
{
    DynamicList<label> failedChains;
    constraint_.correct
    (
        chains_, positionsOld_, deltaT, time_.value(), failedChains
    );
    recordVelocityChange();
    for (const label c : failedChains)
    {
        subStepChain(c, deltaT);
    }
}


void Foam::polymer::chainStepper::constrainUncounted(const scalar deltaT)
{
    // The rod tensions' displacement, for the momentum they pass on; the
    // step proper counts the solves and sub-steps the failures
    DynamicList<label> failed;
    constraint_.correct
    (
        chains_, positionsOld_, deltaT, time_.value(), failed
    );
    constraint_.resetCounters();
    recordVelocityChange();
}


void Foam::polymer::chainStepper::restoreStart()
{
    chains_.positions() = positionsOld_;
    chains_.velocities() = velocitiesOld_;
}


void Foam::polymer::chainStepper::writeRunTotals(dictionary& dict) const
{
    label largestSubCycles = largestSubCycles_;
    label maxBeadsOutside = maxBeadsOutside_;
    scalar beadStepsOutside = beadStepsOutside_;
    {
        packedReduction all;
        all.max(largestSubCycles);
        all.max(maxBeadsOutside);
        all.sum(beadStepsOutside);
        all.reduce();
    }

    dictionary& totals = dict.subDictOrAdd("steps");
    runTotals::add(totals, "flowSteps", flowSteps_);
    runTotals::add(totals, "subCycledSteps", subCycledSteps_);
    runTotals::add(totals, "subCycleSteps", subCycleSteps_);
    runTotals::add(totals, "largestSubCycles", largestSubCycles);
    runTotals::add(totals, "cappedSteps", cappedSteps_);
    runTotals::add(totals, "maxBeadsOutside", maxBeadsOutside);
    runTotals::add(totals, "beadStepsOutside", beadStepsOutside);
}


void Foam::polymer::chainStepper::readRunTotals(const dictionary& dict)
{
    const dictionary* saved = dict.findDict("steps");
    if (!saved)
    {
        return;
    }
    runTotals::read(*saved, "flowSteps", flowSteps_);
    runTotals::read(*saved, "subCycledSteps", subCycledSteps_);
    runTotals::read(*saved, "subCycleSteps", subCycleSteps_);
    runTotals::read(*saved, "largestSubCycles", largestSubCycles_);
    runTotals::read(*saved, "cappedSteps", cappedSteps_);
    runTotals::read(*saved, "maxBeadsOutside", maxBeadsOutside_);
    runTotals::read(*saved, "beadStepsOutside", beadStepsOutside_);
}


// ************************************************************************* //
