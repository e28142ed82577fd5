/*---------------------------------------------------------------------------*\
Description
    Run totals are 64-bit (issue: nothing lost): the constraint's
    iterations and solves, the collision model's events and the wall's
    rebounds pass 2^31 without wrapping, added step by step, added from
    another model's counts and reduced over the processors (serially the
    identity).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "constraintCounters.H"
#include "collisionCounters.H"
#include "wallCounters.H"
#include <limits>

using namespace Foam;
using namespace Foam::polymer;

namespace
{
const int64_t beyond32 = int64_t(std::numeric_limits<int32_t>::max()) + 1000;
}


TEST(runCounters, ConstraintTotalsPass2To31)
{
    constraintCounters c;
    c.iterations = std::numeric_limits<int32_t>::max() - 10;
    c.solves = std::numeric_limits<int32_t>::max();
    c.add(1010, true);
    EXPECT_EQ(c.iterations, beyond32);
    EXPECT_EQ(c.solves, int64_t(std::numeric_limits<int32_t>::max()) + 1);

    constraintCounters total;
    total.add(c);
    total.add(c);
    EXPECT_EQ(total.iterations, 2*beyond32);
    EXPECT_EQ(total.reduced().iterations, 2*beyond32);
}


TEST(runCounters, CollisionAndWallTotalsPass2To31)
{
    collisionCounters step;
    step.events = std::numeric_limits<int32_t>::max();
    collisionCounters total;
    total.add(step);
    total.add(step);
    EXPECT_EQ(total.events, 2*int64_t(std::numeric_limits<int32_t>::max()));
    EXPECT_EQ(total.reduced().events, total.events);

    wallCounters walls;
    walls.rebounds = beyond32;
    wallCounters wallTotal;
    wallTotal.add(walls);
    wallTotal.add(walls);
    EXPECT_EQ(wallTotal.rebounds, 2*beyond32);
    EXPECT_EQ(wallTotal.reduced().rebounds, 2*beyond32);
}


// ************************************************************************* //
