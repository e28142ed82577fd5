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

#include "UIPstream.H"
#include "UOPstream.H"
#include "contiguous.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::polymer::processorNeighbours::exchangeKnownSizes
(
    const UList<List<Type>>& send,
    List<List<Type>>& recv
) const
{
    static_assert
    (
        is_contiguous<Type>::value,
        "exchangeKnownSizes: contiguous data only"
    );

    const int tag = UPstream::msgType();
    const label start = UPstream::nRequests();
    forAll(neighbours_, k)
    {
        if (recv[k].size())
        {
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<char*>(recv[k].data()),
                recv[k].size()*sizeof(Type),
                tag
            );
        }
    }
    forAll(neighbours_, k)
    {
        if (send[k].size())
        {
            UOPstream::write
            (
                UPstream::commsTypes::nonBlocking,
                neighbours_[k],
                reinterpret_cast<const char*>(send[k].cdata()),
                send[k].size()*sizeof(Type),
                tag
            );
        }
    }
    UPstream::waitRequests(start);
}


// ************************************************************************* //
