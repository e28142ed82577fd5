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

#include "flatVolPointInterpolation.H"
#include "emptyFvPatch.H"
#include "coupledPointPatchField.H"
#include "pointConstraints.H"
#include "solution.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type, class CombineOp>
void Foam::polymer::flatVolPointInterpolation::syncCollocated
(
    List<Type>& pointData,
    const CombineOp& cop
) const
{
    if (hasCollocatedPoints_)
    {
        pointConstraints::syncUntransformedData(mesh(), pointData, cop);
    }
}


template<class Type>
void Foam::polymer::flatVolPointInterpolation::pushUntransformedData
(
    List<Type>& pointData
) const
{
    // volPointInterpolation's: through the coupled patch, each master's
    // value copied to its slaves' slots and sent back to them
    if (!hasCollocatedPoints_)
    {
        return;
    }
    const globalMeshData& gmd = mesh().globalData();
    const labelList& meshPoints = gmd.coupledPatch().meshPoints();
    const mapDistribute& slavesMap = gmd.globalCoPointSlavesMap();
    const labelListList& slaves = gmd.globalCoPointSlaves();

    List<Type> elems(slavesMap.constructSize());
    forAll(meshPoints, i)
    {
        elems[i] = pointData[meshPoints[i]];
    }
    forAll(slaves, i)
    {
        for (const label slavei : slaves[i])
        {
            elems[slavei] = elems[i];
        }
    }
    slavesMap.reverseDistribute(elems.size(), elems, false);
    forAll(meshPoints, i)
    {
        pointData[meshPoints[i]] = elems[i];
    }
}


template<class Type>
void Foam::polymer::flatVolPointInterpolation::addSeparated
(
    GeometricField<Type, pointPatchField, pointMesh>& pf
) const
{
    Field<Type>& pfi = pf.primitiveFieldRef();
    auto& patchFields = pf.boundaryFieldRef();
    forAll(patchFields, patchi)
    {
        if (patchFields[patchi].coupled())
        {
            refCast<coupledPointPatchField<Type>>(patchFields[patchi])
                .initSwapAddSeparated(Pstream::commsTypes::nonBlocking, pfi);
        }
    }
    Pstream::waitRequests();
    forAll(patchFields, patchi)
    {
        if (patchFields[patchi].coupled())
        {
            refCast<coupledPointPatchField<Type>>(patchFields[patchi])
                .swapAddSeparated(Pstream::commsTypes::nonBlocking, pfi);
        }
    }
}


template<class Type>
void Foam::polymer::flatVolPointInterpolation::interpolateInternalField
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    Field<Type>& pf
) const
{
    const Field<Type>& cellValues = vf.primitiveField();
    const labelList& cellStart = pointCells_.offsets();
    const labelList& cellOf = pointCells_.m();
    forAll(isPatchPoint_, pointi)
    {
        if (!isPatchPoint_[pointi])
        {
            Type value = Zero;
            for (label k = cellStart[pointi]; k < cellStart[pointi + 1]; ++k)
            {
                value += pointCellWeights_[k]*cellValues[cellOf[k]];
            }
            pf[pointi] = value;
        }
    }
}


template<class Type>
void Foam::polymer::flatVolPointInterpolation::interpolateBoundaryField
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField<Type, pointPatchField, pointMesh>& pf
) const
{
    // The patch faces' values in the boundary's order (zero on coupled and
    // empty patches), as volPointInterpolation::flatBoundaryField
    const fvBoundaryMesh& patches = mesh().boundary();
    Field<Type> boundaryValues(mesh().nBoundaryFaces(), Zero);
    forAll(patches, patchi)
    {
        if
        (
            !isA<emptyFvPatch>(patches[patchi])
         && !vf.boundaryField()[patchi].coupled()
        )
        {
            SubList<Type>
            (
                boundaryValues,
                vf.boundaryField()[patchi].size(),
                patches[patchi].start() - mesh().nInternalFaces()
            ) = vf.boundaryField()[patchi];
        }
    }

    Field<Type>& pfi = pf.primitiveFieldRef();
    const labelList& faceStart = patchPointFaces_.offsets();
    const labelList& faceOf = patchPointFaces_.m();
    forAll(patchPoints_, i)
    {
        Type value = Zero;
        for (label k = faceStart[i]; k < faceStart[i + 1]; ++k)
        {
            value += patchPointFaceWeights_[k]*boundaryValues[faceOf[k]];
        }
        pfi[patchPoints_[i]] = value;
    }

    syncCollocated(pfi, plusEqOp<Type>());
    addSeparated(pf);
    pushUntransformedData(pfi);
}


template<class Type>
void Foam::polymer::flatVolPointInterpolation::constrain
(
    GeometricField<Type, pointPatchField, pointMesh>& pf
) const
{
    if (hasConstrainedPoints_)
    {
        pointConstraints::New(pf.mesh()).constrain(pf, false);
        return;
    }

    // pointConstraints::constrain with no constrained points and no fixed
    // values overridden
    pf.correctBoundaryConditions();
    syncCollocated(pf.primitiveFieldRef(), maxMagSqrEqOp<Type>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::polymer::flatVolPointInterpolation::interpolate
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField<Type, pointPatchField, pointMesh>& pf
) const
{
    interpolateInternalField(vf, pf.primitiveFieldRef());
    interpolateBoundaryField(vf, pf);
    constrain(pf);
}


template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::pointPatchField, Foam::pointMesh>>
Foam::polymer::flatVolPointInterpolation::interpolate
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    const word& name,
    const bool cache
) const
{
    typedef GeometricField<Type, pointPatchField, pointMesh> pointFieldType;

    const pointMesh& pMesh = pointMesh::New(vf.mesh());
    const objectRegistry& db = pMesh.thisDb();
    pointFieldType* cached =
        db.objectRegistry::template getObjectPtr<pointFieldType>(name);

    if (!cache || vf.mesh().changing())
    {
        // An old one removed, not registered twice
        if (cached && cached->ownedByRegistry())
        {
            solution::cachePrintMessage("Deleting", name, vf);
            delete cached;
        }
        auto tpf = tmp<pointFieldType>::New
        (
            IOobject(name, vf.instance(), db),
            pMesh,
            vf.dimensions()
        );
        interpolate(vf, tpf.ref());
        return tpf;
    }

    if (!cached)
    {
        solution::cachePrintMessage("Calculating and caching", name, vf);
        cached = interpolate(vf, name, false).ptr();
        regIOobject::store(cached);
    }
    else if (cached->upToDate(vf))
    {
        solution::cachePrintMessage("Reusing", name, vf);
    }
    else
    {
        solution::cachePrintMessage("Updating", name, vf);
        interpolate(vf, *cached);
    }
    return *cached;
}


// ************************************************************************* //
