/*---------------------------------------------------------------------------*\
Description
    polymerChains::reorder: the chains (the cloud keeps them in order of
    their cells) change places whole, each with its beads, velocities, type
    and global id, and the layout version changes so that per-bead data is
    remapped. Exact: reordering copies values.

    beadData: each bead keeps its own value through random sequences of
    reorders (alone, two in a row, or followed by an append or removal),
    removals and appends, read at every change or every few; a new
    chain's beads are unknown.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "beadData.H"

#include <random>

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
TEST(beadData, FollowsEachBeadThroughReordersRemovalsAndAppends)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("short", 3, 1, 1, 1, 1, false));
    types.set(1, new chainType("long", 5, 1, 1, 1, 1, false));
    polymerChains chains(types);
    std::mt19937_64 engine(5);
    std::uniform_real_distribution<scalar> u(0, 1);

    label nextId = 0;
    auto append = [&]()
    {
        const label type = (u(engine) < 0.5) ? 0 : 1;
        const List<vector> x(types[type].nBeads(), Zero);
        chains.append(type, nextId++, x, x);
    };
    for (label c = 0; c < 20; ++c)
    {
        append();
    }

    // A bead's value: 100 times its chain's global id plus its place in
    // the chain, set when its chain is first seen (unknown: -1)
    beadData<label> data(-1);
    label nChecked = 0;
    label nNew = 0;
    for (label round = 0; round < 300; ++round)
    {
        if (u(engine) < 0.7)
        {
            labelList& values = data.update(chains);
            ASSERT_EQ(values.size(), chains.nBeads());
            for (label c = 0; c < chains.nChains(); ++c)
            {
                for (label k = 0; k < chains.size(c); ++k)
                {
                    label& value = values[chains.start(c) + k];
                    const label expected = 100*chains.globalId(c) + k;
                    if (value == -1)
                    {
                        value = expected;
                        ++nNew;
                    }
                    EXPECT_EQ(value, expected)
                        << "round " << round << " chain " << c;
                    ++nChecked;
                }
            }
        }

        const scalar change = u(engine);
        labelList newToOld(identity(chains.nChains()));
        std::shuffle(newToOld.begin(), newToOld.end(), engine);
        chains.reorder(newToOld);
        if (change < 0.2)
        {
            append();
        }
        else if (change < 0.4 && chains.nChains() > 2)
        {
            chains.remove(labelList({label(u(engine)*chains.nChains())}));
        }
        else if (change < 0.5)
        {
            std::shuffle(newToOld.begin(), newToOld.end(), engine);
            chains.reorder(newToOld);
        }
    }
    EXPECT_GT(nChecked, 5000);
    EXPECT_GT(nNew, 50);
}


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
