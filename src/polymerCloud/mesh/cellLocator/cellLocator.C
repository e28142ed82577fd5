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

#include "cellLocator.H"
#include "Random.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(cellLocator, 0);
} // End namespace polymer
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cellLocator::boxedCells::boxedCells
(
    const polyMesh& mesh,
    const List<treeBoundBox>& boxes
)
:
    treeDataCell(false, mesh, polyMesh::CELL_TETS),
    boxes_(boxes)
{}


Foam::polymer::cellLocator::cellLocator(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, cellLocator>(mesh),
    boxes_(mesh.nCells()),
    tree_(),
    planes_(mesh),
    fans_(mesh)
{
    const pointField& points = mesh.points();
    const cellList& cells = mesh.cells();
    const faceList& faces = mesh.faces();
    forAll(cells, celli)
    {
        treeBoundBox& bb = boxes_[celli];
        bb = treeBoundBox(boundBox::invertedBox);
        for (const label facei : cells[celli])
        {
            for (const label pointi : faces[facei])
            {
                bb.add(points[pointi]);
            }
        }
        bb.inflate(1e-6);
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::tetPointRef Foam::polymer::cellLocator::tetPoints
(
    const polyMesh& mesh,
    const label celli,
    const triFace& triangle
)
{
    // As tetIndices::tet takes them
    const pointField& meshPoints = mesh.points();
    return tetPointRef
    (
        mesh.cellCentres()[celli],
        meshPoints[triangle[0]],
        meshPoints[triangle[1]],
        meshPoints[triangle[2]]
    );
}


bool Foam::polymer::cellLocator::inTet
(
    const polyMesh& mesh,
    const point& p,
    const tetIndices& tet,
    tetPlace& place
)
{
    // cellPointWeight's acceptance: degenerate tets skipped, coordinates
    // down to -SMALL accepted (a point on a face shared by two tets or
    // two cells is in both). A tet is degenerate by its volume relative
    // to its cell's alone: tetrahedron::pointToBarycentric also gives
    // coordinates of 1/4 for a tet whose edge determinant is below SMALL
    // in absolute terms, which is every tet of a mesh in metres with
    // cells of a micrometre. Its arithmetic otherwise (tetTransform)
    place.triangle = tet.faceTriIs(mesh);
    return inTet(mesh, p, tet.cell(), place);
}


bool Foam::polymer::cellLocator::inTet
(
    const polyMesh& mesh,
    const point& p,
    const label celli,
    tetPlace& place
)
{
    const tetPointRef points(tetPoints(mesh, celli, place.triangle));
    const tensor edges(tetTransform::edgeMatrix(points));
    const scalar detT = det(edges);
    if (!(mag(detT/mesh.cellVolumes()[celli]) > SMALL))
    {
        return false;
    }
    place.transform = tetTransform(points, edges, detT);
    place.coordinates = place.transform.coordinates(p);
    return holds(place.coordinates);
}


bool Foam::polymer::cellLocator::isTetOf
(
    const polyMesh& mesh,
    const tetIndices& tet,
    const label celli
)
{
    const label facei = tet.face();
    return
        tet.cell() == celli
     && facei >= 0
     && facei < mesh.nFaces()
     && (
            mesh.faceOwner()[facei] == celli
         || (
                mesh.isInternalFace(facei)
             && mesh.faceNeighbour()[facei] == celli
            )
        )
     && tet.tetPt() >= 1
     && tet.tetPt() <= mesh.faces()[facei].size() - 2;
}


bool Foam::polymer::cellLocator::inTets
(
    const polyMesh& mesh,
    const point& p,
    const label celli,
    tetIndices& tet,
    tetPlace& place
)
{
    // A tet of this cell given in tet first: a bead a step later is most
    // often still in the tet that held it (a hint only: it may be stale)
    const tetIndices first(tet);
    const bool hasFirst = isTetOf(mesh, first, celli);
    if (hasFirst && inTet(mesh, p, first, place))
    {
        return true;
    }

    const faceList& faces = mesh.faces();
    for (const label facei : mesh.cells()[celli])
    {
        const label nTets = faces[facei].size() - 2;
        for (label tetPti = 1; tetPti <= nTets; ++tetPti)
        {
            if (hasFirst && facei == first.face() && tetPti == first.tetPt())
            {
                continue;
            }
            tet = tetIndices(celli, facei, tetPti);
            if (inTet(mesh, p, tet, place))
            {
                return true;
            }
        }
    }
    return false;
}


bool Foam::polymer::cellLocator::inCell
(
    const point& p,
    const label celli,
    tetIndices& tet,
    tetPlace& place
) const
{
    return
        boxes_[celli].contains(p)
     && inTets(mesh(), p, celli, tet, place);
}


bool Foam::polymer::cellLocator::inFan
(
    const point& p,
    const label celli,
    const label k,
    tetIndices& tet,
    tetPlace& place
) const
{
    const cellFaceFans::fan fan(fans_.faceFan(celli, k));
    const label nTets = fan.nTets();
    for (label tetPti = 1; tetPti <= nTets; ++tetPti)
    {
        place.triangle = fan.triangle(tetPti);
        if (inTet(mesh(), p, celli, place))
        {
            tet = tetIndices(celli, planes_.plane(celli, k).face, tetPti);
            return true;
        }
    }
    return false;
}


Foam::label Foam::polymer::cellLocator::rayWalk
(
    const point& p,
    label celli,
    tetIndices& tet,
    tetPlace& place
) const
{
    // Along the ray from each cell's centre to p: p is in the tets on the
    // face the ray leaves by, or beyond that face in the neighbour's. On
    // convex cells one or two tet tests; anything else (a non-convex or
    // warped cell, a boundary face, a long walk) is left to the walk
    const vectorField& centres = mesh().cellCentres();
    for (label stepi = 0; stepi < 16; ++stepi)
    {
        bool inside = false;
        const label k = planes_.exitPlane(p, centres[celli], celli, inside);
        if (k < 0)
        {
            return -1;
        }
        if (inside)
        {
            return inFan(p, celli, k, tet, place) ? celli : -1;
        }
        const label across = planes_.plane(celli, k).across;
        if (across < 0)
        {
            return -1;
        }
        celli = across;
    }
    return -1;
}


bool Foam::polymer::cellLocator::nearCell
(
    const point& p,
    const label celli
) const
{
    // Within two of the cell's sizes of its box
    const treeBoundBox& box = boxes_[celli];
    const vector reach(2*box.span());
    return boundBox(box.min() - reach, box.max() + reach).contains(p);
}


Foam::label Foam::polymer::cellLocator::walk
(
    const point& p,
    label celli,
    tetIndices& tet,
    tetPlace& place
) const
{
    if (inCell(p, celli, tet, place))
    {
        return celli;
    }

    const cellList& cells = mesh().cells();
    const labelList& owner = mesh().faceOwner();
    const labelList& neighbour = mesh().faceNeighbour();
    const vectorField& centres = mesh().cellCentres();
    scalar nearest = magSqr(centres[celli] - p);

    while (true)
    {
        label next = -1;
        for (const label facei : cells[celli])
        {
            if (!mesh().isInternalFace(facei))
            {
                continue;
            }
            const label other =
                (owner[facei] == celli) ? neighbour[facei] : owner[facei];
            if (inCell(p, other, tet, place))
            {
                return other;
            }
            const scalar distance = magSqr(centres[other] - p);
            if (distance < nearest)
            {
                nearest = distance;
                next = other;
            }
        }
        if (next < 0)
        {
            return -1;
        }
        celli = next;
    }
}


const Foam::indexedOctree<Foam::polymer::cellLocator::boxedCells>&
Foam::polymer::cellLocator::tree() const
{
    if (!tree_.valid())
    {
        // The domain and the tree's parameters of meshSearch::cellTree
        Random rndGen(261782);
        treeBoundBox overallBb(mesh().points());
        overallBb = overallBb.extend(rndGen, 1e-4);
        overallBb.min() -= point::uniform(ROOTVSMALL);
        overallBb.max() += point::uniform(ROOTVSMALL);

        tree_.reset
        (
            new indexedOctree<boxedCells>
            (
                boxedCells(mesh(), boxes_),
                overallBb,
                8,      // maxLevel
                10,     // leafSize
                6.0     // duplicity
            )
        );
    }
    return *tree_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::cellLocator::findCell(const point& p) const
{
    return mesh().bounds().contains(p) ? tree().findInside(p) : -1;
}


Foam::label Foam::polymer::cellLocator::findCell
(
    const point& p,
    const label previousCell
) const
{
    tetPlace place;
    return findTet(p, tetIndices(previousCell, -1, -1), place).cell();
}


Foam::tetIndices Foam::polymer::cellLocator::findTet
(
    const point& p,
    const label previousCell,
    barycentric& coordinates
) const
{
    return findTet(p, tetIndices(previousCell, -1, -1), coordinates);
}


Foam::tetIndices Foam::polymer::cellLocator::search
(
    const point& p,
    const tetIndices& previous,
    tetPlace& place
) const
{
    tetIndices tet(previous);
    if (previous.cell() >= 0)
    {
        // Most of the beads that left their tet are found along the ray
        // from their cell's centre
        if (rayWalk(p, previous.cell(), tet, place) >= 0)
        {
            return tet;
        }
        tet = previous;
        if
        (
            nearCell(p, previous.cell())
         && walk(p, previous.cell(), tet, place) >= 0
        )
        {
            return tet;
        }
    }

    // The tree gives the cell (rare: a first search, a walk that stopped
    // short) and, from its inside test, the tet: the one inTets finds in
    // the cell's order, unless it was given a tet of that cell to try
    // first
    const label celli = findCell(p);
    if (celli < 0)
    {
        return tetIndices();
    }
    if (tet.cell() != celli)
    {
        place = tree().shapes().foundPlace();
        return tree().shapes().foundTet();
    }
    if (!inTets(mesh(), p, celli, tet, place))
    {
        return tetIndices();
    }
    return tet;
}


Foam::tetIndices Foam::polymer::cellLocator::findTet
(
    const point& p,
    const tetIndices& previous,
    barycentric& coordinates
) const
{
    tetPlace place;
    const tetIndices tet(findTet(p, previous, place));
    coordinates = place.coordinates;
    return tet;
}


Foam::tetIndices Foam::polymer::cellLocator::findTet
(
    const point& p,
    const tetIndices& previous,
    tetPlace& place
) const
{
    // Most beads are still in the tet that held them
    if
    (
        previous.cell() >= 0
     && isTetOf(mesh(), previous, previous.cell())
     && inTet(mesh(), p, previous, place)
    )
    {
        return previous;
    }
    return search(p, previous, place);
}


Foam::polymer::tetTransform Foam::polymer::cellLocator::transform
(
    const tetIndices& tet
) const
{
    return transform(tet.cell(), tet.faceTriIs(mesh()));
}


Foam::polymer::tetTransform Foam::polymer::cellLocator::transform
(
    const label celli,
    const triFace& triangle
) const
{
    const tetPointRef points(tetPoints(mesh(), celli, triangle));
    const tensor edges(tetTransform::edgeMatrix(points));
    return tetTransform(points, edges, det(edges));
}


void Foam::polymer::cellLocator::prefetch
(
    const label celli,
    const int stage
) const
{
#if defined(__GNUC__)
    if (celli < 0)
    {
        return;
    }
    if (stage == 0)
    {
        planes_.prefetch(celli, 0);
        fans_.prefetch(celli, 0);
        __builtin_prefetch(&mesh().cellCentres()[celli]);
        __builtin_prefetch(&mesh().cellVolumes()[celli]);
    }
    else
    {
        planes_.prefetch(celli, 1);
        fans_.prefetch(celli, 1);
    }
#endif
}


// ************************************************************************* //
