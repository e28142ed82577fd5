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

#include "pointOwners.H"
#include "pointField.H"
#include "cellLocator.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// This processor's claim on each point (its number, or labelMax)
Foam::labelList claims
(
    const Foam::polyMesh& mesh,
    const Foam::UList<Foam::point>& points
)
{
    using namespace Foam;
    using namespace Foam::polymer;

    const cellLocator& locator = cellLocator::New(mesh);
    labelList claim(points.size(), labelMax);
    forAll(points, i)
    {
        if (locator.findCell(points[i]) >= 0)
        {
            claim[i] = Pstream::myProcNo();
        }
    }
    return claim;
}


// The lowest claim of every processor, labelMax as -1
void lowestClaims(Foam::labelList& claim)
{
    using namespace Foam;
    using namespace Foam::polymer;

    if (Pstream::parRun())
    {
        Pstream::listCombineGather(claim, minEqOp<label>());
        Pstream::listCombineScatter(claim);
    }
    for (label& proci : claim)
    {
        if (proci == labelMax)
        {
            proci = -1;
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::polymer::replicatedPointOwners
(
    const polyMesh& mesh,
    const UList<point>& points
)
{
    labelList claim(claims(mesh, points));
    lowestClaims(claim);
    return claim;
}


// ************************************************************************* //
