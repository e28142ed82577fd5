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

#include "cellFacePlanes.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cellFacePlanes::cellFacePlanes(const polyMesh& mesh)
:
    planes_()
{
    const cellList& cells = mesh.cells();
    labelList nFaces(cells.size());
    forAll(cells, celli)
    {
        nFaces[celli] = cells[celli].size();
    }
    planes_ = CompactListList<facePlane>(nFaces);

    const vectorField& faceCentres = mesh.faceCentres();
    const vectorField& faceAreas = mesh.faceAreas();
    const vectorField& cellCentres = mesh.cellCentres();
    const labelList& owner = mesh.faceOwner();
    const labelList& neighbour = mesh.faceNeighbour();
    forAll(cells, celli)
    {
        UList<facePlane> planes = planes_[celli];
        const point& centre = cellCentres[celli];
        forAll(cells[celli], k)
        {
            const label facei = cells[celli][k];
            const bool owned = (owner[facei] == celli);
            facePlane& plane = planes[k];
            plane.outward = owned ? faceAreas[facei] : -faceAreas[facei];
            plane.reach = (faceCentres[facei] - centre) & plane.outward;
            plane.face = facei;
            plane.across =
                !mesh.isInternalFace(facei) ? -1
              : owned ? neighbour[facei]
              : owner[facei];
        }
    }
}


// ************************************************************************* //
