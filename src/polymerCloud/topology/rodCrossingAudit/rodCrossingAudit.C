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
#include "rodsFartherThan.H"
#include "boxesMeet.H"
#include "autoPtr.H"

#include <algorithm>
#include <cmath>
#include <vector>
#include "boundBox.H"
#include "DynamicList.H"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

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


// Crossings by their rods' beads, the translation, then the piece
bool crossingOrder
(
    const Foam::polymer::rodCrossingAudit::crossing& a,
    const Foam::polymer::rodCrossingAudit::crossing& b
)
{
    const auto key = [](const Foam::polymer::rodCrossingAudit::crossing& c)
    {
        return std::make_tuple
        (
            c.rodA.first(), c.rodA.second(), c.rodB.first(), c.rodB.second(),
            c.shift.x(), c.shift.y(), c.shift.z(), c.piece
        );
    };
    return key(a) < key(b);
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::rodCrossingAudit::rodCrossingAudit
(
    const List<labelPair>& rods,
    const UList<vector>& lattice,
    const rodBoxPairs& candidates
)
:
    rods_(rods),
    shifts_(),
    candidates_(candidates)
{
    // Every combination of -2..2 of each lattice vector whose first
    // non-zero coefficient is positive: each image pair once
    DynamicList<vector> shifts;
    List<label> coefficient(lattice.size(), -2);
    label nCombinations = 1;
    for (label k = 0; k < lattice.size(); ++k)
    {
        nCombinations *= 5;
    }
    for (label combination = 0; combination < nCombinations; ++combination)
    {
        label code = combination;
        vector shift(Zero);
        label firstNonZero = 0;
        for (label k = 0; k < lattice.size(); ++k)
        {
            coefficient[k] = code % 5 - 2;
            code /= 5;
            shift += coefficient[k]*lattice[k];
            if (!firstNonZero)
            {
                firstNonZero = coefficient[k];
            }
        }
        if (firstNonZero > 0)
        {
            shifts.append(shift);
        }
    }
    shifts_.transfer(shifts);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

//- The four beads of a rod pair at time fraction t of a straight piece
struct pairPiece
{
    vec p0[4];
    vec p1[4];

    real value(const real t) const
    {
        const vec xi = at(p0[0], p1[0], t);
        const vec xi1 = at(p0[1], p1[1], t);
        const vec xj = at(p0[2], p1[2], t);
        const vec xj1 = at(p0[3], p1[3], t);
        return dot(xi - xj, cross(xi1 - xi, xj1 - xj));
    }

    //- Do the lines meet within both rods at t?
    bool meetWithinRods(const real t) const
    {
        const vec xi = at(p0[0], p1[0], t);
        const vec xj = at(p0[2], p1[2], t);
        const vec u = at(p0[1], p1[1], t) - xi;
        const vec w = at(p0[3], p1[3], t) - xj;
        const vec d = xi - xj;
        const real uu = dot(u, u), uw = dot(u, w), ww = dot(w, w);
        const real det = uu*ww - uw*uw;
        if (det <= 1e-18L*uu*ww)
        {
            return false;
        }
        const real li = (uw*dot(w, d) - ww*dot(u, d))/det;
        const real lj = (uu*dot(w, d) - uw*dot(u, d))/det;
        return li >= 0 && li <= 1 && lj >= 0 && lj <= 1;
    }

    //- Round-off scale of V: |b| |c| (|b| + |c|) times a small factor
    real roundOff() const
    {
        const real b = std::sqrt(dot(p0[1] - p0[0], p0[1] - p0[0]));
        const real c = std::sqrt(dot(p0[3] - p0[2], p0[3] - p0[2]));
        return 1e-10L*b*c*(b + c);
    }

    //- Is V within the tolerance all over [t0, t1]? (sampled at five
    //  points: the intervals asked about are those between a root and a
    //  contact, short on the cubic's scale)
    bool withinRoundOff
    (
        const real t0,
        const real t1,
        const real tolerance
    ) const
    {
        for (int k = 0; k <= 4; ++k)
        {
            if (std::abs(value(t0 + (t1 - t0)*k/4)) > tolerance)
            {
                return false;
            }
        }
        return true;
    }

    //- Sign changes of V in (0, 1), in order: (fraction, sign after)
    void roots(Foam::DynamicList<std::pair<real, int>>& found) const;
};


void pairPiece::roots(Foam::DynamicList<std::pair<real, int>>& found) const
{
    found.clear();

    // V at t = 0, 1/3, 2/3, 1 determines the cubic and its Bernstein
    // coefficients
    const real v0 = value(0), v1 = value(real(1)/3);
    const real v2 = value(real(2)/3), v3 = value(1);

    struct piece
    {
        real b[4];
        real t0, t1;
    };
    Foam::DynamicList<piece> stack;
    stack.append
    (
        piece
        {
            {
                v0,
                (-5*v0 + 18*v1 - 9*v2 + 2*v3)/6,
                (2*v0 - 9*v1 + 18*v2 - 5*v3)/6,
                v3
            },
            0,
            1
        }
    );

    // Depth first, earliest piece first
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
            if ((p.b[0] < 0) != (p.b[3] < 0))
            {
                found.append({(p.t0 + p.t1)/2, p.b[3] < 0 ? -1 : 1});
            }
            continue;
        }

        const real* b = p.b;
        const real b01 = (b[0] + b[1])/2, b12 = (b[1] + b[2])/2;
        const real b23 = (b[2] + b[3])/2;
        const real b012 = (b01 + b12)/2, b123 = (b12 + b23)/2;
        const real mid = (b012 + b123)/2;
        const real tm = (p.t0 + p.t1)/2;

        stack.append(piece{{mid, b123, b23, b[3]}, tm, p.t1});
        stack.append(piece{{b[0], b01, b012, mid}, p.t0, tm});
    }
}

} // End anonymous namespace


void Foam::polymer::rodCrossingAudit::checkPair
(
    const labelPair& a,
    const labelPair& b,
    const vector& shift,
    const UList<UList<point>>& path,
    DynamicList<crossing>& found
) const
{
    const label beads[4] = {a.first(), a.second(), b.first(), b.second()};

    // The sign of V followed along the path; 0 while not yet definite
    int lastSign = 0;
    DynamicList<std::pair<real, int>> roots;

    for (label k = 0; k + 1 < path.size(); ++k)
    {
        pairPiece piece;
        for (int m = 0; m < 4; ++m)
        {
            const vector& image = (m < 2) ? vector::zero : shift;
            piece.p0[m] = toVec(path[k][beads[m]] + image);
            piece.p1[m] = toVec(path[k + 1][beads[m]] + image);
        }
        const real tolerance = piece.roundOff();
        const real start = piece.value(0);
        const real end = piece.value(1);

        // A change of sign across a contact at the piece's start
        if (std::abs(start) > tolerance)
        {
            const int sign = start < 0 ? -1 : 1;
            if (lastSign && sign != lastSign && piece.meetWithinRods(0))
            {
                found.append(crossing{a, b, k, 0, shift});
            }
            lastSign = sign;
        }

        piece.roots(roots);
        real contact = -1;
        for (const std::pair<real, int>& root : roots)
        {
            // A root at a contact at either end, V within round-off of
            // zero all the way from the root to that end, is round-off
            // about zero: the sign is followed across the contact instead.
            // (The root's distance from the end as a fraction of the piece
            // says nothing of this: two events can be 1e-7 of a step
            // apart, and a root 1e-8 of that piece before its end is still
            // a contact.)
            if
            (
                piece.withinRoundOff(0, root.first, tolerance)
             || piece.withinRoundOff(root.first, 1, tolerance)
            )
            {
                contact = root.first;
                continue;
            }
            if (lastSign && root.second != lastSign)
            {
                if (piece.meetWithinRods(root.first))
                {
                    found.append
                    (
                        crossing{a, b, k, scalar(root.first), shift}
                    );
                }
            }
            lastSign = root.second;
        }

        // A change of sign across a contact at the piece's start, seen at
        // its definite end
        if (std::abs(end) > tolerance)
        {
            const int sign = end < 0 ? -1 : 1;
            const real at = (contact >= 0) ? contact : 0;
            if (lastSign && sign != lastSign && piece.meetWithinRods(at))
            {
                found.append(crossing{a, b, k, scalar(at), shift});
            }
            lastSign = sign;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::polymer::rodCrossingAudit::crossing>
Foam::polymer::rodCrossingAudit::checkPath
(
    const UList<UList<point>>& path,
    const boolList& rodsToCheck
) const
{
    // No rod to check (a pass after the contacts that placed no zone):
    // no boxes or grid to build
    if (!rodsToCheck.empty() && !rodsToCheck.found(true))
    {
        return List<crossing>();
    }

    // Boxes swept over the whole path, the rods whose beads move along
    // it (a pair of two rods that stay put keeps its V and cannot cross),
    // and how far a point of each rod moves from its first configuration
    // at most: the sum over the pieces of its beads' larger displacement.
    // Most rods of a re-projection's audit stay put (few chains were
    // re-projected): such a rod's box is its beads' and its reach zero,
    // with no piece's displacements or square roots
    boolList moves(rods_.size(), false);
    scalarList reach(rods_.size(), Zero);
    List<boundBox> boxes(rods_.size());
    forAll(rods_, rodi)
    {
        const label i = rods_[rodi].first(), j = rods_[rodi].second();
        boxes[rodi] = boundBox(path[0][i]);
        boxes[rodi].add(path[0][j]);
        for (label k = 1; k < path.size(); ++k)
        {
            moves[rodi] =
                moves[rodi] || path[k][i] != path[0][i]
             || path[k][j] != path[0][j];
        }
        if (!moves[rodi])
        {
            continue;
        }
        for (label k = 0; k + 1 < path.size(); ++k)
        {
            boxes[rodi].add(path[k + 1][i]);
            boxes[rodi].add(path[k + 1][j]);
            reach[rodi] +=
                max
                (
                    mag(path[k + 1][i] - path[k][i]),
                    mag(path[k + 1][j] - path[k][j])
                );
        }
    }

    // Rods every pair to check has one of: a rod to check, or without
    // those a rod that moves (two rods that stay put cannot cross; where
    // few chains were re-projected most rods stay put)
    const boolList& origin = rodsToCheck.empty() ? moves : rodsToCheck;

    DynamicList<crossing> found;
    // Candidates: the collisions' listed pairs, and a grid of the boxes
    // looked up from the rods they do not hold apart (every rod without
    // them), a pair from its first such rod
    const boolList held(candidates_.heldApart(rods_, path[0], reach));
    autoPtr<boxGrid> grid;
    if (held.size())
    {
        checkListed(boxes, moves, origin, reach, path, found);
    }
    if (held.empty() || held.found(false))
    {
        grid.reset(new boxGrid(boxes));
        checkNear(grid(), boxes, moves, origin, held, reach, path, found);
    }

    // The images, where the rods' box meets its translate (formed only
    // with the lattice)
    boundBox all;
    if (shifts_.size())
    {
        for (const boundBox& box : boxes)
        {
            all.add(box);
        }
    }
    for (const vector& shift : shifts_)
    {
        if (all.overlaps(boundBox(all.min() + shift, all.max() + shift)))
        {
            if (!grid.valid())
            {
                grid.reset(new boxGrid(boxes));
            }
            checkImages
            (
                shift, boxes, moves, reach, rodsToCheck, grid(), path, found
            );
        }
    }

    // The grid lists the pairs in the order of its cells, which changes
    // with their size; the re-projection adds its contacts in the order
    // of the crossings, so they are listed by their rods, translation and
    // piece instead, an order of the rods alone
    std::stable_sort(found.begin(), found.end(), crossingOrder);
    return List<crossing>(std::move(found));
}


void Foam::polymer::rodCrossingAudit::checkIfNear
(
    const label a,
    const label b,
    const scalarList& reach,
    const UList<UList<point>>& path,
    DynamicList<crossing>& found
) const
{
    const labelPair& ra = rods_[a];
    const labelPair& rb = rods_[b];
    if
    (
        !rodsFartherThan
        (
            path[0][ra.first()], path[0][ra.second()],
            path[0][rb.first()], path[0][rb.second()],
            reach[a] + reach[b]
        )
    )
    {
        checkPair(ra, rb, vector::zero, path, found);
    }
}


void Foam::polymer::rodCrossingAudit::checkNear
(
    const boxGrid& grid,
    const UList<boundBox>& boxes,
    const boolList& moves,
    const boolList& origin,
    const boolList& held,
    const scalarList& reach,
    const UList<UList<point>>& path,
    DynamicList<crossing>& found
) const
{
    // Looked up from the rods every pair to check has one of: without
    // the listed pairs the origins, with them the rods not held apart,
    // whose partners are the unlisted rods. The grid meets most rods only
    // to pass them over, so the cheap tests (the pair's order, a rod that
    // moves, no shared bead, the boxes: toCheck) are combined without
    // branches, which a crowd's unpredictable outcomes would mispredict
    const bool withListed = held.size();
    const boolList& from = withListed ? held : origin;
    const bool fromIfSet = !withListed;
    forAll(rods_, a)
    {
        if (from[a] != fromIfSet)
        {
            continue;
        }
        grid.forNear
        (
            boxes[a],
            [&](const label b)
            {
                if
                (
                    ((b > a) | (from[b] != fromIfSet))
                  & toCheck(a, b, boxes, moves, origin)
                  && !(withListed && candidates_.listed(a, b))
                )
                {
                    checkIfNear(min(a, b), max(a, b), reach, path, found);
                }
            }
        );
    }
}


void Foam::polymer::rodCrossingAudit::checkListed
(
    const UList<boundBox>& boxes,
    const boolList& moves,
    const boolList& origin,
    const scalarList& reach,
    const UList<UList<point>>& path,
    DynamicList<crossing>& found
) const
{
    // The pairs the grid's look-ups would take, by the same tests: each
    // listed pair is one unordered pair of rods. A pair with no rod in
    // origin (none of the chains re-projected since the last pass) is
    // passed over first, before its translation and boxes are read
    const UList<labelPair>& pairs = candidates_.pairs();
    forAll(pairs, pairi)
    {
        const label a = min(pairs[pairi].first(), pairs[pairi].second());
        const label b = max(pairs[pairi].first(), pairs[pairi].second());
        if
        (
            !(origin[a] || origin[b])
         || candidates_.shift(pairi) != vector::zero
        )
        {
            continue;
        }
        if (toCheck(a, b, boxes, moves, origin))
        {
            checkIfNear(a, b, reach, path, found);
        }
    }
}


void Foam::polymer::rodCrossingAudit::checkImages
(
    const vector& shift,
    const UList<boundBox>& boxes,
    const boolList& moves,
    const scalarList& reach,
    const boolList& rodsToCheck,
    const boxGrid& grid,
    const UList<UList<point>>& path,
    DynamicList<crossing>& found
) const
{
    // Every ordered pair (a, image of b): (b, image of a by -shift) is the
    // same pair, and -shift is not listed. A rod's own image is its
    // translate, parallel to it: it cannot cross it. The grid is asked
    // with a's box moved back by shift, a little larger than round-off
    forAll(rods_, a)
    {
        const boundBox& boxA = boxes[a];
        const vector margin
        (
            vector::uniform
            (
                1e-9*(cmptMax(cmptMag(boxA.max())) + mag(shift))
              + VSMALL
            )
        );
        const boundBox query
        (
            boxA.min() - shift - margin, boxA.max() - shift + margin
        );
        grid.forNear
        (
            query,
            [&](const label b)
            {
                const boundBox imageB
                (
                    boxes[b].min() + shift, boxes[b].max() + shift
                );
                if
                (
                    b != a && (moves[a] || moves[b])
                 && (rodsToCheck.empty() || rodsToCheck[a] || rodsToCheck[b])
                 && boxA.overlaps(imageB)
                 && !rodsFartherThan
                    (
                        path[0][rods_[a].first()], path[0][rods_[a].second()],
                        path[0][rods_[b].first()] + shift,
                        path[0][rods_[b].second()] + shift,
                        reach[a] + reach[b]
                    )
                )
                {
                    checkPair(rods_[a], rods_[b], shift, path, found);
                }
            }
        );
    }
}


Foam::List<Foam::polymer::rodCrossingAudit::crossing>
Foam::polymer::rodCrossingAudit::check
(
    const UList<List<point>>& path,
    const boolList& rodsToCheck
) const
{
    List<UList<point>> views(path.size());
    forAll(path, k)
    {
        views[k].shallowCopy(path[k]);
    }
    return checkPath(views, rodsToCheck);
}


Foam::List<Foam::polymer::rodCrossingAudit::crossing>
Foam::polymer::rodCrossingAudit::check
(
    const UList<point>& start,
    const UList<point>& end,
    const boolList& rodsToCheck
) const
{
    List<UList<point>> path(2);
    path[0].shallowCopy(start);
    path[1].shallowCopy(end);
    return checkPath(path, rodsToCheck);
}


// ************************************************************************* //
