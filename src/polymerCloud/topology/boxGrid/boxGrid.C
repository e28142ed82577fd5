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

#include "boxGrid.H"

#include <cmath>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::boxGrid::cellOf
(
    const point& p,
    FixedList<label, 3>& cell
) const
{
    // The clamped floor, without a call to floor: x truncates to floor(x)
    // for 0 <= x < n - 1. By multiplication, monotone in the coordinate as
    // a division is: a lower corner between two points lies in the cells
    // between theirs
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar x = (p[d] - region_.min()[d])*cellsPerLength_;
        const scalar last = nCells_[d] - 1;
        cell[d] = x <= 0 ? label(0) : x >= last ? label(last) : label(x);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::boxGrid::boxGrid(const UList<boundBox>& boxes)
:
    region_(boundBox::invertedBox),
    cellSize_(VSMALL),
    nCells_(label(1)),
    cellsPerLength_(1),
    reach_(0),
    cells_()
{
    scalar widest = 0;
    for (const boundBox& box : boxes)
    {
        region_.add(box);
        widest = max(widest, cmptMax(box.span()));
    }
    if (boxes.empty())
    {
        region_ = boundBox(Zero, Zero);
    }

    // The span as computed, and a corner less it, may be off by the
    // round-off of the coordinates; the margin is far larger, and only
    // adds cells to a scan where a corner lies that close to a cell's face
    reach_ =
        widest
      + 1e-9
       *(
            widest + cmptMax(cmptMag(region_.min()))
          + cmptMax(cmptMag(region_.max()))
        )
      + VSMALL;

    // The widest box's span, coarsened to at most eight cells a box. The
    // coarsening starts from the region's volume (its longest side over
    // the cube root of the cells would make the cells of a long channel
    // several times too large)
    const vector span(region_.span());
    const scalar maxCells = max(64, 8*boxes.size());
    cellSize_ = max
    (
        max(widest, VSMALL),
        max
        (
            std::cbrt(span.x()*span.y()*span.z()/maxCells),
            cmptMax(span)/maxCells
        )
    );
    for (;;)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            nCells_[d] = label(span[d]/cellSize_) + 1;
        }
        if (scalar(nCells_[0])*nCells_[1]*nCells_[2] <= maxCells)
        {
            break;
        }
        cellSize_ *= 1.25;
    }
    cellsPerLength_ = 1/cellSize_;

    // The boxes of each cell in one packed list, in the boxes' order:
    // counted, then placed (two allocations, not one a cell)
    labelList cellOfBox(boxes.size());
    labelList sizes(nCells_[0]*nCells_[1]*nCells_[2], 0);
    forAll(boxes, boxi)
    {
        FixedList<label, 3> cell;
        cellOf(boxes[boxi].min(), cell);
        cellOfBox[boxi] = (cell[0]*nCells_[1] + cell[1])*nCells_[2] + cell[2];
        ++sizes[cellOfBox[boxi]];
    }
    cells_.setSize(sizes);
    sizes = 0;
    forAll(boxes, boxi)
    {
        const label celli = cellOfBox[boxi];
        cells_[celli][sizes[celli]++] = boxi;
    }
}


// ************************************************************************* //
