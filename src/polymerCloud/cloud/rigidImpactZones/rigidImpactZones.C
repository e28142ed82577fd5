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

#include "rigidImpactZones.H"
#include <algorithm>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::vector;

Eigen::Vector3d toEigen(const vector& v)
{
    return Eigen::Vector3d(v.x(), v.y(), v.z());
}

vector fromEigen(const Eigen::Vector3d& v)
{
    return vector(v(0), v(1), v(2));
}

// The rotation R minimising sum m |R r - q|^2 for the covariance
// sum m q r^T (Kabsch): U diag(1, 1, d) V^T, d keeping det R = 1
Eigen::Matrix3d bestRotation(const Eigen::Matrix3d& covariance)
{
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd
    (
        covariance, Eigen::ComputeFullU | Eigen::ComputeFullV
    );
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (svd.matrixU()*svd.matrixV().transpose()).determinant() < 0
        ? -1 : 1;
    return svd.matrixU()*D*svd.matrixV().transpose();
}

// omega with I omega = L, I symmetric positive semi-definite; directions
// of no inertia (a straight zone's axis) take no spin
Eigen::Vector3d angularVelocity
(
    const Eigen::Matrix3d& inertia,
    const Eigen::Vector3d& angularMomentum
)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia);
    const Eigen::Vector3d& lambda = eigen.eigenvalues();
    const double cutoff = 1e-12*lambda.cwiseAbs().maxCoeff();
    Eigen::Vector3d omega = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
        if (lambda(k) > cutoff)
        {
            const Eigen::Vector3d e = eigen.eigenvectors().col(k);
            omega += e*(e.dot(angularMomentum)/lambda(k));
        }
    }
    return omega;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::polymer::rigidImpactZones::root(const label chaini)
{
    label r = chaini;
    vector total(Zero);
    while (parent_[r] != r)
    {
        total += offset_[r];
        r = parent_[r];
    }
    for (label c = chaini; c != r; )
    {
        const label next = parent_[c];
        const vector own = offset_[c];
        parent_[c] = r;
        offset_[c] = total;
        total -= own;
        c = next;
    }
    return r;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::rigidImpactZones::reset(const label nChains)
{
    parent_.setSize(nChains);
    parent_ = -1;
    size_.setSize(nChains);
    size_ = 0;
    offset_.setSize(nChains);
    offset_ = Zero;
    held_.setSize(nChains);
    held_ = false;
}


bool Foam::polymer::rigidImpactZones::sameZone
(
    const label chainA,
    const label chainB
)
{
    return inZone(chainA) && inZone(chainB) && root(chainA) == root(chainB);
}


void Foam::polymer::rigidImpactZones::add(const label chaini)
{
    if (!inZone(chaini))
    {
        parent_[chaini] = chaini;
        size_[chaini] = 1;
        offset_[chaini] = Zero;
        held_[chaini] = false;
    }
}


void Foam::polymer::rigidImpactZones::hold(const label chaini)
{
    held_[root(chaini)] = true;
}


bool Foam::polymer::rigidImpactZones::held(const label chaini)
{
    return inZone(chaini) && held_[root(chaini)];
}


Foam::vector Foam::polymer::rigidImpactZones::offset(const label chaini)
{
    return (root(chaini) == chaini) ? vector::zero : offset_[chaini];
}


bool Foam::polymer::rigidImpactZones::merge
(
    const label chainA,
    const label chainB,
    const vector& shift
)
{
    add(chainA);
    add(chainB);
    const label a = root(chainA);
    const label b = root(chainB);
    const vector offsetA = offset(chainA);
    const vector offsetB = offset(chainB);

    // B's image by shift sits beside A: offset(B) = offset(A) + shift
    const vector mismatch = offsetA + shift - offsetB;
    if (a == b)
    {
        // Lattice translations differ by a whole lattice vector or not at
        // all: round-off of their sums is far below this
        return magSqr(mismatch) <= 1e-12*(1 + magSqr(offsetA) + magSqr(shift));
    }
    if (size_[a] < size_[b])
    {
        parent_[a] = b;
        offset_[a] = -mismatch;
        size_[b] += size_[a];
        held_[b] = held_[b] || held_[a];
    }
    else
    {
        parent_[b] = a;
        offset_[b] = mismatch;
        size_[a] += size_[b];
        held_[a] = held_[a] || held_[b];
    }
    return true;
}


Foam::labelListList Foam::polymer::rigidImpactZones::zones
(
    const polymerChains& chains
)
{
    labelList zoneOfRoot(parent_.size(), -1);
    DynamicList<DynamicList<label>> zones;
    forAll(parent_, c)
    {
        if (!inZone(c))
        {
            continue;
        }
        const label r = root(c);
        if (zoneOfRoot[r] < 0)
        {
            zoneOfRoot[r] = zones.size();
            zones.append(DynamicList<label>());
        }
        zones[zoneOfRoot[r]].append(c);
    }

    labelListList result(zones.size());
    forAll(zones, z)
    {
        result[z].transfer(zones[z]);
        std::sort
        (
            result[z].begin(),
            result[z].end(),
            [&](const label a, const label b)
            {
                return chains.globalId(a) < chains.globalId(b);
            }
        );
    }
    return result;
}


Foam::label Foam::polymer::rigidImpactZones::nChainsInZones() const
{
    label n = 0;
    for (const label p : parent_)
    {
        n += (p >= 0);
    }
    return n;
}


void Foam::polymer::rigidImpactZones::place
(
    polymerChains& chains,
    const labelUList& zoneChains,
    const scalar fraction,
    const UList<point>& positionsStart,
    const UList<point>& positionsAfter,
    const UList<vector>& velocitiesAfter,
    const UList<vector>& offsets
)
{
    List<point>& x = chains.positions();
    List<vector>& v = chains.velocities();
    const auto offsetOf = [&](const label k)
    {
        return offsets.empty() ? vector::zero : offsets[k];
    };

    // Centres of mass at the start and after the contacts, mean velocity
    scalar mass = 0;
    vector centreStart(Zero);
    vector centreAfter(Zero);
    vector momentum(Zero);
    forAll(zoneChains, k)
    {
        const label c = zoneChains[k];
        const vector shift = offsetOf(k);
        const scalar m = chains.type(c).beadMass();
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            mass += m;
            centreStart += m*(positionsStart[i] + shift);
            centreAfter += m*(positionsAfter[i] + shift);
            momentum += m*velocitiesAfter[i];
        }
    }
    centreStart /= mass;
    centreAfter /= mass;
    const vector meanVelocity = momentum/mass;
    const vector centre = centreStart + fraction*(centreAfter - centreStart);

    // The rotation of x^n closest to the contacts' positions (its fraction
    // of it), and the angular momentum of the contacts' state about its
    // centre of mass
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    Eigen::Vector3d angularMomentum = Eigen::Vector3d::Zero();
    forAll(zoneChains, k)
    {
        const label c = zoneChains[k];
        const vector shift = offsetOf(k);
        const scalar m = chains.type(c).beadMass();
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            const Eigen::Vector3d q =
                toEigen(positionsAfter[i] + shift - centreAfter);
            covariance += m*q
               *toEigen(positionsStart[i] + shift - centreStart).transpose();
            angularMomentum +=
                m*q.cross(toEigen(velocitiesAfter[i] - meanVelocity));
        }
    }
    Eigen::Matrix3d R = bestRotation(covariance);
    if (fraction != 1)
    {
        const Eigen::AngleAxisd turn(R);
        R = Eigen::AngleAxisd(fraction*turn.angle(), turn.axis())
            .toRotationMatrix();
    }

    Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
    forAll(zoneChains, k)
    {
        const label c = zoneChains[k];
        const vector shift = offsetOf(k);
        const scalar m = chains.type(c).beadMass();
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            const Eigen::Vector3d s =
                R*toEigen(positionsStart[i] + shift - centreStart);
            x[i] = centre + fromEigen(s) - shift;
            inertia += m*(s.squaredNorm()*Eigen::Matrix3d::Identity()
                - s*s.transpose());
        }
    }

    const vector omega =
        fromEigen(angularVelocity(inertia, angularMomentum));
    forAll(zoneChains, k)
    {
        const label c = zoneChains[k];
        const vector shift = offsetOf(k);
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            v[i] = meanVelocity + (omega ^ (x[i] + shift - centre));
        }
    }
}


// ************************************************************************* //
