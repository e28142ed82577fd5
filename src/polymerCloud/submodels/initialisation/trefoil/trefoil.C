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

#include "trefoil.H"
#include "checkedInput.H"
#include "transform.H"
#include "mathematicalConstants.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(initialisationModel, initialisationModels, trefoil)


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::vector Foam::polymer::initialisationModels::trefoil::curve(const scalar t)
{
    return vector
    (
        std::sin(t) + 2*std::sin(2*t),
        std::cos(t) - 2*std::cos(2*t),
        -std::sin(3*t)
    );
}


Foam::scalar Foam::polymer::initialisationModels::trefoil::walk
(
    const scalar s,
    const scalar a,
    const label nChords,
    List<point>& points
)
{
    // |c'(t)| <= 1 + 4 + 3: a step of a/(16 s) in t moves at most a/2
    const scalar dt = a/(16*s);

    points.setSize(nChords + 1);
    points[0] = s*curve(0);

    scalar t = 0;
    for (label i = 1; i <= nChords; ++i)
    {
        const point& from = points[i - 1];

        // March until the chord first exceeds a, then bisect the crossing
        scalar lower = t;
        scalar upper = t + dt;
        while (mag(s*curve(upper) - from) < a)
        {
            lower = upper;
            upper += dt;
        }
        for (int iter = 0; iter < 200 && upper - lower > 0; ++iter)
        {
            const scalar middle = 0.5*(lower + upper);
            if (middle <= lower || middle >= upper)
            {
                break;
            }
            (mag(s*curve(middle) - from) < a ? lower : upper) = middle;
        }

        // Place the bead exactly at distance a along the chord's direction
        t = upper;
        const vector chord = s*curve(t) - from;
        points[i] = from + (a/mag(chord))*chord;
    }

    return t;
}


Foam::List<Foam::point> Foam::polymer::initialisationModels::trefoil::beads
(
    const label nBeads,
    const scalar a,
    const bool ring
)
{
    const scalar period = constant::mathematical::twoPi;

    // The walk of nClosing chords must end where it began, at t = 2 pi
    const label nClosing = ring ? nBeads : nBeads + 1;

    // Chords are shorter than arcs: the scale lies above nClosing a/L
    // for the unit curve's length L, and well below twice that
    scalar length = 0;
    const label nSamples = 100000;
    for (label i = 0; i < nSamples; ++i)
    {
        length += mag
        (
            curve(period*(i + 1)/nSamples) - curve(period*i/nSamples)
        );
    }

    scalar lower = nClosing*a/length;
    scalar upper = 2*lower;
    List<point> points;

    for (int iter = 0; iter < 200; ++iter)
    {
        const scalar middle = 0.5*(lower + upper);
        if (middle <= lower || middle >= upper)
        {
            break;
        }
        // A larger curve needs more of its parameter range per chord walk
        (walk(middle, a, nClosing, points) > period ? lower : upper) = middle;
    }

    walk(upper, a, nClosing, points);

    // Drop the closing point (bead 0 again), and for the cut trefoil the
    // bead before it, which opens a gap of two chords
    points.setSize(nBeads);

    return points;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::initialisationModels::trefoil::trefoil
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    initialisationModel(typeName, dict, mesh),
    chainTypeName_
    (
        checkedInput::required<word>
        (
            coeffDict_, "chainType", "<a chain type of chainTypes>"
        )
    ),
    centre_(coeffDict_.getOrDefault<point>("centre", Zero)),
    axis_(coeffDict_.getOrDefault<vector>("axis", vector(0, 0, 1)))
{
    if (mag(axis_) < VSMALL)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'axis' in " << coeffDict_.name() << " is zero" << nl
            << "    expected: axis <non-zero vector>;"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::initialisationModels::trefoil::create
(
    polymerChains& chains,
    const label seed
) const
{
    const label typei = lookupType(chains.types(), coeffDict_, "chainType");
    const chainType& type = chains.types()[typei];

    List<point> x = beads(type.nBeads(), type.rodLength(), type.ring());

    const tensor rotation = rotationTensor(vector(0, 0, 1), axis_/mag(axis_));
    for (point& p : x)
    {
        p = centre_ + (rotation & p);
    }

    chains.append
    (
        typei,
        chains.nChains(),
        x,
        List<vector>(x.size(), Zero)
    );
    return 1;
}


// ************************************************************************* //
