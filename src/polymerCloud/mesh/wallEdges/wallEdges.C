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

#include "wallEdges.H"
#include "mergePoints.H"
#include "primitiveFacePatch.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::wallEdges::wallEdges
(
    const boundaryFaces& faces,
    const boolList& rebounds
)
:
    points_(),
    edges_(),
    patch_(),
    tree_(),
    edgeBoxes_(),
    grid_()
{
    if (!faces.size())
    {
        return;
    }

    // Points merged by position: a halo face's points are copies of its
    // processor's, equal to the last bit
    const boundBox bounds(faces.points());
    labelList pointMap;
    List<point> merged;
    mergePoints
    (
        faces.points(), 1e-12*mag(bounds.span()), false, pointMap, merged
    );
    faceList mergedFaces(faces.faces());
    for (face& f : mergedFaces)
    {
        inplaceRenumber(pointMap, f);
    }
    points_.transfer(merged);

    const primitiveFacePatch patch(mergedFaces, points_);
    const edgeList& edges = patch.edges();
    const labelListList& edgeFaces = patch.edgeFaces();
    const labelList& meshPoints = patch.meshPoints();
    const pointField centres(patch.faceCentres());

    DynamicList<edge> convex;
    DynamicList<label> convexPatch;
    forAll(edges, edgei)
    {
        const labelList& adjacent = edgeFaces[edgei];
        if (adjacent.size() != 2)
        {
            continue;
        }
        const label f0 = adjacent[0];
        const label f1 = adjacent[1];
        if (!rebounds[faces.patch(f0)] || !rebounds[faces.patch(f1)])
        {
            continue;
        }

        // Each face beyond the other's plane, on the solid side
        const vector& a0 = faces.area(f0);
        const vector& a1 = faces.area(f1);
        const scalar size = sqrt(max(mag(a0), mag(a1)));
        const vector d = centres[f1] - centres[f0];
        if
        (
            (d & a0)/mag(a0) > 1e-8*size
         && (-d & a1)/mag(a1) > 1e-8*size
        )
        {
            const edge& e = edges[edgei];
            convex.append(edge(meshPoints[e.start()], meshPoints[e.end()]));
            convexPatch.append(faces.patch(f0));
        }
    }
    edges_.transfer(convex);
    patch_.transfer(convexPatch);

    if (edges_.empty())
    {
        return;
    }

    tree_.reset
    (
        new indexedOctree<treeDataEdge>
        (
            treeDataEdge(true, edges_, points_, identity(edges_.size())),
            boundaryFaces::treeBounds(points_),
            8,      // maximum depth
            10,     // edges per leaf to refine
            3.0     // duplicity
        )
    );

    edgeBoxes_.setSize(edges_.size());
    forAll(edges_, edgei)
    {
        edgeBoxes_[edgei] = boundBox(start(edgei));
        edgeBoxes_[edgei].add(end(edgei));
    }
    grid_.reset(new boxGrid(edgeBoxes_));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::polymer::wallEdges::near(const boundBox& box) const
{
    if (!grid_)
    {
        return labelList();
    }

    // The edges the octree's findBox finds, by its test of an edge against
    // the box (the segment's, not the edge's box), in the edges' order
    // rather than a hash set's, and without the descent and the set
    const treeBoundBox searchBox(box);
    const treeDataEdge& shapes = tree_->shapes();
    DynamicList<label> found;
    grid_->forNear
    (
        box,
        [&](const label edgei)
        {
            if
            (
                edgeBoxes_[edgei].overlaps(searchBox)
             && shapes.overlaps(edgei, searchBox)
            )
            {
                found.append(edgei);
            }
        }
    );
    Foam::sort(found);
    return labelList(std::move(found));
}


Foam::pointIndexHit Foam::polymer::wallEdges::nearest
(
    const point& p,
    const scalar distSqr
) const
{
    if (!tree_)
    {
        return pointIndexHit();
    }
    return tree_->findNearest(p, distSqr);
}


// ************************************************************************* //
