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

#include "sweptBoxGrid.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::sweptBoxGrid::sweptBoxGrid()
:
    rods_(nullptr),
    imageShift_(),
    imageCode_(),
    box_(),
    bounds_(boundBox::invertedBox),
    region_(boundBox::invertedBox),
    cellSize_(1),
    nCells_(Zero),
    cells_(),
    pairs_(),
    pairShift_(),
    rodPairs_(),
    pairSet_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::sweptBoxGrid::buildImages(const UList<vector>& lattice)
{
    // Every combination of -2..2 per lattice vector, zero first
    imageShift_ = List<vector>(1, Zero);
    imageCode_ = labelList(1, Zero);
    label digit = 1;
    for (const vector& t : lattice)
    {
        const label n = imageShift_.size();
        for (const label times : {1, -1, 2, -2})
        {
            for (label k = 0; k < n; ++k)
            {
                imageShift_.append(imageShift_[k] + times*t);
                imageCode_.append(imageCode_[k] + times*digit);
            }
        }
        digit *= 5;
    }
}


void Foam::polymer::sweptBoxGrid::addPair
(
    label rodA,
    label rodB,
    label code,
    vector shift
)
{
    if
    (
        rods_->chainId(rodA) > rods_->chainId(rodB)
     || (rods_->chainId(rodA) == rods_->chainId(rodB) && rodA > rodB)
    )
    {
        std::swap(rodA, rodB);
        code = -code;
        shift = -shift;
    }

    if (code == 0 && rods_->adjacent(rodA, rodB))
    {
        // Rods sharing a bead always meet there: no crossing to detect
        return;
    }
    if (rodA == rodB)
    {
        // A rod and its own image: never closer than a period
        return;
    }

    // Translations of -2..2 per lattice vector: 125 codes
    const label nRods = rods_->size();
    const uint64_t key =
        (uint64_t(rodA)*uint64_t(nRods) + uint64_t(rodB))*125u
      + uint64_t(code + 62);

    if (pairSet_.insert(key).second)
    {
        const label pairi = pairs_.size();
        pairs_.append(labelPair(rodA, rodB));
        pairShift_.append(shift);
        rodPairs_[rodA].push_back(pairi);
        rodPairs_[rodB].push_back(pairi);
    }
}


void Foam::polymer::sweptBoxGrid::layCells(const label nRods)
{
    // Cells of the largest box's span over the boxes' bounds, coarsened
    // where the rods are sparse so that the cells are at most eight a rod
    region_ = bounds_;
    if (!nRods)
    {
        region_ = boundBox(Zero, Zero);
    }
    const vector span(region_.span());
    const scalar maxCells = max(64, 8*nRods);
    cellSize_ = max(cellSize_, cmptMax(span)/std::cbrt(maxCells));
    for (;;)
    {
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            nCells_[d] = label(span[d]/cellSize_) + 1;
        }
        if (scalar(nCells_.x())*nCells_.y()*nCells_.z() <= maxCells)
        {
            break;
        }
        cellSize_ *= 1.25;
    }

    const label n = nCells_.x()*nCells_.y()*nCells_.z();
    if (label(cells_.size()) < n)
    {
        cells_.resize(n);
    }
    for (label i = 0; i < n; ++i)
    {
        cells_[i].clear();
    }
}


template<class CellOp>
void Foam::polymer::sweptBoxGrid::forCells
(
    const boundBox& box,
    const CellOp& op
) const
{
    // A box reaching beyond the laid region (a grown box, a translated
    // one) takes the edge cells there: two boxes that overlap still share
    // a cell, and the exact box test decides
    label lower[3], upper[3];
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        const scalar origin = region_.min()[d];
        lower[d] = min
        (
            max(label(std::floor((box.min()[d] - origin)/cellSize_)), 0),
            nCells_[d] - 1
        );
        upper[d] = min
        (
            max(label(std::floor((box.max()[d] - origin)/cellSize_)), 0),
            nCells_[d] - 1
        );
    }

    for (label i = lower[0]; i <= upper[0]; ++i)
    {
        for (label j = lower[1]; j <= upper[1]; ++j)
        {
            for (label k = lower[2]; k <= upper[2]; ++k)
            {
                op((i*nCells_.y() + j)*nCells_.z() + k);
            }
        }
    }
}


void Foam::polymer::sweptBoxGrid::query
(
    const label rod,
    const label image
)
{
    const vector& shift = imageShift_[image];
    const boundBox box(box_[rod].min() + shift, box_[rod].max() + shift);
    if (!box.overlaps(bounds_))
    {
        // No rod's box out there
        return;
    }

    forCells
    (
        box,
        [&](const label celli)
        {
            for (const label other : cells_[celli])
            {
                // rod + shift meets other: other - shift is rod's partner
                if (box_[other].overlaps(box))
                {
                    addPair(rod, other, -imageCode_[image], -shift);
                }
            }
        }
    );
}


void Foam::polymer::sweptBoxGrid::insert(const label rod)
{
    // The grid holds the rods' own boxes only. A rod's images are looked
    // up in it, but only those reaching the rods' bounds; every pair
    // (rod, other + translation) is found once, by the rod inserted
    // second
    bounds_.add(box_[rod]);
    forCells
    (
        box_[rod],
        [&](const label celli)
        {
            std::vector<label>& cell = cells_[celli];
            if (cell.empty() || cell.back() != rod)
            {
                cell.push_back(rod);
            }
        }
    );

    // Translations that cannot bring the box to the bounds, with a margin
    // over the round-off of query's own test, are passed over here: most
    // of them on a dense periodic mesh, and the test in query is the one
    // that decides
    const boundBox& box = box_[rod];
    const scalar margin =
        1e-9*(cmptMax(cmptMag(bounds_.min())) + cmptMax(cmptMag(bounds_.max())));
    const vector reachMin(bounds_.min() - box.max() - vector::uniform(margin));
    const vector reachMax(bounds_.max() - box.min() + vector::uniform(margin));
    forAll(imageShift_, image)
    {
        const vector& shift = imageShift_[image];
        if
        (
            shift.x() >= reachMin.x() && shift.x() <= reachMax.x()
         && shift.y() >= reachMin.y() && shift.y() <= reachMax.y()
         && shift.z() >= reachMin.z() && shift.z() <= reachMax.z()
        )
        {
            query(rod, image);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::sweptBoxGrid::build
(
    const chainRods& rods,
    List<boundBox>&& boxes,
    const UList<vector>& lattice
)
{
    rods_ = &rods;

    box_.transfer(boxes);
    scalar largest = 0;
    bounds_ = boundBox::invertedBox;
    for (const boundBox& box : box_)
    {
        largest = max(largest, cmptMax(box.span()));
        bounds_.add(box);
    }
    cellSize_ = max(largest, VSMALL);

    label nImages = 1;
    for (label k = 0; k < lattice.size(); ++k)
    {
        nImages *= 5;
    }
    if (imageShift_.size() != nImages)
    {
        buildImages(lattice);
    }

    layCells(box_.size());
    pairs_.clear();
    pairShift_.clear();
    pairSet_.clear();
    rodPairs_.assign(rods.size(), std::vector<label>());
    forAll(box_, rod)
    {
        insert(rod);
    }
}


void Foam::polymer::sweptBoxGrid::grow(const label rod, const boundBox& box)
{
    if (!box_[rod].contains(box))
    {
        box_[rod].add(box);
        insert(rod);
    }
}


// ************************************************************************* //
