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

#include "tridiagonalSystem.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::tridiagonalSystem::thomas(UList<scalar>& rhs)
{
    const label n = diagonal_.size();
    scalar* factor = factor_.data();

    scalar pivot = diagonal_[0];
    if (pivot == 0)
    {
        return false;
    }
    factor[0] = upper_[0]/pivot;
    rhs[0] /= pivot;

    for (label i = 1; i < n; ++i)
    {
        pivot = diagonal_[i] - lower_[i]*factor[i - 1];
        if (pivot == 0)
        {
            return false;
        }
        factor[i] = upper_[i]/pivot;
        rhs[i] = (rhs[i] - lower_[i]*rhs[i - 1])/pivot;
    }

    for (label i = n - 2; i >= 0; --i)
    {
        rhs[i] -= factor[i]*rhs[i + 1];
    }

    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tridiagonalSystem::resize(const label n)
{
    lower_.resize(n);
    diagonal_.resize(n);
    upper_.resize(n);
    source_.resize(n);
    factor_.resize(n);
    correction_.resize(n);
}


bool Foam::tridiagonalSystem::solve(const bool cyclic)
{
    const label n = diagonal_.size();

    if (!cyclic || n < 3)
    {
        return thomas(source_);
    }

    // Sherman-Morrison: A = T + u v^T with T tridiagonal,
    // u = (gamma, 0, ..., 0, upper[n-1]), v = (1, 0, ..., 0, lower[0]/gamma)
    const scalar cornerLow = lower_[0];
    const scalar cornerHigh = upper_[n - 1];
    const scalar gamma = -diagonal_[0];

    diagonal_[0] -= gamma;
    diagonal_[n - 1] -= cornerLow*cornerHigh/gamma;

    correction_ = Zero;
    correction_[0] = gamma;
    correction_[n - 1] = cornerHigh;

    const bool ok = thomas(source_) && thomas(correction_);

    diagonal_[0] += gamma;
    diagonal_[n - 1] += cornerLow*cornerHigh/gamma;

    if (!ok)
    {
        return false;
    }

    const scalar denominator =
        1 + correction_[0] + cornerLow*correction_[n - 1]/gamma;
    if (denominator == 0)
    {
        return false;
    }

    const scalar weight =
        (source_[0] + cornerLow*source_[n - 1]/gamma)/denominator;

    for (label i = 0; i < n; ++i)
    {
        source_[i] -= weight*correction_[i];
    }

    return true;
}


// ************************************************************************* //
