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

#include "flatVolPointInterpolation.H"
#include "surfaceFields.H"
#include "emptyPolyPatch.H"
#include "emptyPointPatch.H"
#include "cyclicPolyPatch.H"
#include "pointConstraints.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(flatVolPointInterpolation, 0);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Rows of the given sizes, filled with the entries' values (second) in
// the entries' order, each in its row (first)
Foam::CompactListList<Foam::label> compactRows
(
    const Foam::labelUList& rowSizes,
    const Foam::UList<Foam::labelPair>& entries
)
{
    using namespace Foam;

    CompactListList<label> rows(rowSizes);
    labelList next(SubList<label>(rows.offsets(), rowSizes.size()));
    labelList& values = rows.m();
    for (const labelPair& entry : entries)
    {
        values[next[entry.first()]++] = entry.second();
    }
    return rows;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::polymer::flatVolPointInterpolation::interpolatesFromFaces
(
    const label patchi
) const
{
    // volPointInterpolation's test: coupled() of the face areas' patch
    // field, which knows whether a cyclicAMI patch couples
    return
        !isA<emptyPolyPatch>(mesh().boundaryMesh()[patchi])
     && !mesh().magSf().boundaryField()[patchi].coupled();
}


void Foam::polymer::flatVolPointInterpolation::makePatchPointFaces()
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    const label nPoints = mesh().nPoints();

    // Each point of each patch face, faces in the boundary's order, so
    // that each point's faces are listed as primitivePatch's pointFaces
    labelList nPointFaces(nPoints, Zero);
    DynamicList<labelPair> pointFace(nPoints);
    forAll(patches, patchi)
    {
        if (interpolatesFromFaces(patchi))
        {
            const polyPatch& patch = patches[patchi];
            const label start = patch.start() - mesh().nInternalFaces();
            forAll(patch, i)
            {
                for (const label pointi : patch[i])
                {
                    ++nPointFaces[pointi];
                    pointFace.append(labelPair(pointi, start + i));
                }
            }
        }
    }

    isPatchPoint_.setSize(nPoints);
    labelList patchPointi(nPoints, -1);
    DynamicList<label> patchPoints(nPoints);
    forAll(nPointFaces, pointi)
    {
        isPatchPoint_[pointi] = nPointFaces[pointi] > 0;
        if (isPatchPoint_[pointi])
        {
            patchPointi[pointi] = patchPoints.size();
            patchPoints.append(pointi);
        }
    }
    patchPoints_.transfer(patchPoints);

    for (labelPair& pf : pointFace)
    {
        pf.first() = patchPointi[pf.first()];
    }
    patchPointFaces_ = compactRows
    (
        labelList(UIndirectList<label>(nPointFaces, patchPoints_)),
        pointFace
    );
}


void Foam::polymer::flatVolPointInterpolation::makePointCells()
{
    const cellList& cells = mesh().cells();
    const faceList& faces = mesh().faces();
    const label nPoints = mesh().nPoints();

    // Each cell's points other than patch points, each taken once for the
    // cell by the mark of the last cell that took it, in one pass over the
    // cells; in the cells' order, so that each point's cells are listed as
    // primitiveMesh::pointCells lists them
    labelList lastCell(nPoints, -1);
    labelList nPointCells(nPoints, Zero);
    DynamicList<labelPair> pointCell(8*nPoints);
    forAll(cells, celli)
    {
        for (const label facei : cells[celli])
        {
            for (const label pointi : faces[facei])
            {
                if (lastCell[pointi] != celli && !isPatchPoint_[pointi])
                {
                    ++nPointCells[pointi];
                    pointCell.append(labelPair(pointi, celli));
                }
                lastCell[pointi] = celli;
            }
        }
    }
    pointCells_ = compactRows(nPointCells, pointCell);
}


void Foam::polymer::flatVolPointInterpolation::addInverseDistances
(
    scalarField& sumWeight
)
{
    const pointField& points = mesh().points();
    const vectorField& cellCentres = mesh().cellCentres();
    const vectorField& faceCentres = mesh().faceCentres();

    // Added to the sums in volPointInterpolation's order
    const labelList& cellStart = pointCells_.offsets();
    const labelList& cellOf = pointCells_.m();
    pointCellWeights_.setSize(cellOf.size());
    forAll(isPatchPoint_, pointi)
    {
        for (label k = cellStart[pointi]; k < cellStart[pointi + 1]; ++k)
        {
            pointCellWeights_[k] =
                1.0/mag(points[pointi] - cellCentres[cellOf[k]]);
            sumWeight[pointi] += pointCellWeights_[k];
        }
    }
    const labelList& faceStart = patchPointFaces_.offsets();
    const labelList& faceOf = patchPointFaces_.m();
    patchPointFaceWeights_.setSize(faceOf.size());
    forAll(patchPoints_, i)
    {
        const label pointi = patchPoints_[i];
        for (label k = faceStart[i]; k < faceStart[i + 1]; ++k)
        {
            const label facei = mesh().nInternalFaces() + faceOf[k];
            patchPointFaceWeights_[k] =
                1.0/mag(points[pointi] - faceCentres[facei]);
            sumWeight[pointi] += patchPointFaceWeights_[k];
        }
    }
}


void Foam::polymer::flatVolPointInterpolation::normaliseWeights
(
    const scalarField& sumWeight
)
{
    const labelList& cellStart = pointCells_.offsets();
    forAll(isPatchPoint_, pointi)
    {
        for (label k = cellStart[pointi]; k < cellStart[pointi + 1]; ++k)
        {
            pointCellWeights_[k] /= sumWeight[pointi];
        }
    }
    const labelList& faceStart = patchPointFaces_.offsets();
    forAll(patchPoints_, i)
    {
        for (label k = faceStart[i]; k < faceStart[i + 1]; ++k)
        {
            patchPointFaceWeights_[k] /= sumWeight[patchPoints_[i]];
        }
    }
}


bool Foam::polymer::flatVolPointInterpolation::constrainsPoints() const
{
    const pointBoundaryMesh& pointPatches = pointMesh::New(mesh()).boundary();
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    bool constrains = false;
    forAll(pointPatches, patchi)
    {
        const pointPatch& pointPatch = pointPatches[patchi];
        if (!isA<emptyPointPatch>(pointPatch) && !pointPatch.coupled())
        {
            for (const label pointi : patches[patchi].boundaryPoints())
            {
                pointConstraint constraint;
                pointPatch.applyConstraint(pointi, constraint);
                constrains = constrains || constraint.first() != 0;
            }
        }
    }
    return returnReduce(constrains, orOp<bool>());
}


bool Foam::polymer::flatVolPointInterpolation::collocatesPoints() const
{
    if (Pstream::parRun())
    {
        return true;
    }
    for (const polyPatch& patch : mesh().boundaryMesh())
    {
        const cyclicPolyPatch* cyclic =
            dynamic_cast<const cyclicPolyPatch*>(&patch);
        const bool translated =
            cyclic && cyclic->separated() && cyclic->parallel();
        if (patch.coupled() && !translated)
        {
            return true;
        }
    }
    return false;
}


void Foam::polymer::flatVolPointInterpolation::makeWeights()
{
    hasConstrainedPoints_ = constrainsPoints();
    hasCollocatedPoints_ = collocatesPoints();

    makePatchPointFaces();
    makePointCells();

    pointScalarField sumWeights
    (
        IOobject
        (
            "flatVolPointSumWeights",
            mesh().polyMesh::instance(),
            mesh()
        ),
        pointMesh::New(mesh()),
        dimensionedScalar(dimless, Zero)
    );
    addInverseDistances(sumWeights.primitiveFieldRef());

    // The sums over coupled points, as volPointInterpolation::makeWeights
    syncCollocated(sumWeights.primitiveFieldRef(), plusEqOp<scalar>());
    addSeparated(sumWeights);
    pushUntransformedData(sumWeights.primitiveFieldRef());

    normaliseWeights(sumWeights);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::flatVolPointInterpolation::flatVolPointInterpolation
(
    const fvMesh& mesh
)
:
    MeshObject<fvMesh, UpdateableMeshObject, flatVolPointInterpolation>(mesh),
    hasConstrainedPoints_(false),
    hasCollocatedPoints_(true)
{
    makeWeights();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::flatVolPointInterpolation::movePoints()
{
    makeWeights();
    return true;
}


void Foam::polymer::flatVolPointInterpolation::updateMesh(const mapPolyMesh&)
{
    makeWeights();
}


// ************************************************************************* //
