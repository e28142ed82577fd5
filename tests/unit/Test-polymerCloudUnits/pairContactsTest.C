/*---------------------------------------------------------------------------*\
Description
    pairContacts: a pair the event loop resolved is at contact, its triple
    product V within round-off of zero. Rod A along x, (-0.5, 0, 0) to
    (0.5, 0, 0), at rest; rod B along y through x = 0.1 at height z, moving
    along z; V = -z, so B above A is side -1.
    - Leaving its contact on its own side with V on the crossed side by
      round-off (z = -1e-15, moving up): no crossing. The root solver
      alone finds one at s = 1e-15, and after the impulse the same again:
      the tau -> 0 stall of one pair in the dense periodic boxes (issue 19).
    - Turned back toward the crossed side at contact (moving down), from
      either side of zero by round-off: a crossing at once. From the
      crossed side by round-off the root solver alone finds none, and the
      rods pass through each other.
    - The lines meeting beyond rod A's end (B at x = 0.8): no crossing.
    - Resolved and turned back, from any point of the contact's round-off
      band (also crossed by 1.5 and 5 times the tolerance): no second
      event.
    - A pair with no side recorded is the root solver's alone.
\*---------------------------------------------------------------------------*/

#include "collisionScenes.H"
#include "pairContacts.H"

using namespace polymerCloudTest;

namespace
{

rodPairCrossing rodsAt(const scalar xB, const scalar z, const scalar w)
{
    return rodPairCrossing
    (
        vector(-0.5, 0, 0), vector(0.5, 0, 0),
        vector(xB, -0.5, z), vector(xB, 0.5, z),
        Zero, Zero, vector(0, 0, w), vector(0, 0, w)
    );
}

} // End anonymous namespace


TEST(pairContacts, LeavingOnItsOwnSideIsNoCrossing)
{
    const autoPtr<crossingRootSolver> solver(newSolver("isolating"));
    const rodPairCrossing pair(rodsAt(0.1, -1e-15, 1));
    ASSERT_GT(pair.tripleProduct(0), 0);
    ASSERT_LT(pair.tripleProduct(0), pairContacts::tolerance(pair));

    // The root solver alone: a crossing at round-off's distance
    const scalar alone = solver->earliestCrossing(pair, 0.02);
    EXPECT_GE(alone, 0);
    EXPECT_LT(alone, 1e-13);

    pairContacts contacts;
    contacts.record(3, -1);
    label side = 0;
    bool atContact = false;
    EXPECT_EQ
    (
        contacts.earliestCrossing(3, pair, solver(), 0.02, side, atContact),
        -1
    );
    EXPECT_EQ(side, -1);
}


TEST(pairContacts, TurnedBackAtContactCrossesAtOnce)
{
    const autoPtr<crossingRootSolver> solver(newSolver("isolating"));
    pairContacts contacts;
    contacts.record(0, -1);
    for (const scalar z : {-1e-15, 1e-15})
    {
        const rodPairCrossing pair(rodsAt(0.1, z, -1));
        label side = 0;
        bool atContact = false;
        const scalar s =
            contacts.earliestCrossing(0, pair, solver(), 0.02, side, atContact);
        EXPECT_GE(s, 0) << "z " << z;
        EXPECT_TRUE(atContact) << "z " << z;
        EXPECT_LT(s, 1e-13) << "z " << z;
        EXPECT_EQ(side, -1);
        // Past the root by no more than round-off
        EXPECT_LE(mag(pair.tripleProduct(s)), 2*pairContacts::tolerance(pair));
    }

    // From the crossed side by round-off, the root solver alone finds no
    // crossing at all
    EXPECT_LT(solver->earliestCrossing(rodsAt(0.1, -1e-15, -1), 0.02), 0);
}


// A pair resolved at its crossing and turned back (its velocity reversed,
// as the elastic impulse does) is at contact and leaves it on its own side:
// no second event. Before, a pair crossed by round-off beyond the band
// (1.5 tol) was resolved at once, again and again at the same time: the
// stalls of 500 trimers in a periodic cube (3 in 2000 steps).
TEST(pairContacts, ResolvedAndTurnedBackIsNoSecondEvent)
{
    const autoPtr<crossingRootSolver> solver(newSolver("isolating"));
    pairContacts contacts;
    contacts.record(0, -1);
    const scalar tol = pairContacts::tolerance(rodsAt(0.1, 0, -1));
    for (const scalar z : {1e-15, -1e-15, -1.5*tol, -5*tol})
    {
        label side = 0;
        bool atContact = false;
        const scalar s =
            contacts.earliestCrossing(0, rodsAt(0.1, z, -1), solver(), 0.02, side, atContact);
        ASSERT_GE(s, 0) << "z " << z;
        EXPECT_EQ(side, -1);

        // Resolved there: the same positions, the velocity reversed
        const rodPairCrossing after(rodsAt(0.1, z - s, 1));
        EXPECT_EQ(contacts.earliestCrossing(0, after, solver(), 0.02, side, atContact), -1)
            << "z " << z;
    }
}


TEST(pairContacts, LinesMeetingBeyondTheRodsIsNoCrossing)
{
    const autoPtr<crossingRootSolver> solver(newSolver("isolating"));
    pairContacts contacts;
    contacts.record(0, -1);
    label side = 0;
    bool atContact = false;
    EXPECT_EQ
    (
        contacts.earliestCrossing(0, rodsAt(0.8, 1e-15, -1), solver(), 0.02, side, atContact),
        -1
    );
    EXPECT_EQ(side, 1);
}


TEST(pairContacts, UnrecordedPairsAreTheRootSolversAlone)
{
    const autoPtr<crossingRootSolver> solver(newSolver("isolating"));
    pairContacts contacts;
    contacts.record(1, 1);
    contacts.clear();
    for (const scalar z : {-1e-15, 0.01, -0.01})
    {
        const rodPairCrossing pair(rodsAt(0.1, z, 1));
        label side = 0;
        bool atContact = false;
        EXPECT_EQ
        (
            contacts.earliestCrossing(1, pair, solver(), 0.02, side, atContact),
            solver->earliestCrossing(pair, 0.02)
        );
        EXPECT_EQ(side, pair.tripleProduct(0) < 0 ? -1 : 1);
    }
}


// The side a pair crosses from is V's sign just before its root, against
// the slope there: rod B passing down through rod A (V = -z_B rising) from
// above crosses from side -1, up from below from side +1; a zero slope
// keeps the fallback
TEST(pairContacts, SideBeforeTheRoot)
{
    EXPECT_EQ(pairContacts::sideBefore(rodsAt(0.1, 0.01, -1), 0.01, 1), -1);
    EXPECT_EQ(pairContacts::sideBefore(rodsAt(0.1, -0.01, 1), 0.01, -1), 1);
    EXPECT_EQ(pairContacts::sideBefore(rodsAt(0.1, 0.01, 0), 0.01, 1), 1);
    EXPECT_EQ(pairContacts::sideBefore(rodsAt(0.1, 0.01, -1), -1, 1), 1);
}


// Resolutions at the contact band's edge are counted in a row (the event
// loop stops a step whose pair reaches stallEvents of them: a grazing
// contact its impulses do not separate); another resolution ends the row,
// and a new step forgets it
TEST(pairContacts, ContactStreaks)
{
    pairContacts contacts;
    for (label k = 0; k < 3; ++k)
    {
        contacts.record(2, 1, true);
    }
    EXPECT_EQ(contacts.contactStreak(2), 3);
    EXPECT_EQ(contacts.contactStreak(7), 0);
    contacts.record(2, 1, false);
    EXPECT_EQ(contacts.contactStreak(2), 0);
    contacts.record(2, 1, true);
    contacts.clear();
    EXPECT_EQ(contacts.contactStreak(2), 0);
    EXPECT_EQ(contacts.side(2), 0);
}


// ************************************************************************* //
