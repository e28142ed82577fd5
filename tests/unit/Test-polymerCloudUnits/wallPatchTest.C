/*---------------------------------------------------------------------------*\
Description
    Unit tests of wallModel's patch interactions and of the wall models on
    patches other than walls: a path to an outlet (escape, and the
    patchInteraction overrides rebound and stick), levelSet against the
    exact intersection on grid-aligned walls, and paths carried across
    cyclic patches.
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "periodicImages.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;


// A path to the outlet (type patch): the bead stops there and is recorded
// as escaped; then patchInteraction overrides (outlet rebound, stick)
TEST(wallModels, outletEscape)
{
    const fvMesh* mesh = meshOf("wallBox");
    ASSERT_TRUE(mesh);
    const label outlet = patchIndex(*mesh, "outlet");
    ASSERT_GE(outlet, 0);

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> model = newWall(*mesh, type);
        EXPECT_TRUE(model->interaction(outlet) == wallModel::interactionType::escape);
        EXPECT_TRUE
        (
            model->interaction(patchIndex(*mesh, "walls"))
         == wallModel::interactionType::rebound
        );

        wallModel::impact hit;
        const point x0(9, 5.5, 4.5);
        const vector v0(2, 0.2, 0);
        ASSERT_TRUE(model->predict(x0, v0, 1, hit));
        EXPECT_NEAR(hit.time, 0.5, 1e-8);
        EXPECT_EQ(hit.patch, outlet);
        EXPECT_NEAR(mag(hit.normal - vector(-1, 0, 0)), 0, 1e-9);

        // Bead 1 of a two-bead chain reaches the outlet
        beadPaths p
        (
            {point(8, 5.5, 4.5), x0},
            {point(8.5, 5.5, 4.5), x0 + v0},
            {vector(0.5, 0, 0), v0}
        );
        model->correct(p.chains, p.positionsOld, 1, 0);
        ASSERT_EQ(model->escapedBeads().size(), 1);
        EXPECT_EQ(model->escapedBeads()[0], 1);
        // Stopped at the outlet (path velocity zeroed), in the fluid
        const point end = p.chains.positions()[1];
        EXPECT_NEAR(mag(end - (x0 + 0.5*v0)), 0, 1e-8);
        EXPECT_LE(end.x(), 10);
        EXPECT_EQ(model->count().rebounds, 0);
        // Bead 0 is untouched
        EXPECT_EQ(p.chains.positions()[0], point(8.5, 5.5, 4.5));
        model->clearEscaped();
        EXPECT_TRUE(model->escapedBeads().empty());
    }
}


TEST(wallModels, patchInteractionOverride)
{
    const fvMesh* mesh = meshOf("wallBox");
    ASSERT_TRUE(mesh);
    const label outlet = patchIndex(*mesh, "outlet");
    const label walls = patchIndex(*mesh, "walls");

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);

        // outlet rebound: the bead turns back at x = 10 and ends at x = 9
        {
            autoPtr<wallModel> model =
                newWall(*mesh, type, "patchInteraction { outlet rebound; }");
            EXPECT_TRUE(model->interaction(outlet) == wallModel::interactionType::rebound);
            beadPaths p({point(9, 5.5, 4.5)}, {point(11, 5.9, 4.5)}, {vector(2, 0.4, 0)});
            model->correct(p.chains, p.positionsOld, 1, 0);
            EXPECT_TRUE(model->escapedBeads().empty());
            EXPECT_EQ(model->count().rebounds, 1);
            EXPECT_NEAR(mag(p.chains.positions()[0] - point(9, 5.9, 4.5)), 0, 1e-8);
            EXPECT_NEAR(mag(p.chains.velocities()[0] - vector(-2, 0.4, 0)), 0, 1e-9);
        }

        // Regular expression; walls escape, outlet stick
        {
            autoPtr<wallModel> model = newWall
            (
                *mesh, type,
                "patchInteraction { \"out.*\" stick; walls escape; }"
            );
            EXPECT_TRUE(model->interaction(outlet) == wallModel::interactionType::stick);
            EXPECT_TRUE(model->interaction(walls) == wallModel::interactionType::escape);

            beadPaths p
            (
                {point(9, 5.5, 4.5), point(5, 5, 1)},
                {point(11, 5.9, 4.5), point(5, 5, -1)},
                {vector(2, 0.4, 0), vector(0, 0, -2)}
            );
            model->correct(p.chains, p.positionsOld, 1, 0);
            // Bead 0 sticks at the outlet: v-dagger zero
            EXPECT_NEAR(mag(p.chains.positions()[0] - point(10, 5.7, 4.5)), 0, 1e-8);
            EXPECT_EQ(p.chains.velocities()[0], vector::zero);
            EXPECT_EQ(model->count().stuck, 1);
            // Bead 1 escapes through the walls
            ASSERT_EQ(model->escapedBeads().size(), 1);
            EXPECT_EQ(model->escapedBeads()[0], 1);
            EXPECT_NEAR
            (
                mag(p.chains.positions()[1] - point(5, 5, clearanceOf(type))),
                0, 1e-8
            );
        }

        // A name that matches no patch stops with a FatalIOError
        EXPECT_THROW
        (
            newWall(*mesh, type, "patchInteraction { inlet rebound; }"),
            Foam::error
        );
        // An unknown interaction too
        EXPECT_THROW
        (
            newWall(*mesh, type, "patchInteraction { outlet bounce; }"),
            Foam::error
        );
    }
}


// levelSet against the exact intersection on the walls of the box (aligned
// with the grid): random paths from inside the box. Impacts at least two
// cells from the box's edges are compared strictly (there the distance is
// that of one wall, and its interpolation exact); those within one cell of
// an edge, where the distance and its gradient mix two walls, are reported
TEST(wallModels, levelSetMatchesExactOnGridWalls)
{
    const fvMesh* mesh = meshOf("wallBox");
    ASSERT_TRUE(mesh);
    autoPtr<wallModel> exact = newWall(*mesh, "meshFaces");
    autoPtr<wallModel> levelSet = newWall(*mesh, "levelSet");
    const label walls = patchIndex(*mesh, "walls");

    std::mt19937_64 gen(2007);
    std::uniform_real_distribution<double> uniform(0, 1);
    label nCompared = 0, nEdge = 0, nEdgeMissed = 0;
    scalar maxTimeError = 0, maxNormalError = 0;
    scalar edgeTimeError = 0, edgeNormalError = 0;
    for (label k = 0; k < 20000 && nCompared < 300; ++k)
    {
        const point x(1 + 8*uniform(gen), 1 + 8*uniform(gen), 1 + 8*uniform(gen));
        const vector v = (0.5 + 4*uniform(gen))*randomDirection(gen);
        wallModel::impact e, l;
        if (!exact->predict(x, v, 1, e) || e.patch != walls) continue;
        // Paths that reach the level set's zero well within the step
        if (e.time - levelSetClearance/mag(v & e.normal) < 0.01) continue;
        const point p = x + e.time*v;

        // Distance of the impact point to the nearest edge of its wall
        scalar edgeDistance = GREAT;
        for (direction d = 0; d < 3; ++d)
        {
            if (mag(e.normal[d]) > 0.5) continue;
            edgeDistance = min(edgeDistance, min(p[d], 10 - p[d]));
        }

        const bool found = levelSet->predict(x, v, 1, l);
        if (found)
        {
            // The interpolated distance is a convex combination of the
            // cell centres' (inverse-distance weights to the points, a
            // tet's barycentric ones), each within a cell diagonal and a
            // half of the impact point, and the distance is 1-Lipschitz:
            // the impact lies within 1.5 sqrt(3) h of the clearance from
            // the walls (h = 1 here), near an edge too
            const point q = x + l.time*v;
            scalar wallDistance = GREAT;
            for (direction d = 0; d < 3; ++d)
            {
                wallDistance = min(wallDistance, min(q[d], 10 - q[d]));
            }
            EXPECT_LE
            (
                mag(wallDistance - levelSetClearance), 1.5*std::sqrt(3.0)
            ) << str(x) << ' ' << str(v);
        }
        if (edgeDistance < 1)
        {
            // Near an edge the normal blends the two walls' (the distance's
            // kink), so only the impact's position is bounded (above)
            if (!found) { ++nEdgeMissed; continue; }
            edgeTimeError = max
            (
                edgeTimeError,
                mag(l.time - (e.time - levelSetClearance/mag(v & e.normal)))*mag(v)
            );
            edgeNormalError = max(edgeNormalError, mag(l.normal - e.normal));
            ++nEdge;
            continue;
        }
        if (edgeDistance < 2) continue;

        ASSERT_TRUE(found) << str(x) << ' ' << str(v);
        // The level set's zero is the clearance c in front of the wall
        const scalar tExpected = e.time - levelSetClearance/mag(v & e.normal);
        maxTimeError = max(maxTimeError, mag(l.time - tExpected)*mag(v));
        maxNormalError = max(maxNormalError, mag(l.normal - e.normal));
        EXPECT_EQ(l.patch, e.patch);
        ++nCompared;
    }
    std::cout << "[   INFO   ] levelSet vs meshFaces, " << nCompared
        << " impacts >= 2 cells from an edge: max position error "
        << maxTimeError << ", max |n - n_exact| " << maxNormalError << nl
        << "[   INFO   ] within 1 cell of an edge (" << nEdge << " impacts, "
        << nEdgeMissed << " missed): max position error " << edgeTimeError
        << ", max |n - n_exact| " << edgeNormalError << std::endl;
    // A path that meets a wall of the (convex) box ends outside it, so its
    // samples bracket the level set's zero: none is missed near an edge
    EXPECT_EQ(nEdgeMissed, 0);
    EXPECT_GT(nEdge, 0);

    // The level set's own zero (samples in the mesh at distance <= 0) is
    // met only on the wall itself: a path whose last sample is exactly on
    // the wall (elsewhere, samples beyond a wall are outside the mesh and
    // the exact fallback answers)
    {
        wallModel::impact e, l;
        const point x(5.3, 5.2, 0.8);
        const vector v(0.3, -0.2, -0.8);
        const bool fe = exact->predict(x, v, 1, e);
        const bool fl = levelSet->predict(x, v, 1, l);
        std::cout << "[   INFO   ] path ending on the wall: meshFaces "
            << (fe ? "t = " + std::to_string(e.time) : std::string("no impact"))
            << ", levelSet "
            << (fl ? "t = " + std::to_string(l.time) + " n = " + str(l.normal)
                   : std::string("no impact")) << std::endl;
    }

    // Positions to round-off (the distance to a grid-aligned wall is linear,
    // which cellPoint interpolation reproduces); normals from the Gauss
    // gradient of the cell-centred distance, whose cells next to the wall
    // use the wall's zero face value half a cell from their centre: the
    // interpolated gradient there is off by O(1%) (measured 1.3%), so 5%
    EXPECT_GE(nCompared, 100);
    EXPECT_LT(maxTimeError, 1e-6);
    EXPECT_LT(maxNormalError, 0.05);
}


// Cyclic patches carry a path on: in the channel periodic in x and y
// (period 4) between walls at z = 0 and 3, a bead from (3.9, 3.5, 1.5)
// with v = (1, 0.5, -1) leaves through x = 4 at s = 0.1, through y = 4 at
// s = 1, and meets the wall z = 0 at s = 1.5 (levelSet: at its clearance,
// s = 1.4), at the image (1.4, 0.25, 0) of its continuous position. A
// path that crosses cyclic patches only has no impact; nor does a bead
// beyond a cyclic plane (the continuous coordinates of a chain) moving
// inside the period.
TEST(wallModels, cyclicPatchesCarryPaths)
{
    const fvMesh* mesh = meshOf("periodicChannel");
    ASSERT_TRUE(mesh);
    const label walls = patchIndex(*mesh, "walls");
    ASSERT_GE(walls, 0);

    const periodicImages& periodic = periodicImages::New(*mesh);
    ASSERT_TRUE(periodic.active());
    EXPECT_EQ(periodic.lattice().size(), 2);
    const point image1 = periodic.wrap(point(5.4, -0.75, 1));
    const point image2 = periodic.wrap(point(-7.5, 9, 2));
    EXPECT_NEAR(mag(image1 - point(1.4, 3.25, 1)), 0, 1e-12);
    EXPECT_NEAR(mag(image2 - point(0.5, 1, 2)), 0, 1e-12);

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> model = newWall(*mesh, type);

        const point x(3.9, 3.5, 1.5);
        const vector v(1, 0.5, -1);
        wallModel::impact hit;
        ASSERT_TRUE(model->predict(x, v, 2, hit));
        const scalar tImpact = 1.5 - clearanceOf(type);
        EXPECT_NEAR(hit.time, tImpact, 1e-8);
        EXPECT_LE(hit.time, tImpact);
        EXPECT_EQ(hit.patch, walls);
        EXPECT_NEAR(mag(hit.normal - vector(0, 0, 1)), 0, 1e-6);

        // Across cyclic patches only: no impact
        EXPECT_FALSE(model->predict(x, vector(1, 0.5, 0.2), 2, hit));

        // The same path from a continuous position two periods away
        ASSERT_TRUE(model->predict(x + vector(8, -4, 0), v, 2, hit));
        EXPECT_NEAR(hit.time, tImpact, 1e-8);
    }
}


// ************************************************************************* //
