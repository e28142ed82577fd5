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

#include "collisionModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(collisionModel, 0);
    defineRunTimeSelectionTable(collisionModel, dictionary);
} // End namespace polymer
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::collisionModel::collisionModel
(
    const word& type,
    const dictionary& dict
)
:
    countedSubModel<collisionCounters>(type, dict)
{}


// * * * * * * * * * * * * * * * * * Report  * * * * * * * * * * * * * * * * //

void Foam::polymer::collisionModel::writeReport(Ostream& os) const
{
    const collisionCounters total = totalCounters_.reduced();

    os  << "    rod-rod collisions " << total.events
        << " (max per step " << total.maxEventsPerStep
        << "), event-loop stalls " << total.stalls
        << ", crossing-time solves " << total.pairChecks
        << ", audited crossings " << total.auditCrossings << nl;
}


// ************************************************************************* //
