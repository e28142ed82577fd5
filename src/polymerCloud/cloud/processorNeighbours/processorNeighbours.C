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

#include "processorNeighbours.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "UIListStream.H"
#include "cellLocator.H"
#include "allReduce.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::processorNeighbours::formNeighbours()
{
    const label myProc = Pstream::myProcNo();
    const vector grow(vector::uniform(reach_));
    const boundBox& mine = processorBounds_[myProc];

    // Bounds within reach_ of each other along every axis (the lower
    // processor's grown). A processor without cells is every processor's
    // neighbour; otherwise the test is made in the same order on both
    // sides, so that the relation is symmetric to the last bit
    DynamicList<label> neighbours;
    forAll(processorBounds_, proci)
    {
        const boundBox& theirs = processorBounds_[proci];
        if (proci == myProc)
        {
            continue;
        }
        if (!theirs.valid() || !mine.valid())
        {
            neighbours.append(proci);
            continue;
        }
        const boundBox& lower = (proci < myProc) ? theirs : mine;
        const boundBox& upper = (proci < myProc) ? mine : theirs;
        if
        (
            periodic_.overlapsImage
            (
                boundBox(lower.min() - grow, lower.max() + grow),
                upper
            )
        )
        {
            neighbours.append(proci);
        }
    }
    neighbours_.transfer(neighbours);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::processorNeighbours::processorNeighbours(const polyMesh& mesh)
:
    mesh_(mesh),
    periodic_(periodicImages::New(mesh)),
    processorBounds_(processorBounds::New(mesh).bounds()),
    reach_(-1),
    neighbours_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::processorNeighbours::excess
(
    const boundBox& b,
    const boundBox& bounds
)
{
    if (!bounds.valid())
    {
        // No mesh here: every processor is a neighbour anyway
        return 0;
    }
    return max
    (
        scalar(0),
        max(cmptMax(bounds.min() - b.min()), cmptMax(b.max() - bounds.max()))
    );
}


Foam::scalar Foam::polymer::processorNeighbours::excess(const point& p) const
{
    const boundBox& mine = processorBounds_[Pstream::myProcNo()];
    const boundBox at(p, p);
    scalar nearest = excess(at, mine);
    for (const vector& shift : periodic_.imageShifts())
    {
        nearest = min(nearest, excess(boundBox(p + shift, p + shift), mine));
    }
    return nearest;
}


const Foam::labelList&
Foam::polymer::processorNeighbours::neighbours(const scalar reach)
{
    if (reach > reach_ || reach < 0.5*reach_)
    {
        reach_ = 1.1*reach;
        formNeighbours();
    }
    return neighbours_;
}


Foam::PtrList<Foam::OListStream>
Foam::polymer::processorNeighbours::streams() const
{
    PtrList<OListStream> send(neighbours_.size());
    forAll(send, k)
    {
        send.set(k, new OListStream(IOstream::BINARY));
    }
    return send;
}


void Foam::polymer::processorNeighbours::exchange
(
    const PtrList<OListStream>& send,
    List<List<char>>& recv
) const
{
    const label n = neighbours_.size();
    const int tag = UPstream::msgType();

    // The sizes, every neighbour to every neighbour (zero included)
    labelList sendSizes(n), recvSizes(n);
    {
        const label start = UPstream::nRequests();
        forAll(neighbours_, k)
        {
            sendSizes[k] = send[k].size();
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<char*>(&recvSizes[k]),
                sizeof(label),
                tag
            );
        }
        forAll(neighbours_, k)
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<const char*>(&sendSizes[k]),
                sizeof(label),
                tag
            );
        }
        UPstream::waitRequests(start);
    }

    // The data, where there are any
    recv.setSize(n);
    const label start = UPstream::nRequests();
    forAll(neighbours_, k)
    {
        recv[k].setSize(recvSizes[k]);
        if (recvSizes[k])
        {
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                recv[k].data(),
                recvSizes[k],
                tag
            );
        }
    }
    forAll(neighbours_, k)
    {
        if (sendSizes[k])
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                send[k].list().cdata(),
                sendSizes[k],
                tag
            );
        }
    }
    UPstream::waitRequests(start);
}


Foam::labelList Foam::polymer::processorNeighbours::pointOwners
(
    const UList<point>& points
)
{
    // The neighbours for the points' reach beyond this processor's bounds:
    // any processor whose mesh holds one of them
    scalar reach = 0;
    for (const point& p : points)
    {
        reach = max(reach, excess(p));
    }
    neighbours(allReduceMax(reach));

    // Each neighbour is asked about the points in its bounds (no other
    // can be in its mesh) and answers with those its mesh holds
    List<labelList> asked(neighbours_.size());
    PtrList<OListStream> questions(streams());
    forAll(neighbours_, k)
    {
        const boundBox& theirs = processorBounds_[neighbours_[k]];
        DynamicList<label> inside;
        forAll(points, i)
        {
            if (!theirs.valid() || theirs.contains(points[i]))
            {
                inside.append(i);
            }
        }
        asked[k].transfer(inside);
        if (asked[k].size())
        {
            questions[k] << UIndirectList<point>(points, asked[k])();
        }
    }
    List<List<char>> recv;
    exchange(questions, recv);

    // The answers: a flag for each point asked, sizes known both ways
    const cellLocator& locator = cellLocator::New(mesh_);
    List<List<char>> held(neighbours_.size());
    forAll(recv, k)
    {
        if (recv[k].size())
        {
            UIListStream is(recv[k], IOstream::BINARY);
            const List<point> theirs(is);
            held[k].setSize(theirs.size());
            forAll(theirs, i)
            {
                held[k][i] = (locator.findCell(theirs[i]) >= 0);
            }
        }
    }
    List<List<char>> answers(neighbours_.size());
    forAll(answers, k)
    {
        answers[k].setSize(asked[k].size());
    }
    exchangeKnownSizes(held, answers);

    // The lowest holder, this processor included
    labelList owner(points.size(), labelMax);
    forAll(points, i)
    {
        if (locator.findCell(points[i]) >= 0)
        {
            owner[i] = Pstream::myProcNo();
        }
    }
    forAll(answers, k)
    {
        forAll(answers[k], j)
        {
            if (answers[k][j])
            {
                label& proci = owner[asked[k][j]];
                proci = min(proci, neighbours_[k]);
            }
        }
    }
    for (label& proci : owner)
    {
        if (proci == labelMax)
        {
            proci = -1;
        }
    }
    return owner;
}


// ************************************************************************* //
