/*---------------------------------------------------------------------------*\
Description
    The four crossing-time root solvers (isolating, bisection, newton,
    cubic) of Miller & Trebotich 2007, step 3, on constructed cases whose
    roots are known in closed form: a single crossing; two crossings in one
    step; near-parallel and near-coplanar rods; a sign change of V whose
    lines meet outside the rods.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "collisionScenes.H"
#include "rodCrossingAudit.H"
#include "tensor.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * Root solvers  * * * * * * * * * * * * * * //

// (a) A single crossing. Rod J (along y at x = 0.1, height 0.3) moves down
// with 0.7 while its beads slide apart along y with +-0.4, so
// V(s) = -(0.3 - 0.7 s)(1 + 0.8 s): the roots are 3/7 (in the rods:
// lambda_i = 0.6, lambda_j = 0.5) and -1.25. All four solvers should find
// 3/7 to 1e-12, axis-aligned and rotated (newton's iterates approach the
// root from the V > 0 side: it must return the converged iterate's
// uncrossed side, not its secant start 0.3/1.02).
TEST(crossingRootSolver, SingleCrossing)
{
    const scene base = crossScene
    (
        0.1, 0.3, vector(0, -0.4, -0.7), vector(0, 0.4, -0.7)
    );
    const scalar exact = 3.0/7.0;

    for (const bool rotated : {false, true})
    {
        const scene sc =
            rotated ? base.moved(genericRotation(), vector(7, -3, 11)) : base;
        const rodPairCrossing pair = sc.pair();
        ASSERT_LT(pair.tripleProduct(0)*pair.tripleProduct(1), 0);

        for (const word& name : crossingSolverNames)
        {
            const scalar tau = newSolver(name)->earliestCrossing(pair, 1);
            EXPECT_NEAR(tau, exact, 1e-12)
                << name << ", rotated " << rotated;
        }
    }
}


// (b) Two crossings in one step. Rod J (along y at x = 0.1, height h = 0.21)
// slides along y with 0.5 while bead j+1 moves down with 2: the height of
// line J over rod I is h - s + s^2, V(s) = -(s^2 - s + h), roots 0.3 and 0.7
// (lambda_j = 0.35 and 0.15, lambda_i = 0.6): J passes down through I and
// back up. V(0) = V(1) = -h: no sign change between the ends. The isolating
// solver finds the first root; bisection, newton and cubic look only at a
// sign change of V(0) V(T) and return -1 (documented: they miss two
// crossings in one step; the net topology is unchanged but the rods did
// pass through each other twice).
TEST(crossingRootSolver, TwoCrossingsInOneStep)
{
    const scalar h = 0.21;
    const scene base = crossScene
    (
        0.1, h, vector(0, 0.5, 0), vector(0, 0.5, -2)
    );
    const scalar first = 0.5*(1 - std::sqrt(1 - 4*h));

    for (const bool rotated : {false, true})
    {
        const scene sc =
            rotated ? base.moved(genericRotation(), vector(-2, 5, 1)) : base;
        const rodPairCrossing pair = sc.pair();
        ASSERT_GT(pair.tripleProduct(0)*pair.tripleProduct(1), 0);
        ASSERT_LT(pair.tripleProduct(0)*pair.tripleProduct(0.5), 0);
        ASSERT_TRUE(pair.crossesAt(first));
        ASSERT_TRUE(pair.crossesAt(1 - first));

        EXPECT_NEAR
        (
            newSolver("isolating")->earliestCrossing(pair, 1), first, 1e-12
        ) << "rotated " << rotated;
        for (const char* name : {"bisection", "newton", "cubic"})
        {
            EXPECT_EQ(newSolver(name)->earliestCrossing(pair, 1), -1)
                << name << ", rotated " << rotated;
        }
        // Over half the step (one root inside) they all find it
        for (const word& name : crossingSolverNames)
        {
            EXPECT_NEAR
            (
                newSolver(name)->earliestCrossing(pair, 0.5), first, 1e-12
            ) << name << ", rotated " << rotated;
        }
    }
}


// (c) Near-parallel rods: rod J at angle theta to rod I in the x-y plane,
// centred over (0.05, 0), sinking with 0.7 from height 0.3, so that
// V(s) = -(0.3 - 0.7 s) sin(theta): root 3/7 whatever theta.
// - theta >= 1e-5: every solver finds 3/7 to 1e-12. Only the rotated
//   placement is used: on the axis-aligned one V is linear and exact, the
//   secant start of newton lands on V = 0 exactly and newton returns its
//   stale bracket end s = 0 (see SingleCrossing and NearCoplanarRods).
// - theta <= 1e-7: every solver returns -1, because
//   rodPairCrossing::intersection takes det = |b|^2|c|^2 sin^2(theta)
//   <= 1e-12 |b|^2|c|^2 (theta below about 1e-6) for parallel rods, so no
//   lambda and no crossing; the elastic impulse is undefined there too.
//   This is a gap of the detector (the rods do pass through each other:
//   the long-double audit, whose threshold is 1e-18, sees it at 1e-7); for
//   random orientations its probability is about theta^2/2 ~ 1e-12 per
//   approach.
TEST(crossingRootSolver, NearParallelRods)
{
    const scalar exact = 3.0/7.0;
    auto parallelScene = [](const scalar theta)
    {
        const vector d(std::cos(theta), std::sin(theta), 0);
        scene sc;
        sc.x = FixedList<vector, 4>
        ({
            vector(-0.5, 0, 0), vector(0.5, 0, 0),
            vector(0.05, 0, 0.3) - 0.5*d, vector(0.05, 0, 0.3) + 0.5*d
        });
        const vector w(0, 0, -0.7);
        sc.v = FixedList<vector, 4>({Zero, Zero, w, w});
        return sc;
    };

    for (const scalar theta : {1e-2, 1e-4, 1e-5})
    {
        const scene sc =
            parallelScene(theta).moved(genericRotation(), vector(7, -3, 11));
        for (const word& name : crossingSolverNames)
        {
            EXPECT_NEAR
            (
                newSolver(name)->earliestCrossing(sc.pair(), 1), exact, 1e-12
            ) << name << ", theta " << theta;
        }
    }

    for (const scalar theta : {1e-7, 1e-9})
    {
        for (const bool rotated : {false, true})
        {
            const scene sc =
                rotated
              ? parallelScene(theta).moved(genericRotation(), vector(7, -3, 11))
              : parallelScene(theta);
            ASSERT_LT(sc.pair().tripleProduct(0)*sc.pair().tripleProduct(1), 0);
            scalar li, lj;
            EXPECT_FALSE(sc.pair().intersection(exact, li, lj));
            for (const word& name : crossingSolverNames)
            {
                EXPECT_EQ(newSolver(name)->earliestCrossing(sc.pair(), 1), -1)
                    << name << ", theta " << theta << ", rotated " << rotated;
            }
        }
    }

    // The audit sees the theta = 1e-7 crossing the detector does not
    const scene sc = parallelScene(1e-7);
    List<point> start(4), end(4);
    for (label k = 0; k < 4; ++k)
    {
        start[k] = sc.x[k];
        end[k] = sc.x[k] + sc.v[k];
    }
    EXPECT_EQ
    (
        rodCrossingAudit
        (
            List<labelPair>({labelPair(0, 1), labelPair(2, 3)})
        ).check(start, end).size(),
        1
    );
}


// (d) Near-coplanar rods: rod J (along y) starts a height delta above the
// plane of rod I and slides across it in x (from x = 0.6 to -0.4) while
// sinking by 2 delta over the step: V(s) = -delta (1 - 2 s), root 0.5
// (x = 0.1, lambda_i = 0.6, lambda_j = 0.5). V stays within delta of zero
// over the whole step.
// - Axis-aligned, V is exact: every solver should return 0.5 to 1e-12.
//   newton's secant start is exactly the root, where V = 0 ends its
//   iteration: it must return that root, not the stale bracket end s = 0
//   (where the lines meet outside rod I, lambda_i = 1.1).
// - Rotated, V is a sum of O(1) products that cancel to O(delta): its
//   round-off is about 1e-15, so the root is only determined to about
//   1e-15/|V'| = 1e-15/(2 delta): every solver is within 1e-14/delta of
//   0.5. isolating, bisection and newton return a time on the uncrossed
//   side (V(tau) has the sign of V(0)); cubic does not promise this (its
//   formula's root lands on either side: 1e-6 and 1e-9 land past it).
// - Rotated with delta = 1e-15, V(0) and V(1) evaluate with the same sign
//   (round-off exceeds delta): every solver returns -1 - nothing in double
//   precision can see this crossing.
TEST(crossingRootSolver, NearCoplanarRods)
{
    auto coplanarScene = [](const scalar delta)
    {
        return crossScene
        (
            0.6, delta, vector(-1, 0, -2*delta), vector(-1, 0, -2*delta)
        );
    };

    for (const scalar delta : {1e-3, 1e-6, 1e-9, 1e-12})
    {
        const scene axis = coplanarScene(delta);
        for (const word& name : crossingSolverNames)
        {
            EXPECT_NEAR
            (
                newSolver(name)->earliestCrossing(axis.pair(), 1), 0.5, 1e-12
            ) << name << ", axis-aligned, delta " << delta;
        }

        const scene sc = axis.moved(genericRotation(), vector(7, -3, 11));
        const rodPairCrossing pair = sc.pair();
        for (const word& name : crossingSolverNames)
        {
            const scalar tau = newSolver(name)->earliestCrossing(pair, 1);
            EXPECT_NEAR(tau, 0.5, 1e-14/delta)
                << name << ", rotated, delta " << delta;
            if (name != "cubic")
            {
                EXPECT_GT(pair.tripleProduct(tau)*pair.tripleProduct(0), 0)
                    << name << ", rotated, delta " << delta
                    << ": tau on the crossed side";
            }
        }
    }

    const scene sc =
        coplanarScene(1e-15).moved(genericRotation(), vector(7, -3, 11));
    ASSERT_GT(sc.pair().tripleProduct(0)*sc.pair().tripleProduct(1), 0);
    for (const word& name : crossingSolverNames)
    {
        EXPECT_EQ(newSolver(name)->earliestCrossing(sc.pair(), 1), -1)
            << name << ", delta 1e-15";
    }
}


// (e) A sign change of V whose lines meet outside rod I (x = 0.8 beyond its
// end 0.5: lambda_i = 1.3): the rods pass by, -1 for all.
TEST(crossingRootSolver, LinesMeetOutsideRods)
{
    const scene base = crossScene
    (
        0.8, 0.3, vector(0, 0, -0.7), vector(0, 0, -0.7)
    );
    for (const bool rotated : {false, true})
    {
        const scene sc =
            rotated ? base.moved(genericRotation(), vector(1, 1, 1)) : base;
        const rodPairCrossing pair = sc.pair();
        ASSERT_LT(pair.tripleProduct(0)*pair.tripleProduct(1), 0);
        scalar li, lj;
        ASSERT_TRUE(pair.intersection(3.0/7.0, li, lj));
        EXPECT_NEAR(li, 1.3, 1e-12);

        for (const word& name : crossingSolverNames)
        {
            EXPECT_EQ(newSolver(name)->earliestCrossing(pair, 1), -1)
                << name << ", rotated " << rotated;
        }
    }
}


// ************************************************************************* //
