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

#include "cellFaceFans.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cellFaceFans::cellFaceFans(const polyMesh& mesh)
:
    fans_()
{
    const cellList& cells = mesh.cells();
    const faceList& faces = mesh.faces();
    labelList nEntries(cells.size(), 0);
    forAll(cells, celli)
    {
        for (const label facei : cells[celli])
        {
            nEntries[celli] += 1 + faces[facei].size();
        }
    }
    fans_ = CompactListList<label>(nEntries);

    const labelList& basePoints = mesh.tetBasePtIs();
    const labelList& owner = mesh.faceOwner();
    label nUnfanned = 0;
    forAll(cells, celli)
    {
        labelUList entries = fans_[celli];
        label k = 0;
        for (const label facei : cells[celli])
        {
            const face& f = faces[facei];
            const label n = f.size();
            label base = basePoints[facei];
            if (base < 0)
            {
                ++nUnfanned;
                base = 0;
            }
            entries[k++] = (owner[facei] == celli) ? n : -n;
            for (label j = 0; j < n; ++j)
            {
                entries[k++] = f[(base + j) % n];
            }
        }
    }
    if (nUnfanned)
    {
        WarningInFunction
            << nUnfanned << " faces of cells (an internal face for each of its"
            << " two cells) have no"
            << " base point that gives a valid tet decomposition;"
            << " they are fanned from their first point" << endl;
    }
}


// ************************************************************************* //
