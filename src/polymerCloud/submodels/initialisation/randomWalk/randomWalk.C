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
    box_(coeffDict_.get<point>("min"), coeffDict_.get<point>("max")),
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
    noise.uniforms(0, 0, chainNoise::setUpStream, attempt, u);
    x[0] = box.min() + cmptMultiply(vector(u[0], u[1], u[2]), box.span());

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
    const processorNeighbours& neighbours,
    DynamicList<label>& outside
)
{
    // A reference bead outside every processor's bounds is outside every
    // mesh: the master says so without asking (the whole mesh's box
    // first, then each processor's)
    const boundBox& bounds = neighbours.localBounds();
    boundBox meshBounds(boundBox::invertedBox);
    for (const boundBox& bb : neighbours.processorBounds())
    {
        if (bb.valid())
        {
            meshBounds.add(bb);
        }
    }
    DynamicList<label> judged;
    for (const label n : drawing)
    {
        const point p = periodic.wrap(x[n][x[n].size()/2]);
        if (bounds.contains(p))
        {
            judged.append(n);
        }
        else if (Pstream::master())
        {
            bool held = meshBounds.contains(p);
            if (held)
            {
                held = false;
                for (const boundBox& bb : neighbours.processorBounds())
                {
                    if (bb.contains(p))
                    {
                        held = true;
                        break;
                    }
                }
            }
            if (!held)
            {
                outside.append(n);
            }
        }
    }
    return labelList(judged);
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
    List<List<point>> x(walks(type, box, seed, firstId, nChains));

    // The beads' images inside the cyclic patches are what must be in
    // the mesh
    const periodicImages& periodic = periodicImages::New(mesh);
    autoPtr<processorNeighbours> neighbours;
    if (Pstream::parRun())
    {
        neighbours.reset(new processorNeighbours(mesh));
    }
    labelList drawing(identity(nChains));
    for (label attempt = 1; drawing.size(); ++attempt)
    {
        DynamicList<label> outside;
        const labelList judged
        (
            neighbours.valid()
          ? judgedHere(x, drawing, periodic, neighbours(), outside)
          : drawing
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

        forAll(judged, j)
        {
            const SubList<label> beadOwners
            (
                owners, type.nBeads(), j*type.nBeads()
            );
            if (beadOwners.found(-1))
            {
                outside.append(judged[j]);
            }
        }
        if (neighbours.valid())
        {
            // Every processor's, in order (a chain judged by two
            // processors is judged alike)
            labelList all(outside);
            Pstream::combineGather(all, ListOps::appendEqOp<label>());
            Pstream::combineScatter(all);
            drawing = labelHashSet(all).sortedToc();
        }
        else
        {
            drawing.transfer(outside);
        }

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
            x[n] = walk(type, box, seed, firstId + n, attempt);
        }
    }

    return x;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::initialisationModels::randomWalk::create
(
    polymerChains& chains,
    const label seed
) const
{
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
                << chainsDict.name() << " is a ring" << nl
                << "    expected: open chain types; random walks do not"
                << " close (use the trefoil or file initialisation)"
                << exit(FatalIOError);
        }

        const label number = checkedInput::labelAtLeast
        (
            chainsDict, e.keyword(), 0, "<number of chains>"
        );

        const label firstId = chains.nChains();
        const List<List<point>> x
        (
            insideMesh_
          ? walksInside(type, box_, seed, firstId, number, mesh_, coeffDict_)
          : walks(type, box_, seed, firstId, number)
        );

        forAll(x, n)
        {
            chains.append
            (
                typei, firstId + n, x[n], List<vector>(x[n].size(), Zero)
            );
        }
    }
}


// ************************************************************************* //
