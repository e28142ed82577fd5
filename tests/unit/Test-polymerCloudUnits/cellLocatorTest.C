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
      as from the search that tests it on the mesh, and with them the
      found tet's own transform and face triangle, to the bit;
    - in units of the cell, the coordinates of OpenFOAM's
      tetrahedron::pointToBarycentric, to the bit.
    The cells' fans (cellFaceFans) give every tet's face triangle, to the
    label, as tetIndices::faceTriIs does, on the faces' owner and
    neighbour sides (the box, the L-shaped channel, the periodic box).
    And the bead sampler (beadSampler), which keeps each bead's tet and
    its transform from locate to locate (and gives a bead's cell from them
    while the chains' layout is the located one, keptCell): 50 chains of
    10 beads in the box
    in micrometres, located, then over 20 rounds moved by up to 0.3 cells
    a bead, reordered, one removed and one appended, and located again;
    every bead's tet is in the cell that holds it, and the cell centres'
    field sampled there (cellPoint, exact for a linear field on this mesh
    to round-off but in the boundary cells, whose points at the box's
    edges take other values) gives the bead's position back to 1e-12
    cells.
\*---------------------------------------------------------------------------*/

#include "wallScenes.H"
#include "cellLocator.H"
#include "cellFaceFans.H"
#include "beadSampler.H"
#include "interpolation.H"
#include "volPointInterpolation.H"

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
    label nSearched = 0;
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
        polymer::cellLocator::tetPlace kept;
        tetIndices again(from);
        if (!polymer::cellLocator::stillIn(p, transform, kept.coordinates))
        {
            again = locator.search(p, from, kept);

            // The search's transform and triangle are the found tet's,
            // to the bit: they place any point as the tet's own do
            const triFace ownTriangle(again.faceTriIs(*mesh));
            for (label j = 0; j < 3; ++j)
            {
                EXPECT_EQ(kept.triangle[j], ownTriangle[j])
                    << caseName << " point " << str(p);
            }
            const polymer::tetTransform own(locator.transform(again));
            for (const point& q : {p, start, mesh->C()[again.cell()]})
            {
                const barycentric a(kept.transform.coordinates(q));
                const barycentric b(own.coordinates(q));
                for (direction k = 0; k < 4; ++k)
                {
                    EXPECT_EQ(a[k], b[k]) << caseName << " point " << str(q);
                }
            }
            ++nSearched;
        }
        EXPECT_EQ(again, tet) << caseName << " point " << str(p);
        for (direction k = 0; k < 4; ++k)
        {
            EXPECT_EQ(kept.coordinates[k], c[k])
                << caseName << " point " << str(p);
        }
    }
    EXPECT_GT(nChecked, 19900);
    EXPECT_GT(nSearched, 10000);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(cellFaceFans, GiveEveryTetsFaceTriangle)
{
    for (const word caseName : {"wallBox", "wallL", "periodicBox"})
    {
        const fvMesh* mesh = meshOf(caseName);
        ASSERT_TRUE(mesh);
        const polymer::cellFaceFans fans(*mesh);
        label nTets = 0, nNeighbourSide = 0;
        forAll(mesh->cells(), celli)
        {
            const cell& faces = mesh->cells()[celli];
            forAll(faces, k)
            {
                const label facei = faces[k];
                const polymer::cellFaceFans::fan fan(fans.faceFan(celli, k));
                ASSERT_EQ(fan.nTets(), mesh->faces()[facei].size() - 2);
                for (label tetPti = 1; tetPti <= fan.nTets(); ++tetPti)
                {
                    // Label by label: triFace's == takes a triangle
                    // reversed for the same
                    const triFace tri(fan.triangle(tetPti));
                    const triFace expected
                    (
                        tetIndices(celli, facei, tetPti).faceTriIs(*mesh)
                    );
                    for (label j = 0; j < 3; ++j)
                    {
                        EXPECT_EQ(tri[j], expected[j])
                            << caseName << " cell " << celli
                            << " face " << facei << " tet " << tetPti;
                    }
                    ++nTets;
                    nNeighbourSide += (mesh->faceOwner()[facei] != celli);
                }
            }
        }
        EXPECT_EQ(nTets, 12*mesh->nCells()) << caseName;
        EXPECT_GT(nNeighbourSide, 0) << caseName;
    }
}


TEST(cellLocator, FindsTheTetAndCoordinatesInCellUnits)
{
    checkSearches("wallBox", 1);
}


TEST(cellLocator, FindsTheTetAndCoordinatesInMicrometreCells)
{
    checkSearches("micrometreBox", 1e-6);
}


TEST(beadSampler, KeepsEachBeadsTetThroughMovesAndReorders)
{
    const scalar h = 1e-6;
    const fvMesh* mesh = meshOf("micrometreBox");
    ASSERT_TRUE(mesh);
    const PtrList<chainType> types(oneType(10, 0.5*h, 1, 1, 1));
    std::mt19937_64 engine(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    auto inside = [&]()
    {
        return point(h*(1 + 8*u(engine)), h*(1 + 8*u(engine)),
            h*(1 + 8*u(engine)));
    };
    auto newChain = [&](polymerChains& chains, const label id)
    {
        List<vector> x(10), v(10, Zero);
        for (vector& xi : x)
        {
            xi = inside();
        }
        chains.append(0, id, x, v);
    };

    polymerChains chains(types);
    label nextId = 0;
    for (label c = 0; c < 50; ++c)
    {
        newChain(chains, nextId++);
    }

    polymer::beadSampler sampler(*mesh);
    const autoPtr<interpolation<vector>> centres
    (
        interpolation<vector>::New("cellPoint", mesh->C())
    );

    // A field that varies within a cell: its cellPoint interpolation from
    // the point values and the beads' kept triangles is
    // interpolationCellPoint's to the bit
    volVectorField wavy
    (
        IOobject("wavy", mesh->time().timeName(), *mesh),
        mesh->C()
    );
    for (vector& w : wavy.primitiveFieldRef())
    {
        w = vector(Foam::sin(w.x()/h), Foam::cos(w.y()/h), w.x()*w.z()/(h*h));
    }
    const autoPtr<interpolation<vector>> wavyCellPoint
    (
        interpolation<vector>::New("cellPoint", wavy)
    );
    const tmp<pointVectorField> wavyPoints
    (
        volPointInterpolation::New(*mesh).interpolate(wavy)
    );

    label nChecked = 0;
    label nSampled = 0;
    label nStayed = 0;
    label nLeft = 0;
    for (label round = 0; round < 20; ++round)
    {
        sampler.locate(chains);
        List<vector> sampled(chains.positions().size());
        sampler.sample(centres(), sampled);
        List<vector> wavyGeneric(sampled.size());
        List<vector> wavyKept(sampled.size());
        sampler.sample(wavyCellPoint(), wavyGeneric);
        sampler.sample(wavy, wavyPoints(), wavyKept);
        const List<tetIndices>& tets = sampler.hostTets();
        forAll(chains.positions(), i)
        {
            const point& p = chains.positions()[i];
            ASSERT_GE(tets[i].cell(), 0) << "round " << round << str(p);
            const label expected = boxCell(p, h, 1e-9);
            if (expected >= 0)
            {
                EXPECT_EQ(tets[i].cell(), expected)
                    << "round " << round << " bead " << i << str(p);
                ++nChecked;
            }
            // Away from the boundary cells, whose points' values are
            // not the linear field's at the box's edges
            if (cmptMin(p) > h && cmptMax(p) < 9*h)
            {
                EXPECT_LT(mag(sampled[i] - p), 1e-12*h)
                    << "round " << round << " bead " << i << str(p);
                ++nSampled;
            }
            EXPECT_EQ(wavyKept[i], wavyGeneric[i])
                << "round " << round << " bead " << i << str(p);

            // Where it was located: in its kept tet's cell
            label kept = -1;
            EXPECT_TRUE(sampler.keptCell(chains, i, p, kept))
                << "round " << round << " bead " << i << str(p);
            EXPECT_EQ(kept, tets[i].cell()) << "round " << round;
        }

        // Moves within the box, a new order, one chain fewer, one more
        for (vector& x : chains.positions())
        {
            const vector step
            (
                0.3*h*vector(2*u(engine) - 1, 2*u(engine) - 1,
                2*u(engine) - 1)
            );
            const point moved(x + step);
            x = (cmptMin(moved) > 0.5*h && cmptMax(moved) < 9.5*h)
              ? moved : x;
        }
        // Moved, the layout unchanged: a bead still in its kept tet is in
        // that tet's cell; one that left it is not given a cell
        forAll(chains.positions(), i)
        {
            const point& p = chains.positions()[i];
            label kept = -1;
            if (sampler.keptCell(chains, i, p, kept))
            {
                const label expected = boxCell(p, h, 1e-9);
                if (expected >= 0)
                {
                    EXPECT_EQ(kept, expected)
                        << "round " << round << " bead " << i << str(p);
                }
                ++nStayed;
            }
            else
            {
                EXPECT_EQ(kept, -1) << "round " << round << " bead " << i;
                ++nLeft;
            }
        }

        labelList newToOld(identity(chains.nChains()));
        std::shuffle(newToOld.begin(), newToOld.end(), engine);
        chains.reorder(newToOld);

        // A new layout: no bead is given a cell from the kept tets
        label nAfterReorder = 0;
        forAll(chains.positions(), i)
        {
            label kept = -1;
            nAfterReorder +=
                sampler.keptCell(chains, i, chains.positions()[i], kept);
        }
        EXPECT_EQ(nAfterReorder, 0) << "round " << round;
        chains.remove(labelList({label(u(engine)*chains.nChains())}));
        newChain(chains, nextId++);
    }
    EXPECT_GT(nChecked, 9000);
    EXPECT_GT(nSampled, 4000);
    EXPECT_GT(nStayed, 500);
    EXPECT_GT(nLeft, 500);
}


// ************************************************************************* //
