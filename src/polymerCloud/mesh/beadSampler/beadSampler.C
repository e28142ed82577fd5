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

#include "beadSampler.H"
#include "pointOwners.H"
#include "PstreamBuffers.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The indices of the requests going to each processor
Foam::List<Foam::DynamicList<Foam::label>> byProcessor
(
    const Foam::labelUList& proc
)
{
    using namespace Foam;

    List<DynamicList<label>> requests(Pstream::nProcs());
    forAll(proc, j)
    {
        requests[proc[j]].append(j);
    }
    return requests;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::beadSampler::beadSampler(const fvMesh& mesh)
:
    mesh_(mesh),
    locator_(cellLocator::New(mesh)),
    periodic_(periodicImages::New(mesh)),
    hostCells_(),
    remoteOwners_(),
    remoteCells_(),
    unheld_(),
    unheldPoints_(),
    nOutside_(0),
    exchangeSeconds_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::beadSampler::askCells
(
    const UList<point>& points,
    const labelUList& proc,
    const labelUList& startCell
) const
{
    const List<DynamicList<label>> asked(byProcessor(proc));

    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    forAll(asked, proci)
    {
        if (asked[proci].size())
        {
            UOPstream os(proci, requests);
            os  << UIndirectList<point>(points, asked[proci])
                << UIndirectList<label>(startCell, asked[proci]);
        }
    }
    labelList recvSizes;
    requests.finishedSends(recvSizes);

    // Answer the others' requests
    const boundBox& bounds = mesh_.bounds();
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, requests);
            const pointField p(is);
            labelList c(is);
            forAll(p, k)
            {
                c[k] =
                    bounds.contains(p[k])
                  ? locator_.findCell(p[k], c[k])
                  : -1;
            }
            UOPstream os(proci, answers);
            os  << c;
        }
    }
    answers.finishedSends(recvSizes);

    labelList found(points.size(), -1);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, answers);
            const labelList c(is);
            UIndirectList<label>(found, asked[proci]) = c;
        }
    }
    return found;
}


void Foam::beadSampler::locateRemote(labelList& owner, labelList& cell)
{
    const label myProc = Pstream::myProcNo();

    // First where each bead was: most beads stay in the same cell or one
    // next to it
    DynamicList<label> asked(unheld_.size());
    DynamicList<point> askedPoint(unheld_.size());
    DynamicList<label> askedProc(unheld_.size());
    DynamicList<label> askedCell(unheld_.size());
    forAll(unheld_, k)
    {
        const label i = unheld_[k];
        if (owner[i] >= 0 && owner[i] != myProc)
        {
            asked.append(k);
            askedPoint.append(unheldPoints_[k]);
            askedProc.append(owner[i]);
            askedCell.append(cell[i]);
        }
        owner[i] = -1;
        cell[i] = -1;
    }
    const labelList found(askCells(askedPoint, askedProc, askedCell));
    forAll(asked, j)
    {
        if (found[j] >= 0)
        {
            const label i = unheld_[asked[j]];
            owner[i] = askedProc[j];
            cell[i] = found[j];
        }
    }

    // The rest (new, or gone to another processor) from every processor
    DynamicList<label> lost;
    DynamicList<point> lostPoint;
    forAll(unheld_, k)
    {
        if (owner[unheld_[k]] < 0)
        {
            lost.append(k);
            lostPoint.append(unheldPoints_[k]);
        }
    }
    if (returnReduce(lost.empty(), andOp<bool>()))
    {
        return;
    }

    labelList lostProc(pointOwners(mesh_, lostPoint));
    DynamicList<label> located(lost.size());
    forAll(lost, j)
    {
        if (lostProc[j] >= 0 && lostProc[j] != myProc)
        {
            located.append(j);
        }
    }
    const labelList lostCell
    (
        askCells
        (
            UIndirectList<point>(lostPoint, located)(),
            UIndirectList<label>(lostProc, located)(),
            labelList(located.size(), -1)
        )
    );
    forAll(located, m)
    {
        const label i = unheld_[lost[located[m]]];
        owner[i] = lostProc[located[m]];
        cell[i] = lostCell[m];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::beadSampler::locate(const polymerChains& chains)
{
    const List<vector>& x = chains.positions();
    labelList& hostCell = hostCells_.update(chains);
    labelList& owner = remoteOwners_.update(chains);
    labelList& cell = remoteCells_.update(chains);

    unheld_.clear();
    unheldPoints_.clear();

    // A bead outside this processor's bounding box is in another's mesh,
    // or in none: no search here
    const boundBox& bounds = mesh_.bounds();
    forAll(x, i)
    {
        const point p = periodic_.wrap(x[i]);
        hostCell[i] =
            bounds.contains(p) ? locator_.findCell(p, hostCell[i]) : -1;
        if (hostCell[i] < 0)
        {
            unheld_.append(i);
            unheldPoints_.append(p);
        }
        else
        {
            owner[i] = -1;
            cell[i] = -1;
        }
    }

    if (Pstream::parRun())
    {
        clockTime clock;
        locateRemote(owner, cell);
        exchangeSeconds_ += clock.elapsedTime();
    }

    nOutside_ = 0;
    for (const label i : unheld_)
    {
        nOutside_ += (owner[i] < 0);
    }
}


void Foam::beadSampler::sample
(
    const polymerChains& chains,
    const interpolation<vector>& field,
    UList<vector>& values
) const
{
    const List<vector>& x = chains.positions();
    const labelList& hostCell = hostCells_.cells();
    forAll(x, i)
    {
        values[i] =
            (hostCell[i] >= 0)
          ? field.interpolate(periodic_.wrap(x[i]), hostCell[i])
          : Zero;
    }

    if (!Pstream::parRun())
    {
        return;
    }

    // The unheld beads' values from the processors holding them
    clockTime clock;
    const labelList& owner = remoteOwners_.cells();
    const labelList& cell = remoteCells_.cells();
    DynamicList<label> asked(unheld_.size());
    DynamicList<label> askedProc(unheld_.size());
    forAll(unheld_, k)
    {
        if (owner[unheld_[k]] >= 0)
        {
            asked.append(k);
            askedProc.append(owner[unheld_[k]]);
        }
    }
    const List<DynamicList<label>> toProc(byProcessor(askedProc));

    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    forAll(toProc, proci)
    {
        if (toProc[proci].size())
        {
            const labelList k(UIndirectList<label>(asked, toProc[proci]));
            const labelList beads(UIndirectList<label>(unheld_, k));
            UOPstream os(proci, requests);
            os  << UIndirectList<point>(unheldPoints_, k)
                << UIndirectList<label>(cell, beads);
        }
    }
    labelList recvSizes;
    requests.finishedSends(recvSizes);

    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, requests);
            const pointField p(is);
            const labelList c(is);
            vectorField v(p.size());
            forAll(p, k)
            {
                v[k] = field.interpolate(p[k], c[k]);
            }
            UOPstream os(proci, answers);
            os  << v;
        }
    }
    answers.finishedSends(recvSizes);

    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, answers);
            const vectorField v(is);
            forAll(v, m)
            {
                values[unheld_[asked[toProc[proci][m]]]] = v[m];
            }
        }
    }
    exchangeSeconds_ += clock.elapsedTime();
}


// ************************************************************************* //
