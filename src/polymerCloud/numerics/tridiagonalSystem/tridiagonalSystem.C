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

bool Foam::tridiagonalSystem::factorise()
{
    const label n = diagonal_.size();
    scalar* reciprocal = reciprocalPivot_.data();

    scalar pivot = diagonal_[0];
    if (pivot == 0)
    {
        return false;
    }
    reciprocal[0] = 1/pivot;

    for (label i = 1; i < n; ++i)
    {
        pivot = diagonal_[i] - (lower_[i]*upper_[i - 1])/pivot;
        if (pivot == 0)
        {
            return false;
        }
        reciprocal[i] = 1/pivot;
    }

    return true;
}


void Foam::tridiagonalSystem::substitute(UList<scalar>& rhs) const
{
    const label n = diagonal_.size();
    const scalar* reciprocal = reciprocalPivot_.cdata();

    // L y = rhs, with L's multipliers lower_i/pivot_{i-1}
    for (label i = 1; i < n; ++i)
    {
        rhs[i] -= (lower_[i]*reciprocal[i - 1])*rhs[i - 1];
    }

    // U x = y
    rhs[n - 1] *= reciprocal[n - 1];
    for (label i = n - 2; i >= 0; --i)
    {
        rhs[i] = (rhs[i] - upper_[i]*rhs[i + 1])*reciprocal[i];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tridiagonalSystem::resize(const label n)
{
    lower_.resize(n);
    diagonal_.resize(n);
    upper_.resize(n);
    source_.resize(n);
    reciprocalPivot_.resize(n);
    correction_.resize(n);
}


bool Foam::tridiagonalSystem::solve(const bool cyclic)
{
    const label n = diagonal_.size();

    if (!cyclic || n < 3)
    {
        if (!factorise())
        {
            return false;
        }
        substitute(source_);
        return true;
    }

    // Sherman-Morrison: A = T + u v^T with T tridiagonal,
    // u = (gamma, 0, ..., 0, upper[n-1]), v = (1, 0, ..., 0, lower[0]/gamma)
    const scalar cornerLow = lower_[0];
    const scalar cornerHigh = upper_[n - 1];
    const scalar gamma = -diagonal_[0];

    diagonal_[0] -= gamma;
    diagonal_[n - 1] -= cornerLow*cornerHigh/gamma;

    const bool factorised = factorise();

    diagonal_[0] += gamma;
    diagonal_[n - 1] += cornerLow*cornerHigh/gamma;

    if (!factorised)
    {
        return false;
    }

    correction_ = Zero;
    correction_[0] = gamma;
    correction_[n - 1] = cornerHigh;

    substitute(source_);
    substitute(correction_);

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
