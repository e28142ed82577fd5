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

// Is cell (i, j, k) the first that two boxes, starting at cells a and b,
// both span? Evaluated whole, without branches, to combine with boxesMeet
inline bool firstShared
(
    const Foam::Vector<Foam::label>& a,
    const Foam::Vector<Foam::label>& b,
    const Foam::label i,
    const Foam::label j,
    const Foam::label k
)
{
    return
        (Foam::max(a.x(), b.x()) == i)
      & (Foam::max(a.y(), b.y()) == j)
      & (Foam::max(a.z(), b.z()) == k);
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
    lastCell_(),
    bounds_(boundBox::invertedBox),
    region_(boundBox::invertedBox),
    cellSize_(1),
    cellsPerLength_(1),
    nCells_(Zero),
    cellStart_(),
    cellRods_(),
    cellFirst_(),
    grownRods_(),
    grown_(),
    pairs_(),
    pairShift_(),
    pairKey_(),
    rodPairs_(),
    pairKeys_(),
    keysTabled_(false),
    newPairs_(),
    newOrder_(),
    groupStart_(),
    met_()
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


void Foam::polymer::sweptBoxGrid::tableKeys()
{
    if (keysTabled_)
    {
        return;
    }
    std::fill(pairKeys_.begin(), pairKeys_.end(), noKey);
    for (const uint64_t key : pairKey_)
    {
        newPairKey(key);
    }
    keysTabled_ = true;
}


void Foam::polymer::sweptBoxGrid::addPair
(
    label rodA,
    label rodB,
    label code,
    vector shift
)
{
    const label group = rodA;
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

    // A build meets each pair once; a grow's look-ups meet the pairs
    // found before as well
    if (!keysTabled_ || newPairKey(key))
    {
        newPairs_.append(newPair{group, key, labelPair(rodA, rodB), shift});
    }
}


void Foam::polymer::sweptBoxGrid::listNewPairs()
{
    // The look-ups meet the partners in the order of the cells they scan,
    // which changes with the cells' size. The pairs' order orders the
    // first predictions, and with them the events at one time, so a run
    // would depend on the grid's cells; in the order of the rod whose
    // look-up found them (the later rod of the pair, as if the rods were
    // inserted one by one), then of their keys (the rods' indices, then
    // the translation), it depends on the rods alone. A build's pairs are
    // placed by their rod (a rod finds about one), a grow's all have one
    const label nRods = box_.size();
    const label nNew = newPairs_.size();
    newOrder_.setSize(nNew);
    const auto byKey = [this](const label a, const label b)
    {
        return
            newPairs_[a].group < newPairs_[b].group
         || (
                newPairs_[a].group == newPairs_[b].group
             && newPairs_[a].key < newPairs_[b].key
            );
    };
    if (nNew > 1 && newPairs_.first().group == newPairs_.last().group)
    {
        forAll(newOrder_, n)
        {
            newOrder_[n] = n;
        }
        std::sort(newOrder_.begin(), newOrder_.end(), byKey);
    }
    else
    {
        groupStart_.setSize(nRods + 1);
        groupStart_ = 0;
        for (const newPair& p : newPairs_)
        {
            ++groupStart_[p.group + 1];
        }
        for (label rod = 0; rod < nRods; ++rod)
        {
            groupStart_[rod + 1] += groupStart_[rod];
        }
        forAll(newPairs_, n)
        {
            newOrder_[groupStart_[newPairs_[n].group]++] = n;
        }
        // Grouped: an insertion sort moves each within its group
        for (label n = 1; n < nNew; ++n)
        {
            const label m = newOrder_[n];
            label k = n;
            for (; k > 0 && byKey(m, newOrder_[k - 1]); --k)
            {
                newOrder_[k] = newOrder_[k - 1];
            }
            newOrder_[k] = m;
        }
    }

    for (const label n : newOrder_)
    {
        const newPair& p = newPairs_[n];
        const label pairi = pairs_.size();
        pairs_.append(p.rods);
        pairShift_.append(p.shift);
        pairKey_.append(p.key);
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
}


template<class Visit>
void Foam::polymer::sweptBoxGrid::forCells(const label rod, Visit visit)
    const
{
    const Vector<label>& lower = firstCell_[rod];
    const Vector<label>& upper = lastCell_[rod];
    for (label i = lower.x(); i <= upper.x(); ++i)
    {
        for (label j = lower.y(); j <= upper.y(); ++j)
        {
            const label row = (i*nCells_.y() + j)*nCells_.z();
            const unsigned firstXY = (i == lower.x()) | (j == lower.y()) << 1;
            for (label k = lower.z(); k <= upper.z(); ++k)
            {
                visit(row + k, firstXY | (k == lower.z()) << 2);
            }
        }
    }
}


void Foam::polymer::sweptBoxGrid::fillCells()
{
    // Count each cell's rods, then place them in the rods' order
    const label nRods = box_.size();
    firstCell_.setSize(nRods);
    lastCell_.setSize(nRods);
    const label nCells = nCells_.x()*nCells_.y()*nCells_.z();
    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;
    for (label rod = 0; rod < nRods; ++rod)
    {
        cellRange(box_[rod], firstCell_[rod], lastCell_[rod]);
        forCells
        (
            rod,
            [this](const label c, unsigned) { ++cellStart_[c + 1]; }
        );
    }
    for (label c = 0; c < nCells; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }
    cellRods_.setSize(cellStart_[nCells]);
    cellFirst_.setSize(cellStart_[nCells]);
    // Through the lists' data: a byte stored may alias anything, which
    // would have every list's address read again after it
    label* const slot = cellStart_.data();
    label* const cellRod = cellRods_.data();
    unsigned char* const cellFirst = cellFirst_.data();
    for (label rod = 0; rod < nRods; ++rod)
    {
        forCells
        (
            rod,
            [=](const label c, const unsigned first)
            {
                const label entry = slot[c]++;
                cellRod[entry] = rod;
                cellFirst[entry] = first;
            }
        );
    }
    // Each cell's start has moved to the next cell's: back by one
    for (label c = nCells; c > 0; --c)
    {
        cellStart_[c] = cellStart_[c - 1];
    }
    cellStart_[0] = 0;
}


void Foam::polymer::sweptBoxGrid::addCellPairs()
{
    // The pairs of each cell's rods whose boxes meet, a pair only in the
    // first cell both span: each found once, as the later rod's look-up
    // of its own box would find it. Kept by a count, as query keeps them.
    // Both boxes span the cell, so along each axis the later of their
    // first cells is this cell's where the cell is the first of either:
    // the entries' bits, together all three, tell the first shared cell
    // without reading the rods' first cells
    const label nCells = nCells_.x()*nCells_.y()*nCells_.z();
    for (label c = 0; c < nCells; ++c)
    {
        const label start = cellStart_[c];
        const label n = cellStart_[c + 1] - start;
        if (n < 2)
        {
            continue;
        }
        if (met_.size() < size_t(n))
        {
            met_.resize(2*n);
        }
        for (label p = start; p < start + n; ++p)
        {
            const label a = cellRods_[p];
            const unsigned firstA = cellFirst_[p];
            label nMet = 0;
            for (label q = p + 1; q < start + n; ++q)
            {
                const label b = cellRods_[q];
                met_[nMet] = b;
                nMet +=
                    ((firstA | cellFirst_[q]) == 7u)
                  & boxesMeet(box_[a], box_[b]);
            }
            for (label m = 0; m < nMet; ++m)
            {
                addPair(met_[m], a, 0, Zero);
            }
        }
    }
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
    const label image,
    const label limit
)
{
    const vector& shift = imageShift_[image];
    const boundBox box(box_[rod].min() + shift, box_[rod].max() + shift);
    if (!box.overlaps(bounds_))
    {
        // No rod's box out there
        return;
    }

    // A pair is tested in the first cell both boxes span, the first of
    // them the scan meets, and passed over in the others. Every test is
    // evaluated and combined without branches (boxesMeet), and each rod
    // met is kept by a count rather than a branch: a crowd's outcomes,
    // one in five met, would mispredict. The grown boxes, beyond the
    // cells of the build, are tested whole
    Vector<label> lower, upper;
    cellRange(box, lower, upper);
    const size_t most = cellRods_.size() + grownRods_.size();
    if (met_.size() < most)
    {
        met_.resize(2*most);
    }
    label nMet = 0;
    for (label i = lower.x(); i <= upper.x(); ++i)
    {
        for (label j = lower.y(); j <= upper.y(); ++j)
        {
            const label row = (i*nCells_.y() + j)*nCells_.z();
            for (label k = lower.z(); k <= upper.z(); ++k)
            {
                const label end = cellStart_[row + k + 1];
                for (label p = cellStart_[row + k]; p < end; ++p)
                {
                    const label other = cellRods_[p];
                    if (other >= limit)
                    {
                        // A cell's rods are in order
                        break;
                    }
                    met_[nMet] = other;
                    nMet +=
                        firstShared(lower, firstCell_[other], i, j, k)
                      & boxesMeet(box_[other], box);
                }
            }
        }
    }
    for (const label other : grownRods_)
    {
        met_[nMet] = other;
        nMet += boxesMeet(box_[other], box);
    }

    // rod + shift meets other: other - shift is rod's partner
    for (label m = 0; m < nMet; ++m)
    {
        addPair(rod, met_[m], -imageCode_[image], -shift);
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
    fillCells();
    pairs_.clear();
    pairShift_.clear();
    pairKey_.clear();
    keysTabled_ = false;
    grownRods_.clear();
    grown_.setSize(box_.size());
    grown_ = false;
    // Each rod's list emptied, its storage kept for the next steps
    rodPairs_.resize(rods.size());
    for (std::vector<label>& pairsOfRod : rodPairs_)
    {
        pairsOfRod.clear();
    }

    addCellPairs();
    if (imageShift_.size() > 1)
    {
        // A rod meets the rods before it: the bounds of those pass over
        // the images that reach none of them (the first image, no
        // translation, the cells gave)
        const boundBox allBounds(bounds_);
        bounds_ = boundBox::invertedBox;
        forAll(box_, rod)
        {
            bounds_.add(box_[rod]);
            reachingImages(box_[rod], reachingImages_);
            for (const label image : reachingImages_)
            {
                if (image)
                {
                    query(rod, image, rod);
                }
            }
        }
        bounds_ = allBounds;
    }
    listNewPairs();
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
    bounds_.add(box_[rod]);
    if (!grown_[rod])
    {
        grown_[rod] = true;
        grownRods_.append(rod);
    }

    // Every rod's box at each image reaching the bounds; the pairs found
    // before passed over
    tableKeys();
    reachingImages(box_[rod], reachingImages_);
    for (const label image : reachingImages_)
    {
        query(rod, image, box_.size());
    }
    listNewPairs();
    return true;
}


// ************************************************************************* //
