/*---------------------------------------------------------------------------*\
Description
    The broad phase of the topology audit (boxGrid): for 2000 random boxes
    packed along a long, thin region and random query boxes, inside and
    beyond the grid, every box that overlaps the query is visited, and no
    box twice; so are boxes that only touch a query, far from the origin.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "boxGrid.H"

#include <random>

using namespace Foam;
using namespace Foam::polymer;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(boxGrid, VisitsEveryOverlappingBoxOnce)
{
    std::mt19937_64 engine(3);
    std::uniform_real_distribution<scalar> u(0, 1);
    const auto randomBox = [&](const scalar length)
    {
        const point p(length*u(engine), 4*u(engine), u(engine));
        const vector size(0.02 + 0.8*u(engine), 0.8*u(engine), 0.8*u(engine));
        return boundBox(p, p + size);
    };

    List<boundBox> boxes(2000);
    for (boundBox& box : boxes)
    {
        box = randomBox(40);
    }
    const boxGrid grid(boxes);

    label overlaps = 0;
    for (label q = 0; q < 500; ++q)
    {
        // Some queries reach beyond the grid (x up to 60)
        const boundBox query(randomBox(60));
        labelList visits(boxes.size(), Zero);
        grid.forNear(query, [&](const label boxi) { ++visits[boxi]; });
        forAll(boxes, boxi)
        {
            ASSERT_LE(visits[boxi], 1);
            if (boxes[boxi].overlaps(query))
            {
                ++overlaps;
                ASSERT_EQ(visits[boxi], 1) << "box " << boxi << " query " << q;
            }
        }
    }
    EXPECT_GT(overlaps, 1000);
}


TEST(boxGrid, VisitsBoxesThatOnlyTouch)
{
    // Boxes of the widest span at random places far from the origin, each
    // asked about from a query that touches its upper corner only: the
    // grid holds a box by its lower corner, a span below the query's, in
    // a cell at random place across the cells' faces
    std::mt19937_64 engine(5);
    std::uniform_real_distribution<scalar> u(0, 1);
    const point origin(1e3, -1e3, 1e3);
    const vector span(0.8, 0.8, 0.8);
    List<boundBox> boxes(2000);
    for (boundBox& box : boxes)
    {
        const point p(origin + vector(40*u(engine), 4*u(engine), u(engine)));
        box = boundBox(p, p + span);
    }
    const boxGrid grid(boxes);
    forAll(boxes, q)
    {
        const boundBox query(boxes[q].max(), boxes[q].max() + 0.3*span);
        bool met = false;
        grid.forNear(query, [&](const label boxi) { met = met || boxi == q; });
        ASSERT_TRUE(met) << "box " << q;
    }
}


// ************************************************************************* //
