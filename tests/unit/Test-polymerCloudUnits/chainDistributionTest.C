/*---------------------------------------------------------------------------*\
Description
    chainDistribution's serial logic on the periodic channel of
    tests/cases/periodicChannel (period 4 in x and y, walls at z = 0 and 3,
    4 x 4 x 3 unit cells):

    - wrap: a chain whose reference (middle) bead has left the period is
      carried back whole by the period (every bead by the same shift, so
      its rods are unchanged), and counted; a chain whose reference bead is
      inside stays, even with other beads beyond the cyclic plane;
    - sort: the chains end in the order of their reference bead's cell,
      then of their global id, whatever their order before; each chain's
      beads travel with it;
    - keepOwn and gather on one processor keep every chain.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wallScenes.H"
#include "chainDistribution.H"
#include "periodicImages.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

//- A straight chain of three beads along x from start, of the given id
void appendChain(polymerChains& chains, const label id, const point& start)
{
    const List<vector> x
    ({
        start, start + vector(1, 0, 0), start + vector(2, 0, 0)
    });
    chains.append(0, id, x, List<vector>(3, vector(id, 0, 0)));
}

} // End anonymous namespace


TEST(chainDistribution, wrapCarriesWholeChainsByThePeriod)
{
    const fvMesh* mesh = meshOf("periodicChannel");
    ASSERT_TRUE(mesh);
    const periodicImages& periodic = periodicImages::New(*mesh);
    ASSERT_TRUE(periodic.active());

    const PtrList<chainType> types(oneType(3, 1, 1, 1, 1));
    polymerChains chains(types);
    appendChain(chains, 0, point(2.5, 1.5, 1.5));   // reference bead x = 3.5
    appendChain(chains, 1, point(3.5, 1.5, 1.5));   // reference x = 4.5
    appendChain(chains, 2, point(-2.5, 4.5, 1.5));  // reference (-1.5, 4.5)

    chainDistribution distribution(*mesh, periodic, chains, false);
    distribution.wrap();

    EXPECT_EQ(distribution.nWrapped(), 2);
    const List<vector>& x = chains.positions();
    const vector shifts[] =
        {vector(0, 0, 0), vector(-4, 0, 0), vector(4, -4, 0)};
    const point starts[] =
        {point(2.5, 1.5, 1.5), point(3.5, 1.5, 1.5), point(-2.5, 4.5, 1.5)};
    for (label c = 0; c < 3; ++c)
    {
        for (label k = 0; k < 3; ++k)
        {
            EXPECT_EQ
            (
                x[chains.start(c) + k],
                starts[c] + vector(k, 0, 0) + shifts[c]
            ) << "chain " << c << " bead " << k;
        }
    }
}


TEST(chainDistribution, sortOrdersByReferenceCellThenId)
{
    const fvMesh* mesh = meshOf("periodicChannel");
    ASSERT_TRUE(mesh);
    const periodicImages& periodic = periodicImages::New(*mesh);

    const PtrList<chainType> types(oneType(3, 1, 1, 1, 1));
    polymerChains chains(types);

    // Reference beads (the middle ones) in cells of decreasing index; two
    // chains share a cell, the larger id first
    appendChain(chains, 7, point(1.2, 3.5, 2.5));
    appendChain(chains, 5, point(1.6, 3.5, 2.5));
    appendChain(chains, 3, point(0.5, 0.5, 0.5));
    appendChain(chains, 4, point(1.5, 2.5, 0.5));

    chainDistribution distribution(*mesh, periodic, chains, true);
    distribution.keepOwn();
    ASSERT_EQ(chains.nChains(), 4);
    distribution.sort();

    labelList cells(chains.nChains());
    for (label c = 0; c < chains.nChains(); ++c)
    {
        cells[c] = mesh->findCell(chains.positions()[chains.referenceBead(c)]);
        ASSERT_GE(cells[c], 0);
        if (c)
        {
            EXPECT_TRUE
            (
                cells[c - 1] < cells[c]
             || (
                    cells[c - 1] == cells[c]
                 && chains.globalId(c - 1) < chains.globalId(c)
                )
            ) << "chains " << c - 1 << " and " << c << " out of order";
        }

        // The beads came along: a straight chain whose velocities carry
        // its id
        const label id = chains.globalId(c);
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            EXPECT_EQ(chains.velocities()[i], vector(id, 0, 0));
        }
        EXPECT_EQ
        (
            chains.positions()[chains.start(c) + 2]
          - chains.positions()[chains.start(c)],
            vector(2, 0, 0)
        );
    }
    EXPECT_EQ(chains.globalId(0), 3);
    EXPECT_EQ(chains.globalId(3), 7);

    const polymerChains all(distribution.gather());
    EXPECT_EQ(all.nChains(), 4);
}


// ************************************************************************* //
