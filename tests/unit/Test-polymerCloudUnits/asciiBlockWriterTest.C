/*---------------------------------------------------------------------------*\
Description
    asciiBlockWriter gives the bytes an ASCII Ostream gives item by item:
    scalars at the stream's precision (17, as the cloud writes, and 6, the
    default) across magnitudes, signs, zeros, subnormals and infinities,
    labels, vectors and characters, over more than one block.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include <limits>
#include <random>
#include "OStringStream.H"
#include "DynamicList.H"
#include "asciiBlockWriter.H"

using namespace Foam;
using namespace Foam::polymer;

namespace
{

// The values: special ones, then random mantissas over exponents of
// -320 to 320 (subnormals included) of both signs
List<scalar> testScalars()
{
    DynamicList<scalar> x
    ({
        0.0, -0.0, 1.0, -1.0, 0.1, 1.0/3, 2.0/3, 1e-5, 1e-4, 123456.0,
        1234567.0, 1e16, 1e17, 9.999999999999999e22, 5e-324,
        std::numeric_limits<scalar>::min(), std::numeric_limits<scalar>::max(),
        std::numeric_limits<scalar>::infinity(),
        -std::numeric_limits<scalar>::infinity()
    });
    std::mt19937_64 gen(5);
    std::uniform_real_distribution<scalar> mantissa(-10, 10);
    std::uniform_int_distribution<int> exponent(-320, 300);
    for (label i = 0; i < 20000; ++i)
    {
        x.append(mantissa(gen)*std::pow(10.0, exponent(gen)));
    }
    return List<scalar>(std::move(x));
}

} // End anonymous namespace


TEST(asciiBlockWriter, WritesTheStreamsOwnCharacters)
{
    const List<scalar> x(testScalars());
    for (const unsigned precision : {17u, 6u})
    {
        OStringStream expected, written;
        expected.precision(precision);
        written.precision(precision);
        {
            asciiBlockWriter out(written);
            for (label i = 0; i + 2 < x.size(); i += 3)
            {
                const vector v(x[i], x[i + 1], x[i + 2]);
                expected << v << token::SPACE << label(i - 100000) << nl;
                out << v << char(token::SPACE) << label(i - 100000)
                    << char(token::NL);
            }
            for (const scalar xi : x)
            {
                expected << xi << nl;
                out << xi << char(token::NL);
            }
        }
        ASSERT_GT(expected.str().size(), size_t(1 << 17));
        EXPECT_EQ(written.str(), expected.str()) << "precision " << precision;
    }
}


// ************************************************************************* //
