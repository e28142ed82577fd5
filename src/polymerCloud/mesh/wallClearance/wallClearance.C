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

#include "wallClearance.H"

#include <cmath>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::wallClearance::layVoxels(const boundaryFaces& faces)
{
    bounds_ = boundBox(faces.points(), false);
    const vector span(bounds_.span());

    // Cubes, about eight a face but at least eight across the thinnest
    // direction that is not flat (a slit), at most maxVoxels
    const scalar wanted = max(8*faces.size(), 4096);
    const scalar maxVoxels = 2097152;
    scalar volume = 1, thinnest = GREAT;
    label nThick = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (span[d] > 1e-6*cmptMax(span))
        {
            volume *= span[d];
            thinnest = min(thinnest, span[d]);
            ++nThick;
        }
    }
    nThick = max(nThick, 1);
    voxelSize_ = min(std::pow(volume/wanted, 1.0/nThick), thinnest/8);
    voxelSize_ = max(voxelSize_, std::pow(volume/maxVoxels, 1.0/nThick));
    voxelSize_ = max(voxelSize_, VSMALL);
    voxelsPerLength_ = 1/voxelSize_;

    for (direction d = 0; d < vector::nComponents; ++d)
    {
        nVoxels_[d] = max(label(std::ceil(span[d]/voxelSize_)), 1);
    }
}


Foam::scalar Foam::polymer::wallClearance::voxelClearance
(
    const label index
) const
{
    const label k = index % nVoxels_.z();
    const label j = (index/nVoxels_.z()) % nVoxels_.y();
    const label i = index/(nVoxels_.z()*nVoxels_.y());
    const point centre
    (
        bounds_.min() + voxelSize_*vector(i + 0.5, j + 0.5, k + 0.5)
    );

    // Beyond eight half diagonals the nearest face (edge) is not sought
    const scalar halfDiagonal = 0.5*std::sqrt(3.0)*voxelSize_;
    const scalar searched = 8*halfDiagonal;
    const pointIndexHit nearest =
        edges_
      ? edges_->nearest(centre, sqr(searched))
      : faces_.nearest(centre, sqr(searched));
    const scalar distance =
        nearest.hit() ? mag(nearest.hitPoint() - centre) : searched;

    // Less a relative 1e-6 for the round-off of the two searches (and the
    // rounding to float)
    return max(distance - halfDiagonal, 0)*(1 - 1e-6);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::wallClearance::wallClearance(const boundaryFaces& faces)
:
    faces_(faces),
    edges_(nullptr),
    bounds_(),
    voxelSize_(1),
    voxelsPerLength_(1),
    nVoxels_(Zero),
    clearance_()
{
    if (faces.size())
    {
        layVoxels(faces);
        clearance_.setSize(nVoxels_.x()*nVoxels_.y()*nVoxels_.z(), -1);
    }
}


Foam::polymer::wallClearance::wallClearance
(
    const boundaryFaces& faces,
    const wallEdges& edges
)
:
    wallClearance(faces)
{
    // The same voxels: the edges lie on the faces
    edges_ = &edges;
}


// ************************************************************************* //
