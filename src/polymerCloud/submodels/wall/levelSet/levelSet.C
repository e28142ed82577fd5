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

#include "levelSet.H"
#include "wallDist.H"
#include "fvcGrad.H"
#include "wallPolyPatch.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(wallModel, wallModels, levelSet)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::wallModels::levelSet::levelSet
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    wallModel(typeName, dict, mesh),
    nSamples_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "nSamples", 4, 1, "<samples of a path per step>"
        )
    ),
    clearance_
    (
        checkedInput::positiveScalar
        (
            coeffDict_, "clearance", "<least distance of a bead from a wall>"
        )
    ),
    locator_(cellLocator::New(mesh)),
    search_(mesh),
    distance_(wallDist::New(mesh).y()),
    distanceGradient_("levelSetGradient", fvc::grad(distance_)),
    interpolateDistance_(distance_),
    interpolateGradient_(distanceGradient_)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::polymer::wallModels::levelSet::distanceAt
(
    const point& p,
    tetIndices& tet,
    barycentric& coordinates
) const
{
    // Interpolated in the tet the search finds (OpenFOAM's interpolate at
    // a position searches the cell's tets again, with cellPointWeight's
    // absolute degeneracy test: every tet of a mesh of micrometre cells in
    // metres, whose points would all take the same four weights)
    tet = locator_.findTet(periodic_.wrap(p), tet, coordinates);
    if (tet.cell() < 0)
    {
        return -1;
    }
    return interpolateDistance_.interpolate(coordinates, tet) - clearance_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::wallModels::levelSet::predict
(
    const point& x,
    const vector& v,
    const scalar T,
    impact& hit
) const
{
    if (mag(v)*T < VSMALL)
    {
        return false;
    }

    // The tet and coordinates of the last point in front of the level
    // set's zero: the next search starts there, and the impact's normal
    // is interpolated there
    tetIndices tet;
    barycentric coordinates;
    scalar before = 0;
    if (distanceAt(x, tet, coordinates) < 0)
    {
        return faceImpact(x, v, T, hit);
    }

    for (label k = 1; k <= nSamples_; ++k)
    {
        const scalar s = T*k/nSamples_;
        tetIndices sampleTet(tet);
        barycentric sampleCoordinates;
        const scalar d = distanceAt(x + s*v, sampleTet, sampleCoordinates);

        // A sample outside the mesh is behind the boundary too: the
        // bisection below finds where the path leaves the clearance
        // surface or the mesh, whichever comes first
        if (sampleTet.cell() >= 0 && d > 0)
        {
            before = s;
            tet = sampleTet;
            coordinates = sampleCoordinates;
            continue;
        }

        // Bisect the zero of the distance between before and s
        scalar a = before, b = s;
        for (int iter = 0; iter < 60 && b - a > 1e-12*T; ++iter)
        {
            const scalar middle = 0.5*(a + b);
            tetIndices middleTet(tet);
            barycentric middleCoordinates;
            const scalar dm =
                distanceAt(x + middle*v, middleTet, middleCoordinates);
            if (dm > 0 && middleTet.cell() >= 0)
            {
                a = middle;
                tet = middleTet;
                coordinates = middleCoordinates;
            }
            else
            {
                b = middle;
            }
        }

        const point p = periodic_.wrap(x + a*v);
        vector normal = interpolateGradient_.interpolate(coordinates, tet);
        normal = (mag(normal) > VSMALL) ? normal/mag(normal) : -v/mag(v);

        hit.time = a;
        hit.normal = normal;
        const label facei = search_.findNearestBoundaryFace(p);
        hit.patch = mesh_.boundaryMesh().whichPatch(facei);

        // The level set is the distance to the walls: at another patch
        // (an outlet, say) the boundary's normal is its face's. So is it
        // where the gradient does not oppose the path (near a re-entrant
        // corner the interpolated gradient blends two walls'), so that a
        // rebound always turns the bead back; head-on if neither does
        if
        (
            !isA<wallPolyPatch>(mesh_.boundaryMesh()[hit.patch])
         || (v & hit.normal) >= 0
        )
        {
            const vector area = mesh_.faceAreas()[facei];
            hit.normal = -area/mag(area);
            if ((v & hit.normal) >= 0)
            {
                hit.normal = -v/mag(v);
            }
        }
        return true;
    }

    return false;
}


// ************************************************************************* //
