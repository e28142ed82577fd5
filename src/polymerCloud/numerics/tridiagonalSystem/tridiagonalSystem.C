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
    const label m = middle();
    const scalar* l = lower_.cdata();
    const scalar* d = diagonal_.cdata();
    const scalar* u = upper_.cdata();
    scalar* pivot = pivot_.data();

    // Down rows 1 to m - 1 (row k) and up rows n - 2 to m + 1 (row j) in
    // one loop, for the two recurrences to overlap; the upward one has at
    // most one row fewer. The last pivots are carried in registers: the
    // compiler cannot tell that pivot does not alias the coefficients, and
    // a store and reload would lengthen the recurrences.
    scalar down = d[0];
    scalar up = d[n - 1];
    pivot[0] = down;
    pivot[n - 1] = up;
    for (label k = 1; k < m; ++k)
    {
        const label j = n - 1 - k;
        if (down == 0 || up == 0)
        {
            return false;
        }
        down = d[k] - l[k]*u[k - 1]/down;
        pivot[k] = down;
        if (j > m)
        {
            up = d[j] - u[j]*l[j + 1]/up;
            pivot[j] = up;
        }
    }

    // The middle row, eliminated from both sides
    scalar middlePivot = d[m];
    if (m > 0)
    {
        if (down == 0)
        {
            return false;
        }
        middlePivot -= l[m]*u[m - 1]/down;
    }
    if (m + 1 < n)
    {
        if (up == 0)
        {
            return false;
        }
        middlePivot -= u[m]*l[m + 1]/up;
    }
    if (middlePivot == 0)
    {
        return false;
    }
    pivot[m] = middlePivot;

    scalar* reciprocal = reciprocalPivot_.data();
    for (label i = 0; i < n; ++i)
    {
        reciprocal[i] = 1/pivot[i];
    }

    return true;
}


void Foam::tridiagonalSystem::substitute(UList<scalar>& rhs) const
{
    const label n = diagonal_.size();
    const label m = middle();
    const scalar* l = lower_.cdata();
    const scalar* u = upper_.cdata();
    const scalar* reciprocal = reciprocalPivot_.cdata();
    scalar* x = rhs.data();

    // To the middle row from both ends, as the elimination (the running
    // values in registers, as in factorise)
    scalar down = x[0];
    scalar up = x[n - 1];
    for (label k = 1; k < m; ++k)
    {
        const label j = n - 1 - k;
        down = x[k] - (l[k]*reciprocal[k - 1])*down;
        x[k] = down;
        if (j > m)
        {
            up = x[j] - (u[j]*reciprocal[j + 1])*up;
            x[j] = up;
        }
    }
    scalar xm = x[m];
    if (m > 0)
    {
        xm -= (l[m]*reciprocal[m - 1])*down;
    }
    if (m + 1 < n)
    {
        xm -= (u[m]*reciprocal[m + 1])*up;
    }
    xm *= reciprocal[m];
    x[m] = xm;

    // Out from the middle row both ways: up to row 0 (row i) and down to
    // row n - 1 (row j), which has at most one row fewer
    up = xm;
    down = xm;
    for (label k = 1; k <= m; ++k)
    {
        const label i = m - k;
        const label j = m + k;
        up = (x[i] - u[i]*up)*reciprocal[i];
        x[i] = up;
        if (j < n)
        {
            down = (x[j] - l[j]*down)*reciprocal[j];
            x[j] = down;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::tridiagonalSystem::resize(const label n)
{
    lower_.resize(n);
    diagonal_.resize(n);
    upper_.resize(n);
    source_.resize(n);
    pivot_.resize(n);
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
