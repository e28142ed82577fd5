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

#include "constraintModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(constraintModel, 0);
    defineRunTimeSelectionTable(constraintModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::constraintModel::constraintModel
(
    const word& type,
    const dictionary& dict
)
:
    coeffDict_(dict.optionalSubDict(type + "Coeffs")),
    counters_(),
    failuresReported_(0),
    maxFailureReports_
    (
        coeffDict_.getOrDefault<label>("maxFailureReports", 20)
    )
{}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::constraintModel::reportFailure
(
    const polymerChains& chains,
    const label chaini,
    const word& stage,
    const scalar time,
    const scalar residual,
    const label iterations
) const
{
    if (failuresReported_ < maxFailureReports_)
    {
        WarningInFunction
            << stage << " constraint did not converge for chain "
            << chains.globalId(chaini) << " (" << chains.type(chaini).name()
            << ") at time " << time << ": residual " << residual
            << " after " << iterations << " iterations" << endl;

        if (failuresReported_ + 1 == maxFailureReports_)
        {
            Info<< "    (further failures are counted in the statistics"
                << " without a message)" << endl;
        }
    }
    ++failuresReported_;
}


// ************************************************************************* //
