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
    queue_ = std::priority_queue<event>();
    version_.resize(nBeads);
    version_ = 0;
}


void Foam::polymer::collisionEventQueue::push(event e)
{
    e.stamp = stamp(e.beads);
    queue_.push(e);
}


bool Foam::polymer::collisionEventQueue::next(event& e)
{
    while (!queue_.empty())
    {
        e = queue_.top();
        queue_.pop();
        if (stamp(e.beads) == e.stamp)
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
