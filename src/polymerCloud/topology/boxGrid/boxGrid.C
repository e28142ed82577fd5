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

void Foam::polymer::boxGrid::range
(
    const boundBox& box,
    FixedList<label, 3>& lower,
    FixedList<label, 3>& upper
) const
{
    // The clamped floor, without a call to floor: x truncates to floor(x)
    // for 0 <= x < n - 1. By multiplication, monotone in the coordinate as
    // a division is: boxes that overlap share a cell
    const auto cell = [this](const scalar x, const direction d)
    {
        const scalar last = nCells_[d] - 1;
        return x <= 0 ? label(0) : x >= last ? label(last) : label(x);
    };
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar origin = region_.min()[d];
        lower[d] = cell((box.min()[d] - origin)*cellsPerLength_, d);
        upper[d] = cell((box.max()[d] - origin)*cellsPerLength_, d);
    }
}


template<class Op>
void Foam::polymer::boxGrid::forEachCell
(
    const UList<boundBox>& boxes,
    const Op& op
) const
{
    forAll(boxes, boxi)
    {
        FixedList<label, 3> lower, upper;
        range(boxes[boxi], lower, upper);
        for (label i = lower[0]; i <= upper[0]; ++i)
        {
            for (label j = lower[1]; j <= upper[1]; ++j)
            {
                for (label k = lower[2]; k <= upper[2]; ++k)
                {
                    op((i*nCells_[1] + j)*nCells_[2] + k, boxi);
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::boxGrid::boxGrid(const UList<boundBox>& boxes)
:
    region_(boundBox::invertedBox),
    cellSize_(VSMALL),
    nCells_(label(1)),
    cellsPerLength_(1),
    cells_(),
    stamp_(boxes.size(), -1),
    query_(0)
{
    for (const boundBox& box : boxes)
    {
        region_.add(box);
        cellSize_ = max(cellSize_, cmptMax(box.span()));
    }
    if (boxes.empty())
    {
        region_ = boundBox(Zero, Zero);
    }

    // Half the widest box's span, coarsened to at most eight cells a box:
    // a box then spans more cells, but each cell is smaller and holds
    // fewer boxes far from the box asked about, which a query would visit
    // only to pass over. The coarsening starts from the region's volume
    // (its longest side over the cube root of the cells would make the
    // cells of a long channel several times too large)
    cellSize_ *= 0.5;
    const vector span(region_.span());
    const scalar maxCells = max(64, 8*boxes.size());
    cellSize_ = max
    (
        cellSize_,
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
    labelList sizes(nCells_[0]*nCells_[1]*nCells_[2], 0);
    forEachCell
    (
        boxes,
        [&](const label celli, const label)
        {
            ++sizes[celli];
        }
    );
    cells_.setSize(sizes);
    sizes = 0;
    forEachCell
    (
        boxes,
        [&](const label celli, const label boxi)
        {
            cells_[celli][sizes[celli]++] = boxi;
        }
    );
}


// ************************************************************************* //
