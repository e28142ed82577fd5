/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    The cell search (cellLocator::findTet) in a box of 10^3 cells, in units
    of the cell (tests/cases/wallBox) and in metres with cells of 1 um
    (tests/cases/micrometreBox, where every tet's edge determinant, about
    1e-19, is below OpenFOAM's SMALL, 1e-15): of 20000 random points, each
    found by a tree search and then moved by up to 0.3 cells and found
    again from its tet,
    - the tet found is in the cell holding the point (the box's cells are
      known: cell = ix + 10 iy + 100 iz);
    - the barycentric coordinates are none below -SMALL and give the
      point back from the tet's vertices to round-off (1e-12 cells: the
      tets' edge matrices have condition numbers of order 10);
    - the same tet and coordinates, to the bit, from the search that
      starts at the tet and tests it by its kept transform (tetTransform)
      as from the search that tests it on the mesh;
    - in units of the cell, the coordinates of OpenFOAM's
      tetrahedron::pointToBarycentric, to the bit.
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "cellLocator.H"

#include <random>

using namespace polymerCloudTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// The box's cell holding p, with cells of size h (-1 within tol of a face)
label boxCell(const point& p, const scalar h, const scalar tol)
{
    label cell = 0;
    label stride = 1;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar s = p[d]/h;
        const scalar i = std::floor(s);
        if (s - i < tol || i + 1 - s < tol)
        {
            return -1;
        }
        cell += stride*label(i);
        stride *= 10;
    }
    return cell;
}


void checkSearches(const word& caseName, const scalar h)
{
    const fvMesh* mesh = meshOf(caseName);
    ASSERT_TRUE(mesh);
    const polymer::cellLocator& locator = polymer::cellLocator::New(*mesh);

    std::mt19937_64 engine(20261128);
    std::uniform_real_distribution<scalar> u(0, 1);
    label nChecked = 0;
    for (label n = 0; n < 20000; ++n)
    {
        const point start(h*(0.5 + 9*u(engine)), h*(0.5 + 9*u(engine)),
            h*(0.5 + 9*u(engine)));
        barycentric first;
        const tetIndices from(locator.findTet(start, -1, first));
        ASSERT_GE(from.cell(), 0) << caseName << " point " << str(start);

        const point p(start + 0.3*h*vector(2*u(engine) - 1,
            2*u(engine) - 1, 2*u(engine) - 1));
        barycentric c;
        const tetIndices tet(locator.findTet(p, from, c));
        ASSERT_GE(tet.cell(), 0) << caseName << " point " << str(p);

        const label expected = boxCell(p, h, 1e-9);
        if (expected >= 0)
        {
            EXPECT_EQ(tet.cell(), expected) << caseName << " point " << str(p);
            ++nChecked;
        }
        const vector shown(c[0], c[1], c[2]);
        EXPECT_GT(cmptMin(c) + SMALL, 0)
            << caseName << " coordinates " << str(shown);
        const tetPointRef t(tet.tet(*mesh));
        const point back(c[0]*t.a() + c[1]*t.b() + c[2]*t.c() + c[3]*t.d());
        EXPECT_LT(mag(back - p), 1e-12*h)
            << caseName << " point " << str(p) << " coordinates "
            << str(shown);

        // Where the tet's edge determinant is above SMALL (cells of unit
        // size), OpenFOAM's pointToBarycentric gives the same bits
        if (h == 1)
        {
            barycentric openFoam;
            ASSERT_GT(mag(t.pointToBarycentric(p, openFoam)), SMALL);
            for (direction k = 0; k < 4; ++k)
            {
                EXPECT_EQ(openFoam[k], c[k]) << caseName << " " << str(p);
            }
        }

        // From the tet's kept transform: the same tet and coordinates
        polymer::tetTransform transform(locator.transform(from));
        barycentric kept;
        tetIndices again(from);
        if (!polymer::cellLocator::stillIn(p, transform, kept))
        {
            again = locator.search(p, from, kept);
        }
        EXPECT_EQ(again, tet) << caseName << " point " << str(p);
        for (direction k = 0; k < 4; ++k)
        {
            EXPECT_EQ(kept[k], c[k]) << caseName << " point " << str(p);
        }
    }
    EXPECT_GT(nChecked, 19900);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(cellLocator, FindsTheTetAndCoordinatesInCellUnits)
{
    checkSearches("wallBox", 1);
}


TEST(cellLocator, FindsTheTetAndCoordinatesInMicrometreCells)
{
    checkSearches("micrometreBox", 1e-6);
}


// ************************************************************************* //
