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
    The polymerCloud's reports: the summary of what it models, and the
    cost, counts and failures of the run at its end (each sub-model writes
    its own lines), with the processors' loads in parallel runs.

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"
#include "packedReduction.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::polymerCloud::writeProcessorLoads(Ostream& os) const
{
    // A processor's exchange time includes its waits for the others: the
    // busiest one waits least. Every entry starts at zero: the gather
    // fills only the master's list (and, beyond two processors, parts of
    // the intermediate ones'), and the others' must not be read as
    // uninitialised numbers
    List<FixedList<scalar, 4>> loads
    (
        Pstream::nProcs(), FixedList<scalar, 4>(Zero)
    );
    loads[Pstream::myProcNo()] = FixedList<scalar, 4>
    ({
        scalar(chains_.nChains()),
        scalar(chains_.nBeads()),
        evolveSeconds_,
        distribution_->seconds() + flow_->exchangeSeconds()
      + coupling_->exchangeSeconds()
    });
    Pstream::gatherList(loads);
    if (!Pstream::master())
    {
        return;
    }

    os  << "    processors' loads (chains, beads, s of cloud evolution,"
        << " of which exchanging and waiting):" << nl;
    forAll(loads, proci)
    {
        os  << "        processor" << proci << ": "
            << label(loads[proci][0]) << " chains, "
            << label(loads[proci][1]) << " beads, " << loads[proci][2]
            << " s (" << loads[proci][3] << " s)" << nl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::polymerCloud::writeSummary(Ostream& os) const
{
    // Chains per type, over all processors
    labelList nChainsOfType(types_.size(), Zero);
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        ++nChainsOfType[chains_.typeIndex(c)];
    }
    Pstream::listCombineGather(nChainsOfType, plusEqOp<label>());

    os  << name() << ':';
    label nListed = 0;
    forAll(types_, typei)
    {
        if (nChainsOfType[typei])
        {
            os  << (nListed++ ? " +" : "") << ' ' << nChainsOfType[typei]
                << (types_[typei].ring() ? " ring" : " chain")
                << (nChainsOfType[typei] > 1 ? "s" : "") << " x "
                << types_[typei].nBeads() << " beads";
        }
    }
    if (!nListed)
    {
        os  << " no chains";
    }

    os  << "; integration " << integration_->type()
        << "; constraint " << constraint_->type()
        << "; collision " << collision_->type()
        << "; wall " << wall_->type()
        << "; flow " << flow_->type();
    if (forces_.size())
    {
        os  << "; forces";
        for (const forceModel& model : forces_)
        {
            os  << ' ' << model.type();
        }
    }
    os  << (solution_.active() ? "" : " (inactive)") << nl;

    forAll(types_, typei)
    {
        os  << "    ";
        types_[typei].writeSummary(os);
        os  << nl;
    }
}


void Foam::polymer::polymerCloud::writeReport(Ostream& os) const
{
    // The cloud's own figures over all processors, in one reduction
    scalar seconds = evolveSeconds_;
    scalar beadSteps = beadSteps_;
    scalar laterSeconds = evolveSeconds_ - firstStepSeconds_;
    scalar laterBeadSteps = beadSteps_ - firstStepBeadSteps_;
    label nInjected = nInjected_;
    label nWrapped = distribution_->nWrapped();
    label nMoved = distribution_->nMoved();
    scalar movingSeconds = distribution_->seconds();
    scalar sampleSeconds =
        flow_->exchangeSeconds() + coupling_->exchangeSeconds();
    label maxOutside = stepper_->maxBeadsOutside();
    scalar beadStepsOutside = stepper_->beadStepsOutside();
    vector momentumLost = coupling_->momentumLost();
    scalar beadStepsLost = coupling_->beadStepsLost();
    {
        packedReduction all;
        all.max(seconds);
        all.sum(beadSteps);
        all.max(laterSeconds);
        all.sum(laterBeadSteps);
        all.sum(nInjected);
        all.sum(nWrapped);
        all.sum(nMoved);
        all.max(movingSeconds);
        all.max(sampleSeconds);
        all.max(maxOutside);
        all.sum(beadStepsOutside);
        all.sum(momentumLost);
        all.sum(beadStepsLost);
        all.reduce();
    }

    os  << name() << ": " << beadSteps << " bead-steps in " << seconds
        << " s of cloud evolution";
    if (seconds > 0)
    {
        os  << ", " << beadSteps/seconds << " bead-steps/s";
    }
    os  << nl;
    if (laterBeadSteps > 0 && laterSeconds > 0)
    {
        // A short run's figure is mostly its start: the steps after the
        // first give the rate a longer run tends to
        os  << "    after the first step (which also does the run's start-up"
            << " work, such as a field's interpolation weights and every"
            << " bead's first search): "
            << laterBeadSteps << " bead-steps in " << laterSeconds << " s, "
            << laterBeadSteps/laterSeconds << " bead-steps/s" << nl;
    }
    pathTimes_.writeReport(os);
    for (const polymerSubModel& model : models_)
    {
        model.writeReport(os);
    }
    stepper_->writeSubCycleReport(os);
    if (contactProjection_)
    {
        contactProjection_->writeReport(os);
    }
    os  << "    chains injected " << nInjected
        << ", chains carried across cyclic patches " << nWrapped
        << ", chains moved between processors " << nMoved << nl;
    if (Pstream::parRun())
    {
        collisionGroups_->writeReport(os);
        os  << "    parallel exchanges (wall clock, slowest processor):"
            << " moving chains " << movingSeconds
            << " s, beads' flow and momentum " << sampleSeconds << " s" << nl;
        writeProcessorLoads(os);
    }
    os  << "    beads " << nParcels() << ", outside the mesh "
        << nBeadsOutside() << " (checked every step: at most "
        << maxOutside << " in a step, " << beadStepsOutside
        << " bead-steps in all)";
    if (coupling_->twoWay())
    {
        os  << "; momentum they could not give the solvent " << momentumLost
            << " in " << beadStepsLost << " bead-steps";
    }
    os  << nl;
}


// ************************************************************************* //
