/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Description
    Unit tests of the bead-wall models (meshFaces, levelSet) and of
    wallModel's interactions, on constructed bead paths in small meshes.

    The meshes are tests/cases/wallBox (box 0..10, 10^3 cells, 'outlet' at
    x = 10, 'walls' elsewhere), wallL (L-shaped channel, re-entrant corner
    on the edge x = y = 5) and wallSlit (walls at z = 0 and z = 3). Each is
    copied to tests/logs/run/unit.<case> and meshed with blockMesh once per
    run of the test binary (blockMesh from the environment, etc/bashrc).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wallModel.H"
#include "periodicImages.H"
#include "Time.H"
#include "fvMesh.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "testHelpers.H"
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

//- A case's Time and mesh (the mesh destroyed first)
struct caseMesh
{
    std::unique_ptr<Time> runTime;
    std::unique_ptr<fvMesh> mesh;

    ~caseMesh()
    {
        mesh.reset();
        runTime.reset();
    }
};


//- The mesh of tests/cases/<name>, meshed once per run; nullptr (with a
//  test failure) when it cannot be made
const fvMesh* meshOf(const std::string& name)
{
    static std::map<std::string, std::unique_ptr<caseMesh>> meshes;

    auto found = meshes.find(name);
    if (found != meshes.end())
    {
        return found->second->mesh.get();
    }

    const std::string project = getEnv("POLYMERCLOUD_PROJECT");
    if (project.empty())
    {
        ADD_FAILURE()
            << "POLYMERCLOUD_PROJECT is not set (source etc/bashrc)";
        return nullptr;
    }
    const std::string source = project + "/tests/cases/" + name;
    const std::string runDir = project + "/tests/logs/run";
    const std::string dir = runDir + "/unit." + name;

    const std::string command =
        "rm -rf '" + dir + "' && mkdir -p '" + runDir + "' && cp -r '"
      + source + "' '" + dir + "' && blockMesh -case '" + dir + "' > '"
      + dir + "/log.blockMesh' 2>&1";
    if (std::system(command.c_str()) != 0)
    {
        ADD_FAILURE()
            << "Could not mesh " << source << " (" << command << ")";
        return nullptr;
    }

    auto c = std::make_unique<caseMesh>();
    try
    {
    c->runTime = std::make_unique<Time>
    (
        Time::controlDictName,
        fileName(runDir),
        fileName("unit." + name)
    );
    c->mesh = std::make_unique<fvMesh>
    (
        IOobject
        (
            fvMesh::defaultRegion,
            c->runTime->timeName(),
            *c->runTime,
            IOobject::MUST_READ
        )
    );
    }
    catch (const Foam::error& err)
    {
        ADD_FAILURE() << "Reading the mesh of " << dir << ": " << err.message();
        return nullptr;
    }
    const fvMesh* mesh = c->mesh.get();
    meshes[name] = std::move(c);
    return mesh;
}


//- A subModels dictionary from text
dictionary subModels(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}


//- levelSet's clearance in the tests: its zero is that far from the walls
const scalar levelSetClearance = 0.1;

//- The distance from a wall at which a model reports the impact
scalar clearanceOf(const word& type)
{
    return type == "levelSet" ? levelSetClearance : 0;
}

//- Final coordinate of a point moving at speed u for time T between
//  reflecting planes lo and hi, and the number of reflections
scalar fold(scalar z, scalar u, scalar T, scalar lo, scalar hi, label& n)
{
    n = 0;
    scalar t = 0;
    while (true)
    {
        const scalar toWall = (u > 0) ? (hi - z)/u : (u < 0 ? (lo - z)/u : GREAT);
        if (t + toWall >= T) return z + (T - t)*u;
        t += toWall;
        z = (u > 0) ? hi : lo;
        u = -u;
        ++n;
    }
}

//- A wall model of the given type (with optional coefficient text)
autoPtr<wallModel> newWall
(
    const fvMesh& mesh,
    const word& type,
    const std::string& coeffs = ""
)
{
    std::string c = coeffs;
    if (type == "levelSet" && c.find("clearance") == std::string::npos)
    {
        c += " clearance " + std::to_string(levelSetClearance) + ";";
    }
    try
    {
        return wallModel::New
        (
            subModels
            (
                "wall " + type + ";\n"
              + (c.empty() ? "" : type + "Coeffs { " + c + " }\n")
            ),
            mesh
        );
    }
    catch (const Foam::error& err)
    {
        // The message in the test's output (gtest shows only 'std::exception')
        std::cout << "Foam::error constructing wall " << type << ": "
            << err.message() << std::endl;
        throw;
    }
}


label patchIndex(const fvMesh& mesh, const word& name)
{
    return mesh.boundaryMesh().findPatchID(name);
}


//- One chain of the given bead paths (x^n -> x-dagger over deltaT) with
//  the given v-dagger
struct beadPaths
{
    PtrList<chainType> types;
    polymerChains chains;
    List<vector> positionsOld;

    beadPaths
    (
        const List<point>& start,
        const List<point>& end,
        const List<vector>& vDagger
    )
    :
        types(oneType(start.size(), 1, 1, 1, 1)),
        chains(types),
        positionsOld(start)
    {
        chains.append(0, 0, end, vDagger);
    }
};


//- A vector as text, for gtest messages
std::string str(const vector& v)
{
    return "(" + std::to_string(v.x()) + " " + std::to_string(v.y()) + " "
        + std::to_string(v.z()) + ")";
}


const word wallModelTypes[] = {"meshFaces", "levelSet"};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //
// Head-on impacts on each wall of the box: time, normal, patch, rebound

TEST(wallModels, headOnImpactAndRebound)
{
    const fvMesh* mesh = meshOf("wallBox");
    ASSERT_TRUE(mesh);
    const label walls = patchIndex(*mesh, "walls");
    ASSERT_GE(walls, 0);

    // From the middle of the box towards the five walls (centres of their
    // faces' area away from edges), distance 3 at speed 4.5 plus
    // tangential motion: impact at t = 2/3 of T = 1
    // Wall normals into the fluid (x = 10 is the outlet)
    const List<vector> normals
    ({
        vector(1, 0, 0), vector(0, 1, 0), vector(0, -1, 0),
        vector(0, 0, 1), vector(0, 0, -1)
    });

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> model = newWall(*mesh, type);
        ASSERT_TRUE(model->active());

        for (const vector& n : normals)
        {
            SCOPED_TRACE(str(n));
            // Start 3 from the wall, at the centre of the wall's face
            const point wallCentre = point(5, 5, 5) - 5*n;
            const point x = wallCentre + 3*n;
            // tangential part: perpendicular to n
            const vector t1 = (mag(n.x()) > 0.5) ? vector(0, 1, 0) : vector(1, 0, 0);
            const vector t2 = n ^ t1;
            const vector v = -4.5*n + 0.6*t1 - 0.3*t2;

            wallModel::impact hit;
            ASSERT_TRUE(model->predict(x, v, 1, hit));
            // levelSet: exact on grid-aligned walls away from edges (at its
            // clearance from the wall), to its bisection tolerance
            const scalar tImpact = (3 - clearanceOf(type))/4.5;
            EXPECT_NEAR(hit.time, tImpact, 1e-8);
            EXPECT_LE(hit.time, tImpact);   // the bead stays in the fluid
            EXPECT_NEAR(mag(hit.normal - n), 0, 1e-9);
            EXPECT_EQ(hit.patch, walls);

            // Rebound: v - 2 (v.n) n; v-dagger gets the same change
            vector vPath = v;
            vector vDagger(0.1, -0.2, 0.3);
            const vector vDaggerBefore = vDagger;
            model->resetCounters();
            model->interact(7, hit, vPath, vDagger);
            const vector expected = v - 2*(v & hit.normal)*hit.normal;
            EXPECT_NEAR(mag(vPath - expected), 0, 1e-12);
            EXPECT_NEAR(mag(vPath - (v + 9*n)), 0, 1e-8);
            EXPECT_NEAR(mag((vDagger - vDaggerBefore) - (expected - v)), 0, 1e-12);
            EXPECT_EQ(model->count().rebounds, 1);
            EXPECT_TRUE(model->escapedBeads().empty());

            // A path that stops short of the wall has no impact
            EXPECT_FALSE(model->predict(x, v, 0.6, hit));
            // A path moving away from the wall has none either
            EXPECT_FALSE(model->predict(x, -v, 0.3, hit));
        }
    }
}


// Grazing paths: parallel to a wall just inside (no impact), and slightly
// inclined (impact near the end)
TEST(wallModels, grazingPaths)
{
    const fvMesh* mesh = meshOf("wallBox");
    ASSERT_TRUE(mesh);

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> model = newWall(*mesh, type);
        wallModel::impact hit;
        const scalar c = clearanceOf(type);     // heights above the zero

        // Parallel to z = 0 at heights 1e-6 and 1e-3, across cells
        EXPECT_FALSE(model->predict(point(1.2, 5.1, c + 1e-6), vector(7.3, 0.4, 0), 1, hit));
        EXPECT_FALSE(model->predict(point(1.2, 5.1, c + 1e-3), vector(7.3, 0.4, 0), 1, hit));

        // Inclined: from 0.1 above the wall down to 0.01 below it over the
        // step: impact at t = 0.1/0.11
        const point x(1.2, 5.1, c + 0.1);
        const vector v(7.3, 0.4, -0.11);
        ASSERT_TRUE(model->predict(x, v, 1, hit));
        EXPECT_NEAR(hit.time, 0.1/0.11, 1e-8);
        EXPECT_NEAR(mag(hit.normal - vector(0, 0, 1)), 0, 1e-9);

        // Ending 1e-7 above the wall: no impact
        EXPECT_FALSE(model->predict(x, vector(7.3, 0.4, -0.1 + 1e-7), 1, hit));
    }
}


// A path across the notch of the L-shaped channel: both ends are in the
// fluid, but the straight path crosses the solid corner. The exact model
// reports the first face (y = 5 of the lower arm)
TEST(wallModels, nonConvexCorner)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);

    // (7, 3.1) -> (4.6, 5.5) at z = 2.5: crosses y = 5 at x = 5.1
    // (t = 1.9/2.4), leaves the notch through x = 5 at y = 5.1
    const point x(7, 3.1, 2.5);
    const vector v(-2.4, 2.4, 0);
    ASSERT_GE(mesh->findCell(x), 0);
    ASSERT_GE(mesh->findCell(x + v), 0);
    ASSERT_LT(mesh->findCell(point(5.05, 5.05, 2.5)), 0);

    // levelSet with 64 samples: one falls in the notch, outside the mesh,
    // and the exact fallback gives the first face
    const std::pair<word, std::string> models[] =
    {
        {"meshFaces", ""},
        {"levelSet", "nSamples 64;"}
    };
    for (const auto& m : models)
    {
        SCOPED_TRACE(m.first + " " + m.second);
        autoPtr<wallModel> model = newWall(*mesh, m.first, m.second);
        wallModel::impact hit;

        // levelSet: at its clearance c from y = 5 (t = 1.8/2.4), to the
        // interpolation error of the distance near the re-entrant corner
        const bool isExact = (m.first == "meshFaces");
        const scalar c = clearanceOf(m.first);
        const scalar tol = isExact ? 1e-8 : 0.5*c/2.4;

        ASSERT_TRUE(model->predict(x, v, 1, hit));
        EXPECT_NEAR(hit.time, (1.9 - c)/2.4, tol);
        // The level set's normal near the re-entrant corner is a blend of
        // the two walls' (the distance has a kink there): only the exact
        // model's normal is asserted, the level set's is reported
        if (isExact)
        {
            EXPECT_NEAR(mag(hit.normal - vector(0, -1, 0)), 0, 1e-9);
        }
        else
        {
            std::cout << "[   INFO   ] levelSet normal near the corner, |n - n_wall| "
                << mag(hit.normal - vector(0, -1, 0)) << std::endl;
        }

        // The reverse path meets x = 5 of the upper arm first (t = 0.4/2.4)
        ASSERT_TRUE(model->predict(x + v, -v, 1, hit));
        EXPECT_NEAR(hit.time, (0.4 - c)/2.4, tol);
        if (isExact)
        {
            EXPECT_NEAR(mag(hit.normal - vector(-1, 0, 0)), 0, 1e-9);
        }

        // Followed over the step (wallModel::correct): the bead rebounds
        // off y = 5 and ends in the lower arm, never in the notch
        beadPaths p({x}, {x + v}, {v});
        model->correct(p.chains, p.positionsOld, 1, 0);
        const point end = p.chains.positions()[0];
        EXPECT_GE(mesh->findCell(end), 0);
        EXPECT_LT(end.y(), 5);
        if (isExact)
        {
            EXPECT_NEAR(mag(end - point(4.6, 4.5, 2.5)), 0, 1e-8);
            EXPECT_EQ(model->count().rebounds, 1);
        }
        else
        {
            EXPECT_GE(model->count().rebounds, 1);
        }
    }

    // levelSet with its default 4 samples: the samples (t = 1/4 ... 1) are
    // all in the fluid and the corner cut (t in 0.792..0.833) falls between
    // two of them: information only (a limitation of sampled paths)
    {
        autoPtr<wallModel> model = newWall(*mesh, "levelSet");
        wallModel::impact hit;
        const bool found = model->predict(x, v, 1, hit);
        std::cout << "[   INFO   ] levelSet (nSamples 4) on the corner-cutting"
            << " path: " << (found ? "impact reported" : "no impact (cuts the"
            " solid corner; the exact model reports t = 0.7917)") << std::endl;
    }
}


// A path that would cross both walls of a narrow gap in one step, followed
// bead by bead (wallModel::correct): two rebounds, ends inside
TEST(wallModels, twoWallsInOneStep)
{
    const fvMesh* mesh = meshOf("wallSlit");
    ASSERT_TRUE(mesh);

    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> model = newWall(*mesh, type);
        const scalar c = clearanceOf(type);     // the walls at c and 3 - c
        label n0 = 0, n1 = 0;
        const scalar z0 = fold(1.5, 5, 1, c, 3 - c, n0);
        const scalar z1 = fold(1.5, 8.5, 1, c, 3 - c, n1);
        ASSERT_EQ(n0, 2);
        ASSERT_EQ(n1, 3);

        // Bead 0: z 1.5 -> 6.5 over T = 1 in the gap 0..3: meets z = 3 at
        // t = 0.3, z = 0 at t = 0.9, ends at z = 0.5. Bead 1 at rest, bead
        // 2 moves within the gap.
        const List<point> start
            ({point(0, 0, 1.5), point(1, 0, 1.5), point(0.5, 0.8, 1.2)});
        const List<vector> v
            ({vector(0.2, -0.1, 5), vector(0, 0, 0), vector(0.3, 0, 0.4)});
        List<point> end(3);
        forAll(end, i) end[i] = start[i] + v[i];

        beadPaths p(start, end, v);
        model->correct(p.chains, p.positionsOld, 1, 0);

        const List<vector>& x = p.chains.positions();
        const List<vector>& vDagger = p.chains.velocities();
        EXPECT_NEAR(mag(x[0] - point(0.2, -0.1, z0)), 0, 1e-8);
        EXPECT_GT(x[0].z(), 0);
        EXPECT_LT(x[0].z(), 3);
        EXPECT_NEAR(mag(vDagger[0] - v[0]), 0, 1e-9);  // reversed twice
        EXPECT_EQ(x[1], start[1]);
        EXPECT_NEAR(mag(x[2] - end[2]), 0, 1e-12);
        EXPECT_NEAR(mag(vDagger[2] - v[2]), 0, 1e-12);
        EXPECT_EQ(model->count().rebounds, 2);
        EXPECT_TRUE(model->escapedBeads().empty());

        // Three walls: z 1.5 -> 10 meets z = 3, 0, 3 and ends at 2
        beadPaths q({point(0, 0, 1.5)}, {point(0, 0, 10)}, {vector(0, 0, 8.5)});
        model->resetCounters();
        model->correct(q.chains, q.positionsOld, 1, 0);
        // (each impact is placed a relative 1e-9 of the path before the wall)
        EXPECT_NEAR(mag(q.chains.positions()[0] - point(0, 0, z1)), 0, 1e-7);
        EXPECT_NEAR(mag(q.chains.velocities()[0] - vector(0, 0, -8.5)), 0, 1e-9);
        EXPECT_EQ(model->count().rebounds, 3);
    }
}


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
        if (edgeDistance < 1)
        {
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


// ************************************************************************* //


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
