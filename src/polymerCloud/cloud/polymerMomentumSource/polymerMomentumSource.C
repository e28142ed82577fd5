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

#include "polymerMomentumSource.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerMomentumSource::polymerMomentumSource
(
    polymerCloud& polymers
)
:
    polymers_(polymers),
    evolvedTimeIndex_(polymers.mesh().time().timeIndex()),
    predicted_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::polymerMomentumSource::evolve()
{
    const label timeIndex = polymers_.mesh().time().timeIndex();

    if (timeIndex != evolvedTimeIndex_)
    {
        polymers_.evolve();
        evolvedTimeIndex_ = timeIndex;
    }
    predicted_ = false;
}


void Foam::polymer::polymerMomentumSource::predict()
{
    polymers_.predictCoupling();
    predicted_ = true;
}


void Foam::polymer::polymerMomentumSource::addSup(fvVectorMatrix& eqn)
{
    if (!predicted_)
    {
        evolve();
    }

    if (polymers_.twoWay())
    {
        // SU's implicit part takes the field as the matrix's unknown
        eqn += polymers_.SU(const_cast<volVectorField&>(eqn.psi()));
    }
}


// ************************************************************************* //
