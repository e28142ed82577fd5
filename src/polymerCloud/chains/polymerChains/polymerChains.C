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

#include "polymerChains.H"
#include "maxOrNaN.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerChains::polymerChains(const PtrList<chainType>& types)
:
    types_(types),
    positions_(),
    velocities_(),
    chainStart_(1, Zero),
    chainTypeIndex_(),
    globalChainId_(),
    layoutVersion_(0),
    reorderedFrom_(-1),
    lastReorder_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::polymerChains::append
(
    const label typeIndex,
    const label globalId,
    const UList<vector>& positions,
    const UList<vector>& velocities
)
{
    ++layoutVersion_;
    if
    (
        positions.size() != types_[typeIndex].nBeads()
     || velocities.size() != positions.size()
    )
    {
        FatalErrorInFunction
            << "Chain " << globalId << " of type "
            << types_[typeIndex].name() << " has " << positions.size()
            << " positions and " << velocities.size()
            << " velocities; expected " << types_[typeIndex].nBeads()
            << abort(FatalError);
    }

    positions_.append(positions);
    velocities_.append(velocities);
    chainTypeIndex_.append(typeIndex);
    globalChainId_.append(globalId);
    chainStart_.append(positions_.size());
}


Foam::label Foam::polymer::polymerChains::chainOf(const label beadi) const
{
    // The last chain whose first bead is at or before beadi
    return
        label
        (
            std::upper_bound
            (
                chainStart_.cbegin(), chainStart_.cend() - 1, beadi
            )
          - chainStart_.cbegin()
        )
      - 1;
}


void Foam::polymer::polymerChains::remove(const labelUList& chainIndices)
{
    ++layoutVersion_;
    boolList removed(nChains(), false);
    for (const label c : chainIndices)
    {
        removed[c] = true;
    }

    label nKept = 0;
    label nKeptBeads = 0;
    for (label c = 0; c < nChains(); ++c)
    {
        if (removed[c])
        {
            continue;
        }
        const label first = start(c);
        const label n = size(c);
        for (label k = 0; k < n; ++k)
        {
            positions_[nKeptBeads + k] = positions_[first + k];
            velocities_[nKeptBeads + k] = velocities_[first + k];
        }
        chainTypeIndex_[nKept] = chainTypeIndex_[c];
        globalChainId_[nKept] = globalChainId_[c];
        chainStart_[nKept] = nKeptBeads;
        nKeptBeads += n;
        ++nKept;
    }

    chainStart_[nKept] = nKeptBeads;
    chainStart_.resize(nKept + 1);
    chainTypeIndex_.resize(nKept);
    globalChainId_.resize(nKept);
    positions_.resize(nKeptBeads);
    velocities_.resize(nKeptBeads);
}


void Foam::polymer::polymerChains::reorder(const labelUList& newToOld)
{
    reorderedFrom_ = layoutVersion_;
    lastReorder_ = newToOld;
    ++layoutVersion_;
    List<vector> positions(positions_.size());
    List<vector> velocities(velocities_.size());
    labelList typeIndex(nChains());
    labelList globalId(nChains());
    labelList chainStart(nChains() + 1);

    label nBeadsDone = 0;
    forAll(newToOld, c)
    {
        const label old = newToOld[c];
        chainStart[c] = nBeadsDone;
        for (label i = start(old); i < end(old); ++i, ++nBeadsDone)
        {
            positions[nBeadsDone] = positions_[i];
            velocities[nBeadsDone] = velocities_[i];
        }
        typeIndex[c] = chainTypeIndex_[old];
        globalId[c] = globalChainId_[old];
    }
    chainStart[nChains()] = nBeadsDone;

    positions_.transfer(positions);
    velocities_.transfer(velocities);
    chainTypeIndex_.transfer(typeIndex);
    globalChainId_.transfer(globalId);
    chainStart_.transfer(chainStart);
}


void Foam::polymer::polymerChains::clear()
{
    ++layoutVersion_;
    positions_.clear();
    velocities_.clear();
    chainStart_.resize(1);
    chainTypeIndex_.clear();
    globalChainId_.clear();
}


Foam::scalar
Foam::polymer::polymerChains::maxRodLengthError(const label chaini) const
{
    const chainType& t = type(chaini);
    const vector* x = positions_.cdata() + start(chaini);
    const label n = t.nBeads();

    scalar maxError = 0;
    for (label k = 0; k < t.nRods(); ++k)
    {
        const scalar length = mag(x[(k + 1) % n] - x[k]);
        maxError = maxOrNaN(maxError, mag(length - t.rodLength()));
    }

    return maxError/t.rodLength();
}


Foam::scalar Foam::polymer::polymerChains::maxRodLengthError() const
{
    scalar maxError = 0;
    for (label c = 0; c < nChains(); ++c)
    {
        maxError = maxOrNaN(maxError, maxRodLengthError(c));
    }
    return maxError;
}


Foam::vector
Foam::polymer::polymerChains::centreOfMass(const label chaini) const
{
    vector sum(Zero);
    for (label i = start(chaini); i < end(chaini); ++i)
    {
        sum += positions_[i];
    }
    return sum/size(chaini);
}


Foam::scalar
Foam::polymer::polymerChains::radiusOfGyrationSqr(const label chaini) const
{
    const vector centre = centreOfMass(chaini);

    scalar sum = 0;
    for (label i = start(chaini); i < end(chaini); ++i)
    {
        sum += magSqr(positions_[i] - centre);
    }
    return sum/size(chaini);
}


Foam::scalar Foam::polymer::polymerChains::endToEndSqr(const label chaini) const
{
    return magSqr(positions_[end(chaini) - 1] - positions_[start(chaini)]);
}


Foam::scalar
Foam::polymer::polymerChains::kineticEnergy(const label chaini) const
{
    scalar sum = 0;
    for (label i = start(chaini); i < end(chaini); ++i)
    {
        sum += magSqr(velocities_[i]);
    }
    return 0.5*type(chaini).beadMass()*sum;
}


// ************************************************************************* //
