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
#include "SubField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(periodicImages, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::periodicImages::addPatch(const label patchi)
{
    const cyclicPolyPatch& patch =
        refCast<const cyclicPolyPatch>(mesh().boundaryMesh()[patchi]);
    const cyclicPolyPatch& neighbour = patch.neighbPatch();

    const vectorField areas(patch.faceAreas());
    const vectorField centres(patch.faceCentres());
    const vectorField neighbourCentres(neighbour.faceCentres());

    // Sums over the faces of every processor: a patch may be empty here
    const label nFaces = returnReduce(patch.size(), sumOp<label>());
    if (nFaces == 0)
    {
        return;
    }

    const vector areaSum = gSum(areas);
    const vector normal = areaSum/max(mag(areaSum), VSMALL);
    const point centre = gSum(mag(areas)*centres)/gSum(mag(areas));
    const vector translation = gSum(neighbourCentres - centres)/nFaces;

    // Planar and translational: every face parallel to the plane and on
    // it, every face pair matched by the one translation
    const scalar span = max(mag(translation), SMALL);
    scalar worst = 0;
    forAll(patch, facei)
    {
        const vector n = areas[facei]/mag(areas[facei]);
        const vector mismatch =
            neighbourCentres[facei] - centres[facei] - translation;

        worst = max(worst, 1 - (n & normal));
        worst = max(worst, mag((centres[facei] - centre) & normal)/span);
        worst = max(worst, mag(mismatch)/span);
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicImages::periodicImages(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, periodicImages>(mesh),
    planePoint_(),
    planeNormal_(),
    translation_(),
    patch_(),
    patchTranslation_(mesh.boundaryMesh().size(), Zero),
    lattice_()
{
    forAll(mesh.boundaryMesh(), patchi)
    {
        if (isA<cyclicPolyPatch>(mesh.boundaryMesh()[patchi]))
        {
            addPatch(patchi);
        }
    }

    if (active())
    {
        Info<< "periodicImages: chains cross " << patch_.size()
            << " cyclic patches; translations " << lattice_ << endl;
    }
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::vector Foam::periodicImages::shift(const point& p) const
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


// ************************************************************************* //
