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
#include "UIListStream.H"
#include "allReduce.H"
#include "clockTime.H"
#include "flatVolPointInterpolation.H"

#include <algorithm>
#include <cmath>
#include <numeric>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Tets as three label lists (cells, faces, tet points)
void writeTets(Foam::Ostream& os, const Foam::UList<Foam::tetIndices>& tets)
{
    using namespace Foam;
    using namespace Foam::polymer;

    labelList cells(tets.size());
    labelList faces(tets.size());
    labelList tetPts(tets.size());
    forAll(tets, k)
    {
        cells[k] = tets[k].cell();
        faces[k] = tets[k].face();
        tetPts[k] = tets[k].tetPt();
    }
    os  << cells << faces << tetPts;
}


Foam::List<Foam::tetIndices> readTets(Foam::Istream& is)
{
    using namespace Foam;
    using namespace Foam::polymer;

    const labelList cells(is);
    const labelList faces(is);
    const labelList tetPts(is);
    List<tetIndices> tets(cells.size());
    forAll(tets, k)
    {
        tets[k] = tetIndices(cells[k], faces[k], tetPts[k]);
    }
    return tets;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::beadSampler::beadSampler(const fvMesh& mesh)
:
    mesh_(mesh),
    locator_(cellLocator::New(mesh)),
    periodic_(periodicImages::New(mesh)),
    remoteOwners_(-1),
    remoteTets_(tetIndices()),
    unheld_(),
    unheldPoints_(),
    hostTets_(tetIndices()),
    hostCoordinates_(),
    hostTransforms_(tetTransform()),
    hostTriangles_(triFace(-1, -1, -1)),
    leaverTets_(),
    leaverBeads_(),
    leaverPoints_(),
    leaverOrder_(),
    cellOrder_(),
    cellCounts_(),
    answeredTets_(Pstream::nProcs()),
    answeredCoordinates_(Pstream::nProcs()),
    locatedBeads_(Pstream::nProcs()),
    neighbours_(mesh),
    nOutside_(0),
    exchangeSeconds_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::beadSampler::orderByCell
(
    const UList<tetIndices>& tets,
    labelList& order,
    const bool byCell
)
{
    // Beads whose mesh data stay in the cache: their own order, the tets
    // in no cell first (a stable partition, no sort)
    const label nTets = tets.size();
    order.setSize(nTets);
    if (!byCell)
    {
        label nNone = 0;
        forAll(tets, i)
        {
            nNone += (tets[i].cell() < 0);
        }
        label none = 0, some = nNone;
        forAll(tets, i)
        {
            order[tets[i].cell() < 0 ? none++ : some++] = i;
        }
        return nNone;
    }

    // A counting sort costs a pass over the mesh's cells, a comparison
    // sort about n log2(n) comparisons of a few nanoseconds each: a few
    // beads in a large mesh (a dilute scene, a trap array the chains are
    // leaving) take the comparison sort, whose stable order, tets in no
    // cell (-1) first, is the counting sort's
    if (4*nTets*std::log2(scalar(nTets + 1)) < mesh_.nCells())
    {
        std::iota(order.begin(), order.end(), label(0));
        std::stable_sort
        (
            order.begin(),
            order.end(),
            [&tets](const label a, const label b)
            {
                return tets[a].cell() < tets[b].cell();
            }
        );
        return std::count_if
        (
            tets.begin(),
            tets.end(),
            [](const tetIndices& tet) { return tet.cell() < 0; }
        );
    }

    // Slot 0 for the tets in no cell here, slot c + 1 for cell c
    cellCounts_.setSize(mesh_.nCells() + 2);
    cellCounts_ = 0;
    for (const tetIndices& tet : tets)
    {
        ++cellCounts_[tet.cell() + 2];
    }
    for (label slot = 2; slot < cellCounts_.size(); ++slot)
    {
        cellCounts_[slot] += cellCounts_[slot - 1];
    }

    forAll(tets, i)
    {
        order[cellCounts_[tets[i].cell() + 1]++] = i;
    }

    // Slot 0 now counts to the end of the tets in no cell
    return cellCounts_[0];
}


bool Foam::polymer::beadSampler::missesCache(const label nBeads)
{
    // A bead's search reads about a kilobyte of mesh data (its cell's
    // faces, points and geometry). The data of fewer beads than this fit
    // in a processor's cache and stay there from step to step, and asking
    // for them ahead, or sorting the beads by cell, only adds work; those
    // of many more wait for memory
    const label cachedBeads = 16384;
    return nBeads > cachedBeads;
}


bool Foam::polymer::beadSampler::prefetches() const
{
    return missesCache(cellOrder_.size());
}


void Foam::polymer::beadSampler::prefetchMesh
(
    const UList<tetIndices>& tets,
    const labelUList& order,
    const label k,
    const int nStages
) const
{
    // The mesh data of the tets 8, 16, ... places ahead in the order, a
    // stage each (a stage needs the one before in the cache)
    for (int stage = 0; stage < nStages; ++stage)
    {
        const label ahead = k + prefetchSpacing*(nStages - stage);
        if (ahead < order.size())
        {
            locator_.prefetch(tets[order[ahead]].cell(), stage);
        }
    }
}


void Foam::polymer::beadSampler::prefetchBead
(
    const label i,
    const bool withTransform
) const
{
#if defined(__GNUC__)
    __builtin_prefetch(&hostTets_.values()[i], 1);
    __builtin_prefetch(&hostCoordinates_[i], 1);
    __builtin_prefetch(&hostTriangles_.values()[i], 1);
    if (withTransform)
    {
        // A transform spans three cache lines at most: its first, middle
        // and last bytes are in every line it spans
        const char* transform =
            reinterpret_cast<const char*>(&hostTransforms_.values()[i]);
        __builtin_prefetch(transform, 1);
        __builtin_prefetch(transform + sizeof(tetTransform)/2, 1);
        __builtin_prefetch(transform + sizeof(tetTransform) - 1, 1);
    }
#endif
}


void Foam::polymer::beadSampler::prefetchTrianglePoints
(
    const label i
) const
{
#if defined(__GNUC__)
    const triFace& triangle = hostTriangles_.values()[i];
    const pointField& points = mesh_.points();
    __builtin_prefetch(&points[triangle[0]]);
    __builtin_prefetch(&points[triangle[1]]);
    __builtin_prefetch(&points[triangle[2]]);
#endif
}


void Foam::polymer::beadSampler::prefetchPointValues
(
    const vectorField& cellValues,
    const vectorField& pointValues,
    const label k
) const
{
#if defined(__GNUC__)
    if (k >= cellOrder_.size())
    {
        return;
    }
    const label i = cellOrder_[k];
    const label celli = hostTets_.values()[i].cell();
    if (celli < 0)
    {
        return;
    }
    const triFace& tri = hostTriangles_.values()[i];
    __builtin_prefetch(&cellValues[celli]);
    __builtin_prefetch(&pointValues[tri[0]]);
    __builtin_prefetch(&pointValues[tri[1]]);
    __builtin_prefetch(&pointValues[tri[2]]);
#endif
}


void Foam::polymer::beadSampler::keepPlace
(
    const cellLocator::tetPlace& place,
    const label i,
    tetTransform& transform,
    triFace& triangle
)
{
    // As the search's tet test computed them: no mesh data read again
    hostCoordinates_[i] = place.coordinates;
    transform = place.transform;
    triangle = place.triangle;
}


void Foam::polymer::beadSampler::locateUntracked
(
    const polymerChains& chains,
    const label nUntracked,
    List<tetIndices>& hostTet,
    List<tetTransform>& transform,
    List<triFace>& triangle
)
{
    // A bead with no tet (the first locate, a new chain, a bead back from
    // outside) starts from the tet of the bead before it in its chain, a
    // rod length away, rather than a tree search: the untracked beads
    // come first in the cells' order, in bead order
    const List<vector>& x = chains.positions();
    const boundBox& bounds = neighbours_.localBounds();
    label chaini = 0;
    for (label k = 0; k < nUntracked; ++k)
    {
        const label i = cellOrder_[k];
        const point p = periodic_.wrap(x[i]);
        while (chains.end(chaini) <= i)
        {
            ++chaini;
        }
        const bool fromBefore =
            i > chains.start(chaini) && hostTet[i - 1].cell() >= 0;
        barycentric coordinates;
        if (!bounds.contains(p))
        {
            hostTet[i] = tetIndices();
        }
        else if
        (
            fromBefore
         && cellLocator::stillIn(p, transform[i - 1], coordinates)
        )
        {
            // In the tet of the bead before, tested by its kept transform
            // as findTet would test it on the mesh, to the bit
            hostCoordinates_[i] = coordinates;
            hostTet[i] = hostTet[i - 1];
            transform[i] = transform[i - 1];
            triangle[i] = triangle[i - 1];
        }
        else
        {
            cellLocator::tetPlace place;
            hostTet[i] = locator_.search
            (
                p, fromBefore ? hostTet[i - 1] : tetIndices(), place
            );
            if (hostTet[i].cell() >= 0)
            {
                keepPlace(place, i, transform[i], triangle[i]);
            }
        }
    }
}


void Foam::polymer::beadSampler::findLeavers
(
    const UList<vector>& x,
    List<tetIndices>& hostTet,
    const UList<tetTransform>& transform
)
{
    // In bead order: the beads' own arrays are read in sequence, and a
    // bead still in its tet reads no mesh data
    const boundBox& bounds = neighbours_.localBounds();
    leaverTets_.clear();
    leaverBeads_.clear();
    leaverPoints_.clear();
    forAll(x, i)
    {
        if (hostTet[i].cell() < 0)
        {
            continue;
        }
        const point p = periodic_.wrap(x[i]);
        if (!bounds.contains(p))
        {
            hostTet[i] = tetIndices();
        }
        else if
        (
            !cellLocator::stillIn(p, transform[i], hostCoordinates_[i])
        )
        {
            leaverTets_.append(hostTet[i]);
            leaverBeads_.append(i);
            leaverPoints_.append(p);
        }
    }
    orderByCell(leaverTets_, leaverOrder_, prefetches());
}


void Foam::polymer::beadSampler::searchLeavers
(
    List<tetIndices>& hostTet,
    List<tetTransform>& transform,
    List<triFace>& triangle
)
{
    // In the order of their last cells, with the mesh data of the leavers
    // ahead fetched (their tets' cells, faces and points) and their own
    // entries
    const bool prefetching = prefetches();
    const label nLeavers = leaverOrder_.size();
    const int nStages = 2;
    forAll(leaverOrder_, k)
    {
        if (prefetching)
        {
            // The cells' data 16 and 24 places ahead; the points of the
            // old tets 8 ahead (most leavers stay in their cell, whose
            // tets share points); the beads' own entries 32 ahead
            const label next = k + prefetchSpacing;
            prefetchMesh(leaverTets_, leaverOrder_, next, nStages);
            if (next < nLeavers)
            {
                prefetchTrianglePoints(leaverBeads_[leaverOrder_[next]]);
            }
            const label later = k + prefetchSpacing*(nStages + 2);
            if (later < nLeavers)
            {
                prefetchBead(leaverBeads_[leaverOrder_[later]], true);
            }
        }
        const label j = leaverOrder_[k];
        const label i = leaverBeads_[j];
        cellLocator::tetPlace place;
        hostTet[i] = locator_.search(leaverPoints_[j], leaverTets_[j], place);
        if (hostTet[i].cell() >= 0)
        {
            keepPlace(place, i, transform[i], triangle[i]);
        }
    }
}


void Foam::polymer::beadSampler::locateHere
(
    const polymerChains& chains,
    List<tetIndices>& hostTet,
    List<tetTransform>& transform,
    List<triFace>& triangle
)
{
    // A bead outside this processor's bounding box is in another's mesh,
    // or in none: no search here. The untracked beads first (they start
    // from their neighbours' tets as the last locate left them), then
    // those that left their tet
    const label nUntracked =
        orderByCell(hostTet, cellOrder_, missesCache(hostTet.size()));
    locateUntracked(chains, nUntracked, hostTet, transform, triangle);
    findLeavers(chains.positions(), hostTet, transform);
    searchLeavers(hostTet, transform, triangle);
}


Foam::List<Foam::DynamicList<Foam::label>>
Foam::polymer::beadSampler::byNeighbour(const labelUList& proc) const
{
    const labelList& neighbours = neighbours_.neighbours();
    List<DynamicList<label>> requests(neighbours.size());
    forAll(proc, j)
    {
        // The neighbours are in increasing order
        const label k = findSortedIndex(neighbours, proc[j]);
        requests[k].append(j);
    }
    return requests;
}


Foam::List<Foam::tetIndices> Foam::polymer::beadSampler::askTets
(
    const labelUList& beads,
    const UList<point>& points,
    const labelUList& proc,
    const UList<tetIndices>& startTets
)
{
    typedef FixedList<label, 3> tetLabels;
    const labelList& neighbours = neighbours_.neighbours();
    const List<DynamicList<label>> asked(byNeighbour(proc));

    PtrList<OListStream> requests(neighbours_.streams());
    forAll(asked, k)
    {
        if (asked[k].size())
        {
            requests[k] << pointField(UIndirectList<point>(points, asked[k]));
            writeTets
            (
                requests[k],
                UIndirectList<tetIndices>(startTets, asked[k])()
            );
        }
    }
    List<List<char>> recv;
    neighbours_.exchange(requests, recv);

    // Answer the others' requests, keeping the tets found for sample
    const boundBox& bounds = neighbours_.localBounds();
    List<List<tetLabels>> answers(neighbours.size());
    forAll(recv, k)
    {
        if (recv[k].size())
        {
            const label proci = neighbours[k];
            UIListStream is(recv[k], IOstream::BINARY);
            const pointField p(is);
            List<tetIndices> tets(readTets(is));
            answers[k].setSize(p.size());
            forAll(p, m)
            {
                barycentric coordinates;
                tets[m] =
                    bounds.contains(p[m])
                  ? locator_.findTet(p[m], tets[m], coordinates)
                  : tetIndices();
                if (tets[m].cell() >= 0)
                {
                    answeredTets_[proci].append(tets[m]);
                    answeredCoordinates_[proci].append(coordinates);
                }
                answers[k][m] =
                    tetLabels({tets[m].cell(), tets[m].face(), tets[m].tetPt()});
            }
        }
    }
    List<List<tetLabels>> answered(neighbours.size());
    forAll(answered, k)
    {
        answered[k].setSize(asked[k].size());
    }
    neighbours_.exchangeKnownSizes(answers, answered);

    List<tetIndices> found(points.size());
    forAll(answered, k)
    {
        forAll(answered[k], m)
        {
            const label j = asked[k][m];
            const tetLabels& t = answered[k][m];
            found[j] = tetIndices(t[0], t[1], t[2]);
            if (t[0] >= 0)
            {
                locatedBeads_[neighbours[k]].append(beads[j]);
            }
        }
    }
    return found;
}


void Foam::polymer::beadSampler::locateRemote
(
    labelList& owner,
    List<tetIndices>& tet
)
{
    // Each unheld bead is asked of every other processor whose mesh's
    // bounding box holds it (no other mesh can; they are neighbours for
    // the unheld beads' reach), in one exchange: from the tet that held it
    // when that processor did, by a tree search otherwise. The lowest
    // processor that finds it holds it.
    scalar reach = 0;
    for (const point& p : unheldPoints_)
    {
        reach = max(reach, neighbours_.excess(p));
    }
    const labelList& neighbours =
        neighbours_.neighbours(allReduceMax(reach));
    const List<boundBox>& procBounds = neighbours_.processorBounds();

    DynamicList<label> askedBead(unheld_.size());
    DynamicList<point> askedPoint(unheld_.size());
    DynamicList<label> askedProc(unheld_.size());
    DynamicList<tetIndices> askedTet(unheld_.size());
    forAll(unheld_, k)
    {
        const label i = unheld_[k];
        const point& p = unheldPoints_[k];
        for (const label proci : neighbours)
        {
            if (procBounds[proci].contains(p))
            {
                askedBead.append(i);
                askedPoint.append(p);
                askedProc.append(proci);
                askedTet.append(proci == owner[i] ? tet[i] : tetIndices());
            }
        }
        owner[i] = -1;
        tet[i] = tetIndices();
    }

    const List<tetIndices> found
    (
        askTets(askedBead, askedPoint, askedProc, askedTet)
    );
    forAll(askedBead, j)
    {
        const label i = askedBead[j];
        if
        (
            found[j].cell() >= 0
         && (owner[i] < 0 || askedProc[j] < owner[i])
        )
        {
            owner[i] = askedProc[j];
            tet[i] = found[j];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::beadSampler::locate(const polymerChains& chains)
{
    const List<vector>& x = chains.positions();
    List<tetIndices>& hostTet = hostTets_.update(chains);
    List<tetTransform>& hostTransform = hostTransforms_.update(chains);
    List<triFace>& hostTriangle = hostTriangles_.update(chains);

    unheld_.clear();
    unheldPoints_.clear();
    hostCoordinates_.setSize(x.size());
    forAll(answeredTets_, proci)
    {
        answeredTets_[proci].clear();
        answeredCoordinates_[proci].clear();
        locatedBeads_[proci].clear();
    }

    locateHere(chains, hostTet, hostTransform, hostTriangle);

    forAll(hostTet, i)
    {
        if (hostTet[i].cell() < 0)
        {
            unheld_.append(i);
            unheldPoints_.append(periodic_.wrap(x[i]));
        }
    }

    // A serial run has no other mesh to ask: its unheld beads are outside
    // (remoteOwner -1), and the other processors' tets are neither kept
    // nor carried through the chains' reorders
    if (!Pstream::parRun())
    {
        nOutside_ = unheld_.size();
        return;
    }

    labelList& owner = remoteOwners_.update(chains);
    List<tetIndices>& remoteTet = remoteTets_.update(chains);
    forAll(hostTet, i)
    {
        if (hostTet[i].cell() >= 0)
        {
            owner[i] = -1;
            remoteTet[i] = tetIndices();
        }
    }

    clockTime clock;
    locateRemote(owner, remoteTet);
    exchangeSeconds_ += clock.elapsedTime();

    nOutside_ = 0;
    for (const label i : unheld_)
    {
        nOutside_ += (owner[i] < 0);
    }
}


void Foam::polymer::beadSampler::sample
(
    const interpolation<vector>& field,
    UList<vector>& values
) const
{
    const List<tetIndices>& hostTet = hostTets_.values();
    const bool prefetching = prefetches();
    forAll(cellOrder_, k)
    {
        if (prefetching)
        {
            const int nStages = 2;
            prefetchMesh(hostTet, cellOrder_, k, nStages);
            const label later = k + prefetchSpacing*(nStages + 1);
            if (later < cellOrder_.size())
            {
                prefetchBead(cellOrder_[later], false);
            }
        }
        const label i = cellOrder_[k];
        values[i] =
            (hostTet[i].cell() >= 0)
          ? field.interpolate(hostCoordinates_[i], hostTet[i])
          : Zero;
    }

    exchangeSampled
    (
        [&field](const barycentric& coordinates, const tetIndices& tet)
        {
            return field.interpolate(coordinates, tet);
        },
        values
    );
}


bool Foam::polymer::beadSampler::keptCell
(
    const polymerChains& chains,
    const label i,
    const point& p,
    label& celli
) const
{
    if (!hostTets_.current(chains) || !hostTransforms_.current(chains))
    {
        return false;
    }
    const tetIndices& tet = hostTets_.values()[i];
    barycentric coordinates;
    if
    (
        tet.cell() < 0
     || !cellLocator::stillIn(p, hostTransforms_.values()[i], coordinates)
    )
    {
        return false;
    }
    celli = tet.cell();
    return true;
}


Foam::tmp<Foam::pointVectorField> Foam::polymer::beadSampler::pointValues
(
    const volVectorField& cellValues
)
{
    return flatVolPointInterpolation::New(cellValues.mesh()).interpolate
    (
        cellValues,
        "volPointInterpolate(" + cellValues.name() + ')',
        true
    );
}


void Foam::polymer::beadSampler::sample
(
    const volVectorField& cellValues,
    const pointVectorField& pointValues,
    UList<vector>& values
) const
{
    // interpolationCellPoint::interpolate(coordinates, tet)'s expression,
    // its face triangle kept with the tet. In the cells' order, the point
    // values of the beads ahead fetched (their triangles fetched before)
    const List<tetIndices>& hostTet = hostTets_.values();
    const List<triFace>& triangle = hostTriangles_.values();
    const vectorField& psi = cellValues.primitiveField();
    const vectorField& psip = pointValues.primitiveField();
    const bool prefetching = prefetches();
    const label nBeads = cellOrder_.size();
    forAll(cellOrder_, k)
    {
        if (prefetching)
        {
            prefetchPointValues(psi, psip, k + prefetchSpacing);
            if (k + 2*prefetchSpacing < nBeads)
            {
                prefetchBead(cellOrder_[k + 2*prefetchSpacing], false);
            }
        }
        const label i = cellOrder_[k];
        const label celli = hostTet[i].cell();
        if (celli < 0)
        {
            values[i] = Zero;
            continue;
        }
        values[i] =
            cellPointValue(psi, psip, hostCoordinates_[i], celli, triangle[i]);
    }

    exchangeSampled
    (
        [this, &psi, &psip]
        (
            const barycentric& coordinates,
            const tetIndices& tet
        )
        {
            return cellPointValue
            (
                psi, psip, coordinates, tet.cell(), tet.faceTriIs(mesh_)
            );
        },
        values
    );
}


// ************************************************************************* //
