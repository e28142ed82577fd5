/*---------------------------------------------------------------------------*\
Description
    Chain types given in physical terms (kuhnChain): lambda-DNA by its base
    pairs gives 48502 x 0.34 nm of contour in round(L/b) rods of L/n, beads
    of 650 Da a base pair along a rod and Stokes friction 6 pi mu r; a
    polymer by contour and Kuhn lengths with k Kuhn lengths a rod gives
    round(L/(k b)) rods and friction per length times a; a ring keeps
    n beads for n rods. Mixed or missing keywords, a misspelt one and
    kuhnLengthsPerRod below 1 stop with a FatalIOError.
\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "chainType.H"
#include "kuhnChain.H"
#include "mathematicalConstants.H"
#include "IStringStream.H"

using namespace Foam;
using namespace Foam::polymer;

namespace
{

dictionary entries(const char* text)
{
    IStringStream is(text);
    return dictionary(is);
}

} // End anonymous namespace


TEST(kuhnChain, LambdaDNAByBasePairs)
{
    const chainType type
    (
        "lambdaDNA",
        entries
        (
            "basePairs 48502; beadRadius 35e-9; viscosity 1e-3;"
            " temperature 298.15;"
        )
    );

    const scalar L = 48502*0.34e-9;
    const label nRods = std::round(L/100e-9);
    EXPECT_EQ(nRods, 165);
    EXPECT_EQ(type.nBeads(), nRods + 1);
    EXPECT_DOUBLE_EQ(type.rodLength(), L/nRods);
    EXPECT_DOUBLE_EQ
    (
        type.beadMass(),
        650*1.66053907e-27/0.34e-9*(L/nRods)
    );
    EXPECT_DOUBLE_EQ
    (
        type.friction(),
        6*constant::mathematical::pi*1e-3*35e-9
    );
    EXPECT_DOUBLE_EQ(type.kT(), chainType::boltzmannConstant*298.15);
    EXPECT_FALSE(type.ring());
}


TEST(kuhnChain, PolymerWithSeveralKuhnLengthsARod)
{
    const dictionary dict
    (
        entries
        (
            "contourLength 2.5e-6; kuhnLength 1.8e-9; massPerLength 1.3e-16;"
            " kuhnLengthsPerRod 10; frictionPerLength 1e-2; kT 4e-21;"
        )
    );
    const chainType type("polystyrene", dict);
    const kuhnChain polymer("polystyrene", dict, false);

    const label nRods = std::round(2.5e-6/(10*1.8e-9));
    EXPECT_EQ(type.nBeads(), nRods + 1);
    EXPECT_DOUBLE_EQ(type.rodLength(), 2.5e-6/nRods);
    EXPECT_DOUBLE_EQ(type.beadMass(), 1.3e-16*type.rodLength());
    EXPECT_DOUBLE_EQ(type.friction(), 1e-2*type.rodLength());

    // <R^2> = n a^2 = L a: a/b times the polymer's L b, k but for rounding
    EXPECT_DOUBLE_EQ(polymer.sizeFactor(), type.rodLength()/1.8e-9);
    EXPECT_NEAR(polymer.sizeFactor(), 10, 10*0.5/nRods);
}


TEST(kuhnChain, RingOfKuhnLengths)
{
    const chainType type
    (
        "plasmid",
        entries
        (
            "basePairs 5000; ring true; frictionPerLength 1e-3;"
            " temperature 300;"
        )
    );
    EXPECT_TRUE(type.ring());
    EXPECT_EQ(type.nRods(), 17);
    EXPECT_EQ(type.nBeads(), 17);
}


TEST(kuhnChain, BadEntriesStop)
{
    const char* bad[] =
    {
        // both forms
        "basePairs 1000; nBeads 10; frictionPerLength 1; kT 1;",
        // both contours
        "basePairs 1000; contourLength 1e-6; kuhnLength 1e-7;"
        " massPerLength 1; frictionPerLength 1; kT 1;",
        // no Kuhn length for a polymer
        "contourLength 1e-6; massPerLength 1; frictionPerLength 1; kT 1;",
        // no friction, or both
        "basePairs 1000; kT 1;",
        "basePairs 1000; beadRadius 1e-8; viscosity 1e-3;"
        " frictionPerLength 1; kT 1;",
        // a radius without viscosity
        "basePairs 1000; beadRadius 1e-8; kT 1;",
        // rods shorter than a Kuhn length
        "basePairs 1000; kuhnLengthsPerRod 0.5; frictionPerLength 1; kT 1;",
        // misspelt optional keyword
        "basePairs 1000; kuhnLengthPerRod 2; frictionPerLength 1; kT 1;",
        // the reduced form with a keyword of the contour form, which it
        // would ignore
        "nBeads 10; rodLength 1; beadMass 1; friction 1; kT 1;"
        " viscosity 1e-3;",
        "nBeads 10; rodLength 1; beadMass 1; friction 1; kT 1;"
        " kuhnLengthsPerRod 2;",
        // non-physical values
        "basePairs 0; frictionPerLength 1; kT 1;",
        "basePairs 1000; beadRadius -1e-8; viscosity 1e-3; kT 1;",
        "basePairs 1000; frictionPerLength 1; temperature -3;"
    };
    for (const char* text : bad)
    {
        EXPECT_THROW(chainType("bad", entries(text)), Foam::error) << text;
    }
}

// ************************************************************************* //
