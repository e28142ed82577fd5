/*---------------------------------------------------------------------------*\
Description
    exactOU: one step from fixed x0, v0 in a fluid velocity u, over 10^5
    independent beads, against the exact Ornstein-Uhlenbeck moments; and
    positionVarianceFactor(h) against independent evaluations. No drift
    (a solvent at rest) and a drift of zeros: the same bits.

    Tolerances are 5 standard errors of each estimator for n samples:
        mean:       SE = sigma/sqrt(n)
        variance:   SE = var sqrt(2/(n-1))               (Gaussian samples)
        covariance: SE = sqrt((var_x var_v + cov^2)/(n-1)) (Gaussian pair)
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "exactOU.H"

using namespace Foam;
using namespace Foam::polymer;
using namespace polymerCloudTest;

namespace
{

const scalar m = 2, zeta = 3, kT = 0.7, gamma_ = zeta/m;
const label nChains = 1000, nPerChain = 100;   // 10^5 beads
const vector x0(1, -2, 0.5), v0(0.3, -0.1, 0.2), u(0.5, 0.25, -1);

class exactOUMoments : public ::testing::TestWithParam<double> {};

} // End anonymous namespace


// Moments of x and v after one step, each component, against the exact
// formulas of the header; tolerance 5 SE of each estimator (see above).
TEST_P(exactOUMoments, OneStepMatchesExactMoments)
{
    const scalar h = GetParam();
    const scalar dt = h/gamma_;

    PtrList<chainType> types(oneType(nPerChain, 1, m, zeta, kT));
    polymerChains chains(types);
    const List<vector> xs(nPerChain, x0), vs(nPerChain, v0);
    for (label c = 0; c < nChains; ++c)
    {
        chains.append(0, c, xs, vs);
    }

    dictionary d;
    d.add("integration", "exactOU");
    autoPtr<integrationModel> model(integrationModel::New(d));
    model->integrate(chains, List<vector>(chains.nBeads(), u), dt, 7, 11);

    const scalar e = std::exp(-h);
    const scalar varV = kT/m*(1 - e*e);
    const scalar varX =
        kT/(m*gamma_*gamma_)*(2*h - 3 + 4*e - e*e);
    const scalar varXTiny = kT/(m*gamma_*gamma_)*2*h*h*h/3*(1 - 0.75*h);
    const scalar varXExpected = (h < 1e-2) ? varXTiny : varX;
    const scalar covXV = kT/(m*gamma_)*sqr(1 - e);

    const scalar n = chains.nBeads();

    for (direction d = 0; d < 3; ++d)
    {
        const scalar meanV = u[d] + (v0[d] - u[d])*e;
        const scalar meanX = x0[d] + u[d]*dt + (v0[d] - u[d])*(1 - e)/gamma_;

        moments mo;
        for (label i = 0; i < chains.nBeads(); ++i)
        {
            mo.add
            (
                chains.positions()[i][d] - meanX,
                chains.velocities()[i][d] - meanV
            );
        }

        SCOPED_TRACE("h = " + std::to_string(h) + ", component " + std::to_string(int(d)));

        EXPECT_NEAR(mo.meanY(), 0, 5*std::sqrt(varV/n));
        EXPECT_NEAR(mo.meanX(), 0, 5*std::sqrt(varXExpected/n));
        EXPECT_NEAR(mo.varY(), varV, 5*varV*std::sqrt(2/(n - 1)));
        EXPECT_NEAR(mo.varX(), varXExpected, 5*varXExpected*std::sqrt(2/(n - 1)));
        EXPECT_NEAR
        (
            mo.cov(), covXV,
            5*std::sqrt((varXExpected*varV + sqr(covXV))/(n - 1))
        );
    }
}

INSTANTIATE_TEST_SUITE_P
(
    exactOU,
    exactOUMoments,
    ::testing::Values(1e-3, 0.1, 1.0, 50.0)
);


// No cancellation for h >= 0.1: long double direct evaluation, 1e-12 relative
// (double round-off of the library's evaluation is ~1e-15 relative there).
TEST(exactOU, PositionVarianceFactorDirect)
{
    for (const long double h : {0.1L, 0.3L, 0.7L, 0.999L, 1.0L, 1.5L, 5.0L, 50.0L})
    {
        const long double direct =
            2*h - 3 + 4*std::exp(-h) - std::exp(-2*h);
        const double value =
            integrationModels::exactOU::positionVarianceFactor(double(h));
        EXPECT_NEAR(value, double(direct), 1e-12*double(direct)) << "h = " << double(h);
    }
}


// Tiny h: the series 2h^3/3 - h^4/2 + 7h^5/30 - ...; with two terms the
// relative error is ~0.35 h^2, with the leading term alone 0.75 h.
TEST(exactOU, PositionVarianceFactorSmallH)
{
    for (const double h : {1e-2, 1e-4, 1e-6, 1e-10})
    {
        const double value =
            integrationModels::exactOU::positionVarianceFactor(h);
        const double twoTerms = 2*h*h*h/3 - h*h*h*h/2;
        EXPECT_NEAR(value, twoTerms, (0.4*h*h + 1e-14)*twoTerms) << "h = " << h;
        EXPECT_NEAR(value, 2*h*h*h/3, (0.76*h + 1e-14)*2*h*h*h/3) << "h = " << h;
        EXPECT_GT(value, 0) << "h = " << h;
    }
    EXPECT_EQ(integrationModels::exactOU::positionVarianceFactor(0), 0);
}


// The update's coefficients reproduce the exact variances and covariance
// (algebraic identities: 1e-12 relative).
TEST(exactOU, CoefficientsReproduceCovariance)
{
    const chainType type("t", 2, 1, m, zeta, kT);
    for (const double h : {1e-3, 0.1, 1.0, 50.0})
    {
        const scalar dt = h/gamma_;
        const auto k = integrationModels::exactOU::coefficients::exact(type, dt);
        const scalar e = std::exp(-h);
        const scalar varV = kT/m*(1 - e*e);
        const scalar varX = kT/(m*gamma_*gamma_)
            *integrationModels::exactOU::positionVarianceFactor(h);
        const scalar covXV = kT/(m*gamma_)*sqr(1 - e);

        EXPECT_NEAR(k.velocityDecay, e, 1e-15);
        EXPECT_NEAR(k.positionDecay, (1 - e)/gamma_, 1e-12*(1 - e)/gamma_);
        EXPECT_NEAR(sqr(k.velocitySigma), varV, 1e-12*varV);
        EXPECT_NEAR(k.velocitySigma*k.positionFromXi1, covXV, 1e-12*covXV);
        EXPECT_NEAR
        (
            sqr(k.positionFromXi1) + sqr(k.positionFromXi2), varX, 1e-9*varX
        ) << "h = " << h;
    }
}

// ************************************************************************* //


// A solvent at rest given as no drift (an empty list, u not read) and as
// a drift of zeros: the same bits, for exactOU and eulerMaruyama.
TEST(exactOU, NoDriftIsZeroDrift)
{
    for (const word integration : {"exactOU", "eulerMaruyama"})
    {
        PtrList<chainType> types(oneType(37, 1, m, zeta, kT));
        polymerChains atRest(types), zeroDrift(types);
        List<vector> xs(37), vs(37);
        forAll(xs, i)
        {
            xs[i] = x0 + vector(i, 0.5*i, -0.25*i);
            vs[i] = v0 - vector(0.01*i, 0, 0.02*i);
        }
        for (label c = 0; c < 3; ++c)
        {
            atRest.append(0, c, xs, vs);
            zeroDrift.append(0, c, xs, vs);
        }

        dictionary d;
        d.add("integration", integration);
        autoPtr<integrationModel> model(integrationModel::New(d));
        const scalar dt = 0.01;
        for (label step = 1; step <= 3; ++step)
        {
            model->integrate(atRest, List<vector>(), dt, step, 11);
            model->integrate
            (
                zeroDrift, List<vector>(zeroDrift.nBeads(), Zero), dt,
                step, 11
            );
        }
        for (label i = 0; i < atRest.nBeads(); ++i)
        {
            for (direction k = 0; k < 3; ++k)
            {
                ASSERT_EQ(atRest.positions()[i][k], zeroDrift.positions()[i][k])
                    << integration << " bead " << i;
                ASSERT_EQ
                (
                    atRest.velocities()[i][k], zeroDrift.velocities()[i][k]
                ) << integration << " bead " << i;
            }
        }
        EXPECT_NE(atRest.positions()[0], xs[0]);
    }
}
