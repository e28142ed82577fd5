/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    flatVolPointInterpolation gives volPointInterpolation's point values to
    the bit: a field of the cell centres (a smooth non-linear vector field,
    other values on the patches) interpolated to the points of the box
    with an outlet (wallBox), the L-shaped channel (wallL) and the channel
    with cyclic patches in x and y between walls (periodicChannel, where
    the walls' points at the cyclic planes are patch points and the cyclic
    points are summed across) and the graded channel with a cyclic patch,
    symmetry planes and walls (symmetryChannel, whose symmetry planes
    meet at an oblique edge whose points pointConstraints constrains to
    the edge's direction; a test checks that these constraints change
    values the boundary conditions gave),
    compared component by component; that OpenFOAM's synchronisation of
    the collocated coupled points, which the class leaves out in a serial
    run whose cyclic patches are translated, changes nothing there (a sum
    over them of random values); then the same after the interior
    points were moved at random by up to 0.3 cells (irregular weights;
    both made again by the mesh's movePoints), on a mesh of its own read
    from the same case.
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "flatVolPointInterpolation.H"
#include "volPointInterpolation.H"
#include "pointConstraints.H"

#include <random>

using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// A smooth field with no symmetry the mesh shares
vector smoothField(const point& x)
{
    return vector
    (
        std::sin(1.3*x.x() + 0.7*x.y()) + x.z()*x.z(),
        std::cos(0.9*x.y()) * x.x() - 0.3*x.z(),
        std::exp(0.1*x.x()) + std::sin(2.1*x.z())*x.y()
    );
}


// The field at the cell centres, other values at the patch faces
tmp<volVectorField> testField(const fvMesh& mesh)
{
    auto tfield = tmp<volVectorField>::New
    (
        IOobject("flatTestU", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimless, Zero)
    );
    volVectorField& field = tfield.ref();
    forAll(mesh.C(), celli)
    {
        field[celli] = smoothField(mesh.C()[celli]);
    }
    for (fvPatchVectorField& patchField : field.boundaryFieldRef())
    {
        if (!patchField.coupled())
        {
            const vectorField& centres = patchField.patch().Cf();
            forAll(patchField, i)
            {
                patchField[i] = 2*smoothField(centres[i]) + vector(1, 0, 0);
            }
        }
    }
    field.correctBoundaryConditions();
    return tfield;
}


// Both interpolations' point values, compared to the bit
void expectSamePointValues(const fvMesh& mesh, const std::string& scene)
{
    tmp<volVectorField> tfield(testField(mesh));
    tmp<pointVectorField> expected
    (
        volPointInterpolation::New(mesh).interpolate(tfield())
    );
    tmp<pointVectorField> flat
    (
        polymer::flatVolPointInterpolation::New(mesh).interpolate
        (
            tfield(),
            "flatVolPointInterpolate(flatTestU)",
            false
        )
    );
    label nDifferent = 0;
    forAll(expected(), pointi)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (flat()[pointi][d] != expected()[pointi][d])
            {
                ++nDifferent;
                ADD_FAILURE()
                    << scene << " point " << pointi << " component " << d
                    << ": " << flat()[pointi][d] << " against "
                    << expected()[pointi][d];
            }
        }
        if (nDifferent > 10)
        {
            return;
        }
    }
    EXPECT_EQ(flat().size(), mesh.nPoints());
}


// Move every point off the boundary by up to a fraction of a cell
void moveInteriorPoints(fvMesh& mesh, const scalar fraction)
{
    boolList onBoundary(mesh.nPoints(), false);
    for (label facei = mesh.nInternalFaces(); facei < mesh.nFaces(); ++facei)
    {
        for (const label pointi : mesh.faces()[facei])
        {
            onBoundary[pointi] = true;
        }
    }
    const scalar cellSize = Foam::cbrt(gMin(mesh.V().field()));
    std::mt19937_64 generator(20261205);
    std::uniform_real_distribution<scalar> uniform(-1, 1);
    pointField points(mesh.points());
    forAll(points, pointi)
    {
        if (!onBoundary[pointi])
        {
            for (direction d = 0; d < 3; ++d)
            {
                points[pointi][d] += fraction*cellSize*uniform(generator);
            }
        }
    }
    mesh.movePoints(points);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(flatVolPointInterpolation, GivesVolPointInterpolationsValuesToTheBit)
{
    for
    (
        const word caseName
      : {"wallBox", "wallL", "periodicChannel", "symmetryChannel"}
    )
    {
        const fvMesh* mesh = meshOf(caseName);
        ASSERT_TRUE(mesh);
        expectSamePointValues(*mesh, caseName);
    }
}


TEST(flatVolPointInterpolation, MeetsPointConstraintsInTheSymmetryScene)
{
    // symmetryChannel's oblique symmetry planes: its point values with the
    // constraints of their edge (pointConstraints::constrain) are not those
    // with the planes' boundary conditions alone, so that the comparison
    // above would see the constraints left out
    const fvMesh* mesh = meshOf("symmetryChannel");
    ASSERT_TRUE(mesh);
    tmp<volVectorField> tfield(testField(*mesh));
    const volPointInterpolation& interpolation =
        volPointInterpolation::New(*mesh);
    tmp<pointVectorField> constrained(interpolation.interpolate(tfield()));
    pointVectorField conditionsAlone
    (
        IOobject("conditionsAlone", mesh->time().timeName(), *mesh),
        constrained()
    );
    interpolation.interpolateBoundaryField(tfield(), conditionsAlone);
    conditionsAlone.correctBoundaryConditions();
    pointConstraints::syncUntransformedData
    (
        *mesh,
        conditionsAlone.primitiveFieldRef(),
        maxMagSqrEqOp<vector>()
    );
    label nConstrained = 0;
    forAll(conditionsAlone, pointi)
    {
        nConstrained += (conditionsAlone[pointi] != constrained()[pointi]);
    }
    EXPECT_GT(nConstrained, 0);
}


TEST(flatVolPointInterpolation, TranslatedCyclicsHaveNoCollocatedPoints)
{
    // pointConstraints::syncUntransformedData sums nothing in a serial
    // mesh whose cyclic patches are translated: what is left out changes
    // no value
    for (const word caseName : {"periodicChannel", "symmetryChannel"})
    {
        const fvMesh* mesh = meshOf(caseName);
        ASSERT_TRUE(mesh);
        std::mt19937_64 generator(1205);
        std::uniform_real_distribution<scalar> uniform(-1, 1);
        scalarField values(mesh->nPoints());
        for (scalar& value : values)
        {
            value = uniform(generator);
        }
        scalarField synchronised(values);
        pointConstraints::syncUntransformedData
        (
            *mesh,
            synchronised,
            plusEqOp<scalar>()
        );
        label nChanged = 0;
        forAll(values, pointi)
        {
            nChanged += (synchronised[pointi] != values[pointi]);
        }
        EXPECT_EQ(nChanged, 0) << caseName;
        EXPECT_GT(mesh->globalData().coupledPatch().nPoints(), 0) << caseName;
    }
}


TEST(flatVolPointInterpolation, GivesTheSameBitsAfterThePointsMoved)
{
    for
    (
        const word caseName
      : {"wallL", "periodicChannel", "symmetryChannel"}
    )
    {
        // The shared mesh made the case; this test moves a mesh of its own
        ASSERT_TRUE(meshOf(caseName));
        const std::unique_ptr<caseMesh> own
        (
            readCaseMesh
            (
                getEnv("POLYMERCLOUD_PROJECT") + "/tests/logs/run",
                caseName
            )
        );
        fvMesh& mesh = *own->mesh;
        expectSamePointValues(mesh, caseName);
        moveInteriorPoints(mesh, 0.3);
        expectSamePointValues(mesh, caseName + " moved");
    }
}


// ************************************************************************* //
