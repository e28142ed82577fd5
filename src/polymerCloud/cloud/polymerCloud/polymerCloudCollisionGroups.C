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
    Rod-rod collisions between chains of different processors (parallel
    runs). Step (3) resolves the collisions of a step in one event loop,
    earliest first, and a collision changes the later paths of its beads:
    chains that can meet must be in the same loop. Before step (3) each
    chain's swept box (its beads' x^n and x-dagger, grown by twice the
    largest bead displacement of the step, room for the paths that
    collisions and rebounds turn) is compared
    with the other processors' chains whose boxes reach beyond their own
    sub-domain; the chains that can meet a chain of another processor,
    with every chain that can meet those (the closure), form groups, and
    each group goes whole to one processor (the lowest owner) for the
    step. Chains that meet no other processor's chain stay where they are.
    The next step's distribution gives every chain back to the processor
    holding its reference bead.

    Afterwards every chain's end positions are checked against its box: a
    chain that left it may have met a chain it was not grouped with; such
    chains are counted and reported (none in the tests).

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"
#include "PstreamBuffers.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// A chain's swept box over the step, grown by a margin
Foam::boundBox sweptBox
(
    const Foam::polymerChains& chains,
    const Foam::label c,
    const Foam::UList<Foam::vector>& positionsOld,
    const Foam::scalar margin
)
{
    using namespace Foam;

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

Foam::boolList Foam::polymerCloud::chainsMeetingOthers
(
    const List<boundBox>& boxes,
    bool& anyMeeting
) const
{
    const label myProc = Pstream::myProcNo();
    const List<boundBox>& procBounds = processorBounds_;

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


Foam::List<Foam::labelList> Foam::polymerCloud::groupProcessors
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


void Foam::polymerCloud::groupCollidingChains()
{
    if (!Pstream::parRun() || collision_->type() == "none")
    {
        return;
    }

    clockTime clock;
    const label myProc = Pstream::myProcNo();

    // Room for the paths that collisions and rebounds turn: an elastic
    // collision can give a bead up to about twice the largest speed of
    // the beads it involves
    scalar displacement = 0;
    forAll(positionsOld_, i)
    {
        displacement = max
        (
            displacement,
            magSqr(chains_.positions()[i] - positionsOld_[i])
        );
    }
    const scalar margin =
        2*Foam::sqrt(returnReduce(displacement, maxOp<scalar>()));

    List<boundBox> boxes(chains_.nChains());
    forAll(boxes, c)
    {
        boxes[c] = sweptBox(chains_, c, positionsOld_, margin);
    }
    bool anyMeeting = false;
    const boolList meets(chainsMeetingOthers(boxes, anyMeeting));
    if (!anyMeeting)
    {
        // No chains of two processors can meet this step
        collisionBoxes_ = boxes;
        migrationSeconds_ += clock.elapsedTime();
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
    moveChains(toProc, sent, true);
    groupedChains_ += sent.size();

    // The boxes of the chains now here, for the check after the step
    collisionBoxes_.setSize(chains_.nChains());
    forAll(collisionBoxes_, c)
    {
        collisionBoxes_[c] = sweptBox(chains_, c, positionsOld_, margin);
    }
    migrationSeconds_ += clock.elapsedTime();
}


void Foam::polymerCloud::checkCollisionBoxes()
{
    if (!Pstream::parRun() || collision_->type() == "none")
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
                ++chainsOutgrowingBox_;
                break;
            }
        }
    }
}


// ************************************************************************* //
