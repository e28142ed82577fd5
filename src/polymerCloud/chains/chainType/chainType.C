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

#include "chainType.H"
#include "kuhnChain.H"
#include "checkedInput.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::polymer::chainType::boltzmannConstant = 1.380649e-23;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::chainType::checkKeywords(const dictionary& dict) const
{
    // Both forms' keywords: a misspelt optional one would go unnoticed
    static const char* const valid[] =
    {
        "nBeads", "rodLength", "beadMass", "friction", "kT", "temperature",
        "ring", "basePairs", "contourLength", "kuhnLength", "massPerLength",
        "kuhnLengthsPerRod", "beadRadius", "viscosity", "frictionPerLength"
    };

    for (const entry& e : dict)
    {
        if
        (
            std::find(std::begin(valid), std::end(valid), e.keyword())
         == std::end(valid)
        )
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << e.keyword() << "' in chain type '"
                << name_ << "' of " << dict.name() << nl
                << "    expected one of:";
            for (const char* keyword : valid)
            {
                FatalIOError << ' ' << keyword;
            }
            FatalIOError << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::chainType::chainType(const word& name, const dictionary& dict)
:
    name_(name),
    nBeads_(0),
    rodLength_(0),
    beadMass_(0),
    friction_(0),
    kT_(0),
    ring_(dict.getOrDefault<bool>("ring", false)),
    derivation_()
{
    checkKeywords(dict);

    if (kuhnChain::describes(dict))
    {
        const kuhnChain polymer(name, dict, ring_);
        nBeads_ = ring_ ? polymer.nRods() : polymer.nRods() + 1;
        rodLength_ = polymer.rodLength();
        beadMass_ = polymer.beadMass();
        friction_ = polymer.friction();
        derivation_ = polymer.derivation();
    }
    else
    {
        // The contour form's keywords mean nothing without its contour
        for
        (
            const word contour
          : {
                "kuhnLength", "massPerLength", "kuhnLengthsPerRod",
                "beadRadius", "viscosity", "frictionPerLength"
            }
        )
        {
            if (dict.found(contour, keyType::LITERAL))
            {
                FatalIOErrorInFunction(dict)
                    << "Chain type '" << name_ << "' in " << dict.name()
                    << " is given by nBeads, rodLength, beadMass and"
                    << " friction, and also has '" << contour << "', a"
                    << " keyword of the contour form" << nl
                    << "    expected: either basePairs or contourLength with"
                    << " kuhnLength, or nBeads, rodLength, beadMass and"
                    << " friction"
                    << exit(FatalIOError);
            }
        }
        nBeads_ =
            checkedInput::labelAtLeast(dict, "nBeads", 2, "<beads per chain>");
        rodLength_ =
            checkedInput::positiveScalar(dict, "rodLength", "<rod length a>");
        beadMass_ =
            checkedInput::positiveScalar(dict, "beadMass", "<bead mass m>");
        friction_ = checkedInput::positiveScalar
        (
            dict, "friction", "<bead friction coefficient zeta>"
        );
    }

    const bool hasKT = checkedInput::firstOfTwo
    (
        dict, "Chain type '" + name_ + "'", "kT", "temperature",
        "kT <thermal energy>; or temperature <T in K>;"
    );
    kT_ =
        hasKT
      ? checkedInput::positiveScalar(dict, "kT", "<thermal energy kT>")
      : boltzmannConstant
       *checkedInput::positiveScalar(dict, "temperature", "<T in K>");

    if (ring_ && nBeads_ < 3)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'nBeads' in " << dict.name() << " is " << nBeads_
            << " for a ring" << nl
            << "    expected: nBeads <integer >= 3>; when ring is true"
            << exit(FatalIOError);
    }
}


Foam::polymer::chainType::chainType
(
    const word& name,
    const label nBeads,
    const scalar rodLength,
    const scalar beadMass,
    const scalar friction,
    const scalar kT,
    const bool ring
)
:
    name_(name),
    nBeads_(nBeads),
    rodLength_(rodLength),
    beadMass_(beadMass),
    friction_(friction),
    kT_(kT),
    ring_(ring),
    derivation_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::chainType::writeSummary(Ostream& os) const
{
    if (!derivation_.empty())
    {
        os  << name_ << ": " << derivation_.c_str() << nl << "    ";
    }
    os  << name_ << ": " << (ring_ ? "ring" : "open chain") << " of "
        << nBeads_ << " beads, a " << rodLength_ << ", m " << beadMass_
        << ", zeta " << friction_ << ", kT " << kT_
        << " (m/zeta " << inertialTime()
        << ", zeta a^2/4kT " << rodRelaxationTime() << ')';
}


// ************************************************************************* //
