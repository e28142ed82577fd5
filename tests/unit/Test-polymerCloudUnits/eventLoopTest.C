/*---------------------------------------------------------------------------*\
Description
    The event loop's parts on their own: collisionEventQueue gives events
    earliest first and passes over those whose beads changed course since
    they were predicted; chainRods lists the rods of open chains and rings
    with the rods through each bead; sweptBoxGrid finds exactly the pairs of
    non-adjacent rods whose swept boxes overlap (against all pairs tested),
    grows a box with its new pairs, meets rods across a periodic lattice
    with the second rod's translation, and lists the pairs in an order
    that the grid's cells do not change.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "collisionEventQueue.H"
#include "chainRods.H"
#include "sweptBoxGrid.H"
#include <random>
#include <set>

using namespace Foam;
using namespace Foam::polymer;

namespace
{

collisionEventQueue::event eventAt
(
    const scalar time,
    const label pair,
    const FixedList<label, 4>& beads
)
{
    collisionEventQueue::event e;
    e.time = time;
    e.pair = pair;
    e.from = 0;
    e.offset = time;
    e.normal = Zero;
    e.patch = -1;
    e.beads = beads;
    return e;
}


// Two chains along x, one open of 4 beads and one ring of 4 beads
polymerChains twoChains(const PtrList<chainType>& types)
{
    polymerChains chains(types);
    const List<vector> open({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
    const List<vector> ring({{0, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
    chains.append(0, 7, open, List<vector>(4, Zero));
    chains.append(1, 3, ring, List<vector>(4, Zero));
    return chains;
}


// One open chain type of 5 beads
PtrList<chainType> fiveBeadType()
{
    PtrList<chainType> types(1);
    types.set(0, new chainType("five", 5, 1, 1, 1, 1, false));
    return types;
}


// Chains of 5 beads at random in a 4 a cube, rods of length 1
void appendRandomChains
(
    polymerChains& chains,
    const label nChains,
    std::mt19937_64& gen
)
{
    std::uniform_real_distribution<double> u(0, 4);
    for (label c = 0; c < nChains; ++c)
    {
        List<vector> x(5);
        x[0] = vector(u(gen), u(gen), u(gen));
        for (label i = 1; i < 5; ++i)
        {
            vector d(u(gen) - 2, u(gen) - 2, u(gen) - 2);
            x[i] = x[i - 1] + d/mag(d);
        }
        chains.append(0, chains.nChains(), x, List<vector>(5, Zero));
    }
}


// The boxes of the rods, each grown by a random margin up to 0.3
List<boundBox> randomRodBoxes
(
    const polymerChains& chains,
    const chainRods& rods,
    std::mt19937_64& gen
)
{
    std::uniform_real_distribution<double> m(0, 0.3);
    const List<vector>& x = chains.positions();
    List<boundBox> boxes(rods.size());
    forAll(boxes, rod)
    {
        boxes[rod] = boundBox(x[rods[rod].first()]);
        boxes[rod].add(x[rods[rod].second()]);
        boxes[rod].inflate(m(gen));
    }
    return boxes;
}


// Two grids list the same pairs with the same translations, in the same
// order, and the first nRods rods the same pairs in the same order
void expectSameLists
(
    const sweptBoxGrid& a,
    const sweptBoxGrid& b,
    const label nRods
)
{
    ASSERT_EQ(a.pairs().size(), b.pairs().size());
    forAll(a.pairs(), pairi)
    {
        EXPECT_EQ(a.pairs()[pairi], b.pairs()[pairi]) << "pair " << pairi;
        EXPECT_EQ(a.pairShift(pairi), b.pairShift(pairi));
    }
    for (label rod = 0; rod < nRods; ++rod)
    {
        EXPECT_EQ(a.rodPairs(rod), b.rodPairs(rod)) << "rod " << rod;
    }
}

} // End anonymous namespace


TEST(collisionEventQueue, EarliestFirstAndStaleEventsPassedOver)
{
    collisionEventQueue queue;
    queue.reset(6);
    queue.push(eventAt(0.5, 0, {0, 1, 2, 3}));
    queue.push(eventAt(0.2, 1, {2, 3, 4, 5}));
    queue.push(eventAt(0.7, -1 - 5, {5, -1, -1, -1}));
    queue.push(eventAt(0.1, 2, {0, 1, 4, 5}));

    // Bead 4 changes course: the events through it (0.1, 0.2) are stale
    queue.changedCourse(4);
    queue.push(eventAt(0.3, 1, {2, 3, 4, 5}));

    collisionEventQueue::event e;
    ASSERT_TRUE(queue.next(e));
    EXPECT_EQ(e.time, 0.3);
    ASSERT_TRUE(queue.next(e));
    EXPECT_EQ(e.time, 0.5);
    ASSERT_TRUE(queue.next(e));
    EXPECT_EQ(e.time, 0.7);
    EXPECT_EQ(e.pair, -6);
    EXPECT_FALSE(queue.next(e));

    // reset empties the queue and the versions
    queue.push(eventAt(0.4, 0, {0, 1, 2, 3}));
    queue.reset(6);
    EXPECT_FALSE(queue.next(e));
}


TEST(chainRods, OpenChainsAndRings)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("open", 4, 1, 1, 1, 1, false));
    types.set(1, new chainType("ring", 4, 1, 1, 1, 1, true));
    const polymerChains chains(twoChains(types));

    chainRods rods;
    rods.update(chains);
    ASSERT_EQ(rods.size(), 3 + 4);
    EXPECT_EQ(rods[0], labelPair(0, 1));
    EXPECT_EQ(rods[2], labelPair(2, 3));
    EXPECT_EQ(rods[6], labelPair(7, 4));    // the ring's closing rod
    EXPECT_EQ(rods.chain(6), 1);
    EXPECT_EQ(rods.chainId(6), 3);
    EXPECT_EQ(rods.chainId(0), 7);
    EXPECT_EQ(rods.beadRods(0)[0], -1);     // an open chain's end
    EXPECT_EQ(rods.beadRods(0)[1], 0);
    EXPECT_EQ(rods.beadRods(4)[0], 6);      // a ring has no ends
    EXPECT_EQ(rods.beadRods(4)[1], 3);
    EXPECT_TRUE(rods.adjacent(0, 1));
    EXPECT_FALSE(rods.adjacent(0, 2));
    EXPECT_TRUE(rods.adjacent(3, 6));
}


TEST(sweptBoxGrid, FindsExactlyTheOverlappingPairs)
{
    // 30 chains of 5 beads at random in a 4 a cube, boxes of their rods
    // grown by a random margin: the candidates are all non-adjacent pairs
    // whose boxes overlap, each once
    std::mt19937_64 gen(11);
    const PtrList<chainType> types(fiveBeadType());
    polymerChains chains(types);
    appendRandomChains(chains, 30, gen);
    chainRods rods;
    rods.update(chains);
    const List<boundBox> boxes(randomRodBoxes(chains, rods, gen));

    sweptBoxGrid grid;
    grid.build(rods, List<boundBox>(boxes), List<vector>());

    std::set<std::pair<label, label>> expected, found;
    forAll(boxes, a)
    {
        for (label b = a + 1; b < boxes.size(); ++b)
        {
            if (!rods.adjacent(a, b) && boxes[a].overlaps(boxes[b]))
            {
                expected.insert({a, b});
            }
        }
    }
    for (const labelPair& p : grid.pairs())
    {
        const label a = min(p.first(), p.second());
        const label b = max(p.first(), p.second());
        EXPECT_TRUE(found.insert({a, b}).second) << "pair twice";
    }
    EXPECT_GT(expected.size(), 10u);
    EXPECT_EQ(found, expected);

    // Growing a rod's box to hold every box makes it a candidate with
    // every rod it does not share a bead with
    boundBox all(boundBox::invertedBox);
    for (const boundBox& box : boxes)
    {
        all.add(box);
    }
    grid.grow(0, all);
    label withRod0 = 0;
    for (const labelPair& p : grid.pairs())
    {
        withRod0 += (p.first() == 0 || p.second() == 0);
    }
    EXPECT_EQ(withRod0, rods.size() - 2);
    EXPECT_EQ(label(grid.rodPairs(0).size()), withRod0);
}


TEST(sweptBoxGrid, GrownBoxesMeetEachOther)
{
    // Two single-rod chains 10 apart in x: no pair at the build. Each box
    // grown half way towards the other, beyond the cells of the build:
    // the second grow meets the first grown box (which is in no cell of
    // the build there), once
    PtrList<chainType> types(1);
    types.set(0, new chainType("dimer", 2, 1, 1, 1, 1, false));
    polymerChains chains(types);
    chains.append(0, 0, List<vector>({{0, 0, 0}, {0, 1, 0}}),
        List<vector>(2, Zero));
    chains.append(0, 1, List<vector>({{10, 0, 0}, {10, 1, 0}}),
        List<vector>(2, Zero));
    chainRods rods;
    rods.update(chains);
    List<boundBox> boxes(2);
    boxes[0] = boundBox(point(-0.1, -0.1, -0.1), point(0.1, 1.1, 0.1));
    boxes[1] = boundBox(point(9.9, -0.1, -0.1), point(10.1, 1.1, 0.1));

    sweptBoxGrid grid;
    grid.build(rods, List<boundBox>(boxes), List<vector>());
    EXPECT_EQ(grid.pairs().size(), 0);

    EXPECT_TRUE(grid.grow(0, boundBox(point(0, 0, 0), point(5.1, 1, 0))));
    EXPECT_EQ(grid.pairs().size(), 0);
    EXPECT_TRUE(grid.grow(1, boundBox(point(4.9, 0, 0), point(10, 1, 0))));
    ASSERT_EQ(grid.pairs().size(), 1);
    EXPECT_EQ(grid.pairs()[0], labelPair(0, 1));

    // Grown again, the pair is not listed twice
    EXPECT_TRUE(grid.grow(0, boundBox(point(0, 0, 0), point(8, 1, 0))));
    EXPECT_EQ(grid.pairs().size(), 1);
    EXPECT_EQ(label(grid.rodPairs(1).size()), 1);
}


TEST(sweptBoxGrid, MeetsAcrossThePeriodicLattice)
{
    // Two single-rod chains at opposite faces of a period-10 box in x
    PtrList<chainType> types(1);
    types.set(0, new chainType("dimer", 2, 1, 1, 1, 1, false));
    polymerChains chains(types);
    chains.append(0, 0, List<vector>({{0.1, 0, 0}, {0.1, 1, 0}}),
        List<vector>(2, Zero));
    chains.append(0, 1, List<vector>({{9.95, 0.5, -0.5}, {9.95, 0.5, 0.5}}),
        List<vector>(2, Zero));
    chainRods rods;
    rods.update(chains);

    List<boundBox> boxes(2);
    forAll(boxes, rod)
    {
        const List<vector>& x = chains.positions();
        boxes[rod] = boundBox(x[rods[rod].first()]);
        boxes[rod].add(x[rods[rod].second()]);
        boxes[rod].inflate(0.1);
    }

    sweptBoxGrid grid;
    grid.build(rods, List<boundBox>(boxes), List<vector>());
    EXPECT_EQ(grid.pairs().size(), 0);

    grid.build(rods, List<boundBox>(boxes), List<vector>({vector(10, 0, 0)}));
    ASSERT_EQ(grid.pairs().size(), 1);
    EXPECT_EQ(grid.pairs()[0], labelPair(0, 1));
    EXPECT_EQ(grid.pairShift(0), vector(-10, 0, 0));
}


TEST(sweptBoxGrid, ListsThePairsInAnOrderTheCellsDoNotChange)
{
    // The same 60 chains alone, and with a far chain appended: the far
    // rods stretch the bounds the cells are laid over a thousandfold, so
    // the cells of the two grids differ, but the far rods (inserted last)
    // meet no other. The pairs, their translations and each rod's pairs
    // must come in the same order, built and after growing boxes, plain
    // and across a periodic lattice
    std::mt19937_64 gen(23);
    const PtrList<chainType> types(fiveBeadType());
    polymerChains near(types);
    appendRandomChains(near, 60, gen);
    polymerChains withFar(near);
    withFar.append
    (
        0, 60,
        List<vector>({{1000, 1000, 1000}, {1001, 1000, 1000},
            {1001, 1001, 1000}, {1001, 1001, 1001}, {1002, 1001, 1001}}),
        List<vector>(5, Zero)
    );
    chainRods nearRods, allRods;
    nearRods.update(near);
    allRods.update(withFar);
    const List<boundBox> nearBoxes(randomRodBoxes(near, nearRods, gen));
    List<boundBox> allBoxes(randomRodBoxes(withFar, allRods, gen));
    forAll(nearBoxes, rod)
    {
        allBoxes[rod] = nearBoxes[rod];
    }

    for (const List<vector>& lattice :
        {List<vector>(), List<vector>({vector(4, 0, 0), vector(0, 4, 0)})})
    {
        sweptBoxGrid nearGrid, allGrid;
        nearGrid.build(nearRods, List<boundBox>(nearBoxes), lattice);
        allGrid.build(allRods, List<boundBox>(allBoxes), lattice);
        EXPECT_GT(nearGrid.pairs().size(), 200);
        expectSameLists(nearGrid, allGrid, nearRods.size());

        // Boxes grown as events change paths: each grid lists the new
        // pairs of a grown box in the same order
        std::uniform_int_distribution<label> pick(0, nearRods.size() - 1);
        for (label growth = 0; growth < 20; ++growth)
        {
            const label rod = pick(gen);
            boundBox grown(nearBoxes[rod]);
            grown.inflate(0.5 + 0.1*growth);
            nearGrid.grow(rod, grown, 0.05);
            allGrid.grow(rod, grown, 0.05);
        }
        expectSameLists(nearGrid, allGrid, nearRods.size());
    }
}


TEST(sweptBoxGrid, SweepsAndCellsListTheSamePairs)
{
    // 40 chains in a 4 a cube and 40 in a cube 6 a beyond it along x: the
    // boxes spread along x, as a channel's wells spread them. Swept along
    // x or held in cells, a grid must list the same pairs, in the same
    // order, built and after growing boxes (through sorted boxes and
    // through cells); and a sweep whose tests exceed a low limit (one a
    // rod) gives up for the cells, with the same list
    std::mt19937_64 gen(31);
    const PtrList<chainType> types(fiveBeadType());
    polymerChains chains(types);
    appendRandomChains(chains, 40, gen);
    polymerChains beyond(types);
    appendRandomChains(beyond, 40, gen);
    for (label chaini = 0; chaini < beyond.nChains(); ++chaini)
    {
        List<vector> x(SubList<vector>(beyond.positions(), 5, 5*chaini));
        for (vector& xi : x)
        {
            xi.x() += 10;
        }
        chains.append(0, chains.nChains(), x, List<vector>(5, Zero));
    }
    chainRods rods;
    rods.update(chains);
    const List<boundBox> boxes(randomRodBoxes(chains, rods, gen));

    sweptBoxGrid cells(0), swept(labelMax), crowded(1);
    cells.build(rods, List<boundBox>(boxes), List<vector>());
    swept.build(rods, List<boundBox>(boxes), List<vector>());
    crowded.build(rods, List<boundBox>(boxes), List<vector>());
    EXPECT_FALSE(cells.swept());
    EXPECT_TRUE(swept.swept());
    EXPECT_FALSE(crowded.swept());
    EXPECT_GT(cells.pairs().size(), 200);

    expectSameLists(cells, swept, rods.size());
    expectSameLists(cells, crowded, rods.size());

    std::uniform_int_distribution<label> pick(0, rods.size() - 1);
    for (label growth = 0; growth < 30; ++growth)
    {
        const label rod = pick(gen);
        boundBox grown(boxes[rod]);
        grown.inflate(0.2 + 0.2*growth);
        cells.grow(rod, grown, 0.05);
        swept.grow(rod, grown, 0.05);
    }
    expectSameLists(cells, swept, rods.size());
}


// ************************************************************************* //
