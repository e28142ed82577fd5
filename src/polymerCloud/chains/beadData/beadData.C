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
    start_(),
    layout_(-1)
{}


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

    List<Type> values(chains.nBeads(), unknown_);
    Map<label> start(2*chains.nChains());
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label id = chains.globalId(c);
        start.insert(id, chains.start(c));

        const auto old = start_.cfind(id);
        if (old.found())
        {
            for (label k = 0; k < chains.size(c); ++k)
            {
                values[chains.start(c) + k] = values_[old.val() + k];
            }
        }
    }

    values_.transfer(values);
    start_.transfer(start);
    layout_ = chains.layoutVersion();
    return values_;
}


// ************************************************************************* //
