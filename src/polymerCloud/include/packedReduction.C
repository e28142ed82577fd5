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

#include "packedReduction.H"
#include "Pstream.H"
#include "ops.H"
#include "scalarList.H"
#include "boolList.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Combines two processors' packed values as maxOp or sumOp would each,
// the received (y) to the right, as Pstream::gather combines them
struct sumOrMax
{
    const Foam::UList<bool>& isMax;

    void operator()(Foam::scalarList& x, const Foam::scalarList& y) const
    {
        forAll(x, i)
        {
            x[i] =
                isMax[i]
              ? Foam::maxOp<Foam::scalar>()(x[i], y[i])
              : x[i] + y[i];
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::packedReduction::sum(int64_t& value)
{
    int64s_.append(&value);
    int64Maxima_.append(false);
}


void Foam::polymer::packedReduction::sum(label& value)
{
    labels_.append(&value);
    labelMaxima_.append(false);
}


void Foam::polymer::packedReduction::sum(scalar& value)
{
    scalars_.append(&value);
    scalarMaxima_.append(false);
}


void Foam::polymer::packedReduction::sum(vector& value)
{
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        sum(value[d]);
    }
}


void Foam::polymer::packedReduction::max(int64_t& value)
{
    int64s_.append(&value);
    int64Maxima_.append(true);
}


void Foam::polymer::packedReduction::max(label& value)
{
    labels_.append(&value);
    labelMaxima_.append(true);
}


void Foam::polymer::packedReduction::max(scalar& value)
{
    scalars_.append(&value);
    scalarMaxima_.append(true);
}


void Foam::polymer::packedReduction::reduce()
{
    if (!Pstream::parRun())
    {
        return;
    }

    const label nInt64 = int64s_.size();
    const label nLabel = labels_.size();
    scalarList values(nInt64 + nLabel + scalars_.size());
    boolList isMax(values.size());
    label i = 0;
    forAll(int64s_, k)
    {
        isMax[i] = int64Maxima_[k];
        values[i++] = scalar(*int64s_[k]);
    }
    forAll(labels_, k)
    {
        isMax[i] = labelMaxima_[k];
        values[i++] = scalar(*labels_[k]);
    }
    forAll(scalars_, k)
    {
        isMax[i] = scalarMaxima_[k];
        values[i++] = *scalars_[k];
    }

    Pstream::combineGather(values, sumOrMax{isMax});
    Pstream::combineScatter(values);

    i = 0;
    for (int64_t* value : int64s_)
    {
        *value = int64_t(values[i++]);
    }
    for (label* value : labels_)
    {
        *value = label(values[i++]);
    }
    for (scalar* value : scalars_)
    {
        *value = values[i++];
    }
}


// ************************************************************************* //
