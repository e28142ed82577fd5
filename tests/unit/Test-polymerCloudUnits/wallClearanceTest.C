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
    The walls' clearance (wallClearance), by which the wall models pass
    over the face search of a path that cannot reach a face. In the
    L-shaped channel (tests/cases/wallL: fluid x < 5 or y < 5, 0 < z < 5,
    walls all round):
    - at 20000 random points of the fluid the clearance is never more than
      the distance to the nearest face, and never less than that distance
      (up to the search's cap) less a voxel's diagonal;
    - the clearance from the channel's convex edges (its corner, x = y = 5)
      likewise, against the distance to the nearest of those edges;
    - of 20000 random paths from those points, none shorter than its
      start's clearance enters a face, and the wall model's impacts are
      the face search's, path for path;
    - the nearest face (boundaryFaces::nearest, which passes over the
      faces whose bounds lie farther than the nearest found so far) is at
      the least of the faces' own nearest distances, to the bit, at 20000
      random points of the fluid, half of them within a tenth of a wall,
      within the voxels' search radius and without a limit;
    - likewise on a copy of the channel whose points are moved at random
      by up to a tenth of a cell along each axis (warped faces);
    - the first face a segment enters (boundaryFaces::firstEntered, which
      passes over faces whose plane band the segment's end does not
      reach) is the first of every face's own intersections along it, at
      20000 random segments, half of them from within a tenth of the
      floor and half of those crossing it;
    - the faces' bounds (boundaryFaces::clearance) are never farther than
      the nearest face, nor than the reach asked; no path shorter than the
      wall model's clearance enters a face, and where the voxels give
      less than half the distance to the walls (within the reach asked),
      it gives more for at least nine points in ten (flat walls: the
      planes' distance);
    - the faces' bounds from a segment (boundaryFaces::pathClearance) are
      never farther than the nearest face from any of 26 points along it
      (5000 random segments up to 0.5 long), nor than the reach asked; a
      segment of no length has the point's bounds; the wall model's path
      clearance lets no segment whose ends are moved by less enter a
      face, and it is positive for nine in ten of the segments that enter
      none.
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "wallClearance.H"

#include <random>

using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// A random point of the L channel's fluid
point fluidPoint(std::mt19937_64& engine)
{
    std::uniform_real_distribution<scalar> u(0, 1);
    for (;;)
    {
        const point p(10*u(engine), 10*u(engine), 5*u(engine));
        if (p.x() < 5 || p.y() < 5)
        {
            return p;
        }
    }
}


// At 20000 random points of the fluid, every other one at a height drawn
// from [zLow, zHigh] (near the floor), the nearest face that
// boundaryFaces::nearest finds, within the voxels' search radius and
// without a limit, is at the least of every face's own nearest distance
// (OpenFOAM's fan of triangles about the centre), to the bit, and its
// point is the found face's own nearest point; the points found within
// the radius are counted
void expectNearestIsLeast
(
    const boundaryFaces& faces,
    const scalar searched,
    const scalar zLow,
    const scalar zHigh,
    std::mt19937_64& engine,
    label& withinRadius
)
{
    std::uniform_real_distribution<scalar> u(zLow, zHigh);
    const faceList& all = faces.faces();
    withinRadius = 0;
    for (label i = 0; i < 20000; ++i)
    {
        point p(fluidPoint(engine));
        if (i % 2)
        {
            p.z() = u(engine);
        }
        scalar least = GREAT;
        for (const face& f : all)
        {
            least = min(least, f.nearestPoint(p, faces.points()).distance());
        }
        for (const scalar maxDistSqr : {GREAT, sqr(searched)})
        {
            const pointIndexHit nearest = faces.nearest(p, maxDistSqr);
            ASSERT_EQ(nearest.hit(), sqr(least) < maxDistSqr)
                << "at " << str(p);
            if (!nearest.hit())
            {
                continue;
            }
            withinRadius += (maxDistSqr < GREAT);
            const pointHit own =
                all[nearest.index()].nearestPoint(p, faces.points());
            ASSERT_EQ(own.distance(), least) << "at " << str(p);
            ASSERT_EQ(mag(nearest.hitPoint() - own.rawPoint()), 0)
                << "at " << str(p);
        }
    }
}

} // End anonymous namespace


TEST(wallClearance, WithinAVoxelOfTheNearestFace)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    const wallClearance clearance(faces);
    EXPECT_GE(clearance.size(), 4096);

    // From the construction: the distance less a voxel's diagonal, up to
    // the search's cap of eight half diagonals
    const scalar diagonal = std::sqrt(3.0)*clearance.voxelSize();
    std::mt19937_64 engine(7);
    label positive = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p(fluidPoint(engine));
        const pointIndexHit nearest = faces.nearest(p, GREAT);
        ASSERT_TRUE(nearest.hit());
        const scalar distance = mag(nearest.hitPoint() - p);
        ASSERT_LE(clearance(p), distance) << "at " << str(p);
        ASSERT_GE
        (
            clearance(p),
            (min(distance, 4*diagonal) - diagonal)*(1 - 1e-6) - 1e-12
        ) << "at " << str(p);
        positive += clearance(p) > 0;
    }
    EXPECT_GT(positive, 5000);
}


TEST(wallClearance, NearestFaceIsTheLeastOfTheFaces)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    const wallClearance clearance(faces);
    const scalar searched = 4*std::sqrt(3.0)*clearance.voxelSize();

    // Every other point within a tenth of the floor, where a wall is near
    std::mt19937_64 engine(17);
    label withinRadius = 0;
    expectNearestIsLeast(faces, searched, 0, 0.1, engine, withinRadius);
    EXPECT_GT(withinRadius, 10000);
}


TEST(wallClearance, NearestWarpedFaceIsTheLeastOfTheFaces)
{
    // The L channel with every point moved by up to a tenth of a cell
    // along each axis: warped faces, whose bounds (boundaryFaces::nearest
    // passes over a face by its plane less its warp and by its centre's
    // distance less its radius, along the plane and across it) must
    // still never exceed the face's own nearest distance
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    std::mt19937_64 engine(23);
    std::uniform_real_distribution<scalar> u(-1, 1);
    pointField points(mesh->points());
    for (point& p : points)
    {
        p += 0.1*vector(u(engine), u(engine), u(engine));
    }
    polyMesh warped
    (
        IOobject
        (
            "warped",
            mesh->time().timeName(),
            mesh->time(),
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        std::move(points),
        faceList(mesh->faces()),
        labelList(mesh->faceOwner()),
        labelList(mesh->faceNeighbour()),
        false
    );
    List<polyPatch*> patches(mesh->boundaryMesh().size());
    forAll(patches, patchi)
    {
        patches[patchi] =
            mesh->boundaryMesh()[patchi].clone(warped.boundaryMesh()).ptr();
    }
    warped.addPatches(patches);

    const boundaryFaces faces(warped, 0);
    const wallClearance clearance(faces);
    const scalar searched = 4*std::sqrt(3.0)*clearance.voxelSize();
    // Every other point within a tenth of the floor's mean plane, either
    // side
    label withinRadius = 0;
    expectNearestIsLeast(faces, searched, -0.1, 0.1, engine, withinRadius);
    EXPECT_GT(withinRadius, 10000);
}


TEST(wallClearance, FirstEnteredFaceIsTheFirstOfTheFaces)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    const faceList& all = faces.faces();
    const pointField centres
    (
        primitiveFacePatch(all, faces.points()).faceCentres()
    );

    // Every face's own intersection (OpenFOAM's, as the octree's shapes
    // take it) for the faces the segment enters along their area vector
    std::mt19937_64 engine(19);
    std::normal_distribution<scalar> normal(0, 1);
    std::uniform_real_distribution<scalar> u(0, 1);
    label entered = 0;
    for (label i = 0; i < 20000; ++i)
    {
        point p(fluidPoint(engine));
        vector path(normal(engine), normal(engine), normal(engine));
        path *= 0.5*u(engine)/mag(path);
        if (i % 2)
        {
            // From within a tenth of the floor, every other one through it
            p.z() = 0.1*u(engine);
            path.z() = (i % 4 == 1) ? -0.2*u(engine) - p.z() : 0.05*u(engine);
        }
        scalar first = GREAT;
        point firstPoint(Zero);
        label firstFace = -1;
        forAll(all, facei)
        {
            if ((path & faces.area(facei)) > 0)
            {
                const pointHit hit = all[facei].intersection
                (
                    p, path, centres[facei], faces.points(),
                    intersection::HALF_RAY, 0
                );
                if (hit.hit() && hit.distance() <= 1 && hit.distance() < first)
                {
                    first = hit.distance();
                    firstPoint = hit.hitPoint();
                    firstFace = facei;
                }
            }
        }
        // The same point, but for the round-off of two faces' shared edge
        const pointIndexHit h = faces.firstEntered(p, p + path);
        ASSERT_EQ(h.hit(), firstFace >= 0) << "from " << str(p);
        if (h.hit())
        {
            ++entered;
            ASSERT_LE(mag(h.hitPoint() - firstPoint), 1e-12)
                << "from " << str(p);
        }
    }
    EXPECT_GT(entered, 4000);
}


TEST(wallClearance, FromTheEdgesWithinAVoxelOfTheNearestEdge)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");
    const wallEdges& edges = wall->edges();
    ASSERT_EQ(edges.size(), 5);
    const wallClearance clearance(wall->faces(), edges);

    // The corner's edges make up the segment x = y = 5, 0 < z < 5
    const scalar diagonal = std::sqrt(3.0)*clearance.voxelSize();
    std::mt19937_64 engine(13);
    label positive = 0, capped = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p(fluidPoint(engine));
        const point onCorner(5, 5, min(max(p.z(), scalar(0)), scalar(5)));
        const scalar distance = mag(p - onCorner);
        ASSERT_LE(clearance(p), distance) << "at " << str(p);
        ASSERT_GE
        (
            clearance(p),
            (min(distance, 4*diagonal) - diagonal)*(1 - 1e-6) - 1e-12
        ) << "at " << str(p);
        // The edges' clearance, not the faces': far from the corner it
        // reaches the search's cap, however near the point is to a face
        capped += (distance > 5*diagonal && clearance(p) > 2.5*diagonal);
        positive += clearance(p) > 0;
    }
    EXPECT_GT(positive, 15000);
    EXPECT_GT(capped, 5000);
}


TEST(wallClearance, NoPathWithinItEntersAFace)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    const wallClearance clearance(faces);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");

    std::mt19937_64 engine(11);
    std::normal_distribution<scalar> normal(0, 1);
    std::uniform_real_distribution<scalar> u(0, 1);
    label within = 0, hits = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p(fluidPoint(engine));
        vector direction(normal(engine), normal(engine), normal(engine));
        direction /= mag(direction);
        // Lengths about the clearance, up to twice it, and some long ones
        const scalar length =
            (i % 4 == 0 ? 3.0 : 2*clearance(p))*u(engine);
        const vector path(length*direction);

        const pointIndexHit h = faces.firstEntered(p, p + path);
        if (length < clearance(p))
        {
            ++within;
            EXPECT_FALSE(h.hit()) << "path " << str(path) << " from " << str(p);
        }

        wallModel::impact hit;
        const bool met = wall->predict(p, path, 1, hit);
        ASSERT_EQ(met, h.hit()) << "path " << str(path) << " from " << str(p);
        hits += met;
    }
    EXPECT_GT(within, 5000);
    EXPECT_GT(hits, 500);
}


TEST(wallClearance, NearTheWallsNoPathWithinItEntersAFace)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");
    const wallClearance voxels(wall->faces());

    std::mt19937_64 engine(17);
    std::normal_distribution<scalar> normal(0, 1);
    std::uniform_real_distribution<scalar> u(0, 1);
    label within = 0, nearWalls = 0, found = 0;
    for (label i = 0; i < 20000; ++i)
    {
        const point p(fluidPoint(engine));
        const scalar reach = 0.5*u(engine);

        // The bounds: no farther than the nearest face, nor than reach
        const pointIndexHit nearest = faces.nearest(p, GREAT);
        ASSERT_TRUE(nearest.hit());
        const scalar distance = mag(nearest.hitPoint() - p);
        const scalar bound = faces.clearance(p, reach);
        ASSERT_GE(bound, 0) << "at " << str(p);
        ASSERT_LE(bound, min(distance, reach) + 1e-12) << "at " << str(p);

        // The wall model's: paths about it, up to twice it
        const scalar clearance = wall->clearance(p, reach);
        if (voxels(p) < 0.5*min(distance, reach))
        {
            ++nearWalls;
            found += clearance > voxels(p);
        }
        vector direction(normal(engine), normal(engine), normal(engine));
        direction /= mag(direction);
        const vector path(2*clearance*u(engine)*direction);
        if (mag(path) < clearance)
        {
            ++within;
            EXPECT_FALSE(faces.firstEntered(p, p + path).hit())
                << "path " << str(path) << " from " << str(p);
        }
    }
    Info<< "near clearance: " << within << " paths within it, "
        << found << " of " << nearWalls << " points near the walls with"
        << " more clearance than the voxels'" << endl;
    EXPECT_GT(within, 5000);
    EXPECT_GT(found, 0.9*nearWalls);
}


TEST(wallClearance, NoPathNearerThanThePathClearanceEntersAFace)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const boundaryFaces faces(*mesh, 0);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");

    std::mt19937_64 engine(29);
    std::normal_distribution<scalar> normal(0, 1);
    std::uniform_real_distribution<scalar> u(0, 1);
    const auto unit = [&]()
    {
        vector direction(normal(engine), normal(engine), normal(engine));
        return direction/mag(direction);
    };
    label clear = 0, positive = 0;
    for (label i = 0; i < 5000; ++i)
    {
        const point p(fluidPoint(engine));
        const vector path(0.5*u(engine)*unit());
        const scalar reach = 0.5*u(engine);

        // No farther than the nearest face from points along the segment
        const scalar bound = faces.pathClearance(p, p + path, reach);
        ASSERT_GE(bound, 0) << "from " << str(p);
        ASSERT_LE(bound, reach + 1e-12) << "from " << str(p);
        for (label k = 0; k <= 25; ++k)
        {
            const point q(p + (k/25.0)*path);
            const pointIndexHit nearest = faces.nearest(q, GREAT);
            ASSERT_TRUE(nearest.hit());
            ASSERT_LE(bound, mag(nearest.hitPoint() - q) + 1e-12)
                << "segment " << str(p) << ' ' << str(p + path);
        }
        EXPECT_EQ(faces.pathClearance(p, p, reach), faces.clearance(p, reach));

        // Segments that enter no face: one moved by less than the wall
        // model's clearance enters none either
        if (faces.firstEntered(p, p + path).hit())
        {
            continue;
        }
        ++clear;
        const scalar keep = wall->pathClearance(p, path, 1, reach);
        ASSERT_LE(keep, bound);
        positive += keep > 0;
        if (keep > 0)
        {
            const vector off0(0.999*keep*u(engine)*unit());
            const vector off1(0.999*keep*u(engine)*unit());
            EXPECT_FALSE(faces.firstEntered(p + off0, p + path + off1).hit())
                << "segment " << str(p + off0) << ' ' << str(p + path + off1);
        }
    }
    Info<< "path clearance: " << positive << " of " << clear
        << " segments entering no face have one" << endl;
    EXPECT_GT(positive, 0.9*clear);
}


// ************************************************************************* //
