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

#include "meshFaces.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace wallModels
{
    defineTypeNameAndDebug(meshFaces, 0);
    addToRunTimeSelectionTable(wallModel, meshFaces, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallModels::meshFaces::meshFaces
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    wallModel(typeName, dict, mesh),
    search_(mesh),
    solid_(mesh.boundaryMesh().size(), true)
{
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& patch = mesh.boundaryMesh()[patchi];
        solid_[patchi] =
            !isA<emptyPolyPatch>(patch) && !isA<processorPolyPatch>(patch);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::wallModels::meshFaces::predict
(
    const point& x,
    const vector& v,
    const scalar T,
    impact& hit
) const
{
    const vector path = T*v;
    const scalar length = mag(path);
    if (length < VSMALL)
    {
        return false;
    }

    // All boundary faces the segment meets, nearest first
    const List<pointIndexHit> hits = search_.intersections(x, x + path);

    for (const pointIndexHit& h : hits)
    {
        const label facei = h.index();
        const label patchi = mesh_.boundaryMesh().whichPatch(facei);
        if (!solid_[patchi])
        {
            continue;
        }

        const vector area = mesh_.faceAreas()[facei];
        const vector normal = -area/mag(area);

        // Only a path that enters the face from the fluid side meets it
        if ((v & normal) >= 0)
        {
            continue;
        }

        const scalar fraction = ((h.hitPoint() - x) & path)/sqr(length);
        hit.time = T*max(fraction*(1 - 1e-9), scalar(0));
        hit.normal = normal;
        hit.patch = patchi;
        return true;
    }

    return false;
}


// ************************************************************************* //
