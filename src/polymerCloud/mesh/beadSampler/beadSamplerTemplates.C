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
#include "clockTime.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::polymer::beadSampler::addToCells
(
    const UList<Type>& values,
    Field<Type>& cellValues
) const
{
    const List<tetIndices>& hostTet = hostTets_.values();
    forAll(values, i)
    {
        if (hostTet[i].cell() >= 0)
        {
            cellValues[hostTet[i].cell()] += values[i];
        }
    }

    if (!Pstream::parRun())
    {
        return;
    }

    // The unheld beads' values to the processors holding them
    clockTime clock;
    const labelList& owner = remoteOwners_.values();
    const List<tetIndices>& tet = remoteTets_.values();
    List<DynamicList<label>> cells(Pstream::nProcs());
    List<DynamicList<Type>> sent(Pstream::nProcs());
    for (const label i : unheld_)
    {
        if (owner[i] >= 0)
        {
            cells[owner[i]].append(tet[i].cell());
            sent[owner[i]].append(values[i]);
        }
    }

    const labelList& neighbours = neighbours_.neighbours();
    PtrList<OListStream> send(neighbours_.streams());
    forAll(neighbours, k)
    {
        const label proci = neighbours[k];
        if (cells[proci].size())
        {
            send[k] << cells[proci] << sent[proci];
        }
    }
    List<List<char>> recv;
    neighbours_.exchange(send, recv);

    forAll(recv, k)
    {
        if (recv[k].size())
        {
            UIListStream is(recv[k], IOstream::BINARY);
            const labelList c(is);
            const List<Type> v(is);
            forAll(c, m)
            {
                cellValues[c[m]] += v[m];
            }
        }
    }
    exchangeSeconds_ += clock.elapsedTime();
}


template<class ValueAt>
void Foam::polymer::beadSampler::exchangeSampled
(
    const ValueAt& valueAt,
    UList<vector>& values
) const
{
    if (!Pstream::parRun())
    {
        return;
    }

    // The values at the beads located for other processors, to them; the
    // values at this one's unheld beads, from the processors holding them
    // (both sides know how many)
    clockTime clock;
    const labelList& neighbours = neighbours_.neighbours();
    List<List<vector>> send(neighbours.size());
    List<List<vector>> recv(neighbours.size());
    forAll(neighbours, k)
    {
        const label proci = neighbours[k];
        const DynamicList<tetIndices>& tets = answeredTets_[proci];
        const DynamicList<barycentric>& coordinates =
            answeredCoordinates_[proci];
        send[k].setSize(tets.size());
        forAll(tets, m)
        {
            send[k][m] = valueAt(coordinates[m], tets[m]);
        }
        recv[k].setSize(locatedBeads_[proci].size());
    }
    neighbours_.exchangeKnownSizes(send, recv);

    // A bead on the face between two processors' meshes is found by both:
    // the value of the one holding it
    const labelList& owner = remoteOwners_.values();
    forAll(neighbours, k)
    {
        const label proci = neighbours[k];
        const DynamicList<label>& beads = locatedBeads_[proci];
        forAll(beads, m)
        {
            if (owner[beads[m]] == proci)
            {
                values[beads[m]] = recv[k][m];
            }
        }
    }
    exchangeSeconds_ += clock.elapsedTime();
}


// ************************************************************************* //
