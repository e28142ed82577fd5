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

#include "elasticRods.H"
#include "checkedInput.H"
#include "rodCrossingAudit.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace collisionModels
{
    defineTypeNameAndDebug(elasticRods, 0);
    addToRunTimeSelectionTable(collisionModel, elasticRods, dictionary);
}
}


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

Foam::collisionModels::elasticRods::elasticRods(const dictionary& dict)
:
    collisionModel(typeName, dict),
    rootSolver_
    (
        crossingRootSolver::New
        (
            coeffDict_.getOrDefault<word>("rootSolver", "isolating"),
            coeffDict_
        )
    ),
    maxEvents_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "maxEvents", 100000, 1, "<events per time step>"
        )
    ),
    stallTime_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_, "stallTime", 1e-9, "<event spacing / deltaT>"
        )
    ),
    stallEvents_
    (
        checkedInput::labelAtLeastOrDefault
        (
            coeffDict_, "stallEvents", 100, 1, "<successive short events>"
        )
    ),
    audit_(coeffDict_.getOrDefault<bool>("audit", false)),
    cellSize_(1),
    rodsLayout_(-1),
    imageShift_(),
    imageCode_(),
    wall_(nullptr)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::collisionModels::elasticRods::buildRods
(
    const polymerChains& chains
) const
{
    rods_.clear();
    rodChain_.clear();
    rodChainId_.clear();
    beadRods_.resize(chains.nBeads());
    beadRods_ = FixedList<label, 2>({-1, -1});

    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label first = chains.start(c);
        const label n = chains.size(c);

        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            const label a = first + k;
            const label b = first + (k + 1) % n;
            const label rod = rods_.size();

            rods_.append(labelPair(a, b));
            rodChain_.append(c);
            rodChainId_.append(chains.globalId(c));
            beadRods_[a][1] = rod;
            beadRods_[b][0] = rod;
        }
    }
}


inline Foam::vector Foam::collisionModels::elasticRods::positionAt
(
    const label bead,
    const scalar t
) const
{
    return position_[bead] + (t - beadTime_[bead])*velocity_[bead];
}


Foam::boundBox Foam::collisionModels::elasticRods::sweep
(
    const label rod,
    const scalar t,
    const scalar dt
) const
{
    boundBox box(positionAt(rods_[rod].first(), t));
    box.add(positionAt(rods_[rod].second(), t));
    box.add(positionAt(rods_[rod].first(), dt));
    box.add(positionAt(rods_[rod].second(), dt));
    return box;
}


void Foam::collisionModels::elasticRods::buildImages() const
{
    // Every combination of -1, 0, +1 per lattice vector, zero first
    imageShift_ = List<vector>(1, Zero);
    imageCode_ = labelList(1, Zero);
    label digit = 1;
    for (const vector& t : lattice_)
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


Foam::boundBox Foam::collisionModels::elasticRods::entryBox
(
    const label entry
) const
{
    const label nRods = rods_.size();
    const boundBox& box = sweptBox_[entry % nRods];
    const vector& shift = imageShift_[entry/nRods];
    return boundBox(box.min() + shift, box.max() + shift);
}


void Foam::collisionModels::elasticRods::addPair
(
    const label entryA,
    const label entryB
) const
{
    const label nRods = rods_.size();
    label rodA = entryA % nRods, rodB = entryB % nRods;
    label imageA = entryA/nRods, imageB = entryB/nRods;
    if
    (
        rodChainId_[rodA] > rodChainId_[rodB]
     || (rodChainId_[rodA] == rodChainId_[rodB] && rodA > rodB)
    )
    {
        std::swap(rodA, rodB);
        std::swap(imageA, imageB);
    }

    // The translation of the second rod relative to the first
    const label code = imageCode_[imageB] - imageCode_[imageA];
    const labelPair& a = rods_[rodA];
    const labelPair& b = rods_[rodB];
    if
    (
        code == 0
     && (
            rodA == rodB
         || a.first() == b.first() || a.first() == b.second()
         || a.second() == b.first() || a.second() == b.second()
        )
    )
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


void Foam::collisionModels::elasticRods::insertEntry
(
    const label entry,
    const boundBox& box
) const
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
                std::vector<label>& cell = grid_[cellKey(i, j, k)];
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


void Foam::collisionModels::elasticRods::insert(const label rod) const
{
    // Images of a rod are inserted whatever their distance from the
    // chains: the broad phase cost grows by the number of images on
    // periodic meshes only
    const label nRods = rods_.size();
    forAll(imageShift_, image)
    {
        const label entry = rod + image*nRods;
        insertEntry(entry, entryBox(entry));
    }
}


void Foam::collisionModels::elasticRods::predict
(
    const label pairi,
    const scalar t,
    const scalar dt
) const
{
    const label a0 = rods_[pairs_[pairi].first()].first();
    const label a1 = rods_[pairs_[pairi].first()].second();
    const label b0 = rods_[pairs_[pairi].second()].first();
    const label b1 = rods_[pairs_[pairi].second()].second();
    const vector& shift = pairShift_[pairi];

    const rodPairCrossing pair
    (
        positionAt(a0, t), positionAt(a1, t),
        positionAt(b0, t) + shift, positionAt(b1, t) + shift,
        velocity_[a0], velocity_[a1], velocity_[b0], velocity_[b1]
    );

    const scalar s = rootSolver_->earliestCrossing(pair, dt - t);
    ++counters_.pairChecks;

    if (debug > 1 && s >= 0)
    {
        const FixedList<scalar, 4> c = pair.tripleProductCubic();
        scalar li, lj;
        pair.intersection(s, li, lj);
        Pout<< "    predict pair " << rods_[pairs_[pairi].first()] << ' '
            << rods_[pairs_[pairi].second()] << " from " << t << ": s " << s
            << " V " << c << " lambda " << li << ' ' << lj << endl;
    }

    if (s >= 0)
    {
        queue_.push
        (
            event
            {
                t + s,
                pairi,
                version_[a0] + version_[a1] + version_[b0] + version_[b1],
                t,
                s,
                Zero,
                -1
            }
        );
    }
}


void Foam::collisionModels::elasticRods::predictWall
(
    const label bead,
    const scalar t,
    const scalar dt
) const
{
    wallModel::impact hit;
    if
    (
        wall_->predict(positionAt(bead, t), velocity_[bead], dt - t, hit)
    )
    {
        queue_.push
        (
            event
            {
                t + hit.time,
                -1 - bead,
                version_[bead],
                t,
                hit.time,
                hit.normal,
                hit.patch
            }
        );
    }
}


void Foam::collisionModels::elasticRods::repredict
(
    const label bead,
    const scalar t,
    const scalar dt
) const
{
    // Grow the broad phase where the new paths leave the rods' boxes
    for (const label rod : beadRods_[bead])
    {
        if (rod < 0)
        {
            continue;
        }
        const boundBox box = sweep(rod, t, dt);
        if (!sweptBox_[rod].contains(box))
        {
            sweptBox_[rod].add(box);
            insert(rod);
        }
        for (const label pairi : rodPairs_[rod])
        {
            predict(pairi, t, dt);
        }
    }

    if (wall_)
    {
        predictWall(bead, t, dt);
    }
}


void Foam::collisionModels::elasticRods::resolveWall
(
    const event& e,
    UList<vector>& velocitiesDagger
) const
{
    const label bead = -1 - e.pair;

    position_[bead] = positionAt(bead, e.from) + e.offset*velocity_[bead];
    beadTime_[bead] = e.time;

    wall_->interact
    (
        bead,
        wallModel::impact{e.offset, e.normal, e.patch},
        velocity_[bead],
        velocitiesDagger[bead]
    );
    ++version_[bead];
}


bool Foam::collisionModels::elasticRods::resolve
(
    const event& e,
    UList<vector>& velocitiesDagger
) const
{
    const label pairi = e.pair;
    const label beads[4] =
    {
        rods_[pairs_[pairi].first()].first(),
        rods_[pairs_[pairi].first()].second(),
        rods_[pairs_[pairi].second()].first(),
        rods_[pairs_[pairi].second()].second()
    };

    // The impact positions as the root solver evaluated them, on the
    // not-yet-crossed side of the root
    for (const label bead : beads)
    {
        position_[bead] =
            positionAt(bead, e.from) + e.offset*velocity_[bead];
        beadTime_[bead] = e.time;
    }

    const vector& shift = pairShift_[pairi];
    const rodPairCrossing pair
    (
        position_[beads[0]], position_[beads[1]],
        position_[beads[2]] + shift, position_[beads[3]] + shift,
        velocity_[beads[0]], velocity_[beads[1]],
        velocity_[beads[2]], velocity_[beads[3]]
    );

    FixedList<vector, 4> after;
    if (!pair.elasticImpulse(0, after))
    {
        return false;
    }

    for (label k = 0; k < 4; ++k)
    {
        const label bead = beads[k];
        velocitiesDagger[bead] += after[k] - velocity_[bead];
        velocity_[bead] = after[k];
        ++version_[bead];
    }

    return true;
}


void Foam::collisionModels::elasticRods::snapshot(const scalar t) const
{
    List<point> positions(position_.size());
    forAll(positions, i)
    {
        positions[i] = positionAt(i, t);
    }
    snapshots_.append(std::move(positions));
}


Foam::label Foam::collisionModels::elasticRods::auditStep
(
    const scalar time
) const
{
    const List<rodCrossingAudit::crossing> found =
        rodCrossingAudit(rods_).check(snapshots_);

    for (const rodCrossingAudit::crossing& c : found)
    {
        WarningInFunction
            << "Audit: rods (beads " << c.rodA << ") and (" << c.rodB
            << ") crossed in the step to time " << time
            << ", after event " << c.piece << " of the step" << endl;
    }
    const label nFound = found.size();

    snapshots_.clear();
    return nFound;
}


void Foam::collisionModels::elasticRods::reportStall
(
    const polymerChains& chains,
    const label pairi,
    const scalar time,
    const label nEvents
) const
{
    if (pairi < 0)
    {
        WarningInFunction
            << "Event loop stopped at time " << time << " after " << nEvents
            << " events, the last a bead-wall impact of bead " << -1 - pairi
            << ": the beads stay at the last uncrossed state of the step"
            << endl;
        return;
    }

    WarningInFunction
        << "Rod-rod event loop stopped at time " << time << " after "
        << nEvents << " events, the last between chains "
        << chains.globalId(rodChain_[pairs_[pairi].first()]) << " and "
        << chains.globalId(rodChain_[pairs_[pairi].second()])
        << (nEvents >= maxEvents_ ? " (maxEvents)" : " (tau -> 0 stall)")
        << ": the beads stay at the last uncrossed state of the step"
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::collisionModels::elasticRods::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time,
    const wallModel* wall
) const
{
    wall_ = (wall && wall->active()) ? wall : nullptr;

    const label nBeads = chains.nBeads();
    List<vector>& x = chains.positions();
    List<vector>& vDagger = chains.velocities();

    if (rodsLayout_ != chains.layoutVersion() || beadRods_.size() != nBeads)
    {
        buildRods(chains);
        rodsLayout_ = chains.layoutVersion();
    }

    // Straight paths over the step (paper eq. 1), in step time [0, dt]
    position_ = positionsOld;
    velocity_.resize(nBeads);
    for (label i = 0; i < nBeads; ++i)
    {
        velocity_[i] = (x[i] - positionsOld[i])/deltaT;
    }
    beadTime_.resize(nBeads);
    beadTime_ = 0;
    version_.resize(nBeads);
    version_ = 0;

    // Broad phase: rods whose swept boxes overlap
    sweptBox_.resize(rods_.size());
    scalar largest = 0;
    forAll(rods_, rod)
    {
        sweptBox_[rod] = sweep(rod, 0, deltaT);
        largest = max(largest, cmptMax(sweptBox_[rod].span()));
    }
    cellSize_ = max(largest, VSMALL);

    label nImages = 1;
    for (label k = 0; k < lattice_.size(); ++k)
    {
        nImages *= 3;
    }
    if (imageShift_.size() != nImages)
    {
        buildImages();
    }
    grid_.clear();
    pairs_.clear();
    pairShift_.clear();
    pairSet_.clear();
    rodPairs_.assign(rods_.size(), std::vector<label>());
    forAll(rods_, rod)
    {
        insert(rod);
    }

    queue_ = std::priority_queue<event>();
    forAll(pairs_, pairi)
    {
        predict(pairi, 0, deltaT);
    }
    if (wall_)
    {
        for (label bead = 0; bead < nBeads; ++bead)
        {
            predictWall(bead, 0, deltaT);
        }
    }

    if (audit_)
    {
        snapshots_.clear();
        snapshot(0);
    }

    // Multi-collision loop: earliest event first
    label nEvents = 0;
    label nShort = 0;
    scalar now = 0;
    bool stalled = false;

    while (!queue_.empty())
    {
        const event e = queue_.top();
        queue_.pop();

        const bool wallEvent = (e.pair < 0);
        label stamp = 0;
        if (wallEvent)
        {
            stamp = version_[-1 - e.pair];
        }
        else
        {
            const labelPair& pair = pairs_[e.pair];
            stamp =
                version_[rods_[pair.first()].first()]
              + version_[rods_[pair.first()].second()]
              + version_[rods_[pair.second()].first()]
              + version_[rods_[pair.second()].second()];
        }

        if (stamp != e.stamp)
        {
            // A bead of this event has changed course since
            continue;
        }

        nShort = (e.time - now < stallTime_*deltaT) ? nShort + 1 : 0;
        now = e.time;

        if (nShort >= stallEvents_ || nEvents >= maxEvents_)
        {
            reportStall(chains, e.pair, time - deltaT + now, nEvents);
            stalled = true;
            break;
        }

        if (audit_)
        {
            snapshot(now);
        }

        if (wallEvent)
        {
            resolveWall(e, vDagger);
            repredict(-1 - e.pair, now, deltaT);
            continue;
        }

        if (!resolve(e, vDagger))
        {
            continue;
        }
        ++nEvents;

        const labelPair& pair = pairs_[e.pair];
        if (debug)
        {
            Pout<< "elasticRods: event " << nEvents << " at " << now
                << " rods " << rods_[pair.first()] << ' '
                << rods_[pair.second()] << " snapshot "
                << snapshots_.size() - 1 << endl;
        }

        // Re-predict every event of the four beads
        for (const label rod : {pair.first(), pair.second()})
        {
            for (const label bead : {rods_[rod].first(), rods_[rod].second()})
            {
                repredict(bead, now, deltaT);
            }
        }
    }

    // x^{n+1}: the end of the paths, or the last uncrossed state
    const scalar end = stalled ? now : deltaT;
    for (label i = 0; i < nBeads; ++i)
    {
        x[i] = positionAt(i, end);
    }

    if (audit_)
    {
        snapshot(end);
        counters_.auditCrossings += auditStep(time);
    }

    ++counters_.steps;
    counters_.events += nEvents;
    counters_.maxEventsPerStep = max(counters_.maxEventsPerStep, nEvents);
    counters_.stalls += stalled;
}


// ************************************************************************* //
