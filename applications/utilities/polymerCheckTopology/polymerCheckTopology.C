/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Application
    polymerCheckTopology

Group
    grpPostProcessingUtilities

Description
    Audits the topology of a polymerCloud over the saved times of a case,
    independently of the solver's collision detector:

    - between each two successive saved configurations, with the beads
      moved on straight lines, no two non-adjacent rods may pass through
      each other (a continuous edge-edge test, roots isolated in Bernstein
      form in long double). The straight paths are the beads' motion only
      between saves one time step apart without collisions in the step;
      between saves further apart the check is indicative only, and its
      count is reported apart (the solver's elasticRodsCoeffs { audit
      true; } checks every step's exact paths instead);
    - for every ring, the knot determinant |Delta(-1)| from a projection
      (1 unknot, 3 trefoil, 5 figure-eight).

    Chains are matched between saves by their ids (the cloud reorders
    them). On a mesh with cyclic patches every rod is also checked against
    the other rods' periodic images, and a chain the cloud moved across
    the patches by a lattice translation between saves is brought back by
    it first.

    Stops with a FatalError (exit status 1) when a crossing is found
    between saves one step apart, or when -knot N is given and a ring's
    determinant differs from N.

Usage
    polymerCheckTopology [-cloud polymerCloud] [-knot 3] [time options]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "timeSelector.H"
#include "Time.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "polymerCloud.H"
#include "rodCrossingAudit.H"
#include "knotDeterminant.H"
#include "periodicImages.H"
#include "HashTable.H"

using namespace Foam;
using namespace Foam::polymer;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- One saved configuration
struct frame
{
    word timeName;
    label timeIndex;
    List<point> positions;
    labelList chainId;
    labelList chainType;
};


frame readFrame(const Time& runTime, const word& cloudName)
{
    const fileName local(cloud::prefix/cloudName);
    auto io = [&](const word& name)
    {
        return IOobject
        (
            name, runTime.timeName(), local, runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
    };

    frame f;
    f.timeName = runTime.timeName();

    // The time index from uniform/time, -1 when not saved
    const IOdictionary timeDict
    (
        IOobject
        (
            "time", runTime.timeName(), "uniform", runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        )
    );
    f.timeIndex = timeDict.getOrDefault<label>("index", -1);

    f.positions = polymerCloud::readSavedPositions(io("positions"));
    f.chainId = IOField<label>(io("chainId"));
    f.chainType = IOField<label>(io("chainType"));
    return f;
}


//- Rods as bead pairs, and the bead ranges of the rings
void findRods
(
    const frame& f,
    const PtrList<chainType>& types,
    List<labelPair>& rods,
    List<labelPair>& rings
)
{
    DynamicList<labelPair> rodList, ringList;
    const label n = f.positions.size();
    for (label first = 0; first < n; )
    {
        label end = first + 1;
        while (end < n && f.chainId[end] == f.chainId[first])
        {
            ++end;
        }
        for (label i = first; i + 1 < end; ++i)
        {
            rodList.append(labelPair(i, i + 1));
        }
        if (types[f.chainType[first]].ring())
        {
            rodList.append(labelPair(end - 1, first));
            ringList.append(labelPair(first, end));
        }
        first = end;
    }
    rods.transfer(rodList);
    rings.transfer(ringList);
}


//- The current frame's positions in the previous frame's chain order, each
//  chain brought back by the lattice translation nearest to its first
//  bead's displacement (the cloud moves a chain whole across the cyclic
//  patches); false when the two frames do not hold the same chains
bool alignFrame
(
    const frame& previous,
    const frame& current,
    const UList<vector>& lattice,
    List<point>& aligned
)
{
    const label n = previous.positions.size();
    if (current.positions.size() != n)
    {
        return false;
    }

    // The first bead of each chain of the current frame, by chain id
    Map<label> firstBead;
    forAll(current.chainId, i)
    {
        if (i == 0 || current.chainId[i] != current.chainId[i - 1])
        {
            firstBead.insert(current.chainId[i], i);
        }
    }

    aligned.setSize(n);
    for (label first = 0; first < n; )
    {
        const label id = previous.chainId[first];
        label end = first + 1;
        while (end < n && previous.chainId[end] == id)
        {
            ++end;
        }
        const auto found = firstBead.cfind(id);
        if (!found.found())
        {
            return false;
        }
        const label from = found.val();

        vector shift(Zero);
        const vector moved =
            current.positions[from] - previous.positions[first];
        for (const vector& t : lattice)
        {
            shift += std::round((moved & t)/magSqr(t))*t;
        }
        for (label i = first; i < end; ++i)
        {
            const label j = from + i - first;
            if (j >= n || current.chainId[j] != id)
            {
                return false;
            }
            aligned[i] = current.positions[j] - shift;
        }
        first = end;
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Audit a polymerCloud's topology over the saved times: rod-rod"
        " crossings between successive saves, and the knot determinant of"
        " every ring."
    );
    timeSelector::addOptions();
    argList::addOption("cloud", "name", "Cloud name (default polymerCloud)");
    argList::addOption
    (
        "knot",
        "N",
        "Expected knot determinant of every ring (exit 1 otherwise)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    // The lattice of the mesh's periodic translations (empty: none)
    const List<vector>& lattice = periodicImages::New(mesh).lattice();

    const word cloudName =
        args.getOrDefault<word>("cloud", "polymerCloud");
    const label expectedKnot = args.getOrDefault<label>("knot", -1);

    const IOdictionary properties
    (
        IOobject
        (
            cloudName + "Properties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    PtrList<chainType> types;
    for (const entry& e : properties.subDict("chainTypes"))
    {
        types.append(new chainType(e.keyword(), e.dict()));
    }

    const instantList times = timeSelector::select0(runTime, args);

    label nCrossings = 0;
    label nPairsOfSaves = 0;
    label nIndicative = 0;
    label nKnotMismatches = 0;
    autoPtr<frame> previous;
    List<labelPair> rods, rings;

    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        const fileName cloudDir(runTime.timePath()/cloud::prefix/cloudName);
        if (!isFile(cloudDir/"positions") && !isFile(cloudDir/"position"))
        {
            continue;
        }

        autoPtr<frame> current(new frame(readFrame(runTime, cloudName)));
        // The audit's rods are the previous frame's (in its chain order),
        // the rings the current one's
        List<labelPair> currentRods;
        findRods(current(), types, currentRods, rings);

        Info<< "Time " << current->timeName << ':';

        List<point> aligned;
        if
        (
            previous
         && alignFrame(previous(), current(), lattice, aligned)
        )
        {
            const List<rodCrossingAudit::crossing> found =
                rodCrossingAudit(rods, lattice).check
                (
                    previous->positions,
                    aligned
                );
            const label steps =
                (current->timeIndex >= 0 && previous->timeIndex >= 0)
              ? current->timeIndex - previous->timeIndex
              : -1;

            ++nPairsOfSaves;
            if (steps == 1)
            {
                nCrossings += found.size();
                Info<< " crossings since " << previous->timeName << ' '
                    << found.size();
            }
            else
            {
                nIndicative += found.size();
                Info<< " straight-path crossings since " << previous->timeName
                    << ' ' << found.size() << " (saves "
                    << (steps > 0 ? Foam::name(steps) : word("?"))
                    << " steps apart: indicative only)";
            }
            for (const rodCrossingAudit::crossing& c : found)
            {
                if (steps == 1)
                {
                    Info<< nl << "    rods (beads " << c.rodA << ") and ("
                        << c.rodB << ")";
                    if (c.shift != vector::zero)
                    {
                        Info<< " translated by " << c.shift;
                    }
                    Info<< " at fraction " << c.fraction;
                }
            }
        }

        for (const labelPair& ring : rings)
        {
            const label det = knotDeterminant::compute
            (
                SubList<point>
                (
                    current->positions,
                    ring.second() - ring.first(),
                    ring.first()
                )
            );
            Info<< "; ring of chain " << current->chainId[ring.first()]
                << " |Delta(-1)| " << det;
            if (expectedKnot > 0 && det != expectedKnot)
            {
                ++nKnotMismatches;
            }
        }
        Info<< nl;

        previous = std::move(current);
        rods.transfer(currentRods);
    }

    Info<< nl << "polymerCheckTopology: " << nCrossings
        << " rod crossings between saves one step apart, " << nIndicative
        << " indicative straight-path crossings between saves further apart,"
        << " in " << nPairsOfSaves << " intervals";
    if (expectedKnot > 0)
    {
        Info<< "; rings with |Delta(-1)| other than " << expectedKnot << ": "
            << nKnotMismatches;
    }
    Info<< nl << endl;

    // The exit status must be set before argList's destructor ends the run
    if (nCrossings || nKnotMismatches)
    {
        FatalErrorInFunction
            << nCrossings << " rod crossings, " << nKnotMismatches
            << " rings with an unexpected knot determinant"
            << exit(FatalError);
    }

    return 0;
}


// ************************************************************************* //
