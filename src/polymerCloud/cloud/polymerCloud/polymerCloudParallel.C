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
    The polymerCloud's parallel work: chains owned whole by the processor
    holding their reference (middle) bead, moved between processors as
    they go, and gathered for output.

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"
#include "PstreamBuffers.H"
#include "pointField.H"
#include "clockTime.H"
#include "pointOwners.H"
#include "cellLocator.H"
#include "bitSet.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Write chains of a polymerChains to a stream: count, then per chain its
// type, global id, positions and velocities
void sendChains
(
    Foam::Ostream& os,
    const Foam::polymerChains& chains,
    const Foam::labelUList& chainIndices
)
{
    using namespace Foam;

    os  << chainIndices.size();
    for (const label c : chainIndices)
    {
        const label n = chains.size(c);
        const label first = chains.start(c);
        os  << chains.typeIndex(c) << chains.globalId(c)
            << SubList<vector>(chains.positions(), n, first)
            << SubList<vector>(chains.velocities(), n, first);
    }
}


// Read chains written by sendChains and append them
void receiveChains(Foam::Istream& is, Foam::polymerChains& chains)
{
    using namespace Foam;

    label nChains;
    is  >> nChains;
    for (label k = 0; k < nChains; ++k)
    {
        label typeIndex, globalId;
        List<vector> positions, velocities;
        is  >> typeIndex >> globalId >> positions >> velocities;
        chains.append(typeIndex, globalId, positions, velocities);
    }
}


// The beads of the listed chains, in order
Foam::List<Foam::vector> chainBeads
(
    const Foam::polymerChains& chains,
    const Foam::labelUList& chainIndices,
    const Foam::UList<Foam::vector>& field
)
{
    using namespace Foam;

    DynamicList<vector> beads;
    for (const label c : chainIndices)
    {
        beads.append(SubList<vector>(field, chains.size(c), chains.start(c)));
    }
    return List<vector>(beads);
}


// Remove the beads of the listed chains from a field, as
// polymerChains::remove does from the chains
void removeBeads
(
    const Foam::polymerChains& chains,
    const Foam::labelUList& chainIndices,
    Foam::DynamicList<Foam::vector>& field
)
{
    using namespace Foam;

    const bitSet removed(chains.nChains(), chainIndices);
    label nKept = 0;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        if (!removed.test(c))
        {
            for (label i = chains.start(c); i < chains.end(c); ++i)
            {
                field[nKept++] = field[i];
            }
        }
    }
    field.resize(nKept);
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymerCloud::checkParallelSupport(const dictionary& subModels)
{
    if (!Pstream::parRun())
    {
        return;
    }

    processorBounds_.setSize(Pstream::nProcs());
    processorBounds_[Pstream::myProcNo()] = mesh_.bounds();
    Pstream::gatherList(processorBounds_);
    Pstream::scatterList(processorBounds_);

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


void Foam::polymerCloud::distributeChains()
{
    if (!Pstream::parRun())
    {
        return;
    }

    clockTime clock;
    const List<vector>& x = chains_.positions();
    const label myProc = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();

    // Chains whose reference bead this processor's mesh does not hold go
    // to the processor that holds it; one that no processor holds (outside
    // the mesh) stays where it is
    const labelList& cell = referenceCells_.values();
    DynamicList<label> leaving;
    DynamicList<point> leavingPoints;
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const label i = referenceBead(c);
        if (cell[i] < 0)
        {
            leaving.append(c);
            leavingPoints.append(periodic_.wrap(x[i]));
        }
    }
    if (returnReduce(leaving.empty(), andOp<bool>()))
    {
        migrationSeconds_ += clock.elapsedTime();
        return;
    }
    const labelList owner(pointOwners(mesh_, leavingPoints));

    // Send each leaving chain to its new owner
    List<DynamicList<label>> toProc(nProcs);
    DynamicList<label> sent;
    forAll(leaving, k)
    {
        const label proci = owner[k];
        if (proci >= 0 && proci != myProc)
        {
            toProc[proci].append(leaving[k]);
            sent.append(leaving[k]);
        }
    }

    moveChains(toProc, sent, false);
    migrations_ += sent.size();
    migrationSeconds_ += clock.elapsedTime();
}


void Foam::polymerCloud::moveChains
(
    const List<DynamicList<label>>& toProc,
    const labelUList& sent,
    const bool withStart
)
{
    if (withStart && positionsOld_.size() != chains_.nBeads())
    {
        FatalErrorInFunction
            << "The step's start has " << positionsOld_.size()
            << " beads, the chains " << chains_.nBeads()
            << exit(FatalError);
    }

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(toProc, proci)
    {
        if (toProc[proci].size())
        {
            UOPstream os(proci, buffers);
            sendChains(os, chains_, toProc[proci]);
            if (withStart)
            {
                os  << chainBeads(chains_, toProc[proci], positionsOld_)
                    << chainBeads(chains_, toProc[proci], velocitiesOld_);
            }
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    if (withStart)
    {
        removeBeads(chains_, sent, positionsOld_);
        removeBeads(chains_, sent, velocitiesOld_);
    }
    chains_.remove(sent);

    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, buffers);
            receiveChains(is, chains_);
            if (withStart)
            {
                const List<vector> x0(is);
                const List<vector> v0(is);
                positionsOld_.append(x0);
                velocitiesOld_.append(v0);
            }
        }
    }
}


void Foam::polymerCloud::keepOwnChains(const label firstChain)
{
    if (!Pstream::parRun())
    {
        return;
    }

    const List<vector>& x = chains_.positions();
    pointField references(chains_.nChains() - firstChain);
    forAll(references, k)
    {
        references[k] = periodic_.wrap(x[referenceBead(firstChain + k)]);
    }
    const labelList owner(replicatedPointOwners(mesh_, references));

    DynamicList<label> others;
    forAll(owner, k)
    {
        const label proci = (owner[k] < 0) ? Pstream::masterNo() : owner[k];
        if (proci != Pstream::myProcNo())
        {
            others.append(firstChain + k);
        }
    }
    chains_.remove(others);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::polymerChains Foam::polymerCloud::gatherChains() const
{
    polymerChains all(types_);

    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    if (!Pstream::master())
    {
        UOPstream os(Pstream::masterNo(), buffers);
        sendChains(os, chains_, identity(chains_.nChains()));
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    if (Pstream::master())
    {
        for (label c = 0; c < chains_.nChains(); ++c)
        {
            const label n = chains_.size(c);
            const label first = chains_.start(c);
            all.append
            (
                chains_.typeIndex(c),
                chains_.globalId(c),
                SubList<vector>(chains_.positions(), n, first),
                SubList<vector>(chains_.velocities(), n, first)
            );
        }
        forAll(recvSizes, proci)
        {
            if (recvSizes[proci])
            {
                UIPstream is(proci, buffers);
                receiveChains(is, all);
            }
        }
    }

    return all;
}


// ************************************************************************* //
