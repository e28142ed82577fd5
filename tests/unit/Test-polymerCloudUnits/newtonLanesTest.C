/*---------------------------------------------------------------------------*\
Description
    newton and exactRods solve open chains of one type several at a time
    (eight with AVX-512, four otherwise), in the lanes of the vector
    registers (newtonLanes). Their correct() must give every chain the
    bits that correctChain, one chain at a time, gives it: the same
    positions and velocities (memcmp), the same failed chains in the same
    order and the same counts. The scenes take each path: steps of 0.02 a
    (lanes to convergence), 0.3 a with 50 iterations (halved steps and the
    retry along x*: the scalar path from the start), one iteration (given
    up at the cap), two chain types interleaved (the lanes gather a type's
    chains across the other's, the last group of a type short of the lanes,
    repeating its last chain; the second type of 7, 3 or 2 beads, the
    shortest systems of one or two rows), a ring type among open chains,
    and a NaN in one chain; a scene of 15 chains whose last groups are
    short (with eight lanes, a type's last two chains take four lanes).
    Eight lanes and two groups of four give the same bits (on processors
    with AVX-512; skipped elsewhere).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <cstring>
#include <limits>
#include "testHelpers.H"
#include "constraintModel.H"
#include "newtonLanes.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

const scalar a = 1.5, m = 2, kT = 0.5, dt = 0.01;

struct laneScene
{
    word model;
    word directions;
    scalar step;
    label maxIterations;
    bool mixedTypes;
    bool withNaN;
    label nShort = 7;
    label repeats = 3;
};

// Chains of 20 beads (type 0) and 7 beads (type 1, a ring when asked), in
// the order 0 0 0 0 0 0 1 0 0 1 1 0 ... so that runs of 1 to 6 of one
// type follow each other
PtrList<chainType> twoTypes(const bool secondRing, const label nShort)
{
    PtrList<chainType> types(2);
    types.set(0, new chainType("long", 20, a, m, 1, kT, false));
    types.set(1, new chainType("short", nShort, a, m, 1, kT, secondRing));
    return types;
}

List<vector> makeScene
(
    polymerChains& chains,
    const laneScene& scene,
    std::mt19937_64& gen
)
{
    const label pattern[] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 1};
    label id = 0;
    for (label repeat = 0; repeat < scene.repeats; ++repeat)
    {
        for (const label typei : pattern)
        {
            const label t = scene.mixedTypes ? typei : 0;
            const label n = (t == 0) ? 20 : scene.nShort;
            List<point> x = randomWalk(n, a, point(10*id, 0, 0), gen);
            chains.append(t, id, x, List<vector>(n, Zero));
            ++id;
        }
    }
    const List<vector> positionsOld(chains.positions());

    for (vector& x : chains.positions()) x += gaussian(gen, scene.step);
    for (vector& v : chains.velocities()) v = gaussian(gen, std::sqrt(kT/m));
    if (scene.withNaN)
    {
        chains.positions()[chains.start(2) + 5].z() =
            std::numeric_limits<scalar>::quiet_NaN();
    }
    return positionsOld;
}

autoPtr<constraintModel> makeModel(const laneScene& scene)
{
    dictionary coeffs;
    coeffs.add("maxIterations", scene.maxIterations);
    coeffs.add("directions", scene.directions);
    coeffs.add("maxFailureReports", 0);
    coeffs.add("failureAction", "subStep");
    dictionary d;
    d.add("constraint", scene.model);
    d.add(word(scene.model + "Coeffs"), coeffs);
    return constraintModel::New(d);
}

bool sameBits(const UList<vector>& a, const UList<vector>& b)
{
    return
        a.size() == b.size()
     && std::memcmp(a.cdata(), b.cdata(), a.size()*sizeof(vector)) == 0;
}

class newtonLanesScene : public ::testing::TestWithParam<laneScene> {};

std::string sceneName(const ::testing::TestParamInfo<laneScene>& info)
{
    const laneScene& s = info.param;
    return
        s.model + "_" + s.directions + "_step" + std::to_string(std::lround(100*s.step/a))
      + "_iter" + std::to_string(s.maxIterations)
      + (s.mixedTypes ? "_mixed" + std::to_string(s.nShort) : "")
      + (s.withNaN ? "_NaN" : "")
      + (s.repeats != 3 ? "_x" + std::to_string(s.repeats) : "");
}

} // End anonymous namespace


TEST_P(newtonLanesScene, SameBitsAsOneChainAtATime)
{
    const laneScene scene = GetParam();
    std::mt19937_64 gen(2718);

    PtrList<chainType> types
    (
        twoTypes(scene.mixedTypes && scene.step > 0.1 && scene.nShort > 2, scene.nShort)
    );
    polymerChains inLanes(types);
    const List<vector> positionsOld = makeScene(inLanes, scene, gen);
    polymerChains oneByOne(inLanes);

    autoPtr<constraintModel> lanesModel = makeModel(scene);
    DynamicList<label> failedInLanes;
    lanesModel->correct(inLanes, positionsOld, dt, 0, failedInLanes);

    autoPtr<constraintModel> scalarModel = makeModel(scene);
    DynamicList<label> failedOneByOne;
    for (label c = 0; c < oneByOne.nChains(); ++c)
    {
        if (!scalarModel->correctChain(oneByOne, c, positionsOld, dt, 0))
        {
            failedOneByOne.append(c);
        }
    }

    EXPECT_TRUE(sameBits(inLanes.positions(), oneByOne.positions()));
    EXPECT_TRUE(sameBits(inLanes.velocities(), oneByOne.velocities()));
    EXPECT_EQ(failedInLanes, failedOneByOne);
    EXPECT_EQ(lanesModel->count().solves, scalarModel->count().solves);
    EXPECT_EQ(lanesModel->count().iterations, scalarModel->count().iterations);
    EXPECT_EQ
    (
        lanesModel->count().maxIterations,
        scalarModel->count().maxIterations
    );
    EXPECT_EQ(lanesModel->count().failures, scalarModel->count().failures);

    // The scene reaches the paths it is for
    if (scene.step < 0.1 && !scene.withNaN)
    {
        EXPECT_EQ(lanesModel->count().failures, 0);
    }
    if (scene.withNaN || scene.maxIterations == 1)
    {
        EXPECT_GT(lanesModel->count().failures, 0);
    }
}

INSTANTIATE_TEST_SUITE_P
(
    constraint,
    newtonLanesScene,
    ::testing::Values
    (
        laneScene{"newton", "start", 0.02*a, 50, false, false},
        laneScene{"newton", "end", 0.02*a, 50, false, false},
        laneScene{"newton", "start", 0.02*a, 50, true, false},
        laneScene{"newton", "start", 0.3*a, 50, true, false},
        laneScene{"newton", "end", 0.3*a, 50, false, false},
        laneScene{"newton", "start", 0.3*a, 1, false, false},
        laneScene{"newton", "start", 0.02*a, 50, true, true},
        laneScene{"exactRods", "start", 0.02*a, 50, true, false},
        laneScene{"exactRods", "start", 0.3*a, 50, true, false},
        laneScene{"exactRods", "start", 0.6*a, 50, false, false},
        laneScene{"newton", "start", 0.02*a, 50, true, false, 2},
        laneScene{"newton", "start", 0.02*a, 50, true, false, 3},
        laneScene{"newton", "end", 0.3*a, 50, true, false, 2},
        laneScene{"newton", "start", 0.02*a, 50, true, false, 7, 1}
    ),
    sceneName
);


//- The lane counts this processor runs: 4, and 8 with AVX-512
labelList laneCounts()
{
    return
        newtonLanes::registerLanes() == 8 ? labelList({4, 8}) : labelList({4});
}


// A lane whose system has a zero pivot is given up, without a division by
// zero, and the other lanes converge as they would alone: a chain whose
// x* rods are perpendicular to its x^n rods (every diagonal entry zero),
// in lane 2 of four and of eight
TEST(newtonLanes, GivesUpALaneWithAZeroPivot)
{
    const label n = 5;
    List<vector> straight(n), rodsAcross(n);
    for (label i = 0; i < n; ++i)
    {
        straight[i] = vector(i*a*1.01, 0, 0);
        rodsAcross[i] = vector(0, i*a, 0);
    }

    for (const label nLanes : laneCounts())
    {
        newtonLanes lanes(nLanes);
        lanes.resize(n);
        const vector* x[newtonLanes::maxLanes];
        const vector* rodStart[newtonLanes::maxLanes];
        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            x[lanei] = straight.cdata();
            rodStart[lanei] = (lanei == 2 ? rodsAcross : straight).cdata();
        }
        lanes.load(x, rodStart);
        label iterations[newtonLanes::maxLanes];
        lanes.solve(a, 1e-10, 50, iterations);

        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            if (lanei == 2)
            {
                EXPECT_EQ(iterations[lanei], 0) << nLanes << " lanes";
                continue;
            }
            EXPECT_GT(iterations[lanei], 0) << nLanes << " lanes";
            List<vector> solved(straight), v(n, Zero);
            lanes.store(lanei, solved.data(), v.data(), 1);
            for (label k = 0; k + 1 < n; ++k)
            {
                EXPECT_NEAR(mag(solved[k + 1] - solved[k]), a, 1e-9*a);
            }
        }
    }
}


// Eight chains in eight lanes (AVX-512) and in two groups of four: the
// same iterations, positions, velocities and velocity residuals, bit for
// bit, the lanes doing the same arithmetic at either width
TEST(newtonLanes, EightLanesAsTwoGroupsOfFour)
{
    if (newtonLanes::registerLanes() != 8)
    {
        GTEST_SKIP() << "no AVX-512: eight lanes do not run here";
    }

    const label n = 30;
    std::mt19937_64 gen(31);
    List<List<vector>> start(8), x8(8), v8(8);
    for (label c = 0; c < 8; ++c)
    {
        start[c] = randomWalk(n, a, point(5*c, 0, 0), gen);
        x8[c] = start[c];
        for (vector& x : x8[c]) x += gaussian(gen, 0.03*a);
        v8[c] = List<vector>(n);
        for (vector& v : v8[c]) v = gaussian(gen, 1);
    }
    List<List<vector>> x4(x8), v4(v8);

    // Solve chains [first, first + nLanes) in lanes of the given width
    const auto solveIn =
    [&]
    (
        newtonLanes& lanes,
        const label first,
        List<List<vector>>& x,
        List<List<vector>>& v,
        label iterations[],
        bool solved[],
        scalar largest[]
    )
    {
        const label nLanes = lanes.nLanes();
        const vector* xs[newtonLanes::maxLanes];
        const vector* rodStart[newtonLanes::maxLanes];
        vector* vs[newtonLanes::maxLanes];
        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            xs[lanei] = x[first + lanei].cdata();
            rodStart[lanei] = start[first + lanei].cdata();
            vs[lanei] = v[first + lanei].data();
        }
        lanes.resize(n);
        lanes.load(xs, rodStart);
        lanes.solve(a, 1e-10, 50, iterations + first);
        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            ASSERT_GT(iterations[first + lanei], 0);
            lanes.store
            (
                lanei, x[first + lanei].data(), vs[lanei], 1/dt
            );
        }
        lanes.loadVelocities(vs);
        lanes.projectVelocities(solved + first, largest + first);
        for (label lanei = 0; lanei < nLanes; ++lanei)
        {
            ASSERT_TRUE(solved[first + lanei]);
            lanes.storeVelocities(lanei, vs[lanei]);
        }
    };

    label iterations8[8], iterations4[8];
    bool solved8[8], solved4[8];
    scalar largest8[8], largest4[8];
    newtonLanes eight(8), four(4);
    solveIn(eight, 0, x8, v8, iterations8, solved8, largest8);
    solveIn(four, 0, x4, v4, iterations4, solved4, largest4);
    solveIn(four, 4, x4, v4, iterations4, solved4, largest4);

    for (label c = 0; c < 8; ++c)
    {
        EXPECT_EQ(iterations8[c], iterations4[c]);
        EXPECT_EQ
        (
            std::memcmp(&largest8[c], &largest4[c], sizeof(scalar)), 0
        );
        EXPECT_TRUE(sameBits(x8[c], x4[c])) << "chain " << c;
        EXPECT_TRUE(sameBits(v8[c], v4[c])) << "chain " << c;
        EXPECT_FALSE(sameBits(x8[c], start[c]));
    }
}

// ************************************************************************* //
