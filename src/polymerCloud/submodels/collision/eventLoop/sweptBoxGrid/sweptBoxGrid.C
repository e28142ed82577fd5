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
#include <cstring>
#include <limits>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Does box b (lower and negated upper bounds along two axes, four
// values) meet a box whose (upper, negated lower) bounds are a? Both
// lanes of both comparisons true; one SSE2 comparison for two lanes
#ifdef __SSE2__
struct acrossBounds
{
    __m128d first, second;

    explicit acrossBounds(const double* b)
    :
        first(_mm_shuffle_pd(_mm_loadu_pd(b), _mm_loadu_pd(b), 1)),
        second(_mm_shuffle_pd(_mm_loadu_pd(b + 2), _mm_loadu_pd(b + 2), 1))
    {
        const __m128d negative = _mm_set1_pd(-0.0);
        first = _mm_xor_pd(first, negative);
        second = _mm_xor_pd(second, negative);
    }

    bool met(const double* b) const
    {
        return _mm_movemask_pd
        (
            _mm_and_pd
            (
                _mm_cmple_pd(_mm_loadu_pd(b), first),
                _mm_cmple_pd(_mm_loadu_pd(b + 2), second)
            )
        ) == 3;
    }
};
#else
struct acrossBounds
{
    double a[4];

    explicit acrossBounds(const double* b)
    :
        a{-b[1], -b[0], -b[3], -b[2]}
    {}

    bool met(const double* b) const
    {
        return
            (b[0] <= a[0]) & (b[1] <= a[1])
          & (b[2] <= a[2]) & (b[3] <= a[3]);
    }
};
#endif

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

Foam::polymer::sweptBoxGrid::sweptBoxGrid(const label maxSweepTestsPerRod)
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
    maxSweepTestsPerRod_(maxSweepTestsPerRod),
    met_(),
    nBuilds_(0),
    swept_(false),
    sweepAgainAt_(0),
    sweepAxis_(-1),
    sortedAt_(-1),
    sweepOrder_(),
    sweepMin_(),
    sweepMax_(),
    sweepAcross_(),
    sweepSpan_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::polymer::sweptBoxGrid::roundOffMargin() const
{
    return
        1e-9
       *(cmptMax(cmptMag(bounds_.min())) + cmptMax(cmptMag(bounds_.max())));
}


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


void Foam::polymer::sweptBoxGrid::sortAlong(const direction axis)
{
    const label nRods = box_.size();
    const bool kept =
        sortedAt_ == nBuilds_ - 1
     && sweepAxis_ == label(axis)
     && sweepOrder_.size() == nRods;
    sweepAxis_ = axis;
    sortedAt_ = nBuilds_;
    sweepMin_.setSize(nRods);
    if (!kept)
    {
        sweepOrder_.setSize(nRods);
        forAll(sweepOrder_, p)
        {
            sweepOrder_[p] = p;
        }
        std::sort
        (
            sweepOrder_.begin(),
            sweepOrder_.end(),
            [this, axis](const label a, const label b)
            {
                return box_[a].min()[axis] < box_[b].min()[axis];
            }
        );
    }
    forAll(sweepOrder_, p)
    {
        sweepMin_[p] = box_[sweepOrder_[p]].min()[axis];
    }
    // Beyond the last, a lower bound no box ends after: the sweep's stop
    sweepMin_.append(std::numeric_limits<scalar>::infinity());
    if (kept)
    {
        // The boxes move little between builds: an insertion sort of the
        // last order takes a pass and a few moves
        for (label p = 1; p < nRods; ++p)
        {
            const scalar lower = sweepMin_[p];
            const label rod = sweepOrder_[p];
            label q = p;
            for (; q > 0 && sweepMin_[q - 1] > lower; --q)
            {
                sweepMin_[q] = sweepMin_[q - 1];
                sweepOrder_[q] = sweepOrder_[q - 1];
            }
            sweepMin_[q] = lower;
            sweepOrder_[q] = rod;
        }
    }
    // The upper bounds and the bounds across the axis in the order; the
    // longest span with a margin over the round-off of a look-up's window
    const direction across1 = (axis + 1) % 3, across2 = (axis + 2) % 3;
    sweepMax_.setSize(nRods);
    sweepAcross_.setSize(4*nRods);
    sweepSpan_ = roundOffMargin();
    scalar span = 0;
    forAll(sweepOrder_, p)
    {
        const boundBox& box = box_[sweepOrder_[p]];
        sweepMax_[p] = box.max()[axis];
        span = max(span, sweepMax_[p] - sweepMin_[p]);
        scalar* const across = &sweepAcross_[4*p];
        across[0] = box.min()[across1];
        across[1] = -box.max()[across1];
        across[2] = box.min()[across2];
        across[3] = -box.max()[across2];
    }
    sweepSpan_ += span;
}


bool Foam::polymer::sweptBoxGrid::sweep()
{
    // Not across a lattice (the images are looked up in the cells), and
    // not again for a while after a sweep gave up: the rods crowd for
    // many steps
    if
    (
        imageShift_.size() > 1
     || maxSweepTestsPerRod_ <= 0
     || nBuilds_ < sweepAgainAt_
    )
    {
        return false;
    }
    const vector span(bounds_.span());
    sortAlong
    (
        span.x() >= max(span.y(), span.z()) ? 0 : span.y() >= span.z() ? 1 : 2
    );
    const label nRods = max(box_.size(), 1);
    const label maxTests =
        maxSweepTestsPerRod_ < labelMax/nRods
      ? maxSweepTestsPerRod_*nRods
      : labelMax;
    if (addSweptPairs(maxTests))
    {
        return true;
    }
    sweepAgainAt_ = nBuilds_ + 16;
    return false;
}


bool Foam::polymer::sweptBoxGrid::addSweptPairs(const label maxTests)
{
    // Each box against those after it in the order that start before it
    // ends: every pair whose boxes meet, once. Along the axis such boxes
    // meet (the later starts after the earlier starts and before it
    // ends), so the test is across it alone, on the sorted copies: with
    // the upper bounds negated, b's (lower, -upper) <= a's (upper, -lower)
    // along each axis across (negation is exact: the outcomes of
    // boxesMeet's comparisons). Kept by a count, as the cells' pairs are;
    // the later rod of a pair is the one whose look-up found it, as the
    // cells list them
    const label nRods = sweepOrder_.size();
    if (met_.size() < size_t(nRods))
    {
        met_.resize(2*nRods);
    }
    // Through the lists' data: a label stored may alias a list's size
    const label* const order = sweepOrder_.cdata();
    const scalar* const lower = sweepMin_.cdata();
    const scalar* const upper = sweepMax_.cdata();
    const scalar* const across = sweepAcross_.cdata();
    label* const met = met_.data();
    label nTests = 0;
    for (label p = 0; p < nRods; ++p)
    {
        const scalar end = upper[p];
        const acrossBounds a(across + 4*p);
        label q = p + 1;
        label nMet = 0;
        for (; lower[q] <= end; ++q)
        {
            met[nMet] = order[q];
            nMet += a.met(across + 4*q);
        }
        if (q - p - 1 > maxTests - nTests)
        {
            newPairs_.clear();
            return false;
        }
        nTests += q - p - 1;
        for (label m = 0; m < nMet; ++m)
        {
            addPair(max(order[p], met[m]), min(order[p], met[m]), 0, Zero);
        }
    }
    return true;
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
    const scalar margin = roundOffMargin();
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


inline Foam::label Foam::polymer::sweptBoxGrid::cellLookUp
(
    const boundBox& box,
    const label limit
)
{
    // A pair is tested in the first cell both boxes span, the first of
    // them the scan meets, and passed over in the others. Every test is
    // evaluated and combined without branches (boxesMeet), and each rod
    // met is kept by a count rather than a branch: a crowd's outcomes,
    // one in five met, would mispredict
    Vector<label> lower, upper;
    cellRange(box, lower, upper);
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
    return nMet;
}


Foam::label Foam::polymer::sweptBoxGrid::sweepLookUp
(
    const boundBox& box,
    const label limit
)
{
    // The boxes that may meet box start at most the longest box's span
    // before it and no later than its end
    const direction axis = sweepAxis_;
    const auto sorted = sweepMin_.cbegin();
    const auto sortedEnd = sorted + sweepOrder_.size();
    const label first = std::lower_bound
    (
        sorted, sortedEnd, box.min()[axis] - sweepSpan_
    ) - sorted;
    const label last = std::upper_bound
    (
        sorted, sortedEnd, box.max()[axis]
    ) - sorted;
    label nMet = 0;
    for (label p = first; p < last; ++p)
    {
        const label other = sweepOrder_[p];
        met_[nMet] = other;
        nMet += (other < limit) & boxesMeet(box_[other], box);
    }
    return nMet;
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

    // The build's boxes, then the grown boxes, which may reach beyond
    // the cells or the sorted bounds of the build: tested whole. A slot
    // is written before its rod is counted: one more than may be met
    const size_t most = box_.size() + grownRods_.size() + 1;
    if (met_.size() < most)
    {
        met_.resize(2*most);
    }
    label nMet =
        swept_ ? sweepLookUp(box, limit) : cellLookUp(box, limit);
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

    ++nBuilds_;
    swept_ = sweep();
    if (!swept_)
    {
        layCells(box_.size());
        fillCells();
        addCellPairs();
    }
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
