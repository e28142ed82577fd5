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
    paths held apart, and its beads and rods held off the walls, by contact
    constraints before any rigid impact zone.

\*---------------------------------------------------------------------------*/

#include "contactProjection.H"
#include "cpuTimeCxx.H"

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


Foam::label Foam::polymer::contactProjection::heldContacts
(
    const labelPair& rodA,
    const labelPair& rodB
) const
{
    label held = 0;
    for (const contactConstraints::contact& other : contacts_)
    {
        held +=
            (other.rodA == rodA && other.rodB == rodB)
         || (other.rodA == rodB && other.rodB == rodA);
    }
    return held;
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
    const label held = heldContacts(crossing.rodA, crossing.rodB);
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


bool Foam::polymer::contactProjection::addEdgeContacts
(
    const wallModel& wall,
    const label chaini,
    const UList<point>& positionsAfter,
    const bool lastRound,
    bool& added
)
{
    const wallEdges& edges = wall.edges();
    for
    (
        const edgeMeeting& meeting
      : edgeMeetings
        (
            wall, labelList(1, chaini), positionsAfter, edgeClearances_
        )
    )
    {
        // A rod that meets the walls again with its contacts held: a
        // second contact, a zone at the third meeting
        contactConstraints::contact atEdge;
        if
        (
            lastRound || heldContacts(meeting.rod, meeting.rod) >= 2
         || !contactConstraints::makeEdgeContact
            (
                meeting.rod,
                edges.start(meeting.edge) - meeting.shift,
                edges.end(meeting.edge) - meeting.shift,
                chains_, positionsAfter, atEdge
            )
        )
        {
            return false;
        }
        contacts_.append(atEdge);
        added = true;
    }
    return true;
}


bool Foam::polymer::contactProjection::addBeadContacts
(
    const wallModel& wall,
    const label chaini,
    const UList<point>& positionsAfter,
    const bool lastRound,
    bool& added
)
{
    const List<point>& x = chains_.positions();
    for (label i = chains_.start(chaini); i < chains_.end(chaini); ++i)
    {
        // A path shorter than the bead's clearance where the events left
        // it meets no wall (as predict would find): most of the chains'
        // paths are short corrections of their rods' lengths
        const vector path = x[i] - positionsAfter[i];
        wallModel::impact hit;
        if
        (
            (
                wallClearances_.size()
             && mag(path) < wallClearances_[i]
            )
         || !wall.predict(positionsAfter[i], path, 1, hit)
        )
        {
            continue;
        }

        // A bead that meets the wall again with its contact held: a
        // second contact where it meets it now, a zone at the third
        // meeting; a path across a patch that is not a rebound wall (an
        // outlet's, say) is no wall's to hold
        const labelPair bead(i, i);
        contactConstraints::contact atWall;
        if
        (
            lastRound || heldContacts(bead, bead) >= 2
         || wall.interaction(hit.patch) != wallModel::interactionType::rebound
         || !contactConstraints::makeWallContact
            (
                i, positionsAfter[i] + hit.time*path, hit.normal,
                chains_, positionsAfter, atWall
            )
        )
        {
            return false;
        }
        contacts_.append(atWall);
        added = true;
    }
    return true;
}


bool Foam::polymer::contactProjection::addWallContacts
(
    const wallModel& wall,
    const boolList& chainsToCheck,
    const UList<point>& positionsAfter,
    const bool lastRound
)
{
    const bool edges = wallEdges_ && wall.edges().size();
    bool anyAdded = false;
    forAll(chainsToCheck, c)
    {
        if (!chainsToCheck[c] || zones_.inZone(c))
        {
            continue;
        }
        bool added = false;
        if
        (
            (
                edges
             && !addEdgeContacts(wall, c, positionsAfter, lastRound, added)
            )
         || !addBeadContacts(wall, c, positionsAfter, lastRound, added)
        )
        {
            zones_.add(c);
            continue;
        }
        if (added)
        {
            contactGroups_.add(c);
            anyAdded = true;
        }
    }
    return anyAdded;
}


void Foam::polymer::contactProjection::solveContactGroups
(
    const label newContacts,
    boolList& moved,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter,
    const scalar time,
    boolList& solved
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

    solved = false;
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
                if (contactConstraints::isWallContact(held))
                {
                    zones_.add(chains_.chainOf(held.rodA.first()));
                    continue;
                }
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
}


void Foam::polymer::contactProjection::countContactGroups()
{
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
        const bool free =
            !zones_.inZone(chains_.chainOf(held.rodA.first()))
         && !zones_.inZone(chains_.chainOf(held.rodB.first()));
        counts_.contactsHeld += free;
        counts_.wallContactsHeld +=
            free && contactConstraints::isWallContact(held);
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

    // The chains whose paths the walls have not seen: the projected ones,
    // then those each round solves again
    boolList chainsToCheck(moved);
    for (label round = 0; ; ++round)
    {
        const bool lastRound = (round == maxContactRounds_);
        const label newContacts = contacts_.size();
        cpuTimeCxx timer;
        if (uncrossable_)
        {
            const boolList rodsToCheck(rodsToAudit(positionsAudited));
            const List<rodCrossingAudit::crossing> found
            (
                audit.check(positionsAfter, chains_.positions(), rodsToCheck)
            );

            // Crossings of chains in zones, or after the last round, merge
            // zones; the zone passes place and audit them
            for (const rodCrossingAudit::crossing& crossing : found)
            {
                if (lastRound || !addContact(crossing, moved, positionsAfter))
                {
                    mergeCrossing(crossing, moved, time);
                }
            }
        }
        if (wall && wall->active())
        {
            addWallContacts(*wall, chainsToCheck, positionsAfter, lastRound);
        }
        counts_.auditSeconds += timer.cpuTimeIncrement();
        if (contacts_.size() == newContacts)
        {
            break;
        }
        solveContactGroups
        (
            newContacts, moved, positionsAfter, velocitiesAfter, time,
            chainsToCheck
        );
        counts_.contactSeconds += timer.cpuTimeIncrement();
    }
    countContactGroups();
}


// ************************************************************************* //
