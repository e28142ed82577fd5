/*---------------------------------------------------------------------------*\
Description
    Rod-rod collisions (Miller & Trebotich 2007, step 3):

    - rodPairCrossing::elasticImpulse on two dimers meeting head-on and
      off-centre: linear momentum, angular momentum (about any point, at the
      impact positions) and kinetic energy conserved to round-off
      (1e-12 relative); the relative normal velocity at the contact point
      reverses;
    - collisionModels::elasticRods on two 2-bead chains whose straight paths
      cross: one event, nothing for the in-step audit, the end on the
      uncrossed side, momentum of v-dagger conserved; the same in metres
      with rods of a micrometre (no tolerance may be an absolute length);
    - elasticRods meeting rods across periodic images.
    The crossing-time root solvers are tested in crossingRootTest.C, the
    topology audits in topologyTest.C.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "collisionScenes.H"
#include "elasticRods.H"
#include "rodCrossingAudit.H"
#include "trefoil.H"
#include "tensor.H"
#include "mathematicalConstants.H"
#include <sstream>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;


// * * * * * * * * * * * * * * * elasticImpulse  * * * * * * * * * * * * * * //

// Two perpendicular dimers approaching head-on and off-centre (without the
// extra velocities below they would meet at lambda_i = 0.3, lambda_j = 0.8),
// with generic extra velocities (rods turning and stretching) and a generic
// rotation; the impact time is the isolating solver's root. Beads of equal
// masses (the paper's closed form) and of masses 1 and 5 either way round.
TEST(rodCollision, ElasticImpulseConservesMomentaAndEnergy)
{
    const labelPair massPairs[] = {{1, 1}, {1, 5}, {5, 1}};
    for (const labelPair& masses : massPairs)
    {
        const scalar mI = masses.first(), mJ = masses.second();
        const FixedList<scalar, 4> m({mI, mI, mJ, mJ});
        scene base;
        base.x = FixedList<vector, 4>
        ({
            vector(-0.3, 0, 1), vector(0.7, 0, 1),
            vector(0, -0.8, -1), vector(0, 0.2, -1)
        });
        base.v = FixedList<vector, 4>
        ({
            vector(0.1, 0.2, -1), vector(-0.2, 0.1, -0.8),
            vector(0.05, -0.1, 1.1), vector(0.1, 0.1, 0.9)
        });

        for (const bool rotated : {false, true})
        {
            const scene sc =
                rotated
              ? base.moved(genericRotation(), vector(3.1, -2.7, 0.4))
              : base;
            const rodPairCrossing pair = sc.pair();

            const scalar tau =
                newSolver("isolating")->earliestCrossing(pair, 2);
            ASSERT_GT(tau, 0) << "rotated " << rotated;

            FixedList<vector, 4> xImpact;
            for (label k = 0; k < 4; ++k)
            {
                xImpact[k] = sc.x[k] + tau*sc.v[k];
            }

            FixedList<vector, 4> after;
            ASSERT_TRUE(pair.elasticImpulse(tau, after, mI, mJ));

            for (const point& origin : {point(Zero), point(5, -3, 2)})
            {
                const invariants before =
                    invariantsOf(xImpact, sc.v, origin, m);
                const invariants later =
                    invariantsOf(xImpact, after, origin, m);
                const scalar pScale = mI*(mag(sc.v[0]) + mag(sc.v[1]))
                  + mJ*(mag(sc.v[2]) + mag(sc.v[3]));

                EXPECT_LE(mag(later.momentum - before.momentum), 1e-12*pScale);
                EXPECT_LE
                (
                    mag(later.angularMomentum - before.angularMomentum),
                    1e-12*before.scale
                ) << "about " << show(origin) << ", rotated " << rotated
                  << ", masses " << mI << ' ' << mJ;
                EXPECT_LE
                (
                    mag(later.energy - before.energy), 1e-12*before.energy
                );
            }

            // Relative normal velocity at the contact point reverses
            // The lines meet within both rods at tau: the two contact points
            // coincide (to the root's round-off)
            scalar li, lj;
            ASSERT_TRUE(pair.intersection(tau, li, lj));
            EXPECT_GT(li, 0);
            EXPECT_LT(li, 1);
            EXPECT_GT(lj, 0);
            EXPECT_LT(lj, 1);
            EXPECT_LE
            (
                mag
                (
                    ((1 - li)*xImpact[0] + li*xImpact[1])
                  - ((1 - lj)*xImpact[2] + lj*xImpact[3])
                ),
                1e-12
            );
            const vector n0 =
                (xImpact[1] - xImpact[0]) ^ (xImpact[3] - xImpact[2]);
            const vector n = n0/mag(n0);
            auto normalVelocity = [&](const FixedList<vector, 4>& u)
            {
                return
                    (((1 - li)*u[0] + li*u[1]) - ((1 - lj)*u[2] + lj*u[3])) & n;
            };
            const scalar uBefore = normalVelocity(sc.v);
            const scalar uAfter = normalVelocity(after);
            EXPECT_LT(uBefore*uAfter, 0);
            EXPECT_NEAR(uAfter, -uBefore, 1e-12*mag(uBefore));

            // Tangential parts and the rods' length rates are unchanged (the
            // impulse is along n, normal to both rods)
            EXPECT_NEAR
            (
                (after[1] - after[0]) & (xImpact[1] - xImpact[0]),
                (sc.v[1] - sc.v[0]) & (xImpact[1] - xImpact[0]),
                1e-12
            );
            EXPECT_NEAR
            (
                (after[3] - after[2]) & (xImpact[3] - xImpact[2]),
                (sc.v[3] - sc.v[2]) & (xImpact[3] - xImpact[2]),
                1e-12
            );
        }
    }
}


// Parallel rods, whose lines' crossing defines no normal: rod I along x
// from the origin, rod J along x from (0.5, 0, h) moving down with speed w
// (and sliding along x). The contact is the middle of the overlap, lambda_i
// 0.75 and lambda_j 0.25; the normal is their separation (0 0 1), or, where
// they touch (h = 0), their contact points' relative velocity across rod
// I. The impulse reverses that velocity, conserving momentum and energy
// (masses 1 and 5); rods that do not overlap have no contact.
TEST(rodCollision, ParallelRodsArePushedApart)
{
    for (const scalar h : {0.01, 0.0})
    {
        const FixedList<vector, 4> x
        ({
            vector(0, 0, 0), vector(1, 0, 0),
            vector(0.5, 0, h), vector(1.5, 0, h)
        });
        const FixedList<vector, 4> v
        ({
            vector(0, 0, 0), vector(0, 0, 0),
            vector(0.3, 0, -2), vector(0.3, 0, -2)
        });
        const rodPairCrossing pair
        (
            x[0], x[1], x[2], x[3], v[0], v[1], v[2], v[3]
        );

        scalar li, lj;
        vector n;
        ASSERT_TRUE(pair.parallelContact(0, li, lj, n)) << "h " << h;
        EXPECT_NEAR(li, 0.75, 1e-15);
        EXPECT_NEAR(lj, 0.25, 1e-15);
        EXPECT_NEAR(mag(n ^ vector(0, 0, 1)), 0, 1e-15) << "h " << h;

        FixedList<vector, 4> after;
        ASSERT_TRUE(pair.elasticImpulse(0, after, 1, 5)) << "h " << h;
        const FixedList<scalar, 4> m({1, 1, 5, 5});
        const invariants before = invariantsOf(x, v, point::zero, m);
        const invariants later = invariantsOf(x, after, point::zero, m);
        EXPECT_LE(mag(later.momentum - before.momentum), 1e-14);
        EXPECT_NEAR(later.energy, before.energy, 1e-14*before.energy);

        auto normalVelocity = [&](const FixedList<vector, 4>& u)
        {
            return
                (((1 - li)*u[0] + li*u[1]) - ((1 - lj)*u[2] + lj*u[3])) & n;
        };
        EXPECT_NEAR(normalVelocity(after), -normalVelocity(v), 1e-14);
    }

    // Nearly parallel rods crossing through their common plane (rod J
    // turned by 1e-7 in the x-y plane, its lines' intersection undefined
    // to the detector's tolerance, sinking through rod I's plane): pushed
    // apart along the plane's normal, not along their in-plane offset
    {
        const scalar angle = 1e-7;
        const vector dirJ(std::cos(angle), std::sin(angle), 0);
        const rodPairCrossing nearly
        (
            vector(0, 0, 0), vector(1, 0, 0),
            vector(0.5, 1e-9, 0), vector(0.5, 1e-9, 0) + dirJ,
            Zero, Zero, vector(0, 0, -1), vector(0, 0, -1)
        );
        scalar li, lj;
        vector n;
        ASSERT_FALSE(nearly.intersection(0, li, lj));
        ASSERT_TRUE(nearly.contact(0, li, lj, n));
        EXPECT_NEAR(mag(n ^ vector(0, 0, 1)), 0, 1e-9);
        FixedList<vector, 4> after;
        ASSERT_TRUE(nearly.elasticImpulse(0, after));
        // The contacts' relative velocity along n, n.z() before, reverses
        const scalar uAfter =
            (((1 - li)*after[0] + li*after[1])
          - ((1 - lj)*after[2] + lj*after[3])) & n;
        EXPECT_NEAR(uAfter, -n.z(), 1e-12);
    }

    // No overlap along the rods: no contact
    const rodPairCrossing apart
    (
        vector(0, 0, 0), vector(1, 0, 0), vector(2, 0, 0.01),
        vector(3, 0, 0.01), Zero, Zero, vector(0, 0, -1), vector(0, 0, -1)
    );
    scalar li, lj;
    vector n;
    EXPECT_FALSE(apart.parallelContact(0, li, lj, n));
    FixedList<vector, 4> after;
    EXPECT_FALSE(apart.elasticImpulse(0, after));
}


// The impulse through the chains' rods (elasticRods impulse constrained):
// two bent trimers of bead masses 1 and 5, translating until their first
// rods meet at s = 0.6 dt (rod I along x, rod J along y, 0.06 apart in z;
// each third bead 60 degrees out of the plane, away from the other). The
// paper's impulse along the rods' normal n keeps the two meeting rods to
// first order but moves the bead they share with the next rod along n,
// which is not normal to that rod: it changes at first order in the
// time left, (dt - s)|dv|. Through the chains' rods every rod's velocity
// change is normal to it at the impact, so its length at the end is
// exactly sqrt(a^2 + ((dt - s)|dv_rel|)^2), second order. Momentum and
// energy (the translating paths keep the rods) are conserved either way.
TEST(rodCollision, ConstrainedImpulseKeepsRodsToSecondOrder)
{
    const scalar dt = 0.02, s = 0.6*dt;
    PtrList<chainType> types(2);
    types.set(0, new chainType("light", 3, 1, 1, 1, 1, false));
    types.set(1, new chainType("heavy", 3, 1, 5, 1, 1, false));
    const scalar mass[] = {1, 1, 1, 5, 5, 5};

    const scalar h = 0.03, w = h/s, c60 = 0.5, s60 = std::sqrt(0.75);
    const tensor R = genericRotation();
    const vector shift(1.3, 2.2, -0.9);
    const List<vector> x0
    ({
        vector(-0.35, 0, -h), vector(0.65, 0, -h),
        vector(0.65 + c60, 0, -h - s60),
        vector(0, -0.7, h), vector(0, 0.3, h), vector(0, 0.3 + c60, h + s60)
    });
    const vector vI(0.2, 0.1, w), vJ(-0.3, 0.05, -w);
    List<vector> xStart(6), vStart(6);
    forAll(xStart, k)
    {
        xStart[k] = (R & x0[k]) + shift;
        vStart[k] = R & (k < 3 ? vI : vJ);
    }

    scalar endError[2];
    const word impulses[] = {"constrained", "dumbbell"};
    for (label m = 0; m < 2; ++m)
    {
        polymerChains chains(types);
        for (label c = 0; c < 2; ++c)
        {
            const SubList<vector> x(xStart, 3, 3*c), v(vStart, 3, 3*c);
            List<vector> xEnd(3);
            forAll(xEnd, k)
            {
                xEnd[k] = x[k] + dt*v[k];
            }
            chains.append(c, c, xEnd, v);
        }

        dictionary coeffs;
        coeffs.add("audit", true);
        coeffs.add("impulse", impulses[m]);
        dictionary dict;
        dict.add("collision", "elasticRods");
        dict.add("elasticRodsCoeffs", coeffs);
        collisionModels::elasticRods model(dict);
        model.correct(chains, xStart, dt, dt);

        ASSERT_EQ(model.count().events, 1) << impulses[m];
        EXPECT_EQ(model.count().auditCrossings, 0);

        const List<vector>& v = chains.velocities();
        const List<vector>& x = chains.positions();
        vector momentum(Zero);
        scalar energyBefore = 0, energyAfter = 0;
        forAll(v, k)
        {
            momentum += mass[k]*(v[k] - vStart[k]);
            energyBefore += 0.5*mass[k]*magSqr(vStart[k]);
            energyAfter += 0.5*mass[k]*magSqr(v[k]);
        }
        EXPECT_LE(mag(momentum), 1e-12*w) << impulses[m];
        EXPECT_NEAR(energyAfter, energyBefore, 1e-12*energyBefore)
            << impulses[m];

        endError[m] = 0;
        for (const label i : {0, 1, 3, 4})
        {
            const vector rImpact =
                (xStart[i + 1] + s*vStart[i + 1]) - (xStart[i] + s*vStart[i]);
            const vector dvRel =
                (v[i + 1] - v[i]) - (vStart[i + 1] - vStart[i]);
            endError[m] = max
            (
                endError[m],
                rodAfterImpulse
                (
                    rImpact, dvRel, mag(x[i + 1] - x[i]), dt - s, 1e-12,
                    m == 0, i
                )
            );
        }
    }
    EXPECT_LT(endError[0], 0.1*endError[1])
        << "largest rod error: constrained " << endError[0]
        << ", dumbbell " << endError[1];
}


namespace
{

// The full model: two 2-bead chains (dimers) whose straight paths from x^n
// to x-dagger cross once. One event; the in-step audit of the piecewise
// paths finds nothing; the end state is on the side of the start (sign of
// V); v-dagger keeps its momentum and energy. In rod lengths and in metres
// with rods of a micrometre (every length and speed times L)
void dimerCrossingIn(const scalar L)
{
    const scalar dt = 0.02;
    const PtrList<chainType> types(oneType(2, L, 1, 1, 1));

    for (const bool rotated : {false, true})
    {
        // Rod I moves up, rod J down; they meet at s = 0.6 dt at
        // lambda_i = 0.35, lambda_j = 0.7
        scene sc;
        sc.x = FixedList<vector, 4>
        ({
            L*vector(-0.35, 0, -0.3), L*vector(0.65, 0, -0.3),
            L*vector(0, -0.7, 0.3), L*vector(0, 0.3, 0.3)
        });
        const scalar w = 0.3*L/(0.6*dt);
        sc.v = FixedList<vector, 4>
        ({
            vector(0.2*L, 0.1*L, w), vector(0.2*L, 0.1*L, w),
            vector(-0.3*L, 0.05*L, -w), vector(-0.3*L, 0.05*L, -w)
        });
        if (rotated)
        {
            sc = sc.moved(genericRotation(), L*vector(1.3, 2.2, -0.9));
        }

        polymerChains chains(types);
        chains.append
        (
            0, 0,
            List<vector>({sc.x[0] + dt*sc.v[0], sc.x[1] + dt*sc.v[1]}),
            List<vector>({sc.v[0], sc.v[1]})
        );
        chains.append
        (
            0, 1,
            List<vector>({sc.x[2] + dt*sc.v[2], sc.x[3] + dt*sc.v[3]}),
            List<vector>({sc.v[2], sc.v[3]})
        );
        const List<vector> positionsOld({sc.x[0], sc.x[1], sc.x[2], sc.x[3]});

        // The chord audit sees the straight paths cross
        const List<labelPair> rods({labelPair(0, 1), labelPair(2, 3)});
        ASSERT_EQ
        (
            rodCrossingAudit(rods).check(positionsOld, chains.positions())
           .size(),
            1
        );

        dictionary coeffs;
        coeffs.add("rootSolver", "isolating");
        coeffs.add("audit", true);
        dictionary dict;
        dict.add("collision", "elasticRods");
        dict.add("elasticRodsCoeffs", coeffs);
        collisionModels::elasticRods model(dict);

        model.correct(chains, positionsOld, dt, dt);

        EXPECT_EQ(model.count().events, 1)
            << "rotated " << rotated << " L " << L;
        EXPECT_EQ(model.count().auditCrossings, 0);
        EXPECT_EQ(model.count().stalls, 0);
        EXPECT_EQ(model.count().steps, 1);

        const List<vector>& x = chains.positions();
        const rodPairCrossing startPair = sc.pair();
        const rodPairCrossing endPair
        (
            x[0], x[1], x[2], x[3], Zero, Zero, Zero, Zero
        );
        const scalar vStart = startPair.tripleProduct(0);
        const scalar vEnd = endPair.tripleProduct(0);
        EXPECT_GT(vStart*vEnd, 0)
            << "V at the start " << vStart << ", at the end " << vEnd;
        // The straight chord x^n -> x-dagger would have crossed: V at
        // x-dagger has the other sign
        EXPECT_LT(vStart*startPair.tripleProduct(dt), 0);

        const List<vector>& v = chains.velocities();
        vector momentum(Zero);
        scalar energyBefore = 0, energyAfter = 0;
        for (label k = 0; k < 4; ++k)
        {
            momentum += v[k] - sc.v[k];
            energyBefore += 0.5*magSqr(sc.v[k]);
            energyAfter += 0.5*magSqr(v[k]);
        }
        EXPECT_LE(mag(momentum), 1e-12*w);
        EXPECT_NEAR(energyAfter, energyBefore, 1e-12*energyBefore);
    }
}

} // End anonymous namespace


TEST(rodCollision, ElasticRodsResolvesDimerCrossing)
{
    dimerCrossingIn(1);
}


TEST(rodCollision, ElasticRodsResolvesDimerCrossingInMicrometres)
{
    dimerCrossingIn(1e-6);
}


// * * * * * * * * * * * * * * knotDeterminant * * * * * * * * * * * * * * //
TEST(rodCollision, ElasticRodsMeetsPeriodicImages)
{
    const scalar dt = 1;
    const PtrList<chainType> types(oneType(2, 1, 1, 1, 1));
    const List<vector> positionsOld
    ({
        vector(3.8, -0.5, 0), vector(3.8, 0.5, 0),
        vector(0.1, 0, -0.5), vector(0.1, 0, 0.5)
    });
    const vector u(0.4, 0, 0);

    for (const bool periodic : {false, true})
    {
        SCOPED_TRACE(periodic ? "with the lattice" : "without");
        polymerChains chains(types);
        chains.append
        (
            0, 0,
            List<vector>({positionsOld[0] + dt*u, positionsOld[1] + dt*u}),
            List<vector>({u, u})
        );
        chains.append
        (
            0, 1,
            List<vector>({positionsOld[2], positionsOld[3]}),
            List<vector>({Zero, Zero})
        );

        dictionary dict;
        dict.add("collision", "elasticRods");
        collisionModels::elasticRods model(dict);
        if (periodic)
        {
            model.setLattice(List<vector>({vector(4, 0, 0)}));
        }
        model.correct(chains, positionsOld, dt, dt);

        const List<vector>& x = chains.positions();
        const List<vector>& v = chains.velocities();
        if (!periodic)
        {
            EXPECT_EQ(model.count().events, 0);
            EXPECT_NEAR(x[0].x(), 4.2, 1e-12);
            continue;
        }

        EXPECT_EQ(model.count().events, 1);
        EXPECT_EQ(model.count().stalls, 0);
        EXPECT_NEAR(mag(v[0]) + mag(v[1]), 0, 1e-12);
        EXPECT_NEAR(mag(v[2] - u), 0, 1e-12);
        EXPECT_NEAR(mag(v[3] - u), 0, 1e-12);
        EXPECT_LT(x[0].x(), 4.1);
        EXPECT_NEAR(x[0].x(), 3.8 + 0.75*0.4, 1e-9);
        EXPECT_NEAR(x[2].x(), 0.1 + 0.25*0.4, 1e-9);
    }
}
