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

bool Foam::polymer::tridiagonalSystem::eliminate(UList<scalar>& rhs)
{
    const label n = diagonal_.size();
    const label m = middle();
    const scalar* l = lower_.cdata();
    const scalar* d = diagonal_.cdata();
    const scalar* u = upper_.cdata();
    scalar* reciprocal = reciprocalPivot_.data();
    scalar* x = rhs.data();

    if (d[0] == 0 || d[n - 1] == 0)
    {
        return false;
    }

    // Down rows 1 to m - 1 (row k) and up rows n - 2 to m + 1 (row j) in
    // one loop, for the recurrences to overlap; the upward one has at most
    // one row fewer. The running values are carried in registers: the
    // compiler cannot tell that the arrays do not alias, and a store and
    // reload would lengthen the recurrences.
    scalar down = 1/d[0];
    scalar up = 1/d[n - 1];
    scalar xDown = x[0];
    scalar xUp = x[n - 1];
    reciprocal[0] = down;
    reciprocal[n - 1] = up;
    for (label k = 1; k < m; ++k)
    {
        const scalar pivot = d[k] - (l[k]*u[k - 1])*down;
        xDown = x[k] - (l[k]*down)*xDown;
        x[k] = xDown;
        if (pivot == 0)
        {
            return false;
        }
        down = 1/pivot;
        reciprocal[k] = down;

        const label j = n - 1 - k;
        if (j > m)
        {
            const scalar pivot = d[j] - (u[j]*l[j + 1])*up;
            xUp = x[j] - (u[j]*up)*xUp;
            x[j] = xUp;
            if (pivot == 0)
            {
                return false;
            }
            up = 1/pivot;
            reciprocal[j] = up;
        }
    }

    // The middle row, eliminated from both sides
    scalar pivot = d[m];
    scalar xm = x[m];
    if (m > 0)
    {
        pivot -= (l[m]*u[m - 1])*down;
        xm -= (l[m]*down)*xDown;
    }
    if (m + 1 < n)
    {
        pivot -= (u[m]*l[m + 1])*up;
        xm -= (u[m]*up)*xUp;
    }
    if (pivot == 0)
    {
        return false;
    }
    reciprocal[m] = 1/pivot;
    x[m] = xm*reciprocal[m];

    return true;
}


void
Foam::polymer::tridiagonalSystem::forwardSubstitute(UList<scalar>& rhs) const
{
    const label n = diagonal_.size();
    const label m = middle();
    const scalar* l = lower_.cdata();
    const scalar* u = upper_.cdata();
    const scalar* reciprocal = reciprocalPivot_.cdata();
    scalar* x = rhs.data();

    // As in eliminate
    scalar xDown = x[0];
    scalar xUp = x[n - 1];
    for (label k = 1; k < m; ++k)
    {
        const label j = n - 1 - k;
        xDown = x[k] - (l[k]*reciprocal[k - 1])*xDown;
        x[k] = xDown;
        if (j > m)
        {
            xUp = x[j] - (u[j]*reciprocal[j + 1])*xUp;
            x[j] = xUp;
        }
    }

    scalar xm = x[m];
    if (m > 0)
    {
        xm -= (l[m]*reciprocal[m - 1])*xDown;
    }
    if (m + 1 < n)
    {
        xm -= (u[m]*reciprocal[m + 1])*xUp;
    }
    x[m] = xm*reciprocal[m];
}


void Foam::polymer::tridiagonalSystem::backSubstitute(UList<scalar>& rhs) const
{
    const label n = diagonal_.size();
    const label m = middle();
    const scalar* l = lower_.cdata();
    const scalar* u = upper_.cdata();
    const scalar* reciprocal = reciprocalPivot_.cdata();
    scalar* x = rhs.data();

    // Up to row 0 (row i) and down to row n - 1 (row j), which has at most
    // one row fewer
    scalar xUp = x[m];
    scalar xDown = x[m];
    for (label k = 1; k <= m; ++k)
    {
        const label i = m - k;
        const label j = m + k;
        xUp = (x[i] - u[i]*xUp)*reciprocal[i];
        x[i] = xUp;
        if (j < n)
        {
            xDown = (x[j] - l[j]*xDown)*reciprocal[j];
            x[j] = xDown;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::tridiagonalSystem::resize(const label n)
{
    lower_.resize(n);
    diagonal_.resize(n);
    upper_.resize(n);
    source_.resize(n);
    reciprocalPivot_.resize(n);
    correction_.resize(n);
}


bool Foam::polymer::tridiagonalSystem::solve(const bool cyclic)
{
    const label n = diagonal_.size();

    if (!cyclic || n < 3)
    {
        if (!eliminate(source_))
        {
            return false;
        }
        backSubstitute(source_);
        return true;
    }

    // Sherman-Morrison: A = T + u v^T with T tridiagonal,
    // u = (gamma, 0, ..., 0, upper[n-1]), v = (1, 0, ..., 0, lower[0]/gamma)
    const scalar cornerLow = lower_[0];
    const scalar cornerHigh = upper_[n - 1];
    const scalar gamma = -diagonal_[0];

    diagonal_[0] -= gamma;
    diagonal_[n - 1] -= cornerLow*cornerHigh/gamma;

    const bool eliminated = eliminate(source_);

    diagonal_[0] += gamma;
    diagonal_[n - 1] += cornerLow*cornerHigh/gamma;

    if (!eliminated)
    {
        return false;
    }

    correction_ = Zero;
    correction_[0] = gamma;
    correction_[n - 1] = cornerHigh;
    forwardSubstitute(correction_);

    backSubstitute(source_);
    backSubstitute(correction_);

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
