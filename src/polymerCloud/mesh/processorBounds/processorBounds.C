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

#include "processorBounds.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
    defineTypeNameAndDebug(processorBounds, 0);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::processorBounds::processorBounds(const polyMesh& mesh)
:
    MeshObject<polyMesh, GeometricMeshObject, processorBounds>(mesh),
    bounds_(Pstream::parRun() ? Pstream::nProcs() : 1)
{
    if (Pstream::parRun())
    {
        bounds_[Pstream::myProcNo()] = boundBox(mesh.points(), false);
        Pstream::gatherList(bounds_);
        Pstream::scatterList(bounds_);
    }
    else
    {
        bounds_[0] = mesh.bounds();
    }
}


// ************************************************************************* //
