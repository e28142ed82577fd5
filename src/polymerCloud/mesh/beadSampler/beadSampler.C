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
    using namespace Foam::polymer;

    List<DynamicList<label>> requests(Pstream::nProcs());
    forAll(proc, j)
    {
        requests[proc[j]].append(j);
    }
    return requests;
}

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
    bounds_(mesh.points(), false),
    remoteOwners_(-1),
    remoteTets_(tetIndices()),
    unheld_(),
    unheldPoints_(),
    hostTets_(tetIndices()),
    hostCoordinates_(),
    answeredTets_(Pstream::nProcs()),
    answeredCoordinates_(Pstream::nProcs()),
    locatedBeads_(Pstream::nProcs()),
    processorBounds_(),
    nOutside_(0),
    exchangeSeconds_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::tetIndices> Foam::polymer::beadSampler::askTets
(
    const labelUList& beads,
    const UList<point>& points,
    const labelUList& proc,
    const UList<tetIndices>& startTets
)
{
    const List<DynamicList<label>> asked(byProcessor(proc));

    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    forAll(asked, proci)
    {
        if (asked[proci].size())
        {
            UOPstream os(proci, requests);
            os  << UIndirectList<point>(points, asked[proci]);
            writeTets
            (
                os,
                UIndirectList<tetIndices>(startTets, asked[proci])()
            );
        }
    }
    labelList recvSizes;
    requests.finishedSends(recvSizes);

    // Answer the others' requests, keeping the tets found for sample
    const boundBox& bounds = bounds_;
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, requests);
            const pointField p(is);
            List<tetIndices> tets(readTets(is));
            forAll(p, k)
            {
                barycentric coordinates;
                tets[k] =
                    bounds.contains(p[k])
                  ? locator_.findTet(p[k], tets[k], coordinates)
                  : tetIndices();
                if (tets[k].cell() >= 0)
                {
                    answeredTets_[proci].append(tets[k]);
                    answeredCoordinates_[proci].append(coordinates);
                }
            }
            UOPstream os(proci, answers);
            writeTets(os, tets);
        }
    }
    answers.finishedSends(recvSizes);

    List<tetIndices> found(points.size());
    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, answers);
            const List<tetIndices> tets(readTets(is));
            forAll(tets, k)
            {
                const label j = asked[proci][k];
                found[j] = tets[k];
                if (tets[k].cell() >= 0)
                {
                    locatedBeads_[proci].append(beads[j]);
                }
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
    if (processorBounds_.empty())
    {
        processorBounds_.setSize(Pstream::nProcs());
        processorBounds_[Pstream::myProcNo()] = bounds_;
        Pstream::gatherList(processorBounds_);
        Pstream::scatterList(processorBounds_);
    }

    // Each unheld bead is asked of every other processor whose mesh's
    // bounding box holds it (no other mesh can), in one exchange: from the
    // tet that held it when that processor did, by a tree search
    // otherwise. The lowest processor that finds it holds it.
    const label myProc = Pstream::myProcNo();
    DynamicList<label> askedBead(unheld_.size());
    DynamicList<point> askedPoint(unheld_.size());
    DynamicList<label> askedProc(unheld_.size());
    DynamicList<tetIndices> askedTet(unheld_.size());
    forAll(unheld_, k)
    {
        const label i = unheld_[k];
        const point& p = unheldPoints_[k];
        forAll(processorBounds_, proci)
        {
            if (proci != myProc && processorBounds_[proci].contains(p))
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
    labelList& owner = remoteOwners_.update(chains);
    List<tetIndices>& remoteTet = remoteTets_.update(chains);

    unheld_.clear();
    unheldPoints_.clear();
    hostCoordinates_.setSize(x.size());
    forAll(answeredTets_, proci)
    {
        answeredTets_[proci].clear();
        answeredCoordinates_[proci].clear();
        locatedBeads_[proci].clear();
    }

    // A bead outside this processor's bounding box is in another's mesh,
    // or in none: no search here. The search starts from the tet that
    // held the bead at the last locate
    const boundBox& bounds = bounds_;
    forAll(x, i)
    {
        const point p = periodic_.wrap(x[i]);
        hostTet[i] =
            bounds.contains(p)
          ? locator_.findTet(p, hostTet[i], hostCoordinates_[i])
          : tetIndices();
        if (hostTet[i].cell() < 0)
        {
            unheld_.append(i);
            unheldPoints_.append(p);
        }
        else
        {
            owner[i] = -1;
            remoteTet[i] = tetIndices();
        }
    }

    if (Pstream::parRun())
    {
        clockTime clock;
        locateRemote(owner, remoteTet);
        exchangeSeconds_ += clock.elapsedTime();
    }

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
    forAll(hostTet, i)
    {
        values[i] =
            (hostTet[i].cell() >= 0)
          ? field.interpolate(hostCoordinates_[i], hostTet[i])
          : Zero;
    }

    if (!Pstream::parRun())
    {
        return;
    }

    // The values at the beads located for other processors, to them; the
    // values at this one's unheld beads, from the processors holding them
    clockTime clock;
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(answeredTets_, proci)
    {
        const DynamicList<tetIndices>& tets = answeredTets_[proci];
        if (tets.size())
        {
            const DynamicList<barycentric>& coordinates =
                answeredCoordinates_[proci];
            vectorField v(tets.size());
            forAll(tets, k)
            {
                v[k] = field.interpolate(coordinates[k], tets[k]);
            }
            UOPstream os(proci, buffers);
            os  << v;
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    forAll(recvSizes, proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, buffers);
            const vectorField v(is);
            const DynamicList<label>& beads = locatedBeads_[proci];
            if (v.size() != beads.size())
            {
                FatalErrorInFunction
                    << "Processor " << proci << " sent " << v.size()
                    << " values for the " << beads.size()
                    << " beads it located" << abort(FatalError);
            }
            // A bead on the face between two processors' meshes is found
            // by both: the value of the one holding it
            const labelList& owner = remoteOwners_.values();
            forAll(beads, m)
            {
                if (owner[beads[m]] == proci)
                {
                    values[beads[m]] = v[m];
                }
            }
        }
    }
    exchangeSeconds_ += clock.elapsedTime();
}


// ************************************************************************* //
