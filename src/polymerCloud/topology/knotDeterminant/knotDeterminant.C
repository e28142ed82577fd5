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

#include "knotDeterminant.H"
#include "DynamicList.H"

#include <algorithm>
#include <cstdint>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef __int128 wide;

struct diagramCrossing
{
    double under;   //!< curve parameter (edge + fraction) of the under strand
    double over;    //!< curve parameter of the over strand
};


// base^e modulo p
int64_t powerModulo(int64_t base, int64_t e, const int64_t p)
{
    int64_t result = 1;
    base %= p;
    while (e)
    {
        if (e & 1)
        {
            result = wide(result)*base % p;
        }
        base = wide(base)*base % p;
        e >>= 1;
    }
    return result;
}


// Determinant modulo a prime by Gaussian elimination
int64_t determinantModulo(std::vector<std::vector<int64_t>> a, int64_t p)
{
    const size_t n = a.size();
    int64_t det = 1;

    for (size_t col = 0; col < n; ++col)
    {
        size_t pivot = col;
        while (pivot < n && a[pivot][col] == 0)
        {
            ++pivot;
        }
        if (pivot == n)
        {
            return 0;
        }
        if (pivot != col)
        {
            std::swap(a[pivot], a[col]);
            det = (p - det) % p;
        }
        det = wide(det)*a[col][col] % p;
        const int64_t inverse = powerModulo(a[col][col], p - 2, p);
        for (size_t row = col + 1; row < n; ++row)
        {
            if (a[row][col] == 0)
            {
                continue;
            }
            const int64_t factor = wide(a[row][col])*inverse % p;
            for (size_t k = col; k < n; ++k)
            {
                a[row][k] =
                    (a[row][k] - wide(factor)*a[col][k] % p + p) % p;
            }
        }
    }
    return det;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::knotDeterminant::compute
(
    const UList<point>& ring,
    const vector& direction,
    label& nCrossings
)
{
    const label n = ring.size();
    const vector d = direction/mag(direction);

    // Orthonormal basis of the projection plane
    vector e1 = (mag(d.x()) < 0.9) ? vector(1, 0, 0) : vector(0, 1, 0);
    e1 -= (e1 & d)*d;
    e1 /= mag(e1);
    const vector e2 = d ^ e1;

    List<scalar> px(n), py(n), depth(n);
    forAll(ring, i)
    {
        px[i] = ring[i] & e1;
        py[i] = ring[i] & e2;
        depth[i] = ring[i] & d;
    }

    DynamicList<diagramCrossing> crossings;
    for (label i = 0; i < n; ++i)
    {
        const label i1 = (i + 1) % n;
        for (label j = i + 2; j < n; ++j)
        {
            const label j1 = (j + 1) % n;
            if (j1 == i)
            {
                continue;
            }

            // Segment intersection in the plane
            const scalar rx = px[i1] - px[i], ry = py[i1] - py[i];
            const scalar sx = px[j1] - px[j], sy = py[j1] - py[j];
            const scalar denominator = rx*sy - ry*sx;
            if (denominator == 0)
            {
                continue;
            }
            const scalar qx = px[j] - px[i], qy = py[j] - py[i];
            const scalar alpha = (qx*sy - qy*sx)/denominator;
            const scalar beta = (qx*ry - qy*rx)/denominator;
            if (alpha < 0 || alpha >= 1 || beta < 0 || beta >= 1)
            {
                continue;
            }

            const scalar depthI = depth[i] + alpha*(depth[i1] - depth[i]);
            const scalar depthJ = depth[j] + beta*(depth[j1] - depth[j]);

            // The strand nearer the viewer (larger depth) is over
            if (depthI > depthJ)
            {
                crossings.append
                (
                    diagramCrossing{double(j) + beta, double(i) + alpha}
                );
            }
            else
            {
                crossings.append
                (
                    diagramCrossing{double(i) + alpha, double(j) + beta}
                );
            }
        }
    }

    nCrossings = crossings.size();
    if (nCrossings < 2)
    {
        return 1;
    }

    // Arcs run from one under-crossing to the next along the curve
    std::vector<double> unders;
    for (const diagramCrossing& c : crossings)
    {
        unders.push_back(c.under);
    }
    std::sort(unders.begin(), unders.end());
    const label nArcs = unders.size();

    // The arc holding curve parameter t starts at the last under <= t
    auto arcOf = [&](const double t) -> label
    {
        const auto it = std::upper_bound(unders.begin(), unders.end(), t);
        const label k = label(it - unders.begin()) - 1;
        return (k < 0) ? nArcs - 1 : k;
    };

    std::vector<std::vector<int64_t>> matrix
    (
        nArcs, std::vector<int64_t>(nArcs, 0)
    );
    forAll(crossings, ci)
    {
        const label k =
            label
            (
                std::lower_bound
                (
                    unders.begin(), unders.end(), crossings[ci].under
                )
              - unders.begin()
            );
        const label outgoing = k;
        const label incoming = (k + nArcs - 1) % nArcs;
        const label over = arcOf(crossings[ci].over);

        matrix[ci][over] += 2;
        matrix[ci][incoming] -= 1;
        matrix[ci][outgoing] -= 1;
    }

    // Remove the last row and column
    matrix.pop_back();
    for (std::vector<int64_t>& row : matrix)
    {
        row.pop_back();
    }

    const int64_t p1 = 2147483647;
    const int64_t p2 = 2147483629;
    std::vector<std::vector<int64_t>> m1(matrix), m2(matrix);
    for (auto* m : {&m1, &m2})
    {
        const int64_t p = (m == &m1) ? p1 : p2;
        for (std::vector<int64_t>& row : *m)
        {
            for (int64_t& value : row)
            {
                value = ((value % p) + p) % p;
            }
        }
    }
    const int64_t d1 = determinantModulo(m1, p1);
    const int64_t d2 = determinantModulo(m2, p2);

    // Chinese remainder: det = d1 + p1 k with det = d2 (mod p2)
    const int64_t k =
        wide(((d2 - d1) % p2 + p2) % p2)*powerModulo(p1 % p2, p2 - 2, p2)
      % p2;
    wide det = wide(d1) + wide(p1)*k;
    const wide modulus = wide(p1)*p2;
    if (det > modulus/2)
    {
        det -= modulus;
    }

    return label(det < 0 ? -det : det);
}


Foam::label Foam::polymer::knotDeterminant::compute(const UList<point>& ring)
{
    label nCrossings;
    return compute(ring, vector(0.3129, 0.4561, 0.8331), nCrossings);
}


// ************************************************************************* //
