/*---------------------------------------------------------------------------*\
Description
    tridiagonalSystem: random diagonally dominant systems, open and cyclic,
    sizes 1-200: the residual max|Ax - b|/max|b| is below 1e-12 (the solve
    is backward stable for diagonally dominant matrices: round-off ~1e-15).
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "tridiagonalSystem.H"
#include <random>
#include <vector>

using namespace Foam;
using namespace Foam::polymer;

namespace
{

scalar relativeResidual(const label n, const bool cyclic, std::mt19937_64& gen)
{
    std::uniform_real_distribution<double> offDiagonal(-1, 1);
    std::uniform_real_distribution<double> rhs(-10, 10);
    std::uniform_real_distribution<double> margin(0.1, 3);

    std::vector<double> l(n), d(n), u(n), b(n);
    for (label i = 0; i < n; ++i)
    {
        l[i] = offDiagonal(gen);
        u[i] = offDiagonal(gen);
        // dominant; sign varies
        d[i] = (std::abs(l[i]) + std::abs(u[i]) + margin(gen))*(i % 3 ? 1 : -1);
        b[i] = rhs(gen);
    }
    if (!cyclic) { l[0] = 0; u[n - 1] = 0; }

    tridiagonalSystem system;
    system.resize(n);
    for (label i = 0; i < n; ++i)
    {
        system.lower()[i] = l[i];
        system.diagonal()[i] = d[i];
        system.upper()[i] = u[i];
        system.source()[i] = b[i];
    }
    EXPECT_TRUE(system.solve(cyclic));
    const UList<scalar>& x = system.source();

    scalar residual = 0, bMax = 0;
    for (label i = 0; i < n; ++i)
    {
        scalar ax = d[i]*x[i];
        if (n > 1)
        {
            if (i > 0 || cyclic) ax += l[i]*x[(i + n - 1)%n];
            if (i < n - 1 || cyclic) ax += u[i]*x[(i + 1)%n];
        }
        residual = max(residual, mag(ax - b[i]));
        bMax = max(bMax, mag(b[i]));
    }
    return residual/bMax;
}

} // End anonymous namespace


// Open (Thomas) systems of sizes 1 to 200: residual < 1e-12.
TEST(tridiagonalSystem, OpenResidual)
{
    std::mt19937_64 gen(1);
    for (const label n : {1, 2, 3, 5, 50, 200})
    {
        EXPECT_LT(relativeResidual(n, false, gen), 1e-12) << "n = " << n;
    }
}


// Cyclic (Sherman-Morrison) systems, sizes 3 to 200: residual < 1e-12.
TEST(tridiagonalSystem, CyclicResidual)
{
    std::mt19937_64 gen(2);
    for (const label n : {3, 4, 7, 50, 200})
    {
        for (int repeat = 0; repeat < 5; ++repeat)
        {
            EXPECT_LT(relativeResidual(n, true, gen), 1e-12) << "n = " << n;
        }
    }
}

// ************************************************************************* //
