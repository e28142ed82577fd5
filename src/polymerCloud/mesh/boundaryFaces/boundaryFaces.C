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

#include "boundaryFaces.H"
#include "processorBounds.H"
#include "emptyPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "periodicImages.H"
#include "PstreamBuffers.H"
#include "Random.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef Foam::treeDataPrimitivePatch<Foam::primitiveFacePatch> treeFaces;

// Where the faces lie (boundaryFaces' centres, normals, warps and radii):
// every point of a face, a fan of triangles about its centre, is within
// its warp of its plane and within its radius of its centre
struct faceBounds
{
    const Foam::pointField& centres;
    const Foam::vectorField& normals;
    const Foam::scalarField& warps;
    const Foam::scalarField& radii;

    // The distance of p from face i's plane, out of the domain
    Foam::scalar planeDistance(const Foam::label i, const Foam::point& p)
    const
    {
        return normals[i] & (p - centres[i]);
    }

    // A distance from the segment p0-p1 within which face i does not lie
    // (p0 = p1 for a point): its plane less its warp, where the segment
    // stays on one side (a linear function: least at an end), and its
    // centre's distance from the segment's nearest point less its radius
    Foam::scalar segmentBound
    (
        const Foam::label i,
        const Foam::point& p0,
        const Foam::point& p1
    ) const
    {
        const Foam::scalar h0 = planeDistance(i, p0);
        const Foam::scalar h1 = planeDistance(i, p1);
        const Foam::scalar plane =
            ((h0 > 0) == (h1 > 0) && h0 != 0 && h1 != 0)
          ? Foam::min(Foam::mag(h0), Foam::mag(h1)) - warps[i]
          : -warps[i];

        const Foam::vector segment(p1 - p0);
        const Foam::scalar lengthSqr = Foam::magSqr(segment);
        const Foam::vector d0(p0 - centres[i]);
        const Foam::scalar along =
            lengthSqr > 0
          ? Foam::min(Foam::max(-(d0 & segment)/lengthSqr, 0), 1)
          : 0;
        const Foam::scalar centre = Foam::mag(d0 + along*segment) - radii[i];

        return Foam::max(plane, centre);
    }

    // A distance from the point p within which face i does not lie,
    // tighter than segmentBound's for a point beside the face: a point of
    // the face is at least |h| less the warp off the plane (h: p's
    // distance from it) and, along the plane, at least the distance of
    // p's projection from the centre less the radius (less a relative
    // 1e-7 of p's distance from the centre, far above the round-off of
    // that projection's length where h takes nearly all of it)
    Foam::scalar pointBound(const Foam::label i, const Foam::point& p) const
    {
        const Foam::vector d(p - centres[i]);
        const Foam::scalar h = normals[i] & d;
        const Foam::scalar dSqr = Foam::magSqr(d);
        const Foam::scalar dMag = std::sqrt(dSqr);
        const Foam::scalar across =
            Foam::max(Foam::mag(h) - warps[i], 0);
        const Foam::scalar along = Foam::max
        (
            std::sqrt(Foam::max(dSqr - Foam::sqr(h), 0))
          - radii[i] - 1e-7*dMag,
            0
        );
        return Foam::max
        (
            dMag - radii[i],
            std::sqrt(Foam::sqr(across) + Foam::sqr(along))
        );
    }
};


// The intersection of a segment with a face it enters along the face's
// outward area vector (from the fluid side); faces it leaves are passed,
// and so are faces whose plane band (the plane less the warp) the
// segment's end does not reach: a segment that enters along the area
// vector and ends on the fluid side of the band lies there whole, and
// the exact intersection (a fan of triangles about the face's centre)
// would find nothing
class enteringFaceOp
{
    const Foam::indexedOctree<treeFaces>& tree_;
    const Foam::vectorField& areas_;
    const faceBounds bounds_;

public:

    enteringFaceOp
    (
        const Foam::indexedOctree<treeFaces>& tree,
        const Foam::vectorField& areas,
        const faceBounds& bounds
    )
    :
        tree_(tree),
        areas_(areas),
        bounds_(bounds)
    {}

    bool operator()
    (
        const Foam::label index,
        const Foam::point& start,
        const Foam::point& end,
        Foam::point& hitPoint
    ) const
    {
        if (!(((end - start) & areas_[index]) > 0))
        {
            return false;
        }

        // Short of the band by more than round-off (the margin's square
        // roots only for an end beyond the band)
        const Foam::scalar h = bounds_.planeDistance(index, end);
        const Foam::scalar warp = bounds_.warps[index];
        if (h < -warp)
        {
            const Foam::scalar margin =
                1e-9
               *(
                    Foam::mag(end - bounds_.centres[index])
                  + Foam::mag(end - start)
                );
            if (h < -(warp + margin))
            {
                return false;
            }
        }
        return treeFaces::findIntersection(tree_, index, start, end, hitPoint);
    }
};


// The nearest face to a sample, passing over the faces whose bounds lie
// farther than the nearest found so far: the exact nearest point of a
// face (a fan of triangles about its centre) is what a search near the
// walls spends its time on, and most faces within the search's reach are
// farther than the nearest. A face is passed over only where its bound
// exceeds the nearest distance by more than round-off, so the same face
// is found
class boundedNearestOp
{
    const Foam::primitiveFacePatch& patch_;
    const faceBounds bounds_;

public:

    boundedNearestOp
    (
        const Foam::primitiveFacePatch& patch,
        const faceBounds& bounds
    )
    :
        patch_(patch),
        bounds_(bounds)
    {}

    void operator()
    (
        const Foam::labelUList& indices,
        const Foam::point& sample,
        Foam::scalar& nearestDistSqr,
        Foam::label& minIndex,
        Foam::point& nearestPoint
    ) const
    {
        for (const Foam::label index : indices)
        {
            const Foam::scalar bound = bounds_.pointBound(index, sample);
            if (bound > 0 && Foam::sqr(bound) > nearestDistSqr*(1 + 1e-9))
            {
                continue;
            }

            const Foam::pointHit hit
            (
                patch_[index].nearestPoint(sample, patch_.points())
            );
            const Foam::scalar distSqr = Foam::sqr(hit.distance());
            if (distSqr < nearestDistSqr)
            {
                nearestDistSqr = distSqr;
                minIndex = index;
                nearestPoint = hit.rawPoint();
            }
        }
    }

    // The nearest face to a line is not sought
    void operator()
    (
        const Foam::labelUList&,
        const Foam::linePointRef&,
        Foam::treeBoundBox&,
        Foam::label&,
        Foam::point&,
        Foam::point&
    ) const
    {
        FatalErrorInFunction
            << "Not implemented" << Foam::abort(Foam::FatalError);
    }
};


// Append a face, with points of its own, to lists
void appendFace
(
    const Foam::UList<Foam::point>& facePoints,
    const Foam::vector& area,
    const Foam::label patchi,
    Foam::DynamicList<Foam::point>& points,
    Foam::DynamicList<Foam::face>& faces,
    Foam::DynamicList<Foam::vector>& areas,
    Foam::DynamicList<Foam::label>& patches
)
{
    using namespace Foam;
    using namespace Foam::polymer;

    face f(facePoints.size());
    forAll(facePoints, k)
    {
        f[k] = points.size();
        points.append(facePoints[k]);
    }
    faces.append(f);
    areas.append(area);
    patches.append(patchi);
}


} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::boundaryFaces::addOwnFaces(const polyMesh& mesh)
{
    DynamicList<point> points;
    DynamicList<face> faces;
    DynamicList<vector> areas;
    DynamicList<label> patches;

    const polyBoundaryMesh& boundary = mesh.boundaryMesh();
    forAll(boundary, patchi)
    {
        const polyPatch& pp = boundary[patchi];
        label kind = patchi;
        if (isA<processorCyclicPolyPatch>(pp))
        {
            kind = refCast<const processorCyclicPolyPatch>(pp).referPatchID();
        }
        else if (isA<emptyPolyPatch>(pp) || isA<processorPolyPatch>(pp))
        {
            continue;
        }

        forAll(pp, k)
        {
            const label facei = pp.start() + k;
            appendFace
            (
                UIndirectList<point>(mesh.points(), mesh.faces()[facei])(),
                mesh.faceAreas()[facei],
                kind,
                points, faces, areas, patches
            );
        }
    }

    points_.transfer(points);
    faces_.transfer(faces);
    areas_.transfer(areas);
    patch_.transfer(patches);
    nOwnFaces_ = faces_.size();
}


void
Foam::polymer::boundaryFaces::addHalo(const polyMesh& mesh, const scalar reach)
{
    if (!Pstream::parRun())
    {
        return;
    }

    // Every processor's own mesh bounds grown by the reach (a processor
    // without cells has an inverted box, and needs no faces)
    List<boundBox> reachBox(processorBounds::New(mesh).bounds());
    for (boundBox& bb : reachBox)
    {
        if (bb.valid())
        {
            bb.min() -= vector::uniform(reach);
            bb.max() += vector::uniform(reach);
        }
    }

    const periodicImages& periodic = periodicImages::New(mesh);

    // Own faces within each other processor's reach, at any image
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(reachBox, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }

        DynamicList<label> sizes;
        DynamicList<point> points;
        DynamicList<vector> areas;
        DynamicList<label> patches;
        for (label facei = 0; facei < nOwnFaces_; ++facei)
        {
            const face& f = faces_[facei];
            const SubList<point> facePoints(points_, f.size(), f[0]);
            const boundBox faceBox(facePoints, false);
            if (periodic.overlapsImage(reachBox[proci], faceBox))
            {
                sizes.append(f.size());
                points.append(facePoints);
                areas.append(areas_[facei]);
                patches.append(patch_[facei]);
            }
        }
        if (sizes.size())
        {
            UOPstream os(proci, buffers);
            os  << sizes << points << areas << patches;
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    DynamicList<point> points(points_);
    DynamicList<face> faces(faces_);
    DynamicList<vector> areas(areas_);
    DynamicList<label> patches(patch_);
    forAll(recvSizes, proci)
    {
        if (!recvSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, buffers);
        const labelList sizes(is);
        const pointField facePoints(is);
        const vectorField faceAreas(is);
        const labelList facePatches(is);
        label first = 0;
        forAll(sizes, k)
        {
            appendFace
            (
                SubList<point>(facePoints, sizes[k], first),
                faceAreas[k],
                facePatches[k],
                points, faces, areas, patches
            );
            first += sizes[k];
        }
    }

    points_.transfer(points);
    faces_.transfer(faces);
    areas_.transfer(areas);
    patch_.transfer(patches);
}


Foam::treeBoundBox Foam::polymer::boundaryFaces::treeBounds
(
    const pointField& points
)
{
    // As meshSearch's boundary tree: a box a little larger than the
    // points, not aligned with them
    Random random(123456);
    treeBoundBox bb(treeBoundBox(points).extend(random, 1e-4));
    bb.min() -= point::uniform(ROOTVSMALL);
    bb.max() += point::uniform(ROOTVSMALL);
    return bb;
}


void Foam::polymer::boundaryFaces::buildTree()
{
    if (faces_.empty())
    {
        return;
    }

    facePatch_.reset(new primitiveFacePatch(faces_, points_));

    centres_.setSize(faces_.size());
    normals_.setSize(faces_.size());
    warps_.setSize(faces_.size());
    radii_.setSize(faces_.size());
    forAll(faces_, facei)
    {
        const point centre(faces_[facei].centre(points_));
        const vector normal(areas_[facei]/max(mag(areas_[facei]), VSMALL));
        scalar warp = 0, radius = 0;
        for (const label pointi : faces_[facei])
        {
            const vector d(points_[pointi] - centre);
            warp = max(warp, mag(normal & d));
            radius = max(radius, mag(d));
        }
        centres_[facei] = centre;
        normals_[facei] = normal;
        warps_[facei] = warp;
        radii_[facei] = radius;
    }

    faceBoxes_.setSize(faces_.size());
    forAll(faces_, facei)
    {
        faceBoxes_[facei] = boundBox(points_, faces_[facei], false);
    }
    faceGrid_.reset(new boxGrid(faceBoxes_));

    const treeBoundBox bb(treeBounds(points_));
    tree_.reset
    (
        new indexedOctree<treeFaces>
        (
            treeFaces(false, facePatch_(), 0),
            bb,
            8,      // maximum depth
            10,     // faces per leaf to refine
            3.0     // duplicity
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::boundaryFaces::boundaryFaces
(
    const polyMesh& mesh,
    const scalar reach
)
:
    points_(),
    faces_(),
    areas_(),
    patch_(),
    nOwnFaces_(0),
    centres_(),
    normals_(),
    warps_(),
    radii_(),
    facePatch_(),
    tree_(),
    faceGrid_(),
    faceBoxes_()
{
    addOwnFaces(mesh);
    addHalo(mesh, reach);
    buildTree();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pointIndexHit Foam::polymer::boundaryFaces::firstEntered
(
    const point& start,
    const point& end
) const
{
    if (!tree_.valid())
    {
        return pointIndexHit();
    }
    return tree_->findLine
    (
        start,
        end,
        enteringFaceOp
        (
            tree_(), areas_, faceBounds{centres_, normals_, warps_, radii_}
        )
    );
}


Foam::scalar Foam::polymer::boundaryFaces::clearance
(
    const point& p,
    const scalar reach
) const
{
    // A path of no length: the planes' and centres' bounds at p
    return pathClearance(p, p, reach);
}


Foam::scalar Foam::polymer::boundaryFaces::pathClearance
(
    const point& p0,
    const point& p1,
    const scalar reach
) const
{
    // A face nearer than reach to the segment has a point in its box
    // widened by reach, so its bounds overlap that, and the octree's test
    // of the face against the box (as its findBox would list it) passes.
    // That test, the costlier, is made only for a face whose bound would
    // lower the least so far: the least is the same
    if (!tree_.valid() || !(reach > 0))
    {
        return max(reach, 0);
    }
    const vector half(vector::uniform(reach));
    const treeBoundBox box(min(p0, p1) - half, max(p0, p1) + half);
    const treeFaces& shapes = tree_->shapes();
    const faceBounds bounds{centres_, normals_, warps_, radii_};
    scalar lowest = reach;
    faceGrid_->forNear
    (
        box,
        [&](const label facei)
        {
            // The octree's own first test of a face against a box: its
            // points' box must overlap it (the grid offers other faces)
            if (!faceBoxes_[facei].overlaps(box))
            {
                return;
            }
            const scalar bound = bounds.segmentBound(facei, p0, p1);
            if (bound < lowest && shapes.overlaps(facei, box))
            {
                lowest = bound;
            }
        }
    );
    return max(lowest, 0);
}


Foam::pointIndexHit Foam::polymer::boundaryFaces::nearest
(
    const point& p,
    const scalar maxDistSqr
) const
{
    if (!tree_.valid())
    {
        return pointIndexHit();
    }
    return tree_->findNearest
    (
        p,
        maxDistSqr,
        boundedNearestOp
        (
            facePatch_(), faceBounds{centres_, normals_, warps_, radii_}
        )
    );
}


// ************************************************************************* //
