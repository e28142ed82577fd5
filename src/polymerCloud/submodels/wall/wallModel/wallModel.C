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

#include "wallModel.H"
#include "makePolymerModel.H"
#include "wallPolyPatch.H"
#include "cyclicPolyPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModelFamily(wallModel)

const Foam::Enum<Foam::polymer::wallModel::interactionType>
Foam::polymer::wallModel::interactionTypeNames
({
    { interactionType::rebound, "rebound" },
    { interactionType::escape, "escape" },
    { interactionType::stick, "stick" },
    { interactionType::reject, "reject" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::wallModel::wallModel
(
    const word& type,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    countedSubModel<wallCounters>(type, dict),
    mesh_(mesh),
    periodic_(periodicImages::New(mesh)),
    interaction_(mesh.boundaryMesh().size(), interactionType::escape),
    escapedBeads_(),
    rejectedBeads_(),
    faces_(),
    edges_(),
    clearance_(),
    edgeClearance_()
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    forAll(patches, patchi)
    {
        if (isA<wallPolyPatch>(patches[patchi]))
        {
            interaction_[patchi] = interactionType::rebound;
        }
    }

    const dictionary* interactionDict =
        coeffDict_.findDict("patchInteraction", keyType::LITERAL);
    if
    (
        !interactionDict
     && coeffDict_.found("patchInteraction", keyType::LITERAL)
    )
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'patchInteraction' in " << coeffDict_.name()
            << " is not a dictionary" << nl
            << "    expected: patchInteraction { <patch> <rebound | escape |"
            << " stick | reject>; ... }"
            << exit(FatalIOError);
    }

    if (interactionDict)
    {
        for (const entry& e : *interactionDict)
        {
            const labelList matched =
                patches.indices(e.keyword(), true);

            if (matched.empty())
            {
                FatalIOErrorInFunction(*interactionDict)
                    << "No patch matches '" << e.keyword() << "' in "
                    << interactionDict->name() << nl
                    << "    expected: <patch name or regex> <"
                    << interactionTypeNames.sortedToc() << ">; with patches "
                    << patches.names()
                    << exit(FatalIOError);
            }

            const word kindName
            (
                interactionDict->get<word>(e.keyword(), keyType::LITERAL)
            );
            if (!interactionTypeNames.found(kindName))
            {
                FatalIOErrorInFunction(*interactionDict)
                    << "Keyword '" << e.keyword() << "' in "
                    << interactionDict->name() << " is " << kindName << nl
                    << "    expected: " << e.keyword() << " <"
                    << interactionTypeNames.sortedToc() << ">;"
                    << exit(FatalIOError);
            }
            const interactionType kind = interactionTypeNames[kindName];
            for (const label patchi : matched)
            {
                interaction_[patchi] = kind;
            }
        }
    }
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

const Foam::polymer::boundaryFaces& Foam::polymer::wallModel::faces() const
{
    if (!faces_.valid())
    {
        if (Pstream::parRun())
        {
            FatalErrorInFunction
                << "The wall model's boundary faces are made collectively:"
                << " call setReach first in a parallel run"
                << exit(FatalError);
        }
        faces_.reset(new boundaryFaces(mesh_, 0));
    }
    return faces_();
}


const Foam::polymer::wallClearance&
Foam::polymer::wallModel::faceVoxels() const
{
    if (!clearance_.valid())
    {
        clearance_.reset(new wallClearance(faces()));
    }
    return clearance_();
}


Foam::scalar Foam::polymer::wallModel::faceClearance(const point& x) const
{
    return faceVoxels()(periodic_.wrap(x));
}


Foam::scalar Foam::polymer::wallModel::faceDistance
(
    const point& x,
    const scalar reach
) const
{
    const point image(periodic_.wrap(x));
    const scalar voxels = faceVoxels()(image);
    if (!(voxels < reach))
    {
        return voxels;
    }

    const scalar bound = faces().clearance(image, reach);
    return max
    (
        voxels,
        searchSafe(bound, cmptMax(cmptMag(image)) + reach)
    );
}


bool Foam::polymer::wallModel::faceImpact
(
    const point& x,
    const vector& v,
    const scalar T,
    impact& hit
) const
{
    if (T*mag(v) < faceClearance(x))
    {
        // No face within the path's reach: the search would miss
        return false;
    }

    // The path is followed at its image inside the mesh, piece by piece
    // between cyclic faces
    point start = periodic_.wrap(x);
    scalar elapsed = 0;

    for (label piece = 0; piece < 64; ++piece)
    {
        const vector path = (T - elapsed)*v;
        const scalar length = mag(path);
        if (length < VSMALL)
        {
            return false;
        }

        // The first boundary face the segment enters from the fluid side
        const pointIndexHit h = faces().firstEntered(start, start + path);
        if (!h.hit())
        {
            return false;
        }

        const label facei = h.index();
        const label patchi = faces().patch(facei);
        const vector area = faces().area(facei);
        const scalar fraction = ((h.hitPoint() - start) & path)/sqr(length);

        if (!isA<cyclicPolyPatch>(mesh_.boundaryMesh()[patchi]))
        {
            hit.time = elapsed + (T - elapsed)*max(fraction*(1 - 1e-9), 0.0);
            hit.normal = -area/mag(area);
            hit.patch = patchi;
            return true;
        }

        // A cyclic face: the path goes on from the neighbour patch
        start = h.hitPoint() + periodic_.translation(patchi);
        elapsed += (T - elapsed)*fraction;
    }

    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::wallModel::edgeClearance(const point& x) const
{
    if (!edgeClearance_.valid())
    {
        edgeClearance_.reset(new wallClearance(faces(), edges()));
    }
    return edgeClearance_()(x);
}


const Foam::polymer::wallEdges& Foam::polymer::wallModel::edges() const
{
    if (!edges_.valid())
    {
        boolList rebounds(interaction_.size());
        forAll(rebounds, patchi)
        {
            rebounds[patchi] =
                (interaction_[patchi] == interactionType::rebound);
        }
        edges_.reset(new wallEdges(faces(), rebounds));
    }
    return edges_();
}


void Foam::polymer::wallModel::setReach(const scalar reach)
{
    faces_.reset(new boundaryFaces(mesh_, reach));
    edgeClearance_.clear();
    edges_.clear();
    clearance_.clear();
}


void Foam::polymer::wallModel::interact
(
    const label bead,
    const impact& hit,
    vector& v,
    vector& vDagger
) const
{
    switch (interaction_[hit.patch])
    {
        case interactionType::rebound:
        {
            // Only a bead moving into the boundary turns back
            const scalar normalSpeed = v & hit.normal;
            if (normalSpeed < 0)
            {
                const vector change = -2*normalSpeed*hit.normal;
                v += change;
                vDagger += change;
            }
            ++counters_.rebounds;
            break;
        }
        case interactionType::escape:
        {
            v = Zero;
            escapedBeads_.append(bead);
            break;
        }
        case interactionType::stick:
        {
            v = Zero;
            vDagger = Zero;
            ++counters_.stuck;
            break;
        }
        case interactionType::reject:
        {
            v = Zero;
            rejectedBeads_.append(bead);
            break;
        }
    }
}


void Foam::polymer::wallModel::correct
(
    polymerChains& chains,
    const UList<vector>& positionsOld,
    const scalar deltaT,
    const scalar time
) const
{
    List<vector>& x = chains.positions();
    List<vector>& vDagger = chains.velocities();

    forAll(x, i)
    {
        point position = positionsOld[i];
        vector v = (x[i] - positionsOld[i])/deltaT;
        scalar t = 0;

        // A bead that keeps meeting the boundary within the step stays
        // where it is after a hundred impacts
        impact hit;
        label nImpacts = 0;
        while (t < deltaT && predict(position, v, deltaT - t, hit))
        {
            position += hit.time*v;
            t += hit.time;
            interact(i, hit, v, vDagger[i]);
            if (++nImpacts == 100)
            {
                v = Zero;
            }
        }

        x[i] = position + (deltaT - t)*v;
    }
}


// * * * * * * * * * * * * * * * * * Report  * * * * * * * * * * * * * * * * //

void Foam::polymer::wallModel::writeReport(Ostream& os) const
{
    const wallCounters total = totalCounters_.reduced();

    os  << "    bead-wall rebounds " << total.rebounds
        << ", chains that left the domain " << total.escapedChains
        << " (" << total.escapedBeads << " beads)"
        << ", beads stuck " << total.stuck
        << ", chain steps rejected " << total.rejectedSteps << nl;
}


// ************************************************************************* //
