/*---------------------------------------------------------------------------*\
Description
    Rods meet the convex edges of the walls (issue: rods meet wall edges).
    In the L-shaped channel (tests/cases/wallL, fluid x < 5 or y < 5, the
    solid block x, y > 5 protruding at the corner edge x = y = 5):

    - wallEdges finds exactly the corner's convex edges (5 mesh edges
      along z), not the box's concave ones;
    - a dimer swept across the corner with both beads in the fluid (the
      beads alone never meet a wall) meets the edge at 0.4 dt and turns
      back, ending where the reversed motion takes it, for both impulses;
    - 2000 random dimers swept past the corner at up to a rod length a
      step: no rod ends cutting the solid block, every bead in the fluid,
      and every rod whose beads' paths stay in the fluid but whose end
      would cut the corner has a rod-edge contact;
    - after 500 random dimers' steps past the corner, no bead's path from
      its end shorter than elasticRods' wall clearance meets a wall (8
      random directions each), and no edge lies nearer a rod than its edge
      clearance (what the re-projection after contacts relies on).
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "elasticRods.H"
#include "segmentDistance.H"
#include <random>

using namespace polymerCloudTest;

namespace
{

// Does the segment from p to q pass through the solid block x, y > 5
// (deeper than round-off)?
bool cutsTheCorner(const point& p, const point& q)
{
    const scalar tol = 1e-9;
    scalar lo = 0, hi = 1;
    for (const direction k : {vector::X, vector::Y})
    {
        const scalar d = q[k] - p[k];
        if (mag(d) < VSMALL)
        {
            if (p[k] <= 5 + tol)
            {
                return false;
            }
            continue;
        }
        const scalar t = (5 + tol - p[k])/d;
        if (d > 0)
        {
            lo = max(lo, t);
        }
        else
        {
            hi = min(hi, t);
        }
    }
    return lo < hi;
}


// A random rod of unit length near the corner, in the fluid and not
// cutting it, and its beads' velocities: up to a rod length a unit step,
// the second within 0.3 of the first's. Appended to chains (type 0) at the
// end of that step, p + v, as the step's unconstrained positions
void dimerNearTheCorner
(
    std::mt19937_64& gen,
    polymerChains& chains,
    point& p0,
    point& p1,
    vector& v0,
    vector& v1
)
{
    std::uniform_real_distribution<scalar> uniform(-1, 1);
    do
    {
        const point centre =
            point(5, 5, 2.5) + vector(uniform(gen), uniform(gen), 0);
        vector d(uniform(gen), uniform(gen), 0.3*uniform(gen));
        d /= mag(d) + VSMALL;
        p0 = centre - 0.5*d;
        p1 = centre + 0.5*d;
    } while
    (
        (p0.x() > 4.99 && p0.y() > 4.99)
     || (p1.x() > 4.99 && p1.y() > 4.99)
     || cutsTheCorner(p0, p1)
    );
    v0 = vector(uniform(gen), uniform(gen), 0);
    v1 = v0 + 0.3*vector(uniform(gen), uniform(gen), 0);
    chains.append
    (
        0, 0, List<point>({p0 + v0, p1 + v1}), List<vector>({v0, v1})
    );
}


dictionary elasticRodsDict(const word& impulse)
{
    dictionary coeffs;
    coeffs.add("impulse", impulse);
    dictionary dict;
    dict.add("collision", "elasticRods");
    dict.add("elasticRodsCoeffs", coeffs);
    return dict;
}

} // End anonymous namespace


TEST(wallEdges, TheLChannelsCornerIsItsOnlyConvexEdge)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");
    const wallEdges& edges = wall->edges();
    ASSERT_EQ(edges.size(), 5);
    for (label edgei = 0; edgei < edges.size(); ++edgei)
    {
        for (const point& p : {edges.start(edgei), edges.end(edgei)})
        {
            EXPECT_NEAR(p.x(), 5, 1e-12);
            EXPECT_NEAR(p.y(), 5, 1e-12);
        }
        EXPECT_NEAR(mag(edges.end(edgei) - edges.start(edgei)), 1, 1e-12);
    }
}


TEST(wallEdges, ADimerSweptAcrossTheCornerTurnsBack)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const scalar dt = 1;
    const PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    const List<point> positionsOld
    ({
        point(4.2, 5.4, 2.5), point(5.4, 4.2, 2.5)
    });
    const vector u(0.5, 0.5, 0);

    for (const word impulse : {"constrained", "dumbbell"})
    {
        SCOPED_TRACE(impulse);
        for (const word& type : wallModelTypes)
        {
            SCOPED_TRACE(type);
            autoPtr<wallModel> wall = newWall(*mesh, type);
            polymerChains chains(types);
            chains.append
            (
                0, 0,
                List<point>({positionsOld[0] + dt*u, positionsOld[1] + dt*u}),
                List<vector>({u, u})
            );
            ASSERT_TRUE(cutsTheCorner(chains.positions()[0], chains.positions()[1]));

            collisionModels::elasticRods model(elasticRodsDict(impulse));
            model.correct(chains, positionsOld, dt, dt, wall.get());

            EXPECT_EQ(model.count().edgeContacts, 1);
            EXPECT_EQ(model.count().unresolved, 0);
            const List<point>& x = chains.positions();
            const List<vector>& v = chains.velocities();
            for (label i = 0; i < 2; ++i)
            {
                EXPECT_LT(mag(x[i] - (positionsOld[i] - 0.2*u)), 1e-9);
                EXPECT_LT(mag(v[i] + u), 1e-9);
            }
            EXPECT_FALSE(cutsTheCorner(x[0], x[1]));
        }
    }
}


TEST(wallEdges, RandomRodsSweptPastTheCornerDoNotCutIt)
{
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    autoPtr<wallModel> wall = newWall(*mesh, "meshFaces");
    const PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    std::mt19937_64 gen(5);

    for (const word impulse : {"constrained", "dumbbell"})
    {
        SCOPED_TRACE(impulse);
        label nCutBefore = 0, nEdgeOnly = 0, nContacts = 0;
        for (label trial = 0; trial < 2000; ++trial)
        {
            point p0, p1;
            vector v0, v1;
            polymerChains chains(types);
            dimerNearTheCorner(gen, chains, p0, p1, v0, v1);
            const bool cut = cutsTheCorner(p0 + v0, p1 + v1);
            nCutBefore += cut;

            // Neither bead's path meets a wall: only the edge stops the rod
            const bool edgeOnly =
                cut
             && !cutsTheCorner(p0, p0 + v0) && !cutsTheCorner(p1, p1 + v1);
            nEdgeOnly += edgeOnly;

            collisionModels::elasticRods model(elasticRodsDict(impulse));
            model.correct
            (
                chains, List<point>({p0, p1}), 1, 1, wall.get()
            );
            nContacts += model.count().edgeContacts;
            if (edgeOnly)
            {
                EXPECT_GE(model.count().edgeContacts, 1) << "trial " << trial;
            }

            const List<point>& x = chains.positions();
            EXPECT_FALSE(cutsTheCorner(x[0], x[1]))
                << "trial " << trial << ": from " << str(p0) << ' '
                << str(p1) << " with " << str(v0) << ' ' << str(v1)
                << " to " << str(x[0]) << ' ' << str(x[1]);
            for (const point& p : x)
            {
                EXPECT_FALSE(p.x() > 5 + 1e-9 && p.y() > 5 + 1e-9)
                    << "trial " << trial << ": bead in the solid " << str(p);
            }
        }

        // The scene exercises the edge: many straight paths would cut it,
        // some with neither bead meeting a wall
        EXPECT_GE(nEdgeOnly, 10);
        std::cout << impulse << ": " << nCutBefore << " of 2000 straight"
            << " paths would cut the corner, " << nEdgeOnly << " with"
            << " both beads in the fluid; rod-edge contacts " << nContacts
            << std::endl;
    }
}


TEST(wallEdges, TheCollisionsClearancesHoldNoWallNorEdge)
{
    // What the re-projection after contacts takes from elasticRods: a
    // bead's path from where the events left it shorter than its wall
    // clearance meets no wall, and no edge lies nearer a rod than its
    // edge clearance
    const fvMesh* mesh = meshOf("wallL");
    ASSERT_TRUE(mesh);
    const PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    std::mt19937_64 gen(11);
    std::uniform_real_distribution<scalar> uniform(-1, 1);
    for (const word& type : wallModelTypes)
    {
        SCOPED_TRACE(type);
        autoPtr<wallModel> wall = newWall(*mesh, type);
        const wallEdges& edges = wall->edges();
        label nWallCleared = 0, nEdgeCleared = 0;
        for (label trial = 0; trial < 500; ++trial)
        {
            point p0, p1;
            vector v0, v1;
            polymerChains chains(types);
            dimerNearTheCorner(gen, chains, p0, p1, v0, v1);
            collisionModels::elasticRods model(elasticRodsDict("constrained"));
            model.correct(chains, List<point>({p0, p1}), 1, 1, wall.get());

            const List<point>& x = chains.positions();
            const scalarField wallClearance(model.wallClearances());
            const scalarField edgeClearance(model.edgeClearances());
            ASSERT_EQ(wallClearance.size(), 2);
            ASSERT_EQ(edgeClearance.size(), 1);
            forAll(x, i)
            {
                EXPECT_GE(wallClearance[i], 0);
                nWallCleared += (wallClearance[i] > 0);
                for (label k = 0; k < 8 && wallClearance[i] > 0; ++k)
                {
                    vector u(uniform(gen), uniform(gen), uniform(gen));
                    u /= mag(u) + VSMALL;
                    wallModel::impact hit;
                    EXPECT_FALSE
                    (
                        wall->predict(x[i], 0.999*wallClearance[i]*u, 1, hit)
                    ) << "trial " << trial << " bead " << i;
                }
            }
            EXPECT_GE(edgeClearance[0], 0);
            nEdgeCleared += (edgeClearance[0] > 0);
            for (label edgei = 0; edgei < edges.size(); ++edgei)
            {
                EXPECT_GE
                (
                    std::sqrt
                    (
                        segmentDistanceSqr
                        (
                            x[0], x[1], edges.start(edgei), edges.end(edgei)
                        )
                    ),
                    edgeClearance[0]
                ) << "trial " << trial << " edge " << edgei;
            }
        }
        // Most beads and rods near the corner have clearances to check
        // (863 of 1000 and 459 of 500 with meshFaces); levelSet knows no
        // wall clearance (wallModel::clearance), so gives none
        if (type == "meshFaces")
        {
            EXPECT_GT(nWallCleared, 500);
        }
        EXPECT_GT(nEdgeCleared, 250);
    }
}


// ************************************************************************* //
