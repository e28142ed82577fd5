/*---------------------------------------------------------------------------*\
Description
    periodicImages on the periodic channel of tests/cases/periodicChannel
    (period 4 in x and y, walls at z = 0 and 3): shift's box of points
    beyond no plane holds the channel's inside to within a margin, and
    shift gives the planes' tests' translation (shiftByPlanes) at random
    points inside, on, just beside and beyond the cyclic planes and their
    corners, down to a unit in the last place.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "wallScenes.H"
#include "periodicImages.H"

#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(periodicImages, ShiftsAsThePlaneTestsNearAndInsideThePlanes)
{
    const fvMesh* mesh = meshOf("periodicChannel");
    ASSERT_TRUE(mesh);
    const periodicImages& periodic = periodicImages::New(*mesh);
    ASSERT_TRUE(periodic.active());

    // The box spans the channel less a margin of at most 1e-8
    const boundBox& box = periodic.unshiftedBox();
    ASSERT_TRUE(box.valid());
    for (direction d = 0; d < 3; ++d)
    {
        EXPECT_GT(box.min()[d], 0);
        EXPECT_LT(box.min()[d], 1e-8);
    }
    EXPECT_LT(box.max().x(), 4);
    EXPECT_GT(box.max().x(), 4 - 1e-8);
    EXPECT_LT(box.max().y(), 4);
    EXPECT_GT(box.max().y(), 4 - 1e-8);

    // Coordinates at a plane (0 or 4) moved by a random offset of 1e-17 to
    // 1 (and exactly on it), or at any place across the period and beyond
    std::mt19937_64 engine(11);
    std::uniform_real_distribution<scalar> u(0, 1);
    auto coordinate = [&]()
    {
        const scalar kind = u(engine);
        if (kind < 0.3)
        {
            return -2 + 8*u(engine);
        }
        const scalar plane = (u(engine) < 0.5) ? 0 : 4;
        if (kind < 0.4)
        {
            return plane;
        }
        const scalar offset = std::pow(10.0, -17*u(engine));
        return plane + ((u(engine) < 0.5) ? -offset : offset);
    };
    auto nextTo = [&](const scalar x)
    {
        // x, or a unit in the last place either side
        const scalar kind = u(engine);
        return
            (kind < 0.33) ? std::nextafter(x, -GREAT)
          : (kind < 0.67) ? std::nextafter(x, GREAT)
          : x;
    };

    label nShifted = 0;
    label nInBox = 0;
    for (label n = 0; n < 200000; ++n)
    {
        const point p
        (
            nextTo(coordinate()), nextTo(coordinate()), 3*u(engine)
        );
        const vector expected = periodic.shiftByPlanes(p);
        const vector shift = periodic.shift(p);
        EXPECT_TRUE(shift == expected)
            << "at" << str(p) << ": shift" << str(shift) << ", planes"
            << str(expected);
        nShifted += (expected != vector::zero);
        nInBox += box.contains(p);
    }
    EXPECT_GT(nShifted, 50000);
    EXPECT_GT(nInBox, 10000);
}


// ************************************************************************* //
