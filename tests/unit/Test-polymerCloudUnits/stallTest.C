/*---------------------------------------------------------------------------*\
Description
    A stall of elasticRods' event loop holds only the chains of the
    stalling event (issue: nothing silent in the event loop). Four dimers:
    chains 0 and 1 meet at 0.1 dt, which stallTime 0.2 and stallEvents 1
    make a stall; chain 2, far away, moves freely; chain 3 comes down onto
    held chain 0 at 0.6 dt. For either impulse: one stall; chains 0 and 1
    end where they were held (at their contact, uncrossed); chain 2 ends at
    x-dagger; chain 3 bounces off the immovable chain 0 (its normal
    velocity reverses, chain 0 does not move) without crossing it.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "collisionScenes.H"
#include "elasticRods.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(elasticRodsStall, HoldsOnlyTheStallingChains)
{
    const scalar dt = 0.02;
    const PtrList<chainType> types(oneType(2, 1, 1, 1, 1));

    // Chains 0 and 1 meet at z = 0 at 0.1 dt; chain 3 reaches z = 0 at
    // 0.6 dt above chain 0's rod (x = 0.5, lambda 0.85 of chain 0's rod)
    const scalar w = 0.03/(0.1*dt);
    const scalar u = 1.0/(0.6*dt);
    const List<vector> positionsOld
    ({
        vector(-0.35, 0, -0.03), vector(0.65, 0, -0.03),
        vector(0, -0.7, 0.03), vector(0, 0.3, 0.03),
        vector(10, 0, 0), vector(10, 1, 0),
        vector(0.5, -0.5, 1), vector(0.5, 0.5, 1)
    });
    const List<vector> velocities
    ({
        vector(0, 0, w), vector(0, 0, w),
        vector(0, 0, -w), vector(0, 0, -w),
        vector(1, 0, 0), vector(1, 0, 0),
        vector(0, 0, -u), vector(0, 0, -u)
    });

    for (const word impulse : {"constrained", "dumbbell"})
    {
        SCOPED_TRACE(impulse);
        polymerChains chains(types);
        for (label c = 0; c < 4; ++c)
        {
            const label i = 2*c;
            chains.append
            (
                0, c,
                List<vector>
                ({
                    positionsOld[i] + dt*velocities[i],
                    positionsOld[i + 1] + dt*velocities[i + 1]
                }),
                List<vector>({velocities[i], velocities[i + 1]})
            );
        }

        dictionary coeffs;
        coeffs.add("stallTime", 0.2);
        coeffs.add("stallEvents", 1);
        coeffs.add("audit", true);
        coeffs.add("impulse", impulse);
        dictionary dict;
        dict.add("collision", "elasticRods");
        dict.add("elasticRodsCoeffs", coeffs);
        collisionModels::elasticRods model(dict);

        model.correct(chains, positionsOld, dt, dt);

        EXPECT_EQ(model.count().stalls, 1);
        EXPECT_EQ(model.count().events, 1);
        EXPECT_EQ(model.count().auditCrossings, 0);

        // Chains 0 and 1 held at their contact, on the sides they started
        const List<vector>& x = chains.positions();
        for (label i = 0; i < 4; ++i)
        {
            EXPECT_NEAR(x[i].z(), 0, 1e-12) << "bead " << i;
            EXPECT_NEAR(x[i].x(), positionsOld[i].x(), 1e-12);
            EXPECT_NEAR(x[i].y(), positionsOld[i].y(), 1e-12);
        }
        const rodPairCrossing startPair
        (
            positionsOld[0], positionsOld[1], positionsOld[2], positionsOld[3],
            velocities[0], velocities[1], velocities[2], velocities[3]
        );
        const rodPairCrossing endPair
        (
            x[0], x[1], x[2], x[3], Zero, Zero, Zero, Zero
        );
        EXPECT_GE(startPair.tripleProduct(0)*endPair.tripleProduct(0), 0);

        // Chain 2 free: x-dagger
        for (label i = 4; i < 6; ++i)
        {
            EXPECT_EQ(x[i], positionsOld[i] + dt*velocities[i]);
        }

        // Chain 3 reflected off held chain 0 at 0.6 dt: up again by
        // 0.4 dt u, its velocity reversed
        const List<vector>& v = chains.velocities();
        for (label i = 6; i < 8; ++i)
        {
            EXPECT_NEAR(x[i].z(), 0.4*dt*u, 1e-9) << "bead " << i;
            EXPECT_NEAR(mag(v[i] - vector(0, 0, u)), 0, 1e-9*u);
        }
    }
}


// ************************************************************************* //
