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
#include "boxesMeet.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The empty slot of the pairs' key table
constexpr uint64_t noKey = ~uint64_t(0);

inline uint64_t keyHash(const uint64_t key)
{
    const uint64_t h = key*0x9E3779B97F4A7C15ull;
    return h ^ (h >> 29);
}

} // End anonymous namespace

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::sweptBoxGrid::sweptBoxGrid()
:
    rods_(nullptr),
    imageShift_(),
    imageCode_(),
    latticeAxis_(),
    latticeStep_(),
    imageOfCode_(),
    reachingImages_(),
    box_(),
    firstCell_(),
    bounds_(boundBox::invertedBox),
    region_(boundBox::invertedBox),
    cellSize_(1),
    cellsPerLength_(1),
    nCells_(Zero),
    cells_(),
    pairs_(),
    pairShift_(),
    rodPairs_(),
    pairKeys_(),
    newPairs_(),
    met_(),
    nEntries_(0)
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

    // Lattice vectors along distinct axes (exact zeros elsewhere, as
    // blockMesh's cyclic boxes give) have their images found per axis
    labelList axes(lattice.size(), -1);
    bool aligned = true;
    forAll(lattice, d)
    {
        label nonZero = 0;
        for (direction a = 0; a < vector::nComponents; ++a)
        {
            if (lattice[d][a] != 0)
            {
                axes[d] = a;
                ++nonZero;
            }
        }
        aligned = aligned && nonZero == 1 && !axes.found(axes[d], d + 1);
    }
    latticeAxis_ = aligned ? axes : labelList();
    latticeStep_.setSize(latticeAxis_.size());
    forAll(latticeAxis_, d)
    {
        latticeStep_[d] = lattice[d][latticeAxis_[d]];
    }

    const label largest = (digit - 1)/2;
    imageOfCode_ = labelList(digit, -1);
    forAll(imageCode_, image)
    {
        imageOfCode_[imageCode_[image] + largest] = image;
    }
}


bool Foam::polymer::sweptBoxGrid::newPairKey(const uint64_t key)
{
    // Linear probing, at most half full
    const size_t nKeys = pairs_.size() + newPairs_.size();
    if (2*(nKeys + 1) > pairKeys_.size())
    {
        std::vector<uint64_t> keys(max(size_t(64), 2*pairKeys_.size()), noKey);
        std::swap(keys, pairKeys_);
        const size_t mask = pairKeys_.size() - 1;
        for (const uint64_t k : keys)
        {
            if (k != noKey)
            {
                size_t i = keyHash(k) & mask;
                while (pairKeys_[i] != noKey)
                {
                    i = (i + 1) & mask;
                }
                pairKeys_[i] = k;
            }
        }
    }

    const size_t mask = pairKeys_.size() - 1;
    size_t i = keyHash(key) & mask;
    while (pairKeys_[i] != noKey)
    {
        if (pairKeys_[i] == key)
        {
            return false;
        }
        i = (i + 1) & mask;
    }
    pairKeys_[i] = key;
    return true;
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

    if (newPairKey(key))
    {
        newPairs_.append(newPair{key, labelPair(rodA, rodB), shift});
    }
}


void Foam::polymer::sweptBoxGrid::listNewPairs()
{
    // The look-ups meet the partners in the order of the cells they scan,
    // which changes with the cells' size. The pairs' order orders the
    // first predictions, and with them the events at one time, so a run
    // would depend on the grid's cells; in the order of their keys (the
    // rods' indices, then the translation) it depends on the rods alone
    std::sort
    (
        newPairs_.begin(),
        newPairs_.end(),
        [](const newPair& a, const newPair& b) { return a.key < b.key; }
    );
    for (const newPair& p : newPairs_)
    {
        const label pairi = pairs_.size();
        pairs_.append(p.rods);
        pairShift_.append(p.shift);
        rodPairs_[p.rods.first()].push_back(pairi);
        rodPairs_[p.rods.second()].push_back(pairi);
    }
    newPairs_.clear();
}


void Foam::polymer::sweptBoxGrid::layCells(const label nRods)
{
    // Cells of the largest box's span over the boxes' bounds, coarsened
    // where the rods are sparse so that the cells are at most eight a rod,
    // starting from the bounds' volume (their longest side over the cube
    // root of the cells would make the cells of a long channel several
    // times too large)
    region_ = bounds_;
    if (!nRods)
    {
        region_ = boundBox(Zero, Zero);
    }
    const vector span(region_.span());
    const scalar maxCells = max(64, 8*nRods);
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
        if (scalar(nCells_.x())*nCells_.y()*nCells_.z() <= maxCells)
        {
            break;
        }
        cellSize_ *= 1.25;
    }
    cellsPerLength_ = 1/cellSize_;

    const label n = nCells_.x()*nCells_.y()*nCells_.z();
    if (label(cells_.size()) < n)
    {
        cells_.resize(n);
    }
    for (label i = 0; i < n; ++i)
    {
        cells_[i].clear();
    }
    nEntries_ = 0;
}


void Foam::polymer::sweptBoxGrid::cellRange
(
    const boundBox& box,
    Vector<label>& lower,
    Vector<label>& upper
) const
{
    // A box reaching beyond the laid region (a grown box, a translated
    // one) takes the edge cells there: two boxes that overlap still share
    // a cell, and the exact box test decides. The clamped floor, without
    // a call to floor: x truncates to floor(x) for 0 <= x < n - 1
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


void Foam::polymer::sweptBoxGrid::reachingImages
(
    const boundBox& box,
    DynamicList<label>& images
) const
{
    // Translations that cannot bring the box to the bounds, with a margin
    // over the round-off of query's own test, are passed over: most of
    // them on a dense periodic mesh, and the test in query is the one
    // that decides
    const scalar margin =
        1e-9*(cmptMax(cmptMag(bounds_.min())) + cmptMax(cmptMag(bounds_.max())));
    const vector reachMin(bounds_.min() - box.max() - vector::uniform(margin));
    const vector reachMax(bounds_.max() - box.min() + vector::uniform(margin));
    const auto reaches = [&](const vector& shift)
    {
        return
            shift.x() >= reachMin.x() && shift.x() <= reachMax.x()
         && shift.y() >= reachMin.y() && shift.y() <= reachMax.y()
         && shift.z() >= reachMin.z() && shift.z() <= reachMax.z();
    };

    images.clear();
    if (latticeAxis_.empty())
    {
        forAll(imageShift_, image)
        {
            if (reaches(imageShift_[image]))
            {
                images.append(image);
            }
        }
        return;
    }

    // Per lattice vector, the multiples -2..2 within reach along its axis
    // (a little more: each image found is tested whole below), then every
    // combination of them, in the images' order
    const label nLattice = latticeAxis_.size();
    label multiples[3][5];
    label nMultiples[3] = {0, 0, 0};
    label digit = 1, largest = 0;
    for (label d = 0; d < nLattice; ++d)
    {
        const direction a = latticeAxis_[d];
        const scalar slack = 1e-9*mag(latticeStep_[d]);
        for (const label times : {0, 1, -1, 2, -2})
        {
            const scalar s = times*latticeStep_[d];
            if (s >= reachMin[a] - slack && s <= reachMax[a] + slack)
            {
                multiples[d][nMultiples[d]++] = times*digit;
            }
        }
        if (!nMultiples[d])
        {
            return;
        }
        largest += 2*digit;
        digit *= 5;
    }
    label index[3] = {0, 0, 0};
    for (label d = 0; d < nLattice; )
    {
        label code = 0;
        for (label e = 0; e < nLattice; ++e)
        {
            code += multiples[e][index[e]];
        }
        const label image = imageOfCode_[code + largest];
        if (reaches(imageShift_[image]))
        {
            images.append(image);
        }
        // The next combination, the first lattice vector's fastest
        for (d = 0; d < nLattice && ++index[d] == nMultiples[d]; ++d)
        {
            index[d] = 0;
        }
    }
    std::sort(images.begin(), images.end());
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

    // Each rod of the grid is in every cell its box spans, so a pair
    // is tested in the first cell both boxes span, the first of them the
    // scan meets, and passed over in the others. Every test is evaluated
    // and combined without branches (boxesMeet), and each rod met is kept
    // by a count rather than a branch: a crowd's outcomes, one in five
    // met, would mispredict
    Vector<label> lower, upper;
    cellRange(box, lower, upper);
    if (met_.size() < nEntries_)
    {
        met_.resize(2*nEntries_);
    }
    label nMet = 0;
    for (label i = lower.x(); i <= upper.x(); ++i)
    {
        for (label j = lower.y(); j <= upper.y(); ++j)
        {
            for (label k = lower.z(); k <= upper.z(); ++k)
            {
                const label celli = (i*nCells_.y() + j)*nCells_.z() + k;
                for (const label other : cells_[celli])
                {
                    const Vector<label>& first = firstCell_[other];
                    met_[nMet] = other;
                    nMet +=
                        (max(lower.x(), first.x()) == i)
                      & (max(lower.y(), first.y()) == j)
                      & (max(lower.z(), first.z()) == k)
                      & boxesMeet(box_[other], box);
                }
            }
        }
    }

    // rod + shift meets other: other - shift is rod's partner
    for (label m = 0; m < nMet; ++m)
    {
        addPair(rod, met_[m], -imageCode_[image], -shift);
    }
}


void Foam::polymer::sweptBoxGrid::insert(const label rod)
{
    // The grid holds the rods' own boxes only. A rod's images are looked
    // up in it, but only those reaching the rods' bounds; every pair
    // (rod, other + translation) is found once, by the rod inserted
    // second
    bounds_.add(box_[rod]);
    Vector<label> lower, upper;
    cellRange(box_[rod], lower, upper);
    firstCell_[rod] = lower;
    for (label i = lower.x(); i <= upper.x(); ++i)
    {
        for (label j = lower.y(); j <= upper.y(); ++j)
        {
            for (label k = lower.z(); k <= upper.z(); ++k)
            {
                std::vector<label>& cell =
                    cells_[(i*nCells_.y() + j)*nCells_.z() + k];
                if (cell.empty() || cell.back() != rod)
                {
                    cell.push_back(rod);
                    ++nEntries_;
                }
            }
        }
    }

    DynamicList<label>& images = reachingImages_;
    reachingImages(box_[rod], images);
    for (const label image : images)
    {
        query(rod, image);
    }
    listNewPairs();
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
    firstCell_.setSize(box_.size());
    pairs_.clear();
    pairShift_.clear();
    std::fill(pairKeys_.begin(), pairKeys_.end(), noKey);
    // Each rod's list emptied, its storage kept for the next steps
    rodPairs_.resize(rods.size());
    for (std::vector<label>& pairsOfRod : rodPairs_)
    {
        pairsOfRod.clear();
    }

    // A rod meets only the rods inserted before it: the bounds of those
    // pass over the images that reach none of them
    bounds_ = boundBox::invertedBox;
    forAll(box_, rod)
    {
        insert(rod);
    }
}


bool Foam::polymer::sweptBoxGrid::grow
(
    const label rod,
    const boundBox& box,
    const scalar margin
)
{
    if (box_[rod].contains(box))
    {
        return false;
    }
    const vector fat(vector::uniform(margin));
    box_[rod].add(box.min() - fat);
    box_[rod].add(box.max() + fat);
    insert(rod);
    return true;
}


// ************************************************************************* //
