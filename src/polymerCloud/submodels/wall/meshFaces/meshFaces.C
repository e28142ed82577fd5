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

#include "meshFaces.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(wallModel, wallModels, meshFaces)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::wallModels::meshFaces::meshFaces
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    wallModel(typeName, dict, mesh)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::wallModels::meshFaces::predict
(
    const point& x,
    const vector& v,
    const scalar T,
    impact& hit
) const
{
    return faceImpact(x, v, T, hit);
}


Foam::scalar Foam::polymer::wallModels::meshFaces::pathClearance
(
    const point& x,
    const vector& v,
    const scalar T,
    const scalar reach
) const
{
    if (periodic_.active())
    {
        return 0;
    }

    const scalar bound = faces().pathClearance(x, x + T*v, reach);
    return max
    (
        searchSafe(bound, cmptMax(cmptMag(x)) + T*mag(v) + reach),
        0
    );
}


// ************************************************************************* //
