/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

\*---------------------------------------------------------------------------*/

#include "kuhnChain.H"
#include "checkedInput.H"
#include "mathematicalConstants.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::polymer::kuhnChain::dnaRisePerBasePair = 0.34e-9;

const Foam::scalar Foam::polymer::kuhnChain::dnaKuhnLength = 100e-9;

// 650 Da (the sodium salt's mean base pair), 1 Da = 1.66053907e-27 kg
const Foam::scalar Foam::polymer::kuhnChain::dnaMassPerBasePair =
    650*1.66053907e-27;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

bool Foam::polymer::kuhnChain::describes(const dictionary& dict)
{
    return
        dict.found("basePairs", keyType::LITERAL)
     || dict.found("contourLength", keyType::LITERAL);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::kuhnChain::readFriction
(
    const word& name,
    const dictionary& dict
)
{
    OStringStream os;
    if
    (
        checkedInput::firstOfTwo
        (
            dict, "Chain type '" + name + "'", "beadRadius",
            "frictionPerLength",
            "beadRadius <Stokes radius [m]>; viscosity <[Pa s]>;"
            " or frictionPerLength <[kg/(m s)]>;"
        )
    )
    {
        const scalar radius = checkedInput::positiveScalar
        (
            dict, "beadRadius", "<Stokes radius of a bead [m]>"
        );
        const scalar viscosity = checkedInput::positiveScalar
        (
            dict, "viscosity", "<solvent's dynamic viscosity [Pa s]>"
        );
        friction_ = 6*constant::mathematical::pi*viscosity*radius;
        os  << "6 pi mu r, mu " << viscosity << " Pa s, r " << radius << " m";
    }
    else
    {
        const scalar perLength = checkedInput::positiveScalar
        (
            dict, "frictionPerLength", "<friction per contour length [kg/(m s)]>"
        );
        friction_ = perLength*rodLength_;
        os  << "frictionPerLength a, " << perLength << " kg/(m s)";
    }
    frictionOrigin_ = os.str();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::kuhnChain::kuhnChain
(
    const word& name,
    const dictionary& dict,
    const bool ring
)
:
    origin_(),
    contourLength_(0),
    kuhnLength_(0),
    kuhnLengthsPerRod_(0),
    nRods_(0),
    rodLength_(0),
    beadMass_(0),
    friction_(0),
    frictionOrigin_()
{
    const bool dna = checkedInput::firstOfTwo
    (
        dict, "Chain type '" + name + "'", "basePairs", "contourLength",
        "basePairs <DNA base pairs>; or contourLength <L [m]>;"
        " kuhnLength <b [m]>; massPerLength <[kg/m]>;"
    );
    for (const word reduced : {"nBeads", "rodLength", "beadMass", "friction"})
    {
        if (dict.found(reduced, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Chain type '" << name << "' in " << dict.name()
                << " is given by its contour ('basePairs' or"
                << " 'contourLength') and also by '" << reduced << "'" << nl
                << "    expected: either basePairs or contourLength with"
                << " kuhnLength, or nBeads, rodLength, beadMass and friction"
                << exit(FatalIOError);
        }
    }

    scalar massPerLength = 0;
    OStringStream os;
    if (dna)
    {
        const label basePairs = checkedInput::labelAtLeast
        (
            dict, "basePairs", 1, "<DNA base pairs>"
        );
        contourLength_ = basePairs*dnaRisePerBasePair;
        kuhnLength_ = checkedInput::positiveScalarOrDefault
        (
            dict, "kuhnLength", dnaKuhnLength, "<Kuhn length b [m]>"
        );
        massPerLength = dnaMassPerBasePair/dnaRisePerBasePair;
        os  << basePairs << " bp of DNA";
    }
    else
    {
        contourLength_ = checkedInput::positiveScalar
        (
            dict, "contourLength", "<contour length L [m]>"
        );
        kuhnLength_ = checkedInput::positiveScalar
        (
            dict, "kuhnLength", "<Kuhn length b [m]>"
        );
        massPerLength = checkedInput::positiveScalar
        (
            dict, "massPerLength", "<mass per contour length [kg/m]>"
        );
        os  << "a polymer";
    }
    origin_ = os.str();

    kuhnLengthsPerRod_ = checkedInput::positiveScalarOrDefault
    (
        dict, "kuhnLengthsPerRod", 1, "<Kuhn lengths a rod, >= 1>"
    );
    if (kuhnLengthsPerRod_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'kuhnLengthsPerRod' in " << dict.name() << " is "
            << kuhnLengthsPerRod_ << nl
            << "    expected: kuhnLengthsPerRod <Kuhn lengths a rod, >= 1>;"
            << " (a rod shorter than a Kuhn length is stiffer than a"
            << " freely jointed segment)" << exit(FatalIOError);
    }

    const label minRods = ring ? 3 : 1;
    nRods_ = max
    (
        label(std::round(contourLength_/(kuhnLengthsPerRod_*kuhnLength_))),
        minRods
    );
    rodLength_ = contourLength_/nRods_;
    beadMass_ = massPerLength*rodLength_;

    readFriction(name, dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::polymer::kuhnChain::derivation() const
{
    OStringStream os;
    os  << "from " << origin_.c_str() << ": contour length "
        << contourLength_ << " m, Kuhn length " << kuhnLength_ << " m ("
        << contourLength_/kuhnLength_ << " Kuhn lengths), " << nRods_
        << " rods of " << sizeFactor() << " Kuhn length(s), so the"
        << " chain's <R^2> = L a is " << sizeFactor()
        << " times the polymer's L b; zeta from "
        << frictionOrigin_.c_str();
    return os.str();
}


// ************************************************************************* //
