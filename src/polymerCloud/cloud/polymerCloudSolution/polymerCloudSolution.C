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

#include "polymerCloudSolution.H"
#include "checkedInput.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * //

const Foam::Enum
<
    Foam::polymer::polymerCloudSolution::contactTreatmentType
>
Foam::polymer::polymerCloudSolution::contactTreatmentNames
({
    { contactTreatmentType::hierarchical, "hierarchical" },
    { contactTreatmentType::reproject, "reproject" },
});


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * * //

namespace
{

//- The solution sub-dictionary, or an empty one named after it; not the
//  properties themselves (optionalSubDict's answer), whose other entries
//  are no solution keywords
Foam::dictionary solutionDict(const Foam::dictionary& properties)
{
    return properties.subOrEmptyDict("solution", Foam::keyType::LITERAL);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerCloudSolution::polymerCloudSolution
(
    const dictionary& properties
)
:
    active_
    (
        solutionDict(properties)
       .getOrDefault<bool>("active", true)
    ),
    seed_
    (
        checkedInput::labelAtLeastOrDefault
        (
            solutionDict(properties), "seed", 1, 0,
            "<the noise's seed, a whole number>"
        )
    ),
    rodLengthCheck_
    (
        checkedInput::positiveScalarOrDefault
        (
            solutionDict(properties),
            "rodLengthCheck",
            1e-6,
            "<relative rod-length mismatch accepted at start>"
        )
    ),
    maxNeighbourDisplacement_
    (
        solutionDict(properties).found
        (
            "maxNeighbourDisplacement", keyType::LITERAL
        )
      ? checkedInput::positiveScalar
        (
            solutionDict(properties),
            "maxNeighbourDisplacement",
            "<largest predicted displacement of neighbouring beads in a"
            " polymer step, in rod lengths>"
        )
      : 0
    ),
    maxSubCycles_
    (
        checkedInput::labelAtLeastOrDefault
        (
            solutionDict(properties),
            "maxSubCycles",
            64,
            1,
            "<most polymer steps per flow step>"
        )
    ),
    contactTreatment_
    (
        checkedInput::enumOrDefault
        (
            solutionDict(properties),
            "contactTreatment",
            contactTreatmentNames,
            contactTreatmentType::reproject
        )
    ),
    maxContactRounds_
    (
        checkedInput::labelAtLeastOrDefault
        (
            solutionDict(properties),
            "maxContactRounds",
            4,
            0,
            "<most rounds of contact constraints before rigid impact zones,"
            " a whole number; 0: zones at once>"
        )
    )
{
    if (properties.isDict("solution"))
    {
        checkedInput::onlyKeywords
        (
            properties.subDict("solution"),
            {
                "active", "seed", "rodLengthCheck",
                "maxNeighbourDisplacement", "maxSubCycles",
                "contactTreatment", "maxContactRounds"
            },
            "the cloud's solution"
        );
    }
}


// ************************************************************************* //
