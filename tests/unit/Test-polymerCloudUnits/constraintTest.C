/*---------------------------------------------------------------------------*\
Description
    SHAKE, RATTLE and newton on perturbed chains (open random walks and
    trefoil rings): after correct() every rod has length a to the model's
    tolerance and, for RATTLE and newton, no relative velocity along a rod
    to velocityTolerance (the convergence criteria the models promise;
    slack 1e-6 relative for the second-order difference between |s|^2 - a^2
    and |s| - a). Corrections are internal (equal and opposite), so the
    centre of mass and the momentum are unchanged (round-off: 1e-12).
    With one iteration and large perturbations the failures are counted.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <limits>
#include <cmath>
#include "testHelpers.H"
#include "constraintModel.H"
#include "maxOrNaN.H"
#include "isFinite.H"
#include "trefoil.H"
#include <tuple>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

const label nBeads = 20, nChains = 50;
const scalar a = 1.5, m = 2, kT = 0.5, dt = 0.01;
const scalar tolerance = 1e-10, velocityTolerance = 1e-10;

// Chains with exact rods; returns x^n (copy of the positions)
List<vector> makeChains
(
    polymerChains& chains,
    const bool ring,
    std::mt19937_64& gen
)
{
    const List<point> knot = initialisationModels::trefoil::beads(nBeads, a, true);
    for (label c = 0; c < nChains; ++c)
    {
        const point origin(10*c, 0, 0);
        List<point> x;
        if (ring)
        {
            x = knot;
            for (point& p : x) p += origin;
        }
        else
        {
            x = randomWalk(nBeads, a, origin, gen);
        }
        chains.append(0, c, x, List<vector>(nBeads, Zero));
    }
    return List<vector>(chains.positions());
}

// Perturb positions by noise of size sigma (the step's x*) and give
// thermal velocities (v*)
void perturb(polymerChains& chains, const scalar sigma, std::mt19937_64& gen)
{
    for (vector& x : chains.positions()) x += gaussian(gen, sigma);
    for (vector& v : chains.velocities()) v = gaussian(gen, std::sqrt(kT/m));
}

autoPtr<constraintModel> makeModel
(
    const word& model,
    const word& directions,
    const label maxIterations
)
{
    dictionary coeffs;
    coeffs.add("tolerance", tolerance);
    if (model != "SHAKE")
    {
        // SHAKE has no velocity constraint (and stops at the keyword)
        coeffs.add("velocityTolerance", velocityTolerance);
    }
    coeffs.add("maxIterations", maxIterations);
    coeffs.add("directions", directions);
    coeffs.add("maxFailureReports", 2);
    coeffs.add("failureAction", "subStep");
    dictionary d;
    d.add("constraint", model);
    d.add(word(model + "Coeffs"), coeffs);
    return constraintModel::New(d);
}

vector sum(const UList<vector>& list)
{
    vector s(Zero);
    for (const vector& v : list) s += v;
    return s;
}

typedef std::tuple<std::string, bool, std::string> constraintCase;

class constraintProjection : public ::testing::TestWithParam<constraintCase> {};

std::string caseName(const ::testing::TestParamInfo<constraintCase>& info)
{
    return std::get<0>(info.param) + (std::get<1>(info.param) ? "_ring_" : "_open_")
        + std::get<2>(info.param);
}

} // End anonymous namespace


// Perturbation 0.02 a (a step's displacement): rods to tolerance, rod
// velocities to velocityTolerance, no failure, centre of mass and momentum
// unchanged.
TEST_P(constraintProjection, ReachesTolerances)
{
    const auto [model, ring, directions] = GetParam();
    std::mt19937_64 gen(12345);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = makeChains(chains, ring, gen);
    perturb(chains, 0.02*a, gen);

    const vector centre = sum(chains.positions());
    const vector momentum = sum(chains.velocities());

    autoPtr<constraintModel> constraint = makeModel(model, directions, 1000);
    constraint->correct(chains, positionsOld, dt, 0);

    EXPECT_LE(chains.maxRodLengthError(), tolerance*(1 + 1e-6));
    if (constraint->constrainsVelocities())
    {
        EXPECT_LE(maxRodVelocityError(chains), velocityTolerance*(1 + 1e-6));
    }
    EXPECT_EQ(constraint->count().failures, 0);
    EXPECT_EQ(constraint->count().solves, (constraint->constrainsVelocities() ? 2 : 1)*nChains);

    const scalar scale = chains.nBeads()*(10*nChains + nBeads*a);
    EXPECT_LE(mag(sum(chains.positions()) - centre), 1e-12*scale);
    EXPECT_LE
    (
        mag(sum(chains.velocities()) - momentum),
        1e-12*chains.nBeads()*(std::sqrt(kT/m) + 0.02*a/dt)
    );
}


// One iteration from a perturbation of 0.3 a cannot converge to 1e-10:
// the failures are counted, not hidden.
TEST_P(constraintProjection, CountsNonConvergence)
{
    const auto [model, ring, directions] = GetParam();
    std::mt19937_64 gen(54321);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = makeChains(chains, ring, gen);
    perturb(chains, 0.3*a, gen);

    autoPtr<constraintModel> constraint = makeModel(model, directions, 1);
    constraint->correct(chains, positionsOld, dt, 0);

    EXPECT_GT(constraint->count().failures, 0);
    EXPECT_GT(chains.maxRodLengthError(), tolerance);
}

// failureAction stop: a solve that does not converge is a FatalError.
TEST_P(constraintProjection, StopsOnFailureWhenAsked)
{
    const auto [model, ring, directions] = GetParam();
    std::mt19937_64 gen(777);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = makeChains(chains, ring, gen);
    perturb(chains, 0.3*a, gen);

    dictionary coeffs;
    coeffs.add("maxIterations", 1);
    coeffs.add("directions", directions);
    coeffs.add("failureAction", "stop");
    dictionary d;
    d.add("constraint", model);
    d.add(word(model + "Coeffs"), coeffs);
    autoPtr<constraintModel> constraint = constraintModel::New(d);

    EXPECT_THROW(constraint->correct(chains, positionsOld, dt, 0), Foam::error);
}

// A running maximum keeps a NaN wherever it comes (Foam::max passes over
// one that a number follows)
TEST(maxOrNaN, KeepsANaN)
{
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    EXPECT_EQ(maxOrNaN(1, 2), 2);
    EXPECT_EQ(maxOrNaN(3, 2), 3);
    EXPECT_TRUE(std::isnan(maxOrNaN(0, nan)));
    EXPECT_TRUE(std::isnan(maxOrNaN(nan, 1)));
    EXPECT_FALSE(std::isnan(max(max(scalar(0), nan), scalar(1))));
}


// The bit test of a list's values finds every NaN and inf, and only them:
// the largest double, the smallest denormal and -0 are finite; the copy
// is exact whatever the values
TEST(isFinite, FindsEveryNaNAndInfOnly)
{
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const scalar inf = std::numeric_limits<scalar>::infinity();
    const scalar finite[] =
    {
        0, -0.0, 1, -1e300, std::numeric_limits<scalar>::max(),
        -std::numeric_limits<scalar>::max(),
        std::numeric_limits<scalar>::denorm_min(),
        std::numeric_limits<scalar>::min()
    };
    List<vector> values(37, vector(1, 2, 3));
    for (const scalar x : finite)
    {
        values[17] = vector(3, x, -x);
        EXPECT_TRUE(allFinite(values)) << x;
        EXPECT_TRUE(isFinite(values[17])) << x;
    }
    for (const scalar x : {nan, -nan, inf, -inf})
    {
        for (const direction d : {0, 1, 2})
        {
            for (const label i : {0, 17, 36})
            {
                List<vector> bad(values);
                bad[i][d] = x;
                EXPECT_FALSE(allFinite(bad)) << x << " at " << i << ", " << d;
                EXPECT_FALSE(isFinite(bad[i]));
                List<vector> copy;
                EXPECT_FALSE(copyAllFinite(bad, copy));
                ASSERT_EQ(copy.size(), bad.size());
                EXPECT_EQ(std::memcmp(copy.cdata(), bad.cdata(), 37*sizeof(vector)), 0);
            }
        }
    }
    List<vector> copy;
    EXPECT_TRUE(copyAllFinite(values, copy));
    EXPECT_EQ(copy, values);

    // Into a DynamicList (the stepper's x^n), which must keep track of its
    // capacity: it grows and shrinks after the copy as it should
    DynamicList<vector> dynamic(4);
    EXPECT_TRUE(copyAllFinite(values, dynamic));
    EXPECT_EQ(List<vector>(dynamic), values);
    for (label i = 0; i < 100; ++i)
    {
        dynamic.append(vector(i, 0, 0));
    }
    EXPECT_EQ(dynamic.size(), 137);
    EXPECT_TRUE(copyAllFinite(SubList<vector>(values, 5), dynamic));
    dynamic.shrink();
    EXPECT_EQ(dynamic.size(), 5);
    EXPECT_EQ(dynamic.capacity(), 5);
}


// A NaN in a chain (a bead's position) is no convergence: the solve fails
// and is counted, and the chains' rod error is NaN, not the others' largest
// (max() and 'mag(x) > tol' pass over a NaN)
TEST_P(constraintProjection, ANaNIsAFailure)
{
    const auto [model, ring, directions] = GetParam();
    std::mt19937_64 gen(4242);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = makeChains(chains, ring, gen);
    perturb(chains, 0.02*a, gen);
    chains.positions()[nBeads + 3].y() = std::numeric_limits<scalar>::quiet_NaN();

    autoPtr<constraintModel> constraint = makeModel(model, directions, 50);
    constraint->correct(chains, positionsOld, dt, 0);

    EXPECT_GT(constraint->count().failures, 0);
    EXPECT_TRUE(std::isnan(chains.maxRodLengthError()));
    EXPECT_TRUE(std::isnan(chains.maxRodLengthError(1)));
    EXPECT_FALSE(std::isnan(chains.maxRodLengthError(0)));
}

INSTANTIATE_TEST_SUITE_P
(
    constraint,
    constraintProjection,
    ::testing::Combine
    (
        ::testing::Values("SHAKE", "RATTLE", "newton"),
        ::testing::Bool(),
        ::testing::Values("start", "end")
    ),
    caseName
);

// ************************************************************************* //


// Rods of 1e-7 at coordinates of 1 (metres: chains far from the mesh's
// origin in SI units) are below the coordinates' round-off (|x| eps/a =
// 2e-9) for newton's tolerance 1e-10: the solve fails, and the message
// says so instead of only advising smaller steps
TEST(constraintFailure, NamesAToleranceBelowTheRoundOff)
{
    const scalar rod = 1e-7;
    PtrList<chainType> types(oneType(10, rod, 1e-21, 1e-9, 4e-21));
    polymerChains chains(types);
    std::mt19937_64 gen(99);
    List<point> x = randomWalk(10, rod, point(1, 1, 1), gen);
    chains.append(0, 0, x, List<vector>(10, Zero));
    const List<vector> positionsOld(chains.positions());
    for (vector& p : chains.positions()) p += gaussian(gen, 0.02*rod);

    dictionary coeffs;
    coeffs.add("failureAction", "stop");
    dictionary d;
    d.add("constraint", "newton");
    d.add("newtonCoeffs", coeffs);
    autoPtr<constraintModel> constraint = constraintModel::New(d);

    std::string message;
    try
    {
        constraint->correct(chains, positionsOld, 1e-6, 0);
    }
    catch (const Foam::error& err)
    {
        message = err.message();
    }
    EXPECT_NE(message.find("round-off of the chain's coordinates"), std::string::npos)
        << message;

    // The hint is the coordinates': at the origin the same chain has none
    EXPECT_TRUE(constraint->roundOffHint(chains, 0).size());
    for (vector& p : chains.positions()) p -= point(1, 1, 1);
    EXPECT_FALSE(constraint->roundOffHint(chains, 0).size());
}
