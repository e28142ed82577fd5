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

#include "rodBoxPairs.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::rodBoxPairs::rodBoxPairs()
:
    rods_(nullptr),
    boxes_(nullptr),
    pairs_(nullptr),
    shifts_(nullptr)
{}


Foam::polymer::rodBoxPairs::rodBoxPairs
(
    const UList<labelPair>& rods,
    const UList<boundBox>& boxes,
    const UList<labelPair>& pairs,
    const UList<vector>& shifts
)
:
    rods_(&rods),
    boxes_(&boxes),
    pairs_(&pairs),
    shifts_(&shifts)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::rodBoxPairs::clearance
(
    const label rodi,
    const UList<point>& positions
) const
{
    // The rod's segment lies in the box of its two beads: its depth is
    // theirs
    const boundBox& box = (*boxes_)[rodi];
    scalar depth = GREAT;
    for (const label bead : {(*rods_)[rodi].first(), (*rods_)[rodi].second()})
    {
        const point& p = positions[bead];
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            depth = min(depth, min(p[d] - box.min()[d], box.max()[d] - p[d]));
        }
    }
    return depth;
}


Foam::boolList Foam::polymer::rodBoxPairs::heldApart
(
    const UList<labelPair>& rods,
    const UList<point>& positions,
    const UList<scalar>& reach
) const
{
    if (!valid() || rods != *rods_ || boxes_->size() != rods.size())
    {
        return boolList();
    }

    // Two rods of an unlisted pair have boxes apart by a gap g >= 0 along
    // an axis, so their distance is at least g + clearance(a) +
    // clearance(b), more than reach(a) + reach(b) where each rod's reach
    // is less than its depth. The margin, on the scale of the boxes'
    // coordinates (which bounds the rods' lengths), is far above the
    // round-off of the depths and of the audit's contacts (1e-10 of the
    // rods' lengths)
    scalar scale = 0;
    for (const boundBox& box : *boxes_)
    {
        scale = max
        (
            scale,
            max(cmptMax(cmptMag(box.min())), cmptMax(cmptMag(box.max())))
        );
    }
    const scalar margin = 1e-9*scale + VSMALL;
    boolList held(rods.size());
    forAll(rods, rodi)
    {
        const scalar depth = clearance(rodi, positions);
        held[rodi] =
            depth >= 0 && (reach[rodi] == 0 || reach[rodi] + margin < depth);
    }
    return held;
}


// ************************************************************************* //
