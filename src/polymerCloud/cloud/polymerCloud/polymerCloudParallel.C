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
    The polymerCloud's checks of a parallel run's models and its report of
    the processors' loads; the chains' ownership and moves are
    chainDistribution's, the collisions across processors
    collisionGroups'.

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymerCloud::checkParallelSupport(const dictionary& subModels)
{
    if (!Pstream::parRun())
    {
        return;
    }

    if (wall_->active() && !wall_->runsInParallel())
    {
        FatalIOErrorInFunction(subModels)
            << "wall " << wall_->type() << " in " << subModels.name()
            << " runs serially in this version: its distance field is not"
            << " exchanged between processors" << nl
            << "    expected: a serial run, or in parallel wall meshFaces"
            << " (or none)"
            << exit(FatalIOError);
    }

    // A bead of a chain is at most a contour length from the chain's
    // reference bead, which is in its owner's mesh at the step's start,
    // and moves less than a rod length in a step: the walls of other
    // processors within that reach; twice that with collisions, whose
    // groups bring a neighbour's chains into a processor's loop
    if (wall_->active())
    {
        scalar reach = 0;
        for (const chainType& type : types_)
        {
            reach = max(reach, type.nBeads()*type.rodLength());
        }
        if (collision_->type() != "none")
        {
            reach *= 2;
        }
        wall_->setReach(reach);
        Info<< name() << ": wall " << wall_->type() << " sees "
            << returnReduce(wall_->faces().nHaloFaces(), sumOp<label>())
            << " boundary faces of other processors (within "
            << reach << " of each processor's mesh)" << endl;
    }
}


void Foam::polymerCloud::writeProcessorLoads(Ostream& os) const
{
    // A processor's exchange time includes its waits for the others: the
    // busiest one waits least
    List<FixedList<scalar, 4>> loads(Pstream::nProcs());
    loads[Pstream::myProcNo()] = FixedList<scalar, 4>
    ({
        scalar(chains_.nChains()),
        scalar(chains_.nBeads()),
        evolveSeconds_,
        distribution_->seconds() + flow_->exchangeSeconds()
    });
    Pstream::gatherList(loads);

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


// ************************************************************************* //
