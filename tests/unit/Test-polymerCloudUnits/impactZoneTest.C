/*---------------------------------------------------------------------------*\
Description
    Rigid impact zones (rigidImpactZones) on their own: zones merge as
    disjoint sets, listed in the order of the chains' global ids; a placed zone
    keeps every rod at its start length (x^n's, exact), recovers a rigid
    motion of x^n exactly, keeps the momentum and angular momentum the
    contacts left for chains of different bead masses (1 and 5), and has
    rigid velocities (no relative velocity along any rod, nor between any
    two beads' separation); a straight zone, whose inertia about its axis
    is zero, keeps a rigid motion without NaN; a fraction of the motion is
    that rigid motion's fraction (rods kept), none of it x^n. Across
    periodic images: merging with a translation keeps every chain's offset
    consistent whichever the sets' roots, another image of a chain of the
    same zone is refused, a held zone stays held when merged; a zone placed
    with its chains' translations is the zone of the translated chains,
    translated back.
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "rigidImpactZones.H"

using namespace polymerCloudTest;

namespace
{

PtrList<chainType> twoMasses()
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("light", 6, 1, 1, 1, 1, false));
    types.set(1, new chainType("heavy", 5, 1, 5, 1, 1, false));
    return types;
}


// Two random walks of masses 1 and 5 near each other
polymerChains twoWalks(const PtrList<chainType>& types, std::mt19937_64& gen)
{
    polymerChains chains(types);
    chains.append(0, 0, randomWalk(6, 1, point(0, 0, 0), gen),
        List<vector>(6, Zero));
    chains.append(1, 1, randomWalk(5, 1, point(0.5, 0.3, 0.2), gen),
        List<vector>(5, Zero));
    return chains;
}


vector momentum(const polymerChains& chains, const UList<vector>& v)
{
    vector p(Zero);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            p += chains.type(c).beadMass()*v[i];
        }
    }
    return p;
}


vector angularMomentum
(
    const polymerChains& chains,
    const UList<point>& x,
    const UList<vector>& v
)
{
    vector L(Zero);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            L += chains.type(c).beadMass()*(x[i] ^ v[i]);
        }
    }
    return L;
}

} // End anonymous namespace


TEST(rigidImpactZones, ZonesMerge)
{
    PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    polymerChains chains(types);
    const List<point> dimer({{0, 0, 0}, {1, 0, 0}});
    for (const label id : {5, 4, 3, 2, 1, 0})
    {
        chains.append(0, id, dimer, List<vector>(2, Zero));
    }

    rigidImpactZones zones;
    zones.reset(6);
    EXPECT_FALSE(zones.inZone(0));
    zones.add(2);
    zones.merge(0, 1);
    zones.merge(3, 4);
    EXPECT_TRUE(zones.sameZone(0, 1));
    EXPECT_FALSE(zones.sameZone(0, 3));
    EXPECT_FALSE(zones.sameZone(2, 5));
    zones.merge(1, 4);
    EXPECT_TRUE(zones.sameZone(0, 3));
    EXPECT_EQ(zones.nChainsInZones(), 5);

    // Chain c has global id 5 - c: each zone in the order of the ids
    const labelListList z = zones.zones(chains);
    ASSERT_EQ(z.size(), 2);
    EXPECT_EQ(z[0], labelList({4, 3, 1, 0}));
    EXPECT_EQ(z[1], labelList({2}));
}


TEST(rigidImpactZones, RecoversARigidMotionExactly)
{
    std::mt19937_64 gen(11);
    const PtrList<chainType> types(twoMasses());
    polymerChains chains(twoWalks(types, gen));
    const List<point> start(chains.positions());

    // The contacts left both chains turned by 40 degrees and shifted
    const tensor R
    (
        std::cos(0.7), -std::sin(0.7), 0,
        std::sin(0.7), std::cos(0.7), 0,
        0, 0, 1
    );
    List<point> after(start.size());
    forAll(start, i)
    {
        after[i] = (R & start[i]) + vector(0.3, -0.2, 0.1);
    }
    const List<vector> velocitiesAfter(chains.nBeads(), vector(1, 0, 0));

    rigidImpactZones::place
    (
        chains, labelList({0, 1}), 1, start, after, velocitiesAfter
    );
    forAll(after, i)
    {
        EXPECT_LT(mag(chains.positions()[i] - after[i]), 1e-13);
        EXPECT_LT(mag(chains.velocities()[i] - vector(1, 0, 0)), 1e-13);
    }
}


TEST(rigidImpactZones, KeepsRodsMomentumAndAngularMomentum)
{
    for (label seed = 1; seed <= 20; ++seed)
    {
        std::mt19937_64 gen(seed);
        const PtrList<chainType> types(twoMasses());
        polymerChains chains(twoWalks(types, gen));
        const List<point> start(chains.positions());
    
        // The contacts' state: each bead displaced and moving at random
        List<point> after(start.size());
        List<vector> velocitiesAfter(start.size());
        forAll(start, i)
        {
            after[i] = start[i] + vector(0.2, 0, 0) + gaussian(gen, 0.3);
            velocitiesAfter[i] = gaussian(gen, 1);
        }

        rigidImpactZones::place
        (
            chains, labelList({0, 1}), 1, start, after, velocitiesAfter
        );
        const List<point>& x = chains.positions();
        const List<vector>& v = chains.velocities();

        // Every pair of beads keeps its start distance (rods included)
        // and has no relative velocity along its separation
        forAll(x, i)
        {
            for (label j = i + 1; j < x.size(); ++j)
            {
                EXPECT_NEAR(mag(x[j] - x[i]), mag(start[j] - start[i]), 1e-13);
                EXPECT_NEAR(((v[j] - v[i]) & (x[j] - x[i])), 0, 1e-12);
            }
        }
        EXPECT_LT
        (
            mag(momentum(chains, v) - momentum(chains, velocitiesAfter)),
            1e-12
        );
        EXPECT_LT
        (
            mag
            (
                angularMomentum(chains, x, v)
              - angularMomentum(chains, after, velocitiesAfter)
            ),
            1e-11
        ) << "seed " << seed;
    }
}


TEST(rigidImpactZones, StraightZoneKeepsItsMotionDespiteNoInertiaAboutItsAxis)
{
    PtrList<chainType> types(oneType(4, 1, 1, 1, 1));
    polymerChains chains(types);
    const List<point> start({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
    chains.append(0, 0, start, List<vector>(4, Zero));

    // Translating along z and turning about z: a rigid motion the
    // singular inertia (none about x) must keep
    const List<point> after(start);
    List<vector> velocitiesAfter(4);
    forAll(start, i)
    {
        velocitiesAfter[i] = vector(0, (start[i].x() - 1.5), 0.5);
    }
    rigidImpactZones::place
    (
        chains, labelList({0}), 1, start, after, velocitiesAfter
    );
    forAll(start, i)
    {
        const vector& v = chains.velocities()[i];
        EXPECT_TRUE(std::isfinite(v.x() + v.y() + v.z()));
        EXPECT_LT(mag(chains.positions()[i] - start[i]), 1e-14);
        EXPECT_LT(mag(v - velocitiesAfter[i]), 1e-13);
    }
}


TEST(rigidImpactZones, AFractionOfTheMotion)
{
    std::mt19937_64 gen(3);
    const PtrList<chainType> types(twoMasses());
    polymerChains chains(twoWalks(types, gen));
    const List<point> start(chains.positions());

    // The contacts left both chains turned by 40 degrees about z and
    // shifted: half of it is 20 degrees and half the shift
    const auto turned = [](const scalar angle)
    {
        return tensor
        (
            std::cos(angle), -std::sin(angle), 0,
            std::sin(angle), std::cos(angle), 0,
            0, 0, 1
        );
    };
    const vector shift(0.3, -0.2, 0.1);
    List<point> after(start.size());
    forAll(start, i)
    {
        after[i] = (turned(0.7) & start[i]) + shift;
    }
    const List<vector> velocitiesAfter(start.size(), vector(1, 0, 0));

    // The centre of mass of the start, about which the zone turns
    scalar mass = 0;
    vector centre(Zero);
    for (label c = 0; c < 2; ++c)
    {
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            mass += chains.type(c).beadMass();
            centre += chains.type(c).beadMass()*start[i];
        }
    }
    centre /= mass;

    rigidImpactZones::place
    (
        chains, labelList({0, 1}), 0.5, start, after, velocitiesAfter
    );
    const vector halfShift = 0.5*((turned(0.7) & centre) + shift - centre);
    forAll(start, i)
    {
        const point expected =
            centre + halfShift + (turned(0.35) & (start[i] - centre));
        EXPECT_LT(mag(chains.positions()[i] - expected), 1e-13);
    }

    rigidImpactZones::place
    (
        chains, labelList({0, 1}), 0, start, after, velocitiesAfter
    );
    forAll(start, i)
    {
        EXPECT_LT(mag(chains.positions()[i] - start[i]), 1e-14);
        EXPECT_LT(mag(chains.velocities()[i] - vector(1, 0, 0)), 1e-13);
    }
}


TEST(rigidImpactZones, ZonesMergeAcrossPeriodicImages)
{
    const vector Lx(4, 0, 0), Ly(0, 4, 0);
    rigidImpactZones zones;
    zones.reset(5);

    // 0 meets 1's image by Lx; 2 meets 3's image by -Ly; then 3 meets 1's
    // image by Lx + Ly: 1 is 0's by Lx, 3 is 1's by -(Lx + Ly), so 3 is
    // 0's by -Ly and 2 is 0's own
    EXPECT_TRUE(zones.merge(0, 1, Lx));
    EXPECT_TRUE(zones.merge(2, 3, -Ly));
    EXPECT_TRUE(zones.merge(3, 1, Lx + Ly));
    const auto relative = [&](const label a, const label b)
    {
        return zones.offset(b) - zones.offset(a);
    };
    EXPECT_EQ(relative(0, 1), Lx);
    EXPECT_EQ(relative(3, 1), Lx + Ly);
    EXPECT_EQ(relative(2, 3), -Ly);
    EXPECT_EQ(relative(0, 2), vector::zero);

    // The same images again: consistent; another image: refused
    EXPECT_TRUE(zones.merge(1, 0, -Lx));
    EXPECT_TRUE(zones.merge(0, 2, Zero));
    EXPECT_FALSE(zones.merge(0, 2, Lx));

    // Held zones stay held through merges
    EXPECT_FALSE(zones.held(0));
    zones.hold(2);
    EXPECT_TRUE(zones.held(1));
    zones.add(4);
    EXPECT_FALSE(zones.held(4));
    EXPECT_TRUE(zones.merge(4, 0, Zero));
    EXPECT_TRUE(zones.held(4));
    EXPECT_EQ(relative(4, 0), vector::zero);
}


TEST(rigidImpactZones, PlacedWithTranslationsAsTheTranslatedZone)
{
    std::mt19937_64 gen(7);
    const PtrList<chainType> types(twoMasses());
    polymerChains chains(twoWalks(types, gen));
    const List<point> start(chains.positions());
    List<point> after(start.size());
    List<vector> velocitiesAfter(start.size());
    forAll(start, i)
    {
        after[i] = start[i] + vector(0.2, 0, 0) + gaussian(gen, 0.3);
        velocitiesAfter[i] = gaussian(gen, 1);
    }

    // Chain 1 stored one period away: its image by shift is the zone's
    const vector shift(0, 0, 6);
    polymerChains apart(chains);
    List<point> startApart(start), afterApart(after);
    for (label i = apart.start(1); i < apart.end(1); ++i)
    {
        startApart[i] -= shift;
        afterApart[i] -= shift;
    }

    rigidImpactZones::place
    (
        chains, labelList({0, 1}), 0.7, start, after, velocitiesAfter
    );
    rigidImpactZones::place
    (
        apart, labelList({0, 1}), 0.7, startApart, afterApart,
        velocitiesAfter, List<vector>({Zero, shift})
    );
    forAll(start, i)
    {
        const vector back = (i >= apart.start(1)) ? shift : vector::zero;
        EXPECT_LT(mag(apart.positions()[i] + back - chains.positions()[i]), 1e-12);
        EXPECT_LT(mag(apart.velocities()[i] - chains.velocities()[i]), 1e-12);
    }
}


// ************************************************************************* //
