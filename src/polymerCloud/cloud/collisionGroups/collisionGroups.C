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

#include "collisionGroups.H"
#include "PstreamBuffers.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A chain's swept box over the step, grown by a margin
Foam::boundBox sweptBox
(
    const Foam::polymer::polymerChains& chains,
    const Foam::label c,
    const Foam::UList<Foam::vector>& positionsOld,
    const Foam::scalar margin
)
{
    using namespace Foam;
    using namespace Foam::polymer;

    const List<vector>& x = chains.positions();
    boundBox bb(boundBox::invertedBox);
    for (label i = chains.start(c); i < chains.end(c); ++i)
    {
        bb.add(positionsOld[i]);
        bb.add(x[i]);
    }
    const vector grow(vector::uniform(margin + SMALL*mag(bb.span())));
    return boundBox(bb.min() - grow, bb.max() + grow);
}


// Union-find root, halving the path
Foam::label findRoot(Foam::labelList& parent, Foam::label i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::polymer::collisionGroups::chainsMeetingOthers
(
    const List<boundBox>& boxes,
    bool& anyMeeting
) const
{
    const label myProc = Pstream::myProcNo();
    const List<boundBox>& procBounds = distribution_.processorBounds();

    // The chains reaching into another processor's mesh bounds, from every
    // processor
    boolList meets(boxes.size(), false);
    List<List<boundBox>> exposed(Pstream::nProcs());
    {
        DynamicList<boundBox> mine;
        forAll(boxes, c)
        {
            forAll(procBounds, proci)
            {
                if
                (
                    proci != myProc
                 && periodic_.overlapsImage(boxes[c], procBounds[proci])
                )
                {
                    meets[c] = true;
                    mine.append(boxes[c]);
                    break;
                }
            }
        }
        exposed[myProc] = mine;
    }
    Pstream::gatherList(exposed);
    Pstream::scatterList(exposed);

    // Chains that can meet an exposed chain of another processor: of any
    // pair of chains of two processors that can meet, one is exposed, so
    // without such chains anywhere no chains of two processors meet
    anyMeeting = false;
    forAll(boxes, c)
    {
        forAll(exposed, proci)
        {
            if (proci == myProc)
            {
                continue;
            }
            for (const boundBox& other : exposed[proci])
            {
                if (periodic_.overlapsImage(boxes[c], other))
                {
                    meets[c] = true;
                    anyMeeting = true;
                    break;
                }
            }
        }
    }
    reduce(anyMeeting, orOp<bool>());
    if (!anyMeeting)
    {
        return meets;
    }

    // The closure: chains that can meet those
    DynamicList<label> front;
    forAll(meets, c)
    {
        if (meets[c])
        {
            front.append(c);
        }
    }
    while (front.size())
    {
        const label c = front.remove();
        forAll(boxes, d)
        {
            if (!meets[d] && periodic_.overlapsImage(boxes[c], boxes[d]))
            {
                meets[d] = true;
                front.append(d);
            }
        }
    }

    return meets;
}


Foam::List<Foam::labelList> Foam::polymer::collisionGroups::groupProcessors
(
    const List<List<boundBox>>& groupBoxes
) const
{
    // Every processor's grouped chains in one list
    const label nProcs = Pstream::nProcs();
    labelList offset(nProcs + 1, Zero);
    forAll(groupBoxes, proci)
    {
        offset[proci + 1] = offset[proci] + groupBoxes[proci].size();
    }
    const label n = offset[nProcs];

    // Connected by overlapping boxes (sweep along x over every box's
    // images, so that boxes meet across cyclic patches)
    const List<vector>& shifts = periodic_.imageShifts();
    List<boundBox> entries(n*shifts.size());
    labelList entryChain(entries.size());
    forAll(groupBoxes, proci)
    {
        forAll(groupBoxes[proci], k)
        {
            const label i = offset[proci] + k;
            forAll(shifts, s)
            {
                const boundBox& bb = groupBoxes[proci][k];
                entries[i*shifts.size() + s] =
                    boundBox(bb.min() + shifts[s], bb.max() + shifts[s]);
                entryChain[i*shifts.size() + s] = i;
            }
        }
    }
    labelList order(entries.size());
    {
        scalarList minX(entries.size());
        forAll(entries, e)
        {
            minX[e] = entries[e].min().x();
        }
        sortedOrder(minX, order);
    }

    labelList parent(identity(n));
    forAll(order, a)
    {
        const boundBox& bbA = entries[order[a]];
        for (label b = a + 1; b < order.size(); ++b)
        {
            const boundBox& bbB = entries[order[b]];
            if (bbB.min().x() > bbA.max().x())
            {
                break;
            }
            if (bbA.overlaps(bbB))
            {
                parent[findRoot(parent, entryChain[order[a]])] =
                    findRoot(parent, entryChain[order[b]]);
            }
        }
    }

    // Each group to the lowest processor owning one of its chains
    labelList groupProc(n, labelMax);
    forAll(groupBoxes, proci)
    {
        for (label i = offset[proci]; i < offset[proci + 1]; ++i)
        {
            label& proc = groupProc[findRoot(parent, i)];
            proc = min(proc, proci);
        }
    }

    List<labelList> destination(nProcs);
    forAll(groupBoxes, proci)
    {
        destination[proci].setSize(groupBoxes[proci].size());
        forAll(destination[proci], k)
        {
            destination[proci][k] =
                groupProc[findRoot(parent, offset[proci] + k)];
        }
    }
    return destination;
}


void Foam::polymer::collisionGroups::group
(
    DynamicList<vector>& positionsOld,
    DynamicList<vector>& velocitiesOld
)
{
    if (!active_)
    {
        return;
    }

    clockTime clock;
    const label myProc = Pstream::myProcNo();

    // Room for the paths that collisions and rebounds turn: an elastic
    // collision can give a bead up to about twice the largest speed of
    // the beads it involves
    scalar displacement = 0;
    forAll(positionsOld, i)
    {
        displacement = max
        (
            displacement,
            magSqr(chains_.positions()[i] - positionsOld[i])
        );
    }
    const scalar margin =
        2*Foam::sqrt(returnReduce(displacement, maxOp<scalar>()));

    List<boundBox> boxes(chains_.nChains());
    forAll(boxes, c)
    {
        boxes[c] = sweptBox(chains_, c, positionsOld, margin);
    }
    bool anyMeeting = false;
    const boolList meets(chainsMeetingOthers(boxes, anyMeeting));
    if (!anyMeeting)
    {
        // No chains of two processors can meet this step
        collisionBoxes_ = boxes;
        distribution_.addSeconds(clock.elapsedTime());
        return;
    }

    // The groups, formed on the master
    DynamicList<label> grouped;
    List<List<boundBox>> groupBoxes(Pstream::nProcs());
    {
        DynamicList<boundBox> mine;
        forAll(meets, c)
        {
            if (meets[c])
            {
                grouped.append(c);
                mine.append(boxes[c]);
            }
        }
        groupBoxes[myProc] = mine;
    }
    Pstream::gatherList(groupBoxes);
    List<labelList> destination(Pstream::nProcs());
    if (Pstream::master())
    {
        destination = groupProcessors(groupBoxes);
    }
    // (the whole list: scatterList sends a processor only the others')
    Pstream::scatter(destination);

    // Each grouped chain, with its step's start, to its group's processor
    List<DynamicList<label>> toProc(Pstream::nProcs());
    DynamicList<label> sent;
    forAll(grouped, k)
    {
        const label proci = destination[myProc][k];
        if (proci != myProc)
        {
            toProc[proci].append(grouped[k]);
            sent.append(grouped[k]);
        }
    }
    distribution_.move
    (
        toProc,
        sent,
        List<DynamicList<vector>*>({&positionsOld, &velocitiesOld})
    );
    nGrouped_ += sent.size();

    // The boxes of the chains now here, for the check after the step
    collisionBoxes_.setSize(chains_.nChains());
    forAll(collisionBoxes_, c)
    {
        collisionBoxes_[c] = sweptBox(chains_, c, positionsOld, margin);
    }
    distribution_.addSeconds(clock.elapsedTime());
}


void Foam::polymer::collisionGroups::checkBoxes()
{
    if (!active_)
    {
        return;
    }

    const List<vector>& x = chains_.positions();
    forAll(collisionBoxes_, c)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            if (!collisionBoxes_[c].contains(x[i]))
            {
                ++nOutgrowing_;
                break;
            }
        }
    }
}


void Foam::polymer::collisionGroups::writeReport(Ostream& os) const
{
    if (!active_)
    {
        return;
    }

    os  << "    chains grouped with other processors' for their"
        << " collisions " << returnReduce(nGrouped_, sumOp<label>())
        << ", chains that left their swept box "
        << returnReduce(nOutgrowing_, sumOp<label>()) << nl;
}


// ************************************************************************* //
