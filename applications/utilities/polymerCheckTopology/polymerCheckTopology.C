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
      form in long double); meaningful when the saves are close enough for
      straight paths to stand for the motion (every time step, say);
    - for every ring, the knot determinant |Delta(-1)| from a projection
      (1 unknot, 3 trefoil, 5 figure-eight).

    Exits with status 1 when a crossing is found, or when -knot N is given
    and a ring's determinant differs from N.

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

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- One saved configuration
struct frame
{
    word timeName;
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
    f.positions = polymerCloud::readPositions(io("positions"));
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
    label nKnotMismatches = 0;
    autoPtr<frame> previous;
    List<labelPair> rods, rings;

    for (const instant& t : times)
    {
        runTime.setTime(t, 0);
        if (!isFile(runTime.timePath()/cloud::prefix/cloudName/"positions"))
        {
            continue;
        }

        autoPtr<frame> current(new frame(readFrame(runTime, cloudName)));
        if (!previous)
        {
            findRods(current(), types, rods, rings);
        }

        Info<< "Time " << current->timeName << ':';

        if (previous && previous->positions.size() == current->positions.size())
        {
            const List<rodCrossingAudit::crossing> found =
                rodCrossingAudit(rods).check
                (
                    previous->positions,
                    current->positions
                );
            ++nPairsOfSaves;
            nCrossings += found.size();
            Info<< " crossings since " << previous->timeName << ' '
                << found.size();
            for (const rodCrossingAudit::crossing& c : found)
            {
                Info<< nl << "    rods (beads " << c.rodA << ") and ("
                    << c.rodB << ") at fraction " << c.fraction;
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
    }

    Info<< nl << "polymerCheckTopology: " << nCrossings
        << " rod crossings in " << nPairsOfSaves
        << " intervals between saves";
    if (expectedKnot > 0)
    {
        Info<< "; rings with |Delta(-1)| other than " << expectedKnot << ": "
            << nKnotMismatches;
    }
    Info<< nl << endl;

    return (nCrossings || nKnotMismatches) ? 1 : 0;
}


// ************************************************************************* //
