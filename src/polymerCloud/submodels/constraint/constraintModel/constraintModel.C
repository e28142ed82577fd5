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

#include "constraintModel.H"
#include "OStringStream.H"
#include <limits>
#include "makePolymerModel.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(constraintModel)

const Foam::Enum<Foam::polymer::constraintModel::failureActionType>
Foam::polymer::constraintModel::failureActionNames
({
    { failureActionType::stop, "stop" },
    { failureActionType::subStep, "subStep" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::constraintModel::constraintModel
(
    const word& type,
    const dictionary& dict
)
:
    countedSubModel<constraintCounters>(type, dict),
    failureAction_
    (
        checkedInput::enumOrDefault
        (
            coeffDict_, "failureAction", failureActionNames,
            failureActionType::subStep
        )
    ),
    maxSubSteps_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxSubSteps", 64, 2, "<largest number of sub-steps>"
        )
    ),
    failuresReported_(0),
    maxFailureReports_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxFailureReports", 20, 0, "<warnings in the log>"
        )
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::string Foam::polymer::constraintModel::roundOffHint
(
    const polymerChains& chains,
    const label chaini
) const
{
    scalar largest = 0;
    for (label i = chains.start(chaini); i < chains.end(chaini); ++i)
    {
        largest = max(largest, cmptMax(cmptMag(chains.positions()[i])));
    }
    const scalar a = chains.type(chaini).rodLength();
    const scalar roundOff = largest*std::numeric_limits<scalar>::epsilon()/a;
    if (!(lengthTolerance() < 100*roundOff))
    {
        return string();
    }

    OStringStream os;
    os  << "    The rod-length tolerance " << lengthTolerance()
        << " is within a factor 100 of the round-off of the chain's"
        << " coordinates (|x| up to " << largest << ", rod length " << a
        << ": |x| eps/a = " << roundOff << "), which no smaller step"
        << " reduces: put the mesh's origin near the chains (or use"
        << " coordinates of the rods' scale), or raise the tolerance" << nl;
    return os.str();
}


void Foam::polymer::constraintModel::reportFailure
(
    const polymerChains& chains,
    const label chaini,
    const word& stage,
    const scalar time,
    const scalar residual,
    const label iterations
) const
{
    if (failureAction_ == failureActionType::stop)
    {
        FatalErrorInFunction
            << stage << " constraint did not converge for chain "
            << chains.globalId(chaini) << " (" << chains.type(chaini).name()
            << ") at time " << time << ": residual " << residual
            << " after " << iterations << " iterations" << nl
            << roundOffHint(chains, chaini).c_str()
            << "    (failureAction stop; failureAction subStep redoes the"
            << " chain's step in sub-steps)"
            << exit(FatalError);
    }

    if (failuresReported_ < maxFailureReports_)
    {
        WarningInFunction
            << stage << " constraint did not converge for chain "
            << chains.globalId(chaini) << " (" << chains.type(chaini).name()
            << ") at time " << time << ": residual " << residual
            << " after " << iterations << " iterations"
            << (stage == "Rod-length" ? "; sub-stepping the chain" : "")
            << nl << roundOffHint(chains, chaini).c_str() << endl;

        if (failuresReported_ + 1 == maxFailureReports_)
        {
            Info<< "    (further failures are counted in the statistics"
                << " without a message)" << endl;
        }
    }
    ++failuresReported_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::constraintModel::correctChain
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time
) const
{
    scalar residual = 0;
    const label iter =
        correctChainLengths(chains, chaini, positionsOld, deltaT, residual);

    return completeChain(chains, chaini, iter, residual, time);
}


bool Foam::polymer::constraintModel::completeChain
(
    polymerChains& chains,
    const label chaini,
    const label lengthIterations,
    const scalar residual,
    const scalar time
) const
{
    if
    (
        !countSolve
        (
            chains, chaini, "Rod-length", lengthIterations, residual, time
        )
    )
    {
        return false;
    }

    // A velocity solve that stops short leaves a residual in the rods'
    // relative velocities, not in their lengths; smaller steps would not
    // help it (its convergence depends on the chain's shape), so it is
    // reported and the step goes on
    scalar velocityResidual = 0;
    const label iter =
        correctChainVelocities(chains, chaini, velocityResidual);
    countSolve(chains, chaini, "Rod-velocity", iter, velocityResidual, time);

    return true;
}


bool Foam::polymer::constraintModel::countSolve
(
    const polymerChains& chains,
    const label chaini,
    const word& stage,
    const label iterations,
    const scalar residual,
    const scalar time
) const
{
    if (iterations != 0)
    {
        counters_.add(mag(iterations), iterations > 0);
    }
    if (iterations < 0)
    {
        reportFailure(chains, chaini, stage, time, residual, -iterations);
        return false;
    }
    return true;
}


void Foam::polymer::constraintModel::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time,
    DynamicList<label>& failedChains
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        if (!correctChain(chains, c, positionsOld, deltaT, time))
        {
            failedChains.append(c);
        }
    }
}


void Foam::polymer::constraintModel::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time
) const
{
    DynamicList<label> failedChains;
    correct(chains, positionsOld, deltaT, time, failedChains);
}


void Foam::polymer::constraintModel::correctVelocities
(
    polymerChains& chains,
    const scalar time
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        scalar residual = 0;
        const label iter = correctChainVelocities(chains, c, residual);
        countSolve(chains, c, "Rod-velocity", iter, residual, time);
    }
}


// * * * * * * * * * * * * * * * * * Report  * * * * * * * * * * * * * * * * //

void Foam::polymer::constraintModel::writeReport(Ostream& os) const
{
    const constraintCounters total = totalCounters_.reduced();

    os  << "    constraint solves " << total.solves
        << ", iterations per solve "
        << scalar(total.iterations)/max(total.solves, 1)
        << " (max " << total.maxIterations << ")"
        << ", failures " << total.failures
        << ", chains sub-stepped " << total.subStepped << nl;
}


// ************************************************************************* //
