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

#include "elasticRods.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::collisionModels::elasticRods::holdChain
(
    const polymerChains& chains,
    const label chaini,
    const scalar t,
    const scalar dt
)
{
    if (heldChains_.found(chaini))
    {
        return;
    }
    heldChains_.append(chaini);

    const label first = chains.start(chaini);
    const label end = chains.end(chaini);
    for (label i = first; i < end; ++i)
    {
        position_[i] = positionAt(i, t);
        beadTime_[i] = t;
        setVelocity(i, Zero);
    }

    // The chain's rods have new (null) paths: the moving chains' events
    // with them are predicted again; a held bead meets no wall
    repredict(identity(end - first, first), t, dt);
}


void Foam::polymer::collisionModels::elasticRods::holdStalled
(
    const polymerChains& chains,
    const event& e,
    const scalar dt
)
{
    if (e.pair < 0)
    {
        holdChain(chains, chains.chainOf(-1 - e.pair), e.time, dt);
        return;
    }
    if (e.edge)
    {
        holdChain(chains, chains.chainOf(e.beads[0]), e.time, dt);
        return;
    }
    holdChain(chains, chains.chainOf(e.beads[0]), e.time, dt);
    holdChain(chains, chains.chainOf(e.beads[2]), e.time, dt);
}


void Foam::polymer::collisionModels::elasticRods::reportStall
(
    const polymerChains& chains,
    const event& e,
    const scalar time,
    const label nEvents
) const
{
    const label pairi = e.pair;
    const bool runaway = nEvents >= maxEvents_;
    const char* held =
        runaway
      ? ": every bead stays at the last uncrossed state of the step"
      : ": held at their last uncrossed state for the rest of the step,"
        " the other chains go on";

    if (pairi < 0)
    {
        WarningInFunction
            << "Event loop " << (runaway ? "stopped" : "stalled")
            << " at time " << time << " after " << nEvents
            << " events, at a bead-wall impact of bead " << -1 - pairi
            << " of chain " << chains.globalId(chains.chainOf(-1 - pairi))
            << (runaway ? " (maxEvents)" : " (tau -> 0 stall)") << held
            << endl;
        return;
    }

    if (e.edge)
    {
        WarningInFunction
            << "Event loop " << (runaway ? "stopped" : "stalled")
            << " at time " << time << " after " << nEvents
            << " events, at a rod-edge contact of beads " << e.beads[0]
            << ' ' << e.beads[1] << " of chain "
            << chains.globalId(chains.chainOf(e.beads[0]))
            << (
                   runaway ? " (maxEvents)"
                 : edgeContacts_.contactStreak(pairi) >= stallEvents_
                 ? " (resolved stallEvents times in a row at its contact)"
                 : " (tau -> 0 stall)"
               )
            << held << endl;
        return;
    }

    WarningInFunction
        << "Rod-rod event loop " << (runaway ? "stopped" : "stalled")
        << " at time " << time << " after "
        << nEvents << " events, at one between chains "
        << chains.globalId(rods_.chain(grid_.pairs()[pairi].first()))
        << " and "
        << chains.globalId(rods_.chain(grid_.pairs()[pairi].second()))
        << (
               runaway ? " (maxEvents)"
             : contacts_.contactStreak(pairi) >= stallEvents_
             ? " (the pair resolved stallEvents times in a row at its"
               " contact: a grazing contact its impulses do not separate)"
             : " (tau -> 0 stall)"
           )
        << held << endl;
}


// ************************************************************************* //
