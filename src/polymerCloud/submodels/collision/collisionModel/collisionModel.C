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

    os  << "    rod-rod collisions " << total.events
        << " (max per step " << total.maxEventsPerStep
        << "), event-loop stalls " << total.stalls
        << ", crossing-time solves " << total.pairChecks
        << ", rod-edge contacts " << total.edgeContacts
        << ", unresolved events " << total.unresolved
        << ", audited crossings " << total.auditCrossings
        << ", colliding pairs " << total.collidingPairs
        << " (summed step by step: a pair's collisions in one step"
        << " counted once)" << nl;
}


// ************************************************************************* //
