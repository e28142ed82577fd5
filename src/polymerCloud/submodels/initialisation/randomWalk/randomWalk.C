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

#include "randomWalk.H"
#include "periodicImages.H"
#include "pointOwners.H"
#include "processorNeighbours.H"
#include "HashSet.H"
#include "ListOps.H"
#include "chainNoise.H"
#include "checkedInput.H"
#include "mathematicalConstants.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(initialisationModel, initialisationModels, randomWalk)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::initialisationModels::randomWalk::randomWalk
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    initialisationModel(typeName, dict, mesh),
    box_
    (
        checkedInput::required<point>
        (
            coeffDict_, "min",
            "(<x> <y> <z>), the lower corner of the first beads' box"
        ),
        checkedInput::required<point>
        (
            coeffDict_, "max",
            "(<x> <y> <z>), the upper corner of the first beads' box"
        )
    ),
    insideMesh_
    (
        coeffDict_.getOrDefault<bool>
        (
            "insideMesh",
            returnReduce(mesh.nCells(), sumOp<label>()) > 1
        )
    )
{
    if (!box_.valid())
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keywords 'min' " << box_.min() << " and 'max' " << box_.max()
            << " in " << coeffDict_.name() << " make an empty box" << nl
            << "    expected: min (x y z); max (X Y Z); with X >= x, ..."
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::point Foam::polymer::initialisationModels::randomWalk::firstBead
(
    const boundBox& box,
    const label seed,
    const label globalId,
    const label attempt
)
{
    scalar u[4];
    chainNoise(seed, globalId).uniforms
    (
        0, 0, chainNoise::setUpStream, attempt, u
    );
    return box.min() + cmptMultiply(vector(u[0], u[1], u[2]), box.span());
}


Foam::List<Foam::point> Foam::polymer::initialisationModels::randomWalk::walk
(
    const chainType& type,
    const boundBox& box,
    const label seed,
    const label globalId,
    const label attempt
)
{
    const chainNoise noise(seed, globalId);
    List<point> x(type.nBeads());

    scalar u[4];
    x[0] = firstBead(box, seed, globalId, attempt);

    for (label i = 1; i < x.size(); ++i)
    {
        // A uniform direction: cos(theta) uniform in (-1, 1)
        noise.uniforms(0, i, chainNoise::setUpStream, attempt, u);
        const scalar cosTheta = 2*u[0] - 1;
        const scalar sinTheta = std::sqrt(max(1 - sqr(cosTheta), scalar(0)));
        const scalar phi = constant::mathematical::twoPi*u[1];

        x[i] =
            x[i - 1]
          + type.rodLength()
           *vector
            (
                sinTheta*std::cos(phi),
                sinTheta*std::sin(phi),
                cosTheta
            );
    }

    return x;
}


Foam::List<Foam::List<Foam::point>>
Foam::polymer::initialisationModels::randomWalk::walks
(
    const chainType& type,
    const boundBox& box,
    const label seed,
    const label firstId,
    const label nChains
)
{
    List<List<point>> x(nChains);
    forAll(x, n)
    {
        x[n] = walk(type, box, seed, firstId + n, 0);
    }
    return x;
}


Foam::labelList Foam::polymer::initialisationModels::randomWalk::judgedHere
(
    const UList<List<point>>& x,
    const labelUList& drawing,
    const periodicImages& periodic,
    const boundBox& bounds,
    boolList& claimed
)
{
    DynamicList<label> judged;
    forAll(drawing, j)
    {
        const List<point>& chain = x[drawing[j]];
        if
        (
            chain.size()
         && bounds.contains(periodic.wrap(chain[chain.size()/2]))
        )
        {
            judged.append(drawing[j]);
            claimed[j] = true;
        }
    }
    return labelList(judged);
}


bool Foam::polymer::initialisationModels::randomWalk::drawnHere
(
    const chainType& type,
    const boundBox& box,
    const label seed,
    const label globalId,
    const label attempt,
    const periodicImages& periodic,
    const boundBox& bounds
)
{
    // The reference bead is within nBeads/2 rods of the first bead (and a
    // margin over the walk's round-off); the first bead's image inside the
    // cyclic patches is within a period of the reference bead's then
    // (walksInside draws here only for chains shorter than the period)
    const point first = periodic.wrap(firstBead(box, seed, globalId, attempt));
    const vector reach
    (
        vector::uniform((1 + 1e-9)*(type.nBeads()/2)*type.rodLength())
    );
    return periodic.overlapsImage
    (
        boundBox(first - reach, first + reach),
        bounds
    );
}


Foam::List<Foam::List<Foam::point>>
Foam::polymer::initialisationModels::randomWalk::walksInside
(
    const chainType& type,
    const boundBox& box,
    const label seed,
    const label firstId,
    const label nChains,
    const fvMesh& mesh,
    const dictionary& dict
)
{
    // The beads' images inside the cyclic patches are what must be in
    // the mesh
    const periodicImages& periodic = periodicImages::New(mesh);
    autoPtr<processorNeighbours> neighbours;
    if (Pstream::parRun())
    {
        neighbours.reset(new processorNeighbours(mesh));
    }

    // In a parallel run each processor draws only the chains whose
    // reference bead can be in its bounds: a reference bead is within
    // nBeads/2 rods of the first bead, and so within one period of the
    // first bead's image when the periods are along the axes and longer
    // than that; otherwise every processor draws every chain
    bool everyChain = !neighbours.valid();
    const scalar reach = (type.nBeads()/2)*type.rodLength();
    for (const vector& t : periodic.lattice())
    {
        everyChain =
            everyChain
         || reach >= cmptMax(cmptMag(t))
         || cmptSum(cmptMag(t)) != cmptMax(cmptMag(t));
    }
    List<List<point>> x(nChains);
    const auto draw = [&](const label n, const label attempt)
    {
        if
        (
            everyChain
         || drawnHere
            (
                type, box, seed, firstId + n, attempt, periodic,
                neighbours->localBounds()
            )
        )
        {
            x[n] = walk(type, box, seed, firstId + n, attempt);
        }
        else
        {
            x[n].clear();
        }
    };
    forAll(x, n)
    {
        draw(n, 0);
    }

    labelList drawing(identity(nChains));
    for (label attempt = 1; drawing.size(); ++attempt)
    {
        drawing = rejected(type, x, drawing, periodic, neighbours, mesh);

        if (drawing.size() && attempt == 1000)
        {
            FatalIOErrorInFunction(dict)
                << "Chain " << firstId + drawing.first() << " ("
                << type.name() << ") from " << dict.name()
                << " has beads outside the mesh in 1000 random walks from"
                << " the box " << box << nl
                << "    expected: min and max of a box well inside the mesh"
                << " for chains of " << type.nBeads() << " beads"
                << exit(FatalIOError);
        }
        for (const label n : drawing)
        {
            draw(n, attempt);
        }
    }

    return x;
}


Foam::labelList Foam::polymer::initialisationModels::randomWalk::rejected
(
    const chainType& type,
    const UList<List<point>>& x,
    const labelUList& drawing,
    const periodicImages& periodic,
    autoPtr<processorNeighbours>& neighbours,
    const fvMesh& mesh
)
{
    // Each draw judged by the processors whose bounds hold its reference
    // bead, asking their neighbours about its beads
    boolList claimed(drawing.size(), false);
    const labelList judged
    (
        neighbours.valid()
      ? judgedHere(x, drawing, periodic, neighbours->localBounds(), claimed)
      : labelList(drawing)
    );
    pointField images(judged.size()*type.nBeads());
    label k = 0;
    for (const label n : judged)
    {
        for (const point& p : x[n])
        {
            images[k++] = periodic.wrap(p);
        }
    }
    const labelList owners
    (
        neighbours.valid()
      ? neighbours->pointOwners(images)
      : replicatedPointOwners(mesh, images)
    );

    DynamicList<label> outside;
    forAll(judged, j)
    {
        if (SubList<label>(owners, type.nBeads(), j*type.nBeads()).found(-1))
        {
            outside.append(judged[j]);
        }
    }
    if (!neighbours.valid())
    {
        return labelList(outside);
    }

    // Every processor's, in order (a chain judged by two processors is
    // judged alike), and the chains nobody judged: their reference bead is
    // in no processor's bounds, so outside every mesh
    Pstream::listCombineGather(claimed, orEqOp<bool>());
    Pstream::listCombineScatter(claimed);
    forAll(claimed, j)
    {
        if (!claimed[j])
        {
            outside.append(drawing[j]);
        }
    }
    labelList all(outside);
    Pstream::combineGather(all, ListOps::appendEqOp<label>());
    Pstream::combineScatter(all);
    return labelHashSet(all).sortedToc();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::initialisationModels::randomWalk::create
(
    polymerChains& chains,
    const label seed
) const
{
    // Ids follow the chains created before, on every processor alike
    const label firstId = chains.nChains();
    label nextId = firstId;

    const dictionary& chainsDict = checkedInput::subDict
    (
        coeffDict_,
        "chains",
        "<chain type> <number of chains>; ..."
    );

    for (const entry& e : chainsDict)
    {
        const label typei =
            findType(chains.types(), e.keyword(), chainsDict, e.keyword());
        const chainType& type = chains.types()[typei];

        if (type.ring())
        {
            FatalIOErrorInFunction(chainsDict)
                << "Chain type '" << type.name() << "' in "
                << chainsDict.name() << " is a ring (its keyword 'ring' is"
                << " true)" << nl
                << "    expected: open chain types; random walks do not"
                << " close (use the trefoil or file initialisation)"
                << exit(FatalIOError);
        }

        const label number = checkedInput::labelAtLeast
        (
            chainsDict, e.keyword(), 0, "<number of chains>"
        );

        const List<List<point>> x
        (
            insideMesh_
          ? walksInside(type, box_, seed, nextId, number, mesh_, coeffDict_)
          : walks(type, box_, seed, nextId, number)
        );

        // Only the chains drawn here (walksInside: those whose reference
        // bead can be in this processor's bounds)
        forAll(x, n)
        {
            if (x[n].size())
            {
                chains.append
                (
                    typei, nextId + n, x[n], List<vector>(x[n].size(), Zero)
                );
            }
        }
        nextId += number;
    }

    return nextId - firstId;
}


// ************************************************************************* //
