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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerCloudSolution::polymerCloudSolution
(
    const dictionary& solution,
    const Foam::zero
)
:
    active_(solution.getOrDefault<bool>("active", true)),
    seed_
    (
        checkedInput::labelAtLeastOrDefault
        (
            solution, "seed", 1, 0,
            "<the noise's seed, a whole number>"
        )
    ),
    rodLengthCheck_
    (
        checkedInput::positiveScalarOrDefault
        (
            solution,
            "rodLengthCheck",
            1e-6,
            "<relative rod-length mismatch accepted at start>"
        )
    ),
    maxNeighbourDisplacement_
    (
        solution.found("maxNeighbourDisplacement", keyType::LITERAL)
      ? checkedInput::positiveScalar
        (
            solution,
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
            solution,
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
            solution,
            "contactTreatment",
            contactTreatmentNames,
            contactTreatmentType::reproject
        )
    ),
    maxContactRounds_
    (
        checkedInput::labelAtLeastOrDefault
        (
            solution,
            "maxContactRounds",
            4,
            0,
            "<most rounds of contact constraints before rigid impact zones,"
            " a whole number; 0: zones at once>"
        )
    ),
    stopWhenEmpty_(solution.getOrDefault<bool>("stopWhenEmpty", false))
{
    checkedInput::onlyKeywords
    (
        solution,
        {
            "active", "seed", "rodLengthCheck",
            "maxNeighbourDisplacement", "maxSubCycles",
            "contactTreatment", "maxContactRounds", "stopWhenEmpty"
        },
        "the cloud's solution"
    );
}


Foam::polymer::polymerCloudSolution::polymerCloudSolution
(
    const dictionary& properties
)
:
    // The solution dictionary or an empty one, not the properties
    // themselves (optionalSubDict's answer), whose other entries are no
    // solution keywords
    polymerCloudSolution
    (
        properties.subOrEmptyDict("solution", keyType::LITERAL),
        Zero
    )
{}


// ************************************************************************* //
