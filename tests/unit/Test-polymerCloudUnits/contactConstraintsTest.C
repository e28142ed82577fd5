/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    The rod-length projection of chain groups with inelastic contacts
    (contactConstraints). Chains whose rods the contacts of a step left off
    by up to 5 % (open chains of bead masses 1 and 5; a ring and an open
    chain; two rods of one chain; a periodic image), with contacts between
    rods near each other:
    - every rod ends within the tolerance 1e-10 of its length, and every
      contact's gap along its normal is its start value to 1e-10 rod
      lengths;
    - the mass-weighted centre of the beads does not move (the rods' and
      the contacts' moves are internal), to round-off;
    - a contact given twice gives the solution of the contact given once
      (the least-norm solution of the contacts' rank-deficient system);
      one pair held at two gaps has no solution: the solve fails and
      leaves the positions at the start;
    - a contact set where two rods cross on their paths has the normal of
      the rods' plane there, turned from A to B at the start, the weights
      of the crossing point and the start's gap, which the projection
      holds; rods parallel at the crossing give none;
    - a bead held off a wall keeps its start distance from the wall's
      tangent plane, a rod held off a convex edge its nearest point's
      distance from the edge, with the rods exact; a bead or rod that
      starts on the plane or the edge gives no contact.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "contactConstraints.H"
#include "linePointRef.H"

#include <random>

using namespace polymerCloudTest;

namespace
{

const scalar tolerance = 1e-10;


// Beads moved by up to 5 % of a rod, as the contacts of a step might
void perturb(polymerChains& chains, std::mt19937_64& gen)
{
    for (point& x : chains.positions())
    {
        x += gaussian(gen, 0.02);
    }
}


point centreOfMass(const polymerChains& chains)
{
    vector sum(Zero);
    scalar mass = 0;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const scalar m = chains.type(c).beadMass();
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            sum += m*chains.positions()[i];
            mass += m;
        }
    }
    return sum/mass;
}


scalar gapError
(
    const contactConstraints::contact& contact,
    const UList<point>& x
)
{
    return mag(contactConstraints::presentGap(contact, x) - contact.gap);
}


// The pairs of rods, of different chains (or of one, non-adjacent), whose
// nearest points are within reach at the positions x
List<contactConstraints::contact> nearContacts
(
    const polymerChains& chains,
    const scalar reach,
    const label most,
    const vector& shift = Zero
)
{
    const List<point>& x = chains.positions();
    DynamicList<labelPair> rods;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label n = chains.size(c);
        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            rods.append
            (
                labelPair(chains.start(c) + k, chains.start(c) + (k + 1)%n)
            );
        }
    }
    DynamicList<contactConstraints::contact> contacts;
    forAll(rods, r)
    {
        for (label s = r + 1; s < rods.size() && contacts.size() < most; ++s)
        {
            const labelPair& A = rods[r];
            const labelPair& B = rods[s];
            const bool adjacent =
                A.first() == B.first() || A.first() == B.second()
             || A.second() == B.first() || A.second() == B.second();
            point onA, onB;
            linePointRef(x[A.first()], x[A.second()]).nearestDist
            (
                linePointRef(x[B.first()] + shift, x[B.second()] + shift),
                onA, onB
            );
            // Contacts on rods apart from the others' (contacts sharing a
            // rod or its neighbours can contradict each other and the
            // rods' lengths; the caller then falls back to zones)
            bool apart = true;
            for (const contactConstraints::contact& other : contacts)
            {
                for (const label b : other.beads())
                {
                    for (const label i : {A.first(), A.second(), B.first(), B.second()})
                    {
                        apart = apart && mag(i - b) > 1;
                    }
                }
            }
            contactConstraints::contact contact;
            if
            (
                !adjacent && apart && mag(onB - onA) < reach
             && contactConstraints::makeContact
                (
                    A, B, shift, chains, x, contact
                )
            )
            {
                contacts.append(contact);
            }
        }
    }
    return List<contactConstraints::contact>(contacts);
}


// Project and check the rods, the contacts' gaps and the centre of mass
void expectProjected
(
    polymerChains& chains,
    const UList<contactConstraints::contact>& contacts
)
{
    const List<point> start(chains.positions());
    const point centre(centreOfMass(chains));
    labelList group(chains.nChains());
    forAll(group, c)
    {
        group[c] = c;
    }

    contactConstraints solver(tolerance, 50);
    const label iterations = solver.project(chains, group, contacts, start);
    ASSERT_GE(iterations, 1);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        EXPECT_LE(chains.maxRodLengthError(c), tolerance) << "chain " << c;
    }
    for (const contactConstraints::contact& contact : contacts)
    {
        EXPECT_LE(gapError(contact, chains.positions()), tolerance);
    }
    EXPECT_LE(mag(centreOfMass(chains) - centre), 1e-13*(1 + mag(centre)));
}

} // End anonymous namespace


TEST(contactConstraints, OpenChainsOfTwoMasses)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("light", 12, 1, 1, 1, 1, false));
    types.set(1, new chainType("heavy", 10, 1, 5, 1, 1, false));
    for (const unsigned seed : {1u, 2u, 3u, 4u, 5u})
    {
        std::mt19937_64 gen(seed);
        polymerChains chains(types);
        chains.append(0, 0, randomWalk(12, 1, point(0, 0, 0), gen),
            List<vector>(12, Zero));
        chains.append(1, 1, randomWalk(10, 1, point(0.4, 0.3, 0.2), gen),
            List<vector>(10, Zero));
        perturb(chains, gen);
        const List<contactConstraints::contact> contacts
        (
            nearContacts(chains, 0.8, 6)
        );
        ASSERT_GE(contacts.size(), 2) << "seed " << seed;
        expectProjected(chains, contacts);
    }
}


TEST(contactConstraints, RingAndOpenChain)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("ring", 16, 1, 1, 1, 1, true));
    types.set(1, new chainType("open", 8, 1, 1, 1, 1, false));
    std::mt19937_64 gen(7);

    // A regular 16-gon of unit sides in the x-y plane, an open chain
    // through its middle
    const scalar radius = 0.5/std::sin(M_PI/16);
    List<point> ring(16);
    forAll(ring, i)
    {
        ring[i] = radius*vector
        (
            std::cos(2*M_PI*i/16), std::sin(2*M_PI*i/16), 0
        );
    }
    polymerChains chains(types);
    chains.append(0, 0, ring, List<vector>(16, Zero));
    chains.append(1, 1, randomWalk(8, 1, point(radius - 0.3, 0, 0.1), gen),
        List<vector>(8, Zero));
    perturb(chains, gen);
    const List<contactConstraints::contact> contacts
    (
        nearContacts(chains, 0.6, 4)
    );
    ASSERT_GE(contacts.size(), 1);
    expectProjected(chains, contacts);
}


TEST(contactConstraints, RodsOfOneChainAndAPeriodicImage)
{
    PtrList<chainType> types(oneType(20, 1, 1, 1, 1));
    std::mt19937_64 gen(3);

    // A hairpin: two straight arms 0.3 apart, joined at a bead between
    List<point> hairpin(20);
    for (label i = 0; i < 10; ++i)
    {
        hairpin[i] = point(i, 0, 0);
    }
    hairpin[10] = point(9 + std::sqrt(1 - 0.15*0.15), 0.15, 0);
    for (label k = 0; k < 9; ++k)
    {
        hairpin[11 + k] = point(9 - k, 0.3, 0);
    }
    polymerChains chains(types);
    chains.append(0, 0, hairpin, List<vector>(20, Zero));
    perturb(chains, gen);
    const List<contactConstraints::contact> own
    (
        nearContacts(chains, 0.4, 3)
    );
    ASSERT_GE(own.size(), 1);
    expectProjected(chains, own);

    // The chain against its own image one period of 0.5 away along z
    polymerChains shifted(types);
    shifted.append(0, 0, hairpin, List<vector>(20, Zero));
    perturb(shifted, gen);
    const List<contactConstraints::contact> images
    (
        nearContacts(shifted, 0.6, 3, vector(0, 0, 0.5))
    );
    ASSERT_GE(images.size(), 1);
    expectProjected(shifted, images);
}


TEST(contactConstraints, RepeatedAndContradictoryContacts)
{
    PtrList<chainType> types(oneType(10, 1, 1, 1, 1));
    std::mt19937_64 gen(5);
    polymerChains chains(types);
    chains.append(0, 0, randomWalk(10, 1, point(0, 0, 0), gen),
        List<vector>(10, Zero));
    chains.append(0, 1, randomWalk(10, 1, point(0.3, 0.2, 0.1), gen),
        List<vector>(10, Zero));
    perturb(chains, gen);
    const List<contactConstraints::contact> one(nearContacts(chains, 0.5, 1));
    ASSERT_EQ(one.size(), 1);
    const List<point> start(chains.positions());
    const labelList group({0, 1});
    contactConstraints solver(tolerance, 50);

    // Once, then twice: the same solution (least norm of the repeated
    // contacts' system)
    ASSERT_GE(solver.project(chains, group, one, start), 1);
    const List<point> once(chains.positions());
    const List<contactConstraints::contact> twice({one[0], one[0]});
    ASSERT_GE(solver.project(chains, group, twice, start), 1);
    forAll(once, i)
    {
        EXPECT_LE(mag(chains.positions()[i] - once[i]), 1e-12);
    }

    // The same pair held at two gaps: no solution, the positions at start
    List<contactConstraints::contact> contradictory(twice);
    contradictory[1].gap += 0.1;
    EXPECT_EQ(solver.project(chains, group, contradictory, start), -1);
    forAll(start, i)
    {
        EXPECT_EQ(chains.positions()[i], start[i]);
    }
}


TEST(contactConstraints, ContactWhereTheRodsCross)
{
    // Rod A along x through the origin; rod B along y, 0.1 above it, moves
    // to 0.1 below it: they cross at half the path, at A's middle and at
    // B's quarter
    PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    polymerChains chains(types);
    chains.append(0, 0, List<point>({{-0.5, 0, 0}, {0.5, 0, 0}}),
        List<vector>(2, Zero));
    chains.append(0, 1, List<point>({{0, -0.25, 0.1}, {0, 0.75, 0.1}}),
        List<vector>(2, Zero));
    const List<point> from(chains.positions());
    List<point> to(from);
    to[2].z() = -0.1;
    to[3].z() = -0.1;

    contactConstraints::contact contact;
    ASSERT_TRUE
    (
        contactConstraints::makeCrossingContact
        (
            labelPair(0, 1), labelPair(2, 3), Zero, chains, from, to, 0.5,
            contact
        )
    );
    EXPECT_NEAR(mag(contact.normal - vector(0, 0, 1)), 0, 1e-15);
    EXPECT_NEAR(contact.gap, 0.1, 1e-15);
    EXPECT_NEAR(contact.weights[0], -0.5, 1e-15);
    EXPECT_NEAR(contact.weights[1], -0.5, 1e-15);
    EXPECT_NEAR(contact.weights[2], 0.75, 1e-15);
    EXPECT_NEAR(contact.weights[3], 0.25, 1e-15);

    // Held from the crossing configuration: B stays 0.1 above A
    chains.positions() = to;
    contactConstraints solver(tolerance, 50);
    const List<contactConstraints::contact> one({contact});
    ASSERT_GE(solver.project(chains, labelList({0, 1}), one, to), 1);
    EXPECT_LE(gapError(contact, chains.positions()), tolerance);
    EXPECT_LE(chains.maxRodLengthError(), tolerance);

    // Rods parallel at the crossing have no plane: no contact
    List<point> parallel(to);
    parallel[2] = point(-0.5, 0, -0.1);
    parallel[3] = point(0.5, 0, -0.1);
    List<point> parallelFrom(from);
    parallelFrom[2] = point(-0.5, 0, 0.1);
    parallelFrom[3] = point(0.5, 0, 0.1);
    EXPECT_FALSE
    (
        contactConstraints::makeCrossingContact
        (
            labelPair(0, 1), labelPair(2, 3), Zero, chains, parallelFrom,
            parallel, 0.5, contact
        )
    );
}


TEST(contactConstraints, ABeadAndARodHeldOffAWall)
{
    // A chain of 6 beads along x, 0.2 above the wall z = 0, its beads
    // moved down by up to 0.3 (rods off): bead 2's path meets the wall at
    // (2, 0, 0); rod 3-4 passes an edge along y at x = 3.5, z = 0.1
    PtrList<chainType> types(oneType(6, 1, 1, 1, 1));
    polymerChains chains(types);
    List<point> from(6);
    forAll(from, i)
    {
        from[i] = point(i, 0, 0.2);
    }
    chains.append(0, 0, from, List<vector>(6, Zero));
    List<point> to(from);
    to[2].z() = -0.1;
    to[3].z() = 0.05;
    to[4].z() = 0.0;

    contactConstraints::contact atWall, atEdge;
    ASSERT_TRUE
    (
        contactConstraints::makeWallContact
        (
            2, point(2, 0, 0), vector(0, 0, 1), chains, from, atWall
        )
    );
    EXPECT_TRUE(contactConstraints::isWallContact(atWall));
    EXPECT_NEAR(atWall.gap, 0.2, 1e-15);
    ASSERT_TRUE
    (
        contactConstraints::makeEdgeContact
        (
            labelPair(3, 4), point(3.5, -1, 0.1), point(3.5, 1, 0.1),
            chains, from, atEdge
        )
    );
    EXPECT_TRUE(contactConstraints::isWallContact(atEdge));
    EXPECT_NEAR(mag(atEdge.normal - vector(0, 0, 1)), 0, 1e-15);
    EXPECT_NEAR(atEdge.gap, 0.1, 1e-15);
    EXPECT_NEAR(atEdge.weights[2], 0.5, 1e-15);
    EXPECT_NEAR(atEdge.weights[3], 0.5, 1e-15);

    // Projected from the moved beads: bead 2 keeps 0.2 from the wall's
    // plane, rod 3-4's middle 0.1 above the edge, rods exact
    chains.positions() = to;
    const List<contactConstraints::contact> both({atWall, atEdge});
    contactConstraints solver(tolerance, 50);
    ASSERT_GE(solver.project(chains, labelList({0}), both, to), 1);
    const List<point>& x = chains.positions();
    EXPECT_NEAR(x[2].z(), 0.2, tolerance);
    EXPECT_NEAR(0.5*(x[3].z() + x[4].z()), 0.2, tolerance);
    EXPECT_LE(chains.maxRodLengthError(), tolerance);

    // A bead on the wall's plane at the start, or a rod on the edge, gives
    // none
    EXPECT_FALSE
    (
        contactConstraints::makeWallContact
        (
            2, point(2, 0, 0.2), vector(0, 0, 1), chains, from, atWall
        )
    );
    EXPECT_FALSE
    (
        contactConstraints::makeEdgeContact
        (
            labelPair(3, 4), point(3.5, -1, 0.2), point(3.5, 1, 0.2),
            chains, from, atEdge
        )
    );
}


// ************************************************************************* //
