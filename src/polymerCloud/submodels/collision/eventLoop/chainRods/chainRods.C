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

#include "chainRods.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::chainRods::update(const polymerChains& chains)
{
    if
    (
        layout_ == chains.layoutVersion()
     && beadRods_.size() == chains.nBeads()
    )
    {
        return;
    }
    layout_ = chains.layoutVersion();

    rods_.clear();
    rodChain_.clear();
    rodChainId_.clear();
    beadRods_.resize(chains.nBeads());
    beadRods_ = FixedList<label, 2>({-1, -1});

    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label first = chains.start(c);
        const label n = chains.size(c);

        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            const label a = first + k;
            const label b = first + (k + 1) % n;
            const label rod = rods_.size();

            rods_.append(labelPair(a, b));
            rodChain_.append(c);
            rodChainId_.append(chains.globalId(c));
            beadRods_[a][1] = rod;
            beadRods_[b][0] = rod;
        }
    }
}


// ************************************************************************* //
