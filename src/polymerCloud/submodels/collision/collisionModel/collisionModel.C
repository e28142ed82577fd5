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
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(collisionModel)


// * * * * * * * * * * * * * * * * * Report  * * * * * * * * * * * * * * * * //

void Foam::polymer::collisionModel::writeReport(Ostream& os) const
{
    const collisionCounters total = totalCounters_.reduced();

    // The line ends with the audited crossings: scripts anchor on it
    os  << "    rod-rod collisions " << total.events
        << " (max per step " << total.maxEventsPerStep
        << "; colliding pairs " << total.collidingPairs
        << ", a pair counted once a step), event-loop stalls "
        << total.stalls
        << ", crossing-time solves " << total.pairChecks
        << ", rod-edge contacts " << total.edgeContacts
        << ", unresolved events " << total.unresolved
        << ", audited crossings " << total.auditCrossings << nl;
}


// ************************************************************************* //
