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

#include "beadData.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class Type>
Foam::polymer::beadData<Type>::beadData(const Type& unknown)
:
    unknown_(unknown),
    values_(),
    ids_(),
    starts_(1, Zero),
    layout_(-1)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class Type>
Foam::List<Type> Foam::polymer::beadData<Type>::reordered
(
    const labelList& newToOld
) const
{
    List<Type> values(values_.size());
    label i = 0;
    for (const label old : newToOld)
    {
        for (label k = starts_[old]; k < starts_[old + 1]; ++k)
        {
            values[i++] = values_[k];
        }
    }
    return values;
}


template<class Type>
Foam::List<Type> Foam::polymer::beadData<Type>::remapped
(
    const polymerChains& chains
) const
{
    Map<label> oldStart(2*ids_.size());
    forAll(ids_, c)
    {
        oldStart.insert(ids_[c], starts_[c]);
    }

    List<Type> values(chains.nBeads(), unknown_);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const auto old = oldStart.cfind(chains.globalId(c));
        if (old.found())
        {
            for (label k = 0; k < chains.size(c); ++k)
            {
                values[chains.start(c) + k] = values_[old.val() + k];
            }
        }
    }
    return values;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::List<Type>&
Foam::polymer::beadData<Type>::update(const polymerChains& chains)
{
    if
    (
        layout_ == chains.layoutVersion()
     && values_.size() == chains.nBeads()
    )
    {
        return values_;
    }

    const labelList* newToOld = chains.reorderSince(layout_);
    List<Type> values
    (
        (newToOld && values_.size() == chains.nBeads())
      ? reordered(*newToOld)
      : remapped(chains)
    );
    values_.transfer(values);

    ids_.setSize(chains.nChains());
    starts_.setSize(chains.nChains() + 1);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        ids_[c] = chains.globalId(c);
        starts_[c] = chains.start(c);
    }
    starts_[chains.nChains()] = chains.nBeads();
    layout_ = chains.layoutVersion();
    return values_;
}


// ************************************************************************* //
