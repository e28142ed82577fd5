/*---------------------------------------------------------------------------*\
Description
    polymerChains::reorder: the chains (the cloud keeps them in order of
    their cells) change places whole, each with its beads, velocities, type
    and global id, and the layout version changes so that per-bead data is
    remapped. Exact: reordering copies values.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

TEST(polymerChains, ReorderMovesWholeChains)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("short", 3, 1, 1, 1, 1, false));
    types.set(1, new chainType("long", 5, 1, 1, 1, 1, false));
    polymerChains chains(types);

    // Chain with global id g: bead k at (g, k, 0), velocity (0, g, k)
    const labelList typeOf({0, 1, 0});
    const labelList globalIds({7, 3, 12});
    forAll(globalIds, c)
    {
        const label n = types[typeOf[c]].nBeads();
        List<vector> x(n), v(n);
        forAll(x, k)
        {
            x[k] = vector(globalIds[c], k, 0);
            v[k] = vector(0, globalIds[c], k);
        }
        chains.append(typeOf[c], globalIds[c], x, v);
    }

    const label layout = chains.layoutVersion();
    const labelList newToOld({2, 0, 1});
    chains.reorder(newToOld);

    EXPECT_NE(chains.layoutVersion(), layout);
    ASSERT_EQ(chains.nChains(), 3);
    ASSERT_EQ(chains.nBeads(), 11);
    forAll(newToOld, c)
    {
        const label old = newToOld[c];
        const label g = globalIds[old];
        EXPECT_EQ(chains.globalId(c), g);
        EXPECT_EQ(chains.typeIndex(c), typeOf[old]);
        ASSERT_EQ(chains.size(c), types[typeOf[old]].nBeads());
        for (label k = 0; k < chains.size(c); ++k)
        {
            const label i = chains.start(c) + k;
            EXPECT_EQ(chains.positions()[i], vector(g, k, 0));
            EXPECT_EQ(chains.velocities()[i], vector(0, g, k));
            EXPECT_EQ(chains.chainOf(i), c);
        }
    }
    EXPECT_EQ(chains.end(2), chains.nBeads());
}



// The predicted relative displacement of two free beads over dt (the
// cloud's sub-cycling by accuracy): 12 (kT/zeta)(dt - tau (1 - exp(-dt/tau)))
// in rod lengths squared, tau = m/zeta; its limits 12 kT dt/(zeta a^2) for
// dt >> tau (diffusive) and 6 kT dt^2/(m a^2) for dt << tau (ballistic),
// each to its first correction (relative tau/dt and dt/(3 tau))
TEST(chainType, NeighbourDisplacementLimits)
{
    const scalar a = 2, m = 0.5, zeta = 4, kT = 1.5;
    const chainType type("t", 5, a, m, zeta, kT, false);
    const scalar tau = m/zeta;

    const scalar dtLong = 1e4*tau;
    EXPECT_NEAR
    (
        type.neighbourDisplacementSqr(dtLong)/(12*kT*dtLong/(zeta*a*a)),
        1, 1.5e-4
    );

    const scalar dtShort = 1e-4*tau;
    EXPECT_NEAR
    (
        type.neighbourDisplacementSqr(dtShort)
       /(6*kT*dtShort*dtShort/(m*a*a)),
        1, 1e-4
    );

    // At dt = tau exactly: 12 (kT/zeta) tau exp(-1)/a^2
    EXPECT_NEAR
    (
        type.neighbourDisplacementSqr(tau),
        12*kT/zeta*tau*std::exp(-1.0)/(a*a), 1e-14
    );
}

// ************************************************************************* //
