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

#include "exactOU.H"
#include "chainNoise.H"
#include "makePolymerModel.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(integrationModel, integrationModels, exactOU)


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::polymer::integrationModels::exactOU::positionVarianceFactor
(
    const scalar h
)
{
    if (h >= 1)
    {
        return 2*h - 3 + 4*std::exp(-h) - std::exp(-2*h);
    }

    // The terms up to h^2 cancel exactly: sum the series from h^3,
    //     sum_k (-1)^k (4 - 2^k) h^k/k!
    scalar sum = 0;
    scalar hPowerOverFactorial = h*h/2;
    scalar twoPower = 4;
    for (int k = 3; k < 40; ++k)
    {
        hPowerOverFactorial *= h/k;
        twoPower *= 2;
        const scalar term =
            ((k % 2) ? -1 : 1)*(4 - twoPower)*hPowerOverFactorial;
        sum += term;
        if (mag(term) < 1e-18*mag(sum))
        {
            break;
        }
    }
    return sum;
}


Foam::polymer::integrationModels::exactOU::coefficients
Foam::polymer::integrationModels::exactOU::coefficients::exact
(
    const chainType& type,
    const scalar dt
)
{
    const scalar gamma = type.friction()/type.beadMass();
    const scalar h = gamma*dt;
    const scalar thermalVelocitySqr = type.kT()/type.beadMass();

    const scalar oneMinusE = -std::expm1(-h);
    const scalar varV = thermalVelocitySqr*(-std::expm1(-2*h));
    const scalar varX =
        thermalVelocitySqr/sqr(gamma)*positionVarianceFactor(h);
    const scalar covXV = thermalVelocitySqr/gamma*sqr(oneMinusE);

    coefficients c;
    c.velocityDecay = std::exp(-h);
    c.positionDecay = oneMinusE/gamma;
    c.velocitySigma = std::sqrt(varV);
    c.positionFromXi1 = varV > 0 ? covXV/c.velocitySigma : 0;
    c.positionFromXi2 =
        std::sqrt(max(varX - (varV > 0 ? sqr(covXV)/varV : 0), scalar(0)));
    return c;
}


template<bool drifting>
inline void Foam::polymer::integrationModels::exactOU::advance
(
    const coefficients& k,
    const scalar deltaT,
    const label n,
    const scalar* xi,
    const vector* u,
    vector* x,
    vector* v
)
{
    // Without drift u = 0 drops out: the same sums in the same order less
    // their zero terms, the same bits
    for (label i = 0; i < n; ++i)
    {
        const vector xi1(xi[6*i], xi[6*i + 1], xi[6*i + 2]);
        const vector xi2(xi[6*i + 3], xi[6*i + 4], xi[6*i + 5]);

        vector relative = v[i];
        if (drifting)
        {
            relative -= u[i];
        }

        vector move = k.positionDecay*relative;
        vector velocity = k.velocityDecay*relative;
        if (drifting)
        {
            move = u[i]*deltaT + move;
            velocity = u[i] + velocity;
        }

        x[i] += move + k.positionFromXi1*xi1 + k.positionFromXi2*xi2;
        v[i] = velocity + k.velocitySigma*xi1;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::integrationModels::exactOU::exactOU(const dictionary& dict)
:
    integrationModel(typeName, dict),
    cache_(),
    cachedDeltaT_(-1),
    xi_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::integrationModels::exactOU::integrateChain
(
    polymerChains& chains,
    const label chaini,
    const UList<vector>& driftVelocity,
    const scalar deltaT,
    const label timeIndex,
    const label seed,
    const label subStepKey
) const
{
    const PtrList<chainType>& types = chains.types();
    if (deltaT != cachedDeltaT_ || cache_.size() != types.size())
    {
        cache_.setSize(types.size());
        forAll(types, typei)
        {
            cache_[typei] = coefficients::exact(types[typei], deltaT);
        }
        cachedDeltaT_ = deltaT;
    }

    // A copy: the loop's stores to x and v could alias the cache, so the
    // compiler would reload a referenced coefficient at every bead
    const coefficients k = cache_[chains.typeIndex(chaini)];
    const label first = chains.start(chaini);
    const label n = chains.size(chaini);

    xi_.resize(6*n);
    chainNoise(seed, chains.globalId(chaini)).sixNormals
    (
        timeIndex, chainNoise::stepStream0, subStepKey, n, xi_.data()
    );

    vector* x = chains.positions().data() + first;
    vector* v = chains.velocities().data() + first;
    if (driftVelocity.empty())
    {
        advance<false>(k, deltaT, n, xi_.cdata(), nullptr, x, v);
    }
    else
    {
        advance<true>
        (
            k, deltaT, n, xi_.cdata(), driftVelocity.cdata() + first, x, v
        );
    }
}


// ************************************************************************* //
