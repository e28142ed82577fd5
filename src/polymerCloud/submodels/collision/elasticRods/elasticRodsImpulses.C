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

#include "elasticRods.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::polymer::collisionModels::elasticRods::chainResponse
(
    const polymerChains& chains,
    const label chaini,
    const UList<label>& beads,
    const UList<scalar>& weights,
    const vector& n,
    const scalar t,
    List<vector>& response
)
{
    const label first = chains.start(chaini);
    response.setSize(chains.size(chaini));
    response = Zero;
    forAll(beads, k)
    {
        if (chains.chainOf(beads[k]) == chaini)
        {
            response[beads[k] - first] += weights[k]*n;
        }
    }

    // The chain at t, where the impulse acts
    for (label i = first; i < chains.end(chaini); ++i)
    {
        position_[i] = positionAt(i, t);
        beadTime_[i] = t;
    }

    scalar largest;
    if
    (
        !projection_.project
        (
            position_.cdata() + first, chains.type(chaini),
            response.data(), largest
        )
    )
    {
        return false;
    }
    const scalar inverseMass = 1/chains.type(chaini).beadMass();
    for (vector& r : response)
    {
        r *= inverseMass;
    }
    return true;
}


Foam::scalar Foam::polymer::collisionModels::elasticRods::velocityImpulse
(
    const scalar J,
    const scalar u,
    const scalar uDagger,
    const scalar perUnit
) const
{
    if (velocityImpulse_ == velocityImpulseType::pathChange)
    {
        return J;
    }
    return (uDagger*u > 0) ? -2*uDagger/perUnit : 0;
}


Foam::FixedList<Foam::vector, 4>
Foam::polymer::collisionModels::elasticRods::dumbbellVelocityChange
(
    const rodPairCrossing& pair,
    const FixedList<label, 4>& beads,
    const polymerChains& chains,
    const UList<vector>& velocitiesDagger
) const
{
    // The four beads' own elastic impulse, the one the paths took (a held
    // chain an immovable obstacle)
    scalar lambdaI, lambdaJ;
    vector n;
    pair.contact(0, lambdaI, lambdaJ, n);
    const FixedList<scalar, 4> weights
    ({
        1 - lambdaI, lambdaI, lambdaJ - 1, -lambdaJ
    });
    FixedList<scalar, 4> inverseMasses;
    scalar u = 0, uDagger = 0, perUnit = 0;
    for (label k = 0; k < 4; ++k)
    {
        const label c = chains.chainOf(beads[k]);
        const bool held = heldChains_.found(c);
        inverseMasses[k] = held ? 0 : 1/chains.type(c).beadMass();
        u += weights[k]*(velocity_[beads[k]] & n);
        uDagger += held ? 0 : weights[k]*(velocitiesDagger[beads[k]] & n);
        perUnit += sqr(weights[k])*inverseMasses[k];
    }
    const scalar JDagger =
        velocityImpulse(-2*u/perUnit, u, uDagger, perUnit);

    FixedList<vector, 4> change;
    for (label k = 0; k < 4; ++k)
    {
        change[k] = (JDagger*weights[k]*inverseMasses[k])*n;
    }
    return change;
}


void Foam::polymer::collisionModels::elasticRods::applyResponse
(
    const polymerChains& chains,
    const label chaini,
    const scalar J,
    const scalar JDagger,
    const UList<vector>& response,
    UList<vector>& velocitiesDagger
)
{
    const label first = chains.start(chaini);
    for (label i = first; i < chains.end(chaini); ++i)
    {
        setVelocity(i, velocity_[i] + J*response[i - first]);
        velocitiesDagger[i] += JDagger*response[i - first];
        changedBeads_.append(i);
    }
}


bool Foam::polymer::collisionModels::elasticRods::resolveConstrained
(
    const event& e,
    const polymerChains& chains,
    UList<vector>& velocitiesDagger
)
{
    const FixedList<label, 4>& beads = e.beads;
    const vector& shift = grid_.pairShift(e.pair);
    const rodPairCrossing pair
    (
        position_[beads[0]], position_[beads[1]],
        position_[beads[2]] + shift, position_[beads[3]] + shift,
        velocity_[beads[0]], velocity_[beads[1]],
        velocity_[beads[2]], velocity_[beads[3]]
    );
    scalar lambdaI, lambdaJ;
    vector n;
    if (!pair.contact(0, lambdaI, lambdaJ, n))
    {
        return false;
    }

    // Each chain's response to the unit impulse J = 1 at the contact
    const labelList fourBeads(beads);
    const scalarList weights
    ({
        1 - lambdaI, lambdaI, lambdaJ - 1, -lambdaJ
    });
    const label chainI = chains.chainOf(beads[0]);
    const label chainJ = chains.chainOf(beads[2]);
    if (frozenChains_.found(chainI) || frozenChains_.found(chainJ))
    {
        return false;
    }

    // A chain held by a stall is an immovable obstacle: no response
    const bool heldI = heldChains_.found(chainI);
    const bool heldJ = heldChains_.found(chainJ);
    List<vector> responseI, responseJ;
    if (heldI)
    {
        responseI.setSize(chains.size(chainI), Zero);
    }
    if (heldJ)
    {
        responseJ.setSize(chains.size(chainJ), Zero);
    }
    if
    (
        (heldI && heldJ)
     || (
            !heldI
         && !chainResponse
            (
                chains, chainI, fourBeads, weights, n, e.time, responseI
            )
        )
     || (
            chainJ != chainI
         && !heldJ
         && !chainResponse
            (
                chains, chainJ, fourBeads, weights, n, e.time, responseJ
            )
        )
    )
    {
        return false;
    }

    // The contact's relative normal velocity u and its change per unit J
    // (at most the free beads' sum w^2/m; a contact the chains' rods all
    // but lock, as within a short ring, takes the dumbbell impulse)
    scalar u = 0, uDagger = 0, contactResponse = 0, freeResponse = 0;
    for (label k = 0; k < 4; ++k)
    {
        const label c = (k < 2) ? chainI : chainJ;
        const List<vector>& r = (c == chainI) ? responseI : responseJ;
        u += weights[k]*(velocity_[beads[k]] & n);
        contactResponse += weights[k]*(r[beads[k] - chains.start(c)] & n);
        if (c == chainI ? !heldI : !heldJ)
        {
            // A held chain is an immovable obstacle, whatever its v-dagger
            uDagger += weights[k]*(velocitiesDagger[beads[k]] & n);
            freeResponse += sqr(weights[k])/chains.type(c).beadMass();
        }
    }
    if (contactResponse <= 1e-8*freeResponse)
    {
        return false;
    }

    const scalar J = -2*u/contactResponse;
    const scalar JDagger = velocityImpulse(J, u, uDagger, contactResponse);
    changedBeads_.clear();
    if (!heldI)
    {
        applyResponse
        (
            chains, chainI, J, JDagger, responseI, velocitiesDagger
        );
    }
    if (chainJ != chainI && !heldJ)
    {
        applyResponse
        (
            chains, chainJ, J, JDagger, responseJ, velocitiesDagger
        );
    }
    return true;
}


bool Foam::polymer::collisionModels::elasticRods::reverseThroughChain
(
    const polymerChains& chains,
    const UList<label>& beads,
    const UList<scalar>& weights,
    const vector& n,
    const scalar t,
    UList<vector>& velocitiesDagger
)
{
    const label c = chains.chainOf(beads[0]);
    List<vector> response;
    if
    (
        frozenChains_.found(c)
     || !chainResponse(chains, c, beads, weights, n, t, response)
    )
    {
        return false;
    }

    // The contact's normal velocity u and its change per unit impulse
    const label first = chains.start(c);
    vector contactVelocity(Zero), contactVelocityDagger(Zero);
    scalar perUnit = 0, freeResponse = 0;
    forAll(beads, k)
    {
        contactVelocity += weights[k]*velocity_[beads[k]];
        contactVelocityDagger += weights[k]*velocitiesDagger[beads[k]];
        perUnit += weights[k]*(response[beads[k] - first] & n);
        freeResponse += sqr(weights[k]);
    }
    const scalar u = contactVelocity & n;
    if (perUnit <= 1e-8*(freeResponse/chains.type(c).beadMass()))
    {
        return false;
    }
    const scalar J = -2*u/perUnit;
    changedBeads_.clear();
    applyResponse
    (
        chains, c, J,
        velocityImpulse(J, u, contactVelocityDagger & n, perUnit),
        response, velocitiesDagger
    );
    return true;
}


bool Foam::polymer::collisionModels::elasticRods::reboundConstrained
(
    const event& e,
    const polymerChains& chains,
    UList<vector>& velocitiesDagger
)
{
    const label bead = -1 - e.pair;
    if
    (
        (velocity_[bead] & e.normal) >= 0
     || !reverseThroughChain
        (
            chains, labelList({bead}), scalarList({1.0}), e.normal, e.time,
            velocitiesDagger
        )
    )
    {
        return false;
    }
    wall_->countRebound();
    return true;
}


bool Foam::polymer::collisionModels::elasticRods::resolve
(
    const event& e,
    const polymerChains& chains,
    UList<vector>& velocitiesDagger
)
{
    const label pairi = e.pair;
    const FixedList<label, 4>& beads = e.beads;

    // The impact positions as the root solver evaluated them, on the
    // not-yet-crossed side of the root
    for (const label bead : beads)
    {
        position_[bead] =
            positionAt(bead, e.from) + e.offset*velocity_[bead];
        beadTime_[bead] = e.time;
    }

    if
    (
        impulse_ == impulseType::constrained
     && resolveConstrained(e, chains, velocitiesDagger)
    )
    {
        contacts_.record(pairi, e.side, e.atContact);
        return true;
    }

    const vector& shift = grid_.pairShift(pairi);
    const rodPairCrossing pair
    (
        position_[beads[0]], position_[beads[1]],
        position_[beads[2]] + shift, position_[beads[3]] + shift,
        velocity_[beads[0]], velocity_[beads[1]],
        velocity_[beads[2]], velocity_[beads[3]]
    );

    // A chain held by a stall takes the impulse as an infinite mass
    const label chainI = chains.chainOf(beads[0]);
    const label chainJ = chains.chainOf(beads[2]);
    const bool heldI = heldChains_.found(chainI);
    const bool heldJ = heldChains_.found(chainJ);
    FixedList<vector, 4> after;
    if
    (
        (heldI && heldJ)
     || !pair.elasticImpulse
        (
            0,
            after,
            heldI ? VGREAT : chains.type(chainI).beadMass(),
            heldJ ? VGREAT : chains.type(chainJ).beadMass()
        )
    )
    {
        return false;
    }

    // The velocities' change: the paths' (the paper's 3g) or their own
    // elastic impulse
    FixedList<vector, 4> change;
    if (velocityImpulse_ == velocityImpulseType::elastic)
    {
        change = dumbbellVelocityChange(pair, beads, chains, velocitiesDagger);
    }
    else
    {
        for (label k = 0; k < 4; ++k)
        {
            change[k] = after[k] - velocity_[beads[k]];
        }
    }
    for (label k = 0; k < 4; ++k)
    {
        if (!(k < 2 ? heldI : heldJ))
        {
            velocitiesDagger[beads[k]] += change[k];
            setVelocity(beads[k], after[k]);
        }
    }

    contacts_.record(pairi, e.side, e.atContact);

    // The four beads, in the order of the pair's rods
    const labelPair& rods = grid_.pairs()[pairi];
    changedBeads_.clear();
    for (const label rod : {rods.first(), rods.second()})
    {
        changedBeads_.append(rods_[rod].first());
        changedBeads_.append(rods_[rod].second());
    }

    return true;
}


// ************************************************************************* //
