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
#include "allReduce.H"
#include "bitSet.H"
#include "UIListStream.H"
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

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::List<Foam::boundBox>>
Foam::polymer::collisionGroups::exchangeBoxes
(
    const List<boundBox>& boxes,
    const labelUList& chainIndices
) const
{
    PtrList<OListStream> send(neighbours_.streams());
    if (chainIndices.size())
    {
        const List<boundBox> mine(UIndirectList<boundBox>(boxes, chainIndices));
        for (OListStream& os : send)
        {
            os  << mine;
        }
    }
    List<List<char>> recv;
    neighbours_.exchange(send, recv);

    List<List<boundBox>> theirs(recv.size());
    forAll(recv, k)
    {
        if (recv[k].size())
        {
            UIListStream is(recv[k], IOstream::BINARY);
            is  >> theirs[k];
        }
    }
    return theirs;
}


Foam::labelList Foam::polymer::collisionGroups::chainsMeetingOthers
(
    const List<boundBox>& boxes,
    bool& anyMeeting
) const
{
    const List<boundBox>& procBounds = distribution_.processorBounds();
    const labelList& neighbours = neighbours_.neighbours();

    // The chains reaching beyond this processor's mesh bounds or into a
    // neighbour's (no other processor's bounds are within their reach),
    // exchanged with the neighbours. Two boxes of chains of processors p
    // and q meet at a point x: outside q's bounds, q's chain reaches
    // beyond them; inside, p's chain reaches into them
    const boundBox& myBounds = procBounds[Pstream::myProcNo()];
    bitSet meets(boxes.size());
    DynamicList<label> exposed;
    forAll(boxes, c)
    {
        bool reaches =
            !myBounds.contains(boxes[c].min())
         || !myBounds.contains(boxes[c].max());
        for (const label proci : neighbours)
        {
            if
            (
                reaches
             || periodic_.overlapsImage(boxes[c], procBounds[proci])
            )
            {
                reaches = true;
                break;
            }
        }
        if (reaches)
        {
            meets.set(c);
            exposed.append(c);
        }
    }
    const List<List<boundBox>> theirs(exchangeBoxes(boxes, exposed));

    // Chains that can meet an exposed chain of another processor: of any
    // pair of chains of two processors that can meet, one is exposed, so
    // without such chains anywhere no chains of two processors meet
    anyMeeting = false;
    forAll(boxes, c)
    {
        for (const List<boundBox>& others : theirs)
        {
            for (const boundBox& other : others)
            {
                if (periodic_.overlapsImage(boxes[c], other))
                {
                    meets.set(c);
                    anyMeeting = true;
                    break;
                }
            }
        }
    }
    anyMeeting = allReduceOr(anyMeeting);
    if (!anyMeeting)
    {
        return labelList();
    }

    // The closure, chains that can meet those, by components: each
    // meeting chain not reached yet starts one, and every chain joined to
    // it by overlapping boxes is in it
    labelList component(boxes.size(), -1);
    label nComponents = 0;
    DynamicList<label> front;
    forAll(boxes, s)
    {
        if (!meets.test(s) || component[s] >= 0)
        {
            continue;
        }
        component[s] = nComponents;
        front.append(s);
        while (front.size())
        {
            const label c = front.remove();
            forAll(boxes, d)
            {
                if
                (
                    component[d] < 0
                 && periodic_.overlapsImage(boxes[c], boxes[d])
                )
                {
                    component[d] = nComponents;
                    front.append(d);
                }
            }
        }
        ++nComponents;
    }

    return component;
}


Foam::List<Foam::labelPairList>
Foam::polymer::collisionGroups::overlappingChains
(
    const List<boundBox>& mine,
    const List<List<boundBox>>& theirs
) const
{
    // Both processors of a pair test the same boxes in the same order
    // (the lower processor's first), so that each sees the overlaps the
    // other sees, to the last bit
    const labelList& neighbours = neighbours_.neighbours();
    List<labelPairList> overlaps(theirs.size());
    forAll(theirs, j)
    {
        const bool mineFirst = Pstream::myProcNo() < neighbours[j];
        DynamicList<labelPair> pairs;
        forAll(theirs[j], i)
        {
            forAll(mine, k)
            {
                if
                (
                    mineFirst
                  ? periodic_.overlapsImage(mine[k], theirs[j][i])
                  : periodic_.overlapsImage(theirs[j][i], mine[k])
                )
                {
                    pairs.append(labelPair(k, i));
                }
            }
        }
        overlaps[j].transfer(pairs);
    }
    return overlaps;
}


Foam::labelList Foam::polymer::collisionGroups::groupProcessors
(
    const List<boundBox>& boxes,
    const labelUList& grouped,
    const labelUList& component
) const
{
    // Each of this processor's components labelled by its lowest
    // (processor, grouped chain) pair
    const label myProc = Pstream::myProcNo();
    const label n = grouped.size();
    labelList root(n);
    label nComponents = 0;
    forAll(root, k)
    {
        root[k] = component[grouped[k]];
        nComponents = max(nComponents, root[k] + 1);
    }
    List<labelPair> componentLabel(nComponents, labelPair(labelMax, labelMax));
    forAll(root, k)
    {
        const labelPair own(myProc, k);
        if (own < componentLabel[root[k]])
        {
            componentLabel[root[k]] = own;
        }
    }

    // The grouped chains' boxes and labels to the neighbours, theirs back
    const List<boundBox> groupedBoxes(UIndirectList<boundBox>(boxes, grouped));
    List<labelPair> sent(UIndirectList<labelPair>(componentLabel, root));
    List<List<boundBox>> theirBoxes(neighbours_.neighbours().size());
    List<List<labelPair>> theirLabels(theirBoxes.size());
    {
        PtrList<OListStream> send(neighbours_.streams());
        if (n)
        {
            for (OListStream& os : send)
            {
                os  << groupedBoxes << sent;
            }
        }
        List<List<char>> recv;
        neighbours_.exchange(send, recv);
        forAll(recv, j)
        {
            if (recv[j].size())
            {
                UIListStream is(recv[j], IOstream::BINARY);
                is  >> theirBoxes[j] >> theirLabels[j];
            }
        }
    }
    const List<labelPairList> overlaps
    (
        overlappingChains(groupedBoxes, theirBoxes)
    );

    // The lowest label of every component spanning several processors
    // spreads along the overlaps, a neighbour a round: the component then
    // goes whole to its lowest processor, as one processor forming every
    // group would send it. A label falls in a round only where one fell
    // in the round before, in a component overlapping a higher label of
    // the neighbour's: with none such anywhere the labels are final.
    // Asking costs a collective, so it is asked every second round: a
    // group over two or three sub-domains is then labelled in one
    for (label round = 1; ; ++round)
    {
        bool pending = false;
        forAll(overlaps, j)
        {
            for (const labelPair& ki : overlaps[j])
            {
                labelPair& mine = componentLabel[root[ki.first()]];
                const labelPair& theirs = theirLabels[j][ki.second()];
                if (theirs < mine)
                {
                    mine = theirs;
                }
            }
        }
        forAll(overlaps, j)
        {
            for (const labelPair& ki : overlaps[j])
            {
                const labelPair& mine = componentLabel[root[ki.first()]];
                pending =
                    pending
                 || (
                        mine < sent[ki.first()]
                     && mine < theirLabels[j][ki.second()]
                    );
            }
        }
        if (round % 2 == 0 && !allReduceOr(pending))
        {
            break;
        }
        sent = UIndirectList<labelPair>(componentLabel, root);
        neighbours_.exchangeKnownSizes
        (
            List<List<labelPair>>(theirLabels.size(), sent),
            theirLabels
        );
    }

    labelList destination(n);
    forAll(destination, k)
    {
        destination[k] = componentLabel[root[k]].first();
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
        2*Foam::sqrt(allReduceMax(displacement));

    // The boxes, and the neighbours for their reach beyond this
    // processor's bounds
    const boundBox& myBounds = distribution_.processorBounds()[myProc];
    List<boundBox> boxes(chains_.nChains());
    scalar reach = 0;
    forAll(boxes, c)
    {
        boxes[c] = sweptBox(chains_, c, positionsOld, margin);
        reach = max(reach, processorNeighbours::excess(boxes[c], myBounds));
    }
    // (two boxes meet only if their processors' bounds are within the sum
    // of their reaches)
    neighbours_.neighbours(2*allReduceMax(reach));
    bool anyMeeting = false;
    const labelList component(chainsMeetingOthers(boxes, anyMeeting));
    if (!anyMeeting)
    {
        // No chains of two processors can meet this step
        collisionBoxes_ = boxes;
        distribution_.addSeconds(clock.elapsedTime());
        return;
    }

    // The groups, formed among the neighbours
    DynamicList<label> grouped;
    forAll(component, c)
    {
        if (component[c] >= 0)
        {
            grouped.append(c);
        }
    }
    const labelList destination(groupProcessors(boxes, grouped, component));

    // Each grouped chain, with its step's start, to its group's processor
    List<DynamicList<label>> toProc(Pstream::nProcs());
    DynamicList<label> sent;
    forAll(grouped, k)
    {
        const label proci = destination[k];
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
        List<DynamicList<vector>*>({&positionsOld, &velocitiesOld}),
        neighbours_
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
