/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    contactProjection's contact rounds: the crossings of the re-projection's
    paths held apart by contact constraints before any rigid impact zone.

\*---------------------------------------------------------------------------*/

#include "contactProjection.H"
#include "cpuTime.H"

#include <algorithm>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelPair Foam::polymer::contactProjection::rodKey
(
    const labelPair& rod
) const
{
    const label c = chains_.chainOf(rod.first());
    return labelPair(chains_.globalId(c), rod.first() - chains_.start(c));
}


bool Foam::polymer::contactProjection::addContact
(
    const rodCrossingAudit::crossing& crossing,
    const boolList& moved,
    const UList<point>& positionsAfter
)
{
    const label a = chains_.chainOf(crossing.rodA.first());
    const label b = chains_.chainOf(crossing.rodB.first());
    if (zones_.inZone(a) || zones_.inZone(b) || (!moved[a] && !moved[b]))
    {
        return false;
    }

    // A pair that crosses again with its contact held crosses elsewhere
    // along the rods: its next contact is where they cross, and a pair
    // that crosses a third time takes a zone
    label held = 0;
    for (const contactConstraints::contact& other : contacts_)
    {
        held +=
            (other.rodA == crossing.rodA && other.rodB == crossing.rodB)
         || (other.rodA == crossing.rodB && other.rodB == crossing.rodA);
    }
    if (held >= 2)
    {
        return false;
    }

    // Rod A the first by global position (chain's global id, bead in the
    // chain), whatever the processor's order: the same bits in parallel
    const bool swap = rodKey(crossing.rodB) < rodKey(crossing.rodA);
    const labelPair& rodA = swap ? crossing.rodB : crossing.rodA;
    const labelPair& rodB = swap ? crossing.rodA : crossing.rodB;
    const vector shift = swap ? -crossing.shift : crossing.shift;
    contactConstraints::contact added;
    if
    (
        held
      ? !contactConstraints::makeCrossingContact
        (
            rodA, rodB, shift, chains_, positionsAfter, chains_.positions(),
            crossing.fraction, added
        )
      : !contactConstraints::makeContact
        (
            rodA, rodB, shift, chains_, positionsAfter, added
        )
    )
    {
        return false;
    }
    contacts_.append(added);
    contactGroups_.merge(a, b);
    return true;
}


void Foam::polymer::contactProjection::solveContactGroups
(
    const label newContacts,
    boolList& moved,
    const wallModel* wall,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter,
    const scalar time
)
{
    // The groups with a new contact, and the contacts of each (those of
    // chains in zones no longer count: the zones are placed and audited)
    const labelListList groups(contactGroups_.zones(chains_));
    labelList groupOf(chains_.nChains(), -1);
    forAll(groups, g)
    {
        for (const label c : groups[g])
        {
            groupOf[c] = g;
        }
    }
    boolList solve(groups.size(), false);
    List<DynamicList<contactConstraints::contact>> groupContacts(groups.size());
    forAll(contacts_, q)
    {
        const label a = chains_.chainOf(contacts_[q].rodA.first());
        const label b = chains_.chainOf(contacts_[q].rodB.first());
        if (!zones_.inZone(a) && !zones_.inZone(b))
        {
            groupContacts[groupOf[a]].append(contacts_[q]);
            solve[groupOf[a]] = solve[groupOf[a]] || q >= newContacts;
        }
    }

    boolList solved(chains_.nChains(), false);
    forAll(groups, g)
    {
        if (!solve[g])
        {
            continue;
        }

        // The contacts in the order of their rods' keys: the same system,
        // to the bit, whatever order the audit found them in
        DynamicList<contactConstraints::contact>& held = groupContacts[g];
        std::sort
        (
            held.begin(), held.end(),
            [this]
            (
                const contactConstraints::contact& x,
                const contactConstraints::contact& y
            )
            {
                const labelPair xA(rodKey(x.rodA)), yA(rodKey(y.rodA));
                if (xA != yA)
                {
                    return xA < yA;
                }
                return rodKey(x.rodB) < rodKey(y.rodB);
            }
        );

        ++counts_.groupSolves;
        const label iterations = contactSolver_.project
        (
            chains_, groups[g], groupContacts[g], positionsAfter
        );
        if (iterations < 0)
        {
            if (!counts_.groupFailures)
            {
                WarningInFunction
                    << "The contact constraints of " << groups[g].size()
                    << " chains (chain " << chains_.globalId(groups[g][0])
                    << " first) at time " << time << " did not converge:"
                    << " they move in rigid impact zones instead; such"
                    << " groups are counted in the final report" << endl;
            }
            ++counts_.groupFailures;
            for (const contactConstraints::contact& held : groupContacts[g])
            {
                rodCrossingAudit::crossing crossing;
                crossing.rodA = held.rodA;
                crossing.rodB = held.rodB;
                crossing.shift = held.shift;
                mergeCrossing(crossing, moved, time);
            }
            continue;
        }

        // The contacts' velocities, but for the rods' relative ones
        for (const label c : groups[g])
        {
            for (label i = chains_.start(c); i < chains_.end(c); ++i)
            {
                chains_.velocities()[i] = velocitiesAfter[i];
            }
            scalar residual = 0;
            constraint_.correctChainVelocities(chains_, c, residual);
            moved[c] = true;
            solved[c] = true;
        }
    }
    addWallZones(wall, solved, positionsAfter);
}


void Foam::polymer::contactProjection::countContactGroups()
{
    labelList chainsOfRoot(chains_.nChains(), 0);
    label groups = 0;
    for (const labelList& group : contactGroups_.zones(chains_))
    {
        label free = 0;
        for (const label c : group)
        {
            free += !zones_.inZone(c);
        }
        groups += (free > 0);
        counts_.contactChainSteps += free;
    }
    counts_.contactGroups += groups;
    for (const contactConstraints::contact& held : contacts_)
    {
        counts_.contactsHeld +=
            !zones_.inZone(chains_.chainOf(held.rodA.first()))
         && !zones_.inZone(chains_.chainOf(held.rodB.first()));
    }
}


void Foam::polymer::contactProjection::resolveContacts
(
    const rodCrossingAudit& audit,
    boolList& moved,
    const wallModel* wall,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter,
    List<point>& positionsAudited,
    const scalar time
)
{
    contacts_.clear();
    contactGroups_.reset(chains_.nChains());
    for (label round = 0; ; ++round)
    {
        cpuTime timer;
        const boolList rodsToCheck(rodsToAudit(positionsAudited));
        const List<rodCrossingAudit::crossing> found
        (
            audit.check(positionsAfter, chains_.positions(), rodsToCheck)
        );
        counts_.auditSeconds += timer.cpuTimeIncrement();

        // Crossings of chains in zones, or after the last round, merge
        // zones; the zone passes place and audit them
        const label newContacts = contacts_.size();
        for (const rodCrossingAudit::crossing& crossing : found)
        {
            if
            (
                round == maxContactRounds_
             || !addContact(crossing, moved, positionsAfter)
            )
            {
                mergeCrossing(crossing, moved, time);
            }
        }
        if (contacts_.size() == newContacts)
        {
            break;
        }
        solveContactGroups
        (
            newContacts, moved, wall, positionsAfter, velocitiesAfter, time
        );
        counts_.contactSeconds += timer.cpuTimeIncrement();
    }
    countContactGroups();
}


// ************************************************************************* //
