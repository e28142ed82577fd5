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

#include "rodCrossingAudit.H"
#include "boundBox.H"
#include "DynamicList.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

typedef long double real;

struct vec
{
    real x, y, z;
};

inline vec operator-(const vec& a, const vec& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

inline vec cross(const vec& a, const vec& b)
{
    return {a.y*b.z - a.z*b.y, a.z*b.x - a.x*b.z, a.x*b.y - a.y*b.x};
}

inline real dot(const vec& a, const vec& b)
{
    return a.x*b.x + a.y*b.y + a.z*b.z;
}

inline vec toVec(const Foam::point& p)
{
    return {p.x(), p.y(), p.z()};
}

inline vec at(const vec& a, const vec& b, const real t)
{
    return {a.x + t*(b.x - a.x), a.y + t*(b.y - a.y), a.z + t*(b.z - a.z)};
}

inline real bernsteinValue(const real b[4], const real t)
{
    const real s = 1 - t;
    return s*s*s*b[0] + 3*s*s*t*b[1] + 3*s*t*t*b[2] + t*t*t*b[3];
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rodCrossingAudit::rodCrossingAudit(const List<labelPair>& rods)
:
    rods_(rods)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::rodCrossingAudit::crosses
(
    const labelPair& a,
    const labelPair& b,
    const UList<point>& start,
    const UList<point>& end,
    scalar& fraction
) const
{
    const vec p0[4] =
    {
        toVec(start[a.first()]), toVec(start[a.second()]),
        toVec(start[b.first()]), toVec(start[b.second()])
    };
    const vec p1[4] =
    {
        toVec(end[a.first()]), toVec(end[a.second()]),
        toVec(end[b.first()]), toVec(end[b.second()])
    };

    // V(t) at t = 0, 1/3, 2/3, 1 determines the cubic; its Bernstein
    // coefficients follow from these four values
    real value[4];
    for (int k = 0; k < 4; ++k)
    {
        const real t = real(k)/3;
        const vec xi = at(p0[0], p1[0], t);
        const vec xi1 = at(p0[1], p1[1], t);
        const vec xj = at(p0[2], p1[2], t);
        const vec xj1 = at(p0[3], p1[3], t);
        value[k] = dot(xi - xj, cross(xi1 - xi, xj1 - xj));
    }
    real coeffs[4] =
    {
        value[0],
        (-5*value[0] + 18*value[1] - 9*value[2] + 2*value[3])/6,
        (2*value[0] - 9*value[1] + 18*value[2] - 5*value[3])/6,
        value[3]
    };

    // Depth-first subdivision, earliest interval first
    struct piece
    {
        real b[4];
        real t0, t1;
    };
    DynamicList<piece> stack;
    stack.append(piece{{coeffs[0], coeffs[1], coeffs[2], coeffs[3]}, 0, 1});

    while (stack.size())
    {
        const piece p = stack.remove();
        const real lo = std::min({p.b[0], p.b[1], p.b[2], p.b[3]});
        const real hi = std::max({p.b[0], p.b[1], p.b[2], p.b[3]});
        if (lo > 0 || hi < 0)
        {
            continue;
        }

        if (p.t1 - p.t0 < 1e-13L)
        {
            // A pass-through needs a sign change across the root
            if (p.b[0]*p.b[3] > 0)
            {
                continue;
            }

            const real t = (p.t0 + p.t1)/2;
            const vec xi = at(p0[0], p1[0], t);
            const vec xj = at(p0[2], p1[2], t);
            const vec u = at(p0[1], p1[1], t) - xi;
            const vec w = at(p0[3], p1[3], t) - xj;
            const vec d = xi - xj;
            const real uu = dot(u, u), uw = dot(u, w), ww = dot(w, w);
            const real det = uu*ww - uw*uw;
            if (det <= 1e-18L*uu*ww)
            {
                continue;
            }
            const real li = (uw*dot(w, d) - ww*dot(u, d))/det;
            const real lj = (uu*dot(w, d) - uw*dot(u, d))/det;
            if (li >= 0 && li <= 1 && lj >= 0 && lj <= 1)
            {
                fraction = scalar(t);
                return true;
            }
            continue;
        }

        // de Casteljau at the midpoint
        const real* b = p.b;
        const real b01 = (b[0] + b[1])/2, b12 = (b[1] + b[2])/2;
        const real b23 = (b[2] + b[3])/2;
        const real b012 = (b01 + b12)/2, b123 = (b12 + b23)/2;
        const real mid = (b012 + b123)/2;
        const real tm = (p.t0 + p.t1)/2;

        stack.append(piece{{mid, b123, b23, b[3]}, tm, p.t1});
        stack.append(piece{{b[0], b01, b012, mid}, p.t0, tm});
    }

    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::rodCrossingAudit::crossing> Foam::rodCrossingAudit::check
(
    const UList<point>& start,
    const UList<point>& end
) const
{
    List<boundBox> boxes(rods_.size());
    forAll(rods_, rodi)
    {
        boxes[rodi] = boundBox(start[rods_[rodi].first()]);
        boxes[rodi].add(start[rods_[rodi].second()]);
        boxes[rodi].add(end[rods_[rodi].first()]);
        boxes[rodi].add(end[rods_[rodi].second()]);
    }

    // Sweep along x: sort the boxes by their lower x bound
    labelList order(rods_.size());
    forAll(order, i)
    {
        order[i] = i;
    }
    std::sort
    (
        order.begin(),
        order.end(),
        [&](const label a, const label b)
        {
            return boxes[a].min().x() < boxes[b].min().x();
        }
    );

    DynamicList<crossing> found;
    forAll(order, oi)
    {
        const label a = order[oi];
        for (label oj = oi + 1; oj < order.size(); ++oj)
        {
            const label b = order[oj];
            if (boxes[b].min().x() > boxes[a].max().x())
            {
                break;
            }
            const labelPair& ra = rods_[a];
            const labelPair& rb = rods_[b];
            if
            (
                ra.first() == rb.first() || ra.first() == rb.second()
             || ra.second() == rb.first() || ra.second() == rb.second()
             || !boxes[a].overlaps(boxes[b])
            )
            {
                continue;
            }
            scalar fraction;
            if (crosses(ra, rb, start, end, fraction))
            {
                found.append(crossing{ra, rb, fraction});
            }
        }
    }

    return List<crossing>(std::move(found));
}


// ************************************************************************* //
