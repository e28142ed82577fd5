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

#include "periodicImages.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "SubField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(periodicImages, 0);
} // End namespace polymer
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::periodicImages::patchFaces
(
    const label patchi,
    vectorField& areas,
    pointField& centres
) const
{
    // A cyclic patch's own faces, and in a decomposed mesh those of the
    // processorCyclic patches made from it
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    labelList ids(processorCyclicPolyPatch::patchIDs
    (
        patches[patchi].name(),
        patches
    ));
    ids.append(patchi);

    DynamicList<vector> a;
    DynamicList<point> c;
    for (const label id : ids)
    {
        a.append(vectorField(patches[id].faceAreas()));
        c.append(pointField(patches[id].faceCentres()));
    }
    areas.transfer(a);
    centres.transfer(c);
}


Foam::point Foam::polymer::periodicImages::centroid
(
    const vectorField& areas,
    const pointField& centres
) const
{
    return gSum(mag(areas)*centres)/max(gSum(mag(areas)), VSMALL);
}


void Foam::polymer::periodicImages::addPatch(const label patchi)
{
    const cyclicPolyPatch& patch =
        refCast<const cyclicPolyPatch>(mesh().boundaryMesh()[patchi]);

    vectorField areas, neighbourAreas;
    pointField centres, neighbourCentres;
    patchFaces(patchi, areas, centres);
    patchFaces(patch.neighbPatchID(), neighbourAreas, neighbourCentres);

    if (returnReduce(areas.size(), sumOp<label>()) == 0)
    {
        return;
    }

    // The patches' planes, over the faces of every processor: the
    // translation maps the patch's centroid to its neighbour's
    const vector areaSum = gSum(areas);
    const vector normal = areaSum/max(mag(areaSum), VSMALL);
    const point centre = centroid(areas, centres);
    const vector translation =
        centroid(neighbourAreas, neighbourCentres) - centre;

    // Planar and translational: every face of both patches parallel to
    // the plane, and on its own patch's plane
    const scalar span = max(mag(translation), SMALL);
    const point neighbourCentre = centre + translation;
    scalar worst = 0;
    forAll(areas, facei)
    {
        const vector n = areas[facei]/mag(areas[facei]);
        worst = max(worst, 1 - (n & normal));
        worst = max(worst, mag((centres[facei] - centre) & normal)/span);
    }
    forAll(neighbourAreas, facei)
    {
        const vector n = neighbourAreas[facei]/mag(neighbourAreas[facei]);
        worst = max(worst, 1 + (n & normal));
        worst = max
        (
            worst,
            mag((neighbourCentres[facei] - neighbourCentre) & normal)/span
        );
    }
    reduce(worst, maxOp<scalar>());

    if (!patch.parallel() || worst > 1e-6)
    {
        FatalErrorInFunction
            << "Cyclic patch " << patch.name() << " of the mesh is not a"
            << " planar translational cyclic (mismatch " << worst << ")"
            << nl << "    expected: cyclic patches that are planes matched"
            << " by a translation; chains cannot cross rotational or"
            << " curved cyclics"
            << exit(FatalError);
    }

    planePoint_.append(centre);
    planeNormal_.append(normal);
    translation_.append(translation);
    patch_.append(patchi);
    patchTranslation_[patchi] = translation;

    if (patch.owner())
    {
        lattice_.append(translation);
    }
}


void Foam::polymer::periodicImages::setUnshiftedBox(const polyMesh& mesh)
{
    // The linear test (p - P).n is largest over a box at a corner, and its
    // round-off is below 1e-15 of the bounds' diagonal for points within
    // them: a corner below -1e-12 of the diagonal keeps the whole box
    // inside the plane in floating point too
    const boundBox bounds(mesh.points(), true);
    const scalar diagonal = bounds.mag();
    const vector margin(vector::uniform(1e-9*diagonal));
    const boundBox box(bounds.min() + margin, bounds.max() - margin);
    unshifted_ = boundBox::invertedBox;
    if (!active() || !box.valid())
    {
        return;
    }
    const tmp<pointField> corners(box.points());
    for (const point& corner : corners())
    {
        forAll(planePoint_, k)
        {
            const scalar beyond = (corner - planePoint_[k]) & planeNormal_[k];
            if (!(beyond < -1e-12*diagonal))
            {
                return;
            }
        }
    }
    unshifted_ = box;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::periodicImages::periodicImages(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, periodicImages>(mesh),
    planePoint_(),
    planeNormal_(),
    translation_(),
    patch_(),
    patchTranslation_(mesh.boundaryMesh().size(), Zero),
    lattice_(),
    imageShifts_(),
    unshifted_(boundBox::invertedBox)
{
    forAll(mesh.boundaryMesh(), patchi)
    {
        if (isA<cyclicPolyPatch>(mesh.boundaryMesh()[patchi]))
        {
            addPatch(patchi);
        }
    }

    DynamicList<vector> shifts(1, Zero);
    for (const vector& t : lattice_)
    {
        const label n = shifts.size();
        for (label k = 0; k < n; ++k)
        {
            shifts.append(shifts[k] + t);
            shifts.append(shifts[k] - t);
        }
    }
    imageShifts_.transfer(shifts);
    setUnshiftedBox(mesh);

    if (active())
    {
        Info<< "periodicImages: chains cross " << patch_.size()
            << " cyclic patches; translations " << lattice_ << endl;
    }
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::polymer::periodicImages::shiftByPlanes(const point& p) const
{
    // A point beyond several planes (a corner) needs a pass per plane; a
    // point many periods away needs more: stop after a generous number
    vector total(Zero);
    for (label pass = 0; pass < 64; ++pass)
    {
        bool moved = false;
        forAll(patch_, k)
        {
            if (((p + total - planePoint_[k]) & planeNormal_[k]) > 0)
            {
                total += translation_[k];
                moved = true;
            }
        }
        if (!moved)
        {
            break;
        }
    }
    return total;
}


bool Foam::polymer::periodicImages::overlapsImage
(
    const boundBox& a,
    const boundBox& b
) const
{
    if (a.overlaps(b))
    {
        return true;
    }
    if (!active())
    {
        return false;
    }
    for (const vector& shift : imageShifts_)
    {
        if (boundBox(a.min() + shift, a.max() + shift).overlaps(b))
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
