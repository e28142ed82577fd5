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

#include "rodVelocityProjection.H"
#include "maxOrNaN.H"

// * * * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * //

void Foam::polymer::rodVelocityProjection::padRods
(
    const vector* x,
    const chainType& type,
    DynamicList<vector>& rods
)
{
    const label n = type.nBeads();
    const label nRods = type.nRods();

    rods.resize(nRods + 2);
    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        rods[k + 1] = x[j] - x[k];
    }
    rods[0] = type.ring() ? rods[nRods] : vector::zero;
    rods[nRods + 1] = type.ring() ? rods[1] : vector::zero;
}


void Foam::polymer::rodVelocityProjection::padSolution
(
    const UList<scalar>& solution,
    const chainType& type,
    DynamicList<scalar>& padded
)
{
    const label nRods = type.nRods();

    padded.resize(nRods + 2);
    for (label k = 0; k < nRods; ++k)
    {
        padded[k + 1] = solution[k];
    }
    padded[0] = type.ring() ? solution[nRods - 1] : 0;
    padded[nRods + 1] = type.ring() ? solution[0] : 0;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //


Foam::scalar Foam::polymer::rodVelocityProjection::kick
(
    vector* w,
    const chainType& type
) const
{
    const label n = type.nBeads();

    // r[k] is rod k and m[k] its kick, r[k - 1], m[k - 1] its neighbour's:
    // bead i's w changes by m[i] r[i] - m[i - 1] r[i - 1]
    const vector* r = rods_.cdata() + 1;
    const scalar* m = multipliers_.cdata() + 1;

    // Each rod's relative component once both its beads have their kicks
    scalar largest = 0;
    w[0] += m[0]*r[0] - m[-1]*r[-1];
    for (label k = 0; k + 1 < n; ++k)
    {
        w[k + 1] += m[k + 1]*r[k + 1] - m[k]*r[k];
        largest = maxOrNaN(largest, mag(r[k] & (w[k + 1] - w[k])));
    }
    if (type.ring())
    {
        largest = maxOrNaN(largest, mag(r[n - 1] & (w[0] - w[n - 1])));
    }

    return largest;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::rodVelocityProjection::project
(
    const vector* x,
    const chainType& type,
    vector* w,
    scalar& largest
)
{
    const label n = type.nBeads();
    const label nRods = type.nRods();

    system_.resize(nRods);
    padRods(x, type, rods_);

    // r[k] is rod k, r[k - 1] and r[k + 1] its neighbours
    const vector* r = rods_.cdata() + 1;
    scalar* lower = system_.lower().data();
    scalar* diagonal = system_.diagonal().data();
    scalar* upper = system_.upper().data();
    scalar* source = system_.source().data();

    for (label k = 0; k < nRods; ++k)
    {
        const label j = (k + 1 < n) ? k + 1 : 0;
        lower[k] = -(r[k] & r[k - 1]);
        diagonal[k] = 2*(r[k] & r[k]);
        upper[k] = -(r[k] & r[k + 1]);
        source[k] = r[k] & (w[j] - w[k]);
    }

    // A failed solve leaves w, and has its residual measured
    const bool solved = system_.solve(type.ring());
    if (solved)
    {
        padSolution(system_.source(), type, multipliers_);
    }
    else
    {
        multipliers_.resize(nRods + 2);
        multipliers_ = Zero;
    }
    largest = kick(w, type);

    return solved;
}


// ************************************************************************* //
