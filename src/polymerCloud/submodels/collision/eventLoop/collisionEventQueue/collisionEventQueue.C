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

#include "collisionEventQueue.H"

#include <algorithm>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::collisionEventQueue::stamp
(
    const FixedList<label, 4>& beads
) const
{
    label sum = 0;
    for (const label bead : beads)
    {
        if (bead >= 0)
        {
            sum += version_[bead];
        }
    }
    return sum;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::collisionEventQueue::reset(const label nBeads)
{
    events_.clear();
    heap_.clear();
    version_.resize(nBeads);
    version_ = 0;
}


void Foam::polymer::collisionEventQueue::push(event e)
{
    e.stamp = stamp(e.beads);
    heap_.push_back(entry{e.time, label(events_.size())});
    events_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end());
}


bool Foam::polymer::collisionEventQueue::next(event& e)
{
    while (!heap_.empty())
    {
        std::pop_heap(heap_.begin(), heap_.end());
        const event& top = events_[heap_.back().index];
        heap_.pop_back();
        if (stamp(top.beads) == top.stamp)
        {
            e = top;
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
