/*---------------------------------------------------------------------------*\
Description
    exactRods, the projection that always returns exact rods: from
    perturbations of 0.02 a (a small step) to 1.5 a (far past where the
    projection along the constraint directions has no solution), on open
    random walks and trefoil rings, every rod has length a (to newton's
    tolerance, 1e-10, where newton converges, to round-off elsewhere), with
    no failure, the centre of mass and the momentum kept
    (the corrections are internal) and no relative velocity along a rod
    (velocityTolerance). Where newton converges the result is newton's,
    bit for bit; where it does not, a nearest configuration: x* minus the
    result has no component along the constraint set's tangent (to the
    descent's tolerance, 1e-8 a; checked with 1e-7 a).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "constraintModel.H"
#include "trefoil.H"
#include <tuple>
#include <limits>
#include <cmath>

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

const label nBeads = 20, nChains = 40;
const scalar a = 1.5, m = 2, kT = 0.5, dt = 0.01;

// Chains with exact rods; returns x^n
List<vector> exactChains
(
    polymerChains& chains,
    const bool ring,
    std::mt19937_64& gen
)
{
    const List<point> knot =
        initialisationModels::trefoil::beads(nBeads, a, true);
    for (label c = 0; c < nChains; ++c)
    {
        const point origin(20*c, 0, 0);
        List<point> x(ring ? knot : randomWalk(nBeads, a, origin, gen));
        if (ring)
        {
            for (point& p : x) p += origin;
        }
        chains.append(0, c, x, List<vector>(nBeads, Zero));
    }
    return List<vector>(chains.positions());
}

autoPtr<constraintModel> model(const word& name, const word& directions)
{
    dictionary coeffs;
    coeffs.add("directions", directions);
    coeffs.add("maxFailureReports", 0);
    if (name == "exactRods")
    {
        coeffs.add("maxDescentIterations", 1000);
    }
    dictionary d;
    d.add("constraint", name);
    d.add(word(name + "Coeffs"), coeffs);
    return constraintModel::New(d);
}

vector sum(const UList<vector>& list)
{
    vector s(Zero);
    for (const vector& v : list) s += v;
    return s;
}

scalar distance(const UList<vector>& x, const UList<vector>& y)
{
    scalar d = 0;
    forAll(x, i) d += magSqr(x[i] - y[i]);
    return d;
}

class exactRodsProjection
:
    public ::testing::TestWithParam<std::tuple<bool, double>>
{};

} // End anonymous namespace


TEST_P(exactRodsProjection, ExactRodsAtAnyDisplacement)
{
    const auto [ring, delta] = GetParam();
    std::mt19937_64 gen(2468);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = exactChains(chains, ring, gen);
    for (vector& x : chains.positions()) x += gaussian(gen, delta*a);
    for (vector& v : chains.velocities()) v = gaussian(gen, std::sqrt(kT/m));

    const vector centre = sum(chains.positions());
    const vector momentum = sum(chains.velocities());

    autoPtr<constraintModel> exact = model("exactRods", "start");
    exact->correct(chains, positionsOld, dt, 0);

    // newton's tolerance where it converges, round-off elsewhere
    EXPECT_LE(chains.maxRodLengthError(), 1e-10*(1 + 1e-6));
    EXPECT_LE(maxRodVelocityError(chains), 1e-10*(1 + 1e-6));
    EXPECT_EQ(exact->count().failures, 0);

    const scalar scale = chains.nBeads()*(20*nChains + nBeads*a);
    EXPECT_LE(mag(sum(chains.positions()) - centre), 1e-12*scale);
    EXPECT_LE
    (
        mag(sum(chains.velocities()) - momentum),
        1e-12*chains.nBeads()*(std::sqrt(kT/m) + 3*delta*a/dt)
    );
}


// A NaN in a chain is a failure of exactRods too (it returns exact rods
// for any finite state), counted, not a projection
TEST(exactRods, ANaNIsAFailure)
{
    std::mt19937_64 gen(99);
    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, false));
    polymerChains chains(types);
    const List<vector> positionsOld = exactChains(chains, false, gen);
    chains.positions()[2].z() = std::numeric_limits<scalar>::quiet_NaN();

    autoPtr<constraintModel> exact = model("exactRods", "start");
    exact->correct(chains, positionsOld, dt, 0);
    EXPECT_GT(exact->count().failures, 0);
    EXPECT_TRUE(std::isnan(chains.maxRodLengthError()));
}


TEST_P(exactRodsProjection, NewtonsWhereItConvergesNearestElsewhere)
{
    const auto [ring, delta] = GetParam();
    std::mt19937_64 gen(1357);

    PtrList<chainType> types(oneType(nBeads, a, m, 1, kT, ring));
    polymerChains chains(types);
    const List<vector> positionsOld = exactChains(chains, ring, gen);
    for (vector& x : chains.positions()) x += gaussian(gen, delta*a);
    for (vector& v : chains.velocities()) v = gaussian(gen, std::sqrt(kT/m));
    const List<vector> target(chains.positions());

    polymerChains exact(chains);
    model("exactRods", "start")->correct(exact, positionsOld, dt, 0);
    polymerChains paper(chains);
    model("newton", "start")->correct(paper, positionsOld, dt, 0);

    // x* - x has no tangent component where newton failed: the velocity
    // constraint (newton's direct solve) leaves nothing of it
    polymerChains normal(exact);
    forAll(target, i)
    {
        normal.velocities()[i] = target[i] - exact.positions()[i];
    }
    model("newton", "end")->correctVelocities(normal, 0);

    label nFailed = 0;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const bool newtonConverged = paper.maxRodLengthError(c) <= 1e-9;
        scalar tangent = 0, difference = 0;
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            tangent = max(tangent, mag(normal.velocities()[i]));
            difference = max
            (
                difference,
                mag(exact.positions()[i] - paper.positions()[i])
              + mag(exact.velocities()[i] - paper.velocities()[i])
            );
        }
        if (newtonConverged)
        {
            EXPECT_EQ(difference, 0) << "chain " << c;
        }
        else
        {
            ++nFailed;
            EXPECT_LE(tangent, 1e-7*a) << "chain " << c;
        }
    }
    if (delta >= 0.7)
    {
        EXPECT_GT(nFailed, 0) << "newton converged everywhere";
    }
}


INSTANTIATE_TEST_SUITE_P
(
    exactRods,
    exactRodsProjection,
    ::testing::Combine
    (
        ::testing::Bool(),
        ::testing::Values(0.02, 0.3, 0.7, 1.5)
    )
);

// ************************************************************************* //
