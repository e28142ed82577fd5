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

#include "fixman.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(forceModel, forceModels, fixman)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::forceModels::fixman::fixman
(
    const dictionary& dict,
    const fvMesh&
)
:
    forceModel(typeName, dict)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::forceModels::fixman::addChainForce
(
    const polymerChains& chains,
    const label chaini,
    UList<vector>& force
) const
{
    const chainType& type = chains.type(chaini);
    if (type.ring())
    {
        FatalErrorInFunction
            << "The fixman force handles open chains; chain type "
            << type.name() << " is a ring"
            << exit(FatalError);
    }

    const label first = chains.start(chaini);
    const label nRods = type.nRods();
    const vector* x = chains.positions().cdata() + first;
    vector* f = force.data() + first;

    if (nRods < 2)
    {
        return;
    }

    unitRod_.resize(nRods);
    rodLength_.resize(nRods);
    for (label k = 0; k < nRods; ++k)
    {
        const vector s = x[k + 1] - x[k];
        rodLength_[k] = mag(s);
        unitRod_[k] = s/rodLength_[k];
    }

    // Minors of T with off-diagonal b_k = -u_k.u_{k+1}:
    // leading_[i] = det of rows 0..i-1, trailing_[i] = det of rows i..R-1
    leading_.resize(nRods + 1);
    trailing_.resize(nRods + 2);
    leading_[0] = 1;
    leading_[1] = 2;
    for (label i = 2; i <= nRods; ++i)
    {
        const scalar b = unitRod_[i - 2] & unitRod_[i - 1];
        leading_[i] = 2*leading_[i - 1] - sqr(b)*leading_[i - 2];
    }
    trailing_[nRods + 1] = 0;
    trailing_[nRods] = 1;
    trailing_[nRods - 1] = 2;
    for (label i = nRods - 2; i >= 0; --i)
    {
        const scalar b = unitRod_[i] & unitRod_[i + 1];
        trailing_[i] = 2*trailing_[i + 1] - sqr(b)*trailing_[i + 2];
    }

    const scalar det = leading_[nRods];

    for (label k = 0; k + 1 < nRods; ++k)
    {
        // (T^-1)_{k,k+1} = -b_k det(rows < k) det(rows > k+1)/det T
        const scalar cosine = unitRod_[k] & unitRod_[k + 1];
        const scalar weight =
            type.kT()*cosine*leading_[k]*trailing_[k + 2]/det;

        // grad of u_k.u_{k+1} with respect to the rod vectors s_k, s_{k+1}
        const vector dRod0 =
            (unitRod_[k + 1] - cosine*unitRod_[k])/rodLength_[k];
        const vector dRod1 =
            (unitRod_[k] - cosine*unitRod_[k + 1])/rodLength_[k + 1];

        f[k] -= weight*dRod0;
        f[k + 1] += weight*(dRod0 - dRod1);
        f[k + 2] += weight*dRod1;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::forceModels::fixman::addForce
(
    const polymerChains& chains,
    UList<vector>& force
) const
{
    for (label c = 0; c < chains.nChains(); ++c)
    {
        addChainForce(chains, c, force);
    }
}


// ************************************************************************* //
