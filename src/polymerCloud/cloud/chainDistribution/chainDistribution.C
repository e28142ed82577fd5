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

#include "chainDistribution.H"
#include "packedReduction.H"
#include "allReduce.H"
#include "PstreamBuffers.H"
#include "pointField.H"
#include "clockTime.H"
#include "pointOwners.H"
#include "cellLocator.H"
#include "beadSampler.H"
#include "bitSet.H"
#include "UIListStream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Write chains of a polymerChains to a stream: count, then per chain its
// type, global id, positions and velocities (separated, for the text
// tokens of a binary OListStream; a Pstream drops the spaces)
void sendChains
(
    Foam::Ostream& os,
    const Foam::polymer::polymerChains& chains,
    const Foam::labelUList& chainIndices
)
{
    using namespace Foam;
    using namespace Foam::polymer;

    os  << chainIndices.size();
    for (const label c : chainIndices)
    {
        const label n = chains.size(c);
        const label first = chains.start(c);
        os  << token::SPACE << chains.typeIndex(c)
            << token::SPACE << chains.globalId(c)
            << SubList<vector>(chains.positions(), n, first)
            << SubList<vector>(chains.velocities(), n, first);
    }
}


// Read chains written by sendChains and append them
void receiveChains(Foam::Istream& is, Foam::polymer::polymerChains& chains)
{
    using namespace Foam;
    using namespace Foam::polymer;

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
    const Foam::polymer::polymerChains& chains,
    const Foam::labelUList& chainIndices,
    const Foam::UList<Foam::vector>& field
)
{
    using namespace Foam;
    using namespace Foam::polymer;

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
    const Foam::polymer::polymerChains& chains,
    const Foam::labelUList& chainIndices,
    Foam::DynamicList<Foam::vector>& field
)
{
    using namespace Foam;
    using namespace Foam::polymer;

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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::chainDistribution::chainDistribution
(
    const fvMesh& mesh,
    const periodicImages& periodic,
    polymerChains& chains,
    const bool sorted
)
:
    mesh_(mesh),
    periodic_(periodic),
    chains_(chains),
    sorted_(sorted),
    neighbours_(mesh),
    referenceCells_(-1),
    keptTets_(nullptr),
    nMoved_(0),
    nWrapped_(0),
    seconds_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void
Foam::polymer::chainDistribution::locateReferenceBeads(const bool unknownOnly)
{
    if (!sorted_ && !Pstream::parRun())
    {
        return;
    }

    const cellLocator& locator = cellLocator::New(mesh_);
    const boundBox& bounds = neighbours_.localBounds();
    const List<vector>& x = chains_.positions();
    labelList& cell = referenceCells_.update(chains_);
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const label i = chains_.referenceBead(c);
        if (unknownOnly && cell[i] >= 0)
        {
            continue;
        }
        const point p = periodic_.wrap(x[i]);
        if (keptTets_ && keptTets_->keptCell(chains_, i, p, cell[i]))
        {
            // The cell the search from cell[i] finds (a point on a face
            // between two cells, to SMALL, could be given the other)
            continue;
        }
        cell[i] = bounds.contains(p) ? locator.findCell(p, cell[i]) : -1;
    }
}


void Foam::polymer::chainDistribution::distribute()
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
        const label i = chains_.referenceBead(c);
        if (cell[i] < 0)
        {
            leaving.append(c);
            leavingPoints.append(periodic_.wrap(x[i]));
        }
    }
    if (allReduceAnd(leaving.empty()))
    {
        seconds_ += clock.elapsedTime();
        return;
    }
    const labelList owner(neighbours_.pointOwners(leavingPoints));

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

    // (the owners are this processor's neighbours)
    moveAmongNeighbours
    (
        toProc, sent, UList<DynamicList<vector>*>(), neighbours_
    );
    nMoved_ += sent.size();
    seconds_ += clock.elapsedTime();
}


void Foam::polymer::chainDistribution::move
(
    const List<DynamicList<label>>& toProc,
    const labelUList& sent,
    const UList<DynamicList<vector>*>& beadFields,
    const processorNeighbours& neighbourExchange
)
{
    for (const DynamicList<vector>* field : beadFields)
    {
        if (field->size() != chains_.nBeads())
        {
            FatalErrorInFunction
                << "A field carried with the chains has " << field->size()
                << " beads, the chains " << chains_.nBeads()
                << exit(FatalError);
        }
    }

    // Among the neighbours alone, unless a destination is not one
    const labelList& neighbours = neighbourExchange.neighbours();
    bool general = false;
    forAll(toProc, proci)
    {
        general = general || (toProc[proci].size() && !neighbours.found(proci));
    }
    if (allReduceOr(general))
    {
        moveAnywhere(toProc, sent, beadFields);
    }
    else
    {
        moveAmongNeighbours(toProc, sent, beadFields, neighbourExchange);
    }
}


void Foam::polymer::chainDistribution::moveAmongNeighbours
(
    const List<DynamicList<label>>& toProc,
    const labelUList& sent,
    const UList<DynamicList<vector>*>& beadFields,
    const processorNeighbours& neighbourExchange
)
{
    const labelList& neighbours = neighbourExchange.neighbours();
    PtrList<OListStream> send(neighbourExchange.streams());
    label nSent = 0;
    forAll(neighbours, k)
    {
        const labelList& chainIndices = toProc[neighbours[k]];
        nSent += chainIndices.size();
        if (chainIndices.size())
        {
            sendChains(send[k], chains_, chainIndices);
            for (const DynamicList<vector>* field : beadFields)
            {
                send[k] << chainBeads(chains_, chainIndices, *field);
            }
        }
    }
    if (nSent != sent.size())
    {
        FatalErrorInFunction
            << sent.size() - nSent << " chains are for processors that are"
            << " not this one's neighbours " << neighbours
            << abort(FatalError);
    }
    List<List<char>> recv;
    neighbourExchange.exchange(send, recv);

    for (DynamicList<vector>* field : beadFields)
    {
        removeBeads(chains_, sent, *field);
    }
    chains_.remove(sent);

    forAll(recv, k)
    {
        if (recv[k].size())
        {
            UIListStream is(recv[k], IOstream::BINARY);
            receiveChains(is, chains_);
            for (DynamicList<vector>* field : beadFields)
            {
                const List<vector> values(is);
                field->append(values);
            }
        }
    }
}


void Foam::polymer::chainDistribution::moveAnywhere
(
    const List<DynamicList<label>>& toProc,
    const labelUList& sent,
    const UList<DynamicList<vector>*>& beadFields
)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(toProc, proci)
    {
        if (toProc[proci].size())
        {
            UOPstream os(proci, buffers);
            sendChains(os, chains_, toProc[proci]);
            for (const DynamicList<vector>* field : beadFields)
            {
                os  << chainBeads(chains_, toProc[proci], *field);
            }
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    for (DynamicList<vector>* field : beadFields)
    {
        removeBeads(chains_, sent, *field);
    }
    chains_.remove(sent);

    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, buffers);
            receiveChains(is, chains_);
            for (DynamicList<vector>* field : beadFields)
            {
                const List<vector> values(is);
                field->append(values);
            }
        }
    }
}


void Foam::polymer::chainDistribution::keepOwnReplicated
(
    const label firstChain
)
{
    const List<vector>& x = chains_.positions();
    pointField references(chains_.nChains() - firstChain);
    forAll(references, k)
    {
        const label i = chains_.referenceBead(firstChain + k);
        references[k] = periodic_.wrap(x[i]);
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


void Foam::polymer::chainDistribution::keepOwn
(
    const label firstChain,
    const label nCreated
)
{
    if (!Pstream::parRun())
    {
        return;
    }

    // The chains whose reference bead lies in this processor's bounds:
    // only this processor and its neighbours can hold it
    const List<vector>& x = chains_.positions();
    const boundBox& bounds = neighbours_.localBounds();
    DynamicList<label> candidates;
    DynamicList<point> references;
    for (label c = firstChain; c < chains_.nChains(); ++c)
    {
        const point p = periodic_.wrap(x[chains_.referenceBead(c)]);
        if (bounds.contains(p))
        {
            candidates.append(c);
            references.append(p);
        }
    }
    const labelList owner(neighbours_.pointOwners(references));

    // Every chain kept once, unless one is outside every mesh (the master
    // keeps those: all processors must then look at all chains, so all
    // must hold all)
    label nKept = 0;
    forAll(owner, k)
    {
        nKept += (owner[k] == Pstream::myProcNo());
    }
    scalar nKeptAll = nKept;
    reduce(nKeptAll, sumOp<scalar>());
    const label nNew = chains_.nChains() - firstChain;
    if (label(nKeptAll) != (nCreated < 0 ? nNew : nCreated))
    {
        if (nCreated >= 0 && returnReduce(nNew != nCreated, orOp<bool>()))
        {
            FatalErrorInFunction
                << nCreated << " chains were created and " << nKeptAll
                << " are kept: a chain created only where it could be owned"
                << " has no owner among those processors"
                << exit(FatalError);
        }
        keepOwnReplicated(firstChain);
        return;
    }

    bitSet mine(chains_.nChains());
    forAll(owner, k)
    {
        if (owner[k] == Pstream::myProcNo())
        {
            mine.set(candidates[k]);
        }
    }
    DynamicList<label> others;
    for (label c = firstChain; c < chains_.nChains(); ++c)
    {
        if (!mine.test(c))
        {
            others.append(c);
        }
    }
    chains_.remove(others);
}


Foam::polymer::polymerChains Foam::polymer::chainDistribution::gather() const
{
    polymerChains all(chains_.types());

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


void Foam::polymer::chainDistribution::sort()
{
    if (!sorted_)
    {
        return;
    }

    // Chains that arrived from other processors are not located yet
    locateReferenceBeads(true);
    const labelList& cell = referenceCells_.values();

    // By cell (those outside this processor's mesh last), then by global
    // id, so that the order does not depend on the chains' history
    const label nCells = mesh_.nCells();
    auto key = [&](const label c)
    {
        const label celli = cell[chains_.referenceBead(c)];
        return std::make_pair
        (
            celli < 0 ? nCells : celli,
            chains_.globalId(c)
        );
    };
    auto before = [&](const label a, const label b)
    {
        return key(a) < key(b);
    };

    labelList order(identity(chains_.nChains()));
    if (!std::is_sorted(order.cbegin(), order.cend(), before))
    {
        std::sort(order.begin(), order.end(), before);
        chains_.reorder(order);
    }
}


void Foam::polymer::chainDistribution::wrap()
{
    if (!periodic_.active())
    {
        return;
    }

    List<vector>& x = chains_.positions();
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        const label first = chains_.start(c);
        const vector shift = periodic_.shift(x[chains_.referenceBead(c)]);
        if (shift == vector::zero)
        {
            continue;
        }
        for (label i = first; i < chains_.end(c); ++i)
        {
            x[i] += shift;
        }
        ++nWrapped_;
    }
}


void Foam::polymer::chainDistribution::update()
{
    wrap();

    // What a time step writes is in order: a restart sorts its chains
    const Time& runTime = mesh_.time();
    const bool sortNow =
        runTime.timeIndex() % sortInterval == 0 || runTime.writeTime();

    // The reference beads' cells give the chains' owners in a parallel
    // run; in a serial one they serve the order alone
    if (Pstream::parRun() || sortNow)
    {
        locateReferenceBeads();
    }
    distribute();
    if (sortNow)
    {
        sort();
    }
}


void Foam::polymer::chainDistribution::writeRunTotals(dictionary& dict) const
{
    label moved = nMoved_;
    label wrapped = nWrapped_;
    packedReduction all;
    all.sum(moved);
    all.sum(wrapped);
    all.reduce();

    dictionary& totals = dict.subDictOrAdd("chains");
    runTotals::add(totals, "moved", moved);
    runTotals::add(totals, "wrapped", wrapped);
}


void Foam::polymer::chainDistribution::readRunTotals(const dictionary& dict)
{
    const dictionary* saved = dict.findDict("chains");
    if (saved)
    {
        runTotals::read(*saved, "moved", nMoved_);
        runTotals::read(*saved, "wrapped", nWrapped_);
    }
}


// ************************************************************************* //
