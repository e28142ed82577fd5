/*---------------------------------------------------------------------------*\
Description
    trefoil::beads: every chord has length a (placed exactly along the chord:
    1e-12 relative, round-off); a ring closes (its closing chord is fixed by
    bisection of the scale: 1e-10 relative); the cut trefoil is open (the end
    gap spans the missing bead, so it exceeds a).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "trefoil.H"

using namespace Foam;
using namespace Foam::polymer;

namespace
{

scalar maxChordError(const List<point>& x, const scalar a, const label nChords)
{
    scalar largest = 0;
    for (label i = 0; i < nChords; ++i)
    {
        largest = max
        (
            largest, mag(mag(x[(i + 1)%x.size()] - x[i]) - a)/a
        );
    }
    return largest;
}

} // End anonymous namespace


// Open (cut) trefoil, N = 400: N-1 chords of a to 1e-12; gap > a.
TEST(trefoil, OpenChordsEqualRodLength)
{
    for (const scalar a : {1.0, 1e-7})
    {
        const List<point> x =
            initialisationModels::trefoil::beads(400, a, false);
        ASSERT_EQ(x.size(), 400);
        EXPECT_LE(maxChordError(x, a, 399), 1e-12) << "a = " << a;
        EXPECT_GT(mag(x[399] - x[0]), a*(1 + 1e-6)) << "a = " << a;
    }
}


// Ring trefoil: all N chords including the closing one to 1e-10.
TEST(trefoil, RingClosesWithRodLength)
{
    for (const label n : {30, 400})
    {
        for (const scalar a : {1.0, 1e-7})
        {
            const List<point> x =
                initialisationModels::trefoil::beads(n, a, true);
            ASSERT_EQ(x.size(), n);
            EXPECT_LE(maxChordError(x, a, n - 1), 1e-12)
                << "N = " << n << ", a = " << a;
            EXPECT_LE(mag(mag(x[0] - x[n - 1]) - a)/a, 1e-10)
                << "closing chord, N = " << n << ", a = " << a;
        }
    }
}


// Non-adjacent beads of the knot stay apart (no two beads on top of each
// other, which would make the trefoil degenerate): > a/2.
TEST(trefoil, BeadsDoNotOverlap)
{
    const List<point> x = initialisationModels::trefoil::beads(200, 1, true);
    scalar closest = GREAT;
    for (label i = 0; i < x.size(); ++i)
    {
        for (label j = i + 2; j < x.size(); ++j)
        {
            if (i == 0 && j == x.size() - 1) continue;
            closest = min(closest, mag(x[i] - x[j]));
        }
    }
    EXPECT_GT(closest, 0.5);
}

// ************************************************************************* //
