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

#include "beadCells.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::beadCells::beadCells()
:
    cells_(),
    start_(),
    layout_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList& Foam::beadCells::update(const polymerChains& chains)
{
    if (layout_ == chains.layoutVersion() && cells_.size() == chains.nBeads())
    {
        return cells_;
    }

    labelList cells(chains.nBeads(), -1);
    Map<label> start(2*chains.nChains());
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label id = chains.globalId(c);
        start.insert(id, chains.start(c));

        const auto old = start_.cfind(id);
        if (old.found())
        {
            for (label k = 0; k < chains.size(c); ++k)
            {
                cells[chains.start(c) + k] = cells_[old.val() + k];
            }
        }
    }

    cells_.transfer(cells);
    start_.transfer(start);
    layout_ = chains.layoutVersion();
    return cells_;
}


// ************************************************************************* //
