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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Key of a grid cell from its integer coordinates
inline uint64_t cellKey(const int64_t i, const int64_t j, const int64_t k)
{
    const uint64_t mask = (uint64_t(1) << 21) - 1;
    return
        (uint64_t(i) & mask)
      | ((uint64_t(j) & mask) << 21)
      | ((uint64_t(k) & mask) << 42);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::sweptBoxGrid::sweptBoxGrid()
:
    rods_(nullptr),
    imageShift_(),
    imageCode_(),
    box_(),
    cellSize_(1),
    cells_(),
    pairs_(),
    pairShift_(),
    rodPairs_(),
    pairSet_()
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::sweptBoxGrid::buildImages(const UList<vector>& lattice)
{
    // Every combination of -1, 0, +1 per lattice vector, zero first
    imageShift_ = List<vector>(1, Zero);
    imageCode_ = labelList(1, Zero);
    label digit = 1;
    for (const vector& t : lattice)
    {
        const label n = imageShift_.size();
        for (const label sign : {1, -1})
        {
            for (label k = 0; k < n; ++k)
            {
                imageShift_.append(imageShift_[k] + sign*t);
                imageCode_.append(imageCode_[k] + sign*digit);
            }
        }
        digit *= 5;
    }
}


Foam::boundBox Foam::polymer::sweptBoxGrid::entryBox
(
    const label entry
) const
{
    const label nRods = rods_->size();
    const boundBox& box = box_[entry % nRods];
    const vector& shift = imageShift_[entry/nRods];
    return boundBox(box.min() + shift, box.max() + shift);
}


void Foam::polymer::sweptBoxGrid::addPair
(
    const label entryA,
    const label entryB
)
{
    const label nRods = rods_->size();
    label rodA = entryA % nRods, rodB = entryB % nRods;
    label imageA = entryA/nRods, imageB = entryB/nRods;
    if
    (
        rods_->chainId(rodA) > rods_->chainId(rodB)
     || (rods_->chainId(rodA) == rods_->chainId(rodB) && rodA > rodB)
    )
    {
        std::swap(rodA, rodB);
        std::swap(imageA, imageB);
    }

    // The translation of the second rod relative to the first
    const label code = imageCode_[imageB] - imageCode_[imageA];
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

    // Codes of two images differ by -2..2 per lattice vector: 125 values
    const uint64_t key =
        (uint64_t(rodA)*uint64_t(nRods) + uint64_t(rodB))*125u
      + uint64_t(code + 62);

    if (pairSet_.insert(key).second)
    {
        const label pairi = pairs_.size();
        pairs_.append(labelPair(rodA, rodB));
        pairShift_.append(imageShift_[imageB] - imageShift_[imageA]);
        rodPairs_[rodA].push_back(pairi);
        rodPairs_[rodB].push_back(pairi);
    }
}


void Foam::polymer::sweptBoxGrid::insertEntry
(
    const label entry,
    const boundBox& box
)
{
    const int64_t i0 = std::floor(box.min().x()/cellSize_);
    const int64_t j0 = std::floor(box.min().y()/cellSize_);
    const int64_t k0 = std::floor(box.min().z()/cellSize_);
    const int64_t i1 = std::floor(box.max().x()/cellSize_);
    const int64_t j1 = std::floor(box.max().y()/cellSize_);
    const int64_t k1 = std::floor(box.max().z()/cellSize_);

    for (int64_t i = i0; i <= i1; ++i)
    {
        for (int64_t j = j0; j <= j1; ++j)
        {
            for (int64_t k = k0; k <= k1; ++k)
            {
                std::vector<label>& cell = cells_[cellKey(i, j, k)];
                for (const label other : cell)
                {
                    if (entryBox(other).overlaps(box))
                    {
                        addPair(entry, other);
                    }
                }
                if (cell.empty() || cell.back() != entry)
                {
                    cell.push_back(entry);
                }
            }
        }
    }
}


void Foam::polymer::sweptBoxGrid::insert(const label rod)
{
    // Images of a rod are inserted whatever their distance from the
    // chains: the broad phase cost grows by the number of images on
    // periodic meshes only
    const label nRods = rods_->size();
    forAll(imageShift_, image)
    {
        const label entry = rod + image*nRods;
        insertEntry(entry, entryBox(entry));
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
    for (const boundBox& box : box_)
    {
        largest = max(largest, cmptMax(box.span()));
    }
    cellSize_ = max(largest, VSMALL);

    label nImages = 1;
    for (label k = 0; k < lattice.size(); ++k)
    {
        nImages *= 3;
    }
    if (imageShift_.size() != nImages)
    {
        buildImages(lattice);
    }

    cells_.clear();
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
