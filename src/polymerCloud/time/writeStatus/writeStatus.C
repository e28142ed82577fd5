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

#include "writeStatus.H"
#include "checkedInput.H"
#include "IFstream.H"
#include "IOdictionary.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::polymer::writeStatus::incompleteAction>
Foam::polymer::writeStatus::incompleteActionNames
({
    { incompleteAction::skip, "skip" },
    { incompleteAction::stop, "stop" },
});

const Foam::word Foam::polymer::writeStatus::markerName("writeStatus");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::writeStatus::writeStatus(Time& runTime)
:
    runTime_(runTime),
    writing_(false)
{
    const word s(status(runTime.timePath()));
    const bool incomplete = !s.empty() && s != "complete";
    if (returnReduce(incomplete, orOp<bool>()))
    {
        FatalErrorInFunction
            << "The start time, " << runTime.timeName() << ", was not"
            << " completely written (a run stopped while writing it): its "
            << markerName << " on this processor says "
            << (s.empty() ? word("nothing (none)") : s) << nl
            << "    expected: a complete start time; start from an earlier"
            << " time, or from latestTime with incompleteTimes skip; in "
            << runTime.controlDict().name()
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::word Foam::polymer::writeStatus::status(const fileName& dir)
{
    const fileName file(dir/markerName);
    if (!isFile(file))
    {
        return word::null;
    }

    // A marker cut short does not parse: that is an answer, not an error
    const bool throwingIO = FatalIOError.throwExceptions();
    const bool throwing = FatalError.throwExceptions();
    word result("unreadable");
    try
    {
        IFstream is(file);
        if (is.good())
        {
            const dictionary dict(is);
            result = dict.getOrDefault<word>("status", result);
        }
    }
    catch (const Foam::error&)
    {}
    FatalIOError.throwExceptions(throwingIO);
    FatalError.throwExceptions(throwing);

    return result;
}


void Foam::polymer::writeStatus::mark
(
    const Time& runTime,
    const fileName& local,
    const word& status
)
{
    IOdictionary marker
    (
        IOobject
        (
            markerName,
            runTime.timeName(),
            local,
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    marker.add("time", runTime.value());
    marker.add("index", runTime.timeIndex());
    marker.add("status", status);

    if (!marker.regIOobject::write())
    {
        FatalErrorInFunction
            << "Cannot write " << marker.objectPath()
            << exit(FatalError);
    }
}


bool Foam::polymer::writeStatus::complete(const fileName& timeDir)
{
    const word s(status(timeDir));
    if (s.empty())
    {
        // Not written by this solver, unless killed between creating the
        // directory and writing the marker into it
        return
            !readDir(timeDir, fileName::FILE).empty()
         || !readDir(timeDir, fileName::DIRECTORY).empty();
    }
    return s == "complete";
}


void Foam::polymer::writeStatus::checkTimePrecision
(
    const dictionary& controlDict,
    const instant& start
)
{
    // Not "constant", which findTimes gives a case without times
    scalar value;
    if
    (
        !readScalar(start.name(), value)
     || controlDict.getOrDefault<word>("timeFormat", "general") != "general"
    )
    {
        return;
    }
    const label precision =
        controlDict.getOrDefault<label>("timePrecision", 6);

    // v1912's search (Time::setControls): from the most digits
    // (Time::maxPrecision_) down, stopping where two numbers of digits
    // give the same name
    const label maxDigits = 3 - log10(SMALL);
    word previous(Time::timeName(start.value(), precision));
    bool found = (previous == start.name());
    for (label digits = maxDigits; !found && digits > precision; --digits)
    {
        const word name(Time::timeName(start.value(), digits));
        if (name == previous)
        {
            break;
        }
        previous = name;
        found = (name == start.name());
    }
    if (found)
    {
        return;
    }

    label needed = precision + 1;
    while
    (
        needed < maxDigits
     && Time::timeName(start.value(), needed) != start.name()
    )
    {
        ++needed;
    }
    FatalIOErrorInFunction(controlDict)
        << "The latest time directory, " << start.name() << ", is named with"
        << " more digits than timePrecision " << precision << " gives ("
        << Time::timeName(start.value(), precision) << "), as the time step"
        << " adjusted by maxCo makes, and OpenFOAM v1912 would not find it:"
        << " the run would start without its fields and chains" << nl
        << "    expected: timePrecision " << needed << "; (or more) in "
        << controlDict.name()
        << exit(FatalIOError);
}


void Foam::polymer::writeStatus::selectComplete(const argList& args)
{
    const fileName dictFile(args.globalPath()/"system"/"controlDict");
    IFstream is(dictFile);
    if (!is.good())
    {
        return;     // the Time reports it
    }
    const dictionary controlDict(is);
    const word startFrom
    (
        controlDict.getOrDefault<word>("startFrom", "latestTime")
    );
    if (startFrom != "latestTime")
    {
        return;
    }
    const incompleteAction action = checkedInput::enumOrDefault
    (
        controlDict, "incompleteTimes", incompleteActionNames,
        incompleteAction::skip
    );

    for (;;)
    {
        // The time directories ("constant", which findTimes lists first
        // as time 0, is none)
        DynamicList<instant> times;
        for (const instant& t : TimePaths::findTimes(args.path()))
        {
            if (t.name() != "constant")
            {
                times.append(t);
            }
        }
        const scalar mine = times.empty() ? -GREAT : times.last().value();
        const scalar latest = returnReduce(mine, maxOp<scalar>());
        if (latest == -GREAT)
        {
            return;
        }

        // The only time of a processor may be an empty directory (its
        // initial conditions): incomplete only if marked so
        const bool haveLatest = !times.empty() && mine == latest;

        // Its name as the directory has it (the master's, which has it
        // unless the run was stopped before the master made it)
        word latestName
        (
            haveLatest ? times.last().name() : Time::timeName(latest)
        );
        Pstream::scatter(latestName);
        const fileName dir(haveLatest ? args.path()/times.last().name() : "");
        const bool completeHere =
            haveLatest
         && (
                complete(dir)
             || (times.size() == 1 && status(dir).empty())
            );
        if (returnReduce(completeHere, andOp<bool>()))
        {
            checkTimePrecision(controlDict, times.last());
            return;
        }

        const label nIncomplete =
            returnReduce(label(!completeHere), sumOp<label>());
        if (action == incompleteAction::stop)
        {
            FatalIOErrorInFunction(controlDict)
                << "The latest time, " << latestName << ", was not completely"
                << " written (a run stopped while writing it) on "
                << nIncomplete << " of " << Pstream::nProcs()
                << " processor(s)" << nl
                << "    expected: a complete latest time (its " << markerName
                << " with 'status complete;'), or incompleteTimes skip; in "
                << dictFile << " to continue from the last complete time"
                << exit(FatalIOError);
        }

        fileName target;
        if (haveLatest)
        {
            target = dir + ".incomplete";
            for (label i = 1; exists(target, false); ++i)
            {
                target = dir + ".incomplete" + Foam::name(i);
            }
            if (!mv(dir, target))
            {
                FatalErrorInFunction
                    << "Cannot move the incomplete time directory " << dir
                    << " aside to " << target << exit(FatalError);
            }
        }
        Pstream::scatter(target);

        WarningInFunction
            << "The latest time, " << latestName << ", was not completely written"
            << " (a run stopped while writing it) on " << nIncomplete
            << " of " << Pstream::nProcs() << " processor(s): moved aside"
            << " to " << target << (Pstream::parRun() ? " on each" : "")
            << "; starting from the last complete time"
            << " (incompleteTimes skip; in " << dictFile << ")" << endl;
    }
}


bool Foam::polymer::writeStatus::run()
{
    const bool running = runTime_.run();

    if (writing_)
    {
        mark(runTime_, fileName::null, "complete");
        writing_ = false;
    }
    return running;
}


bool Foam::polymer::writeStatus::write()
{
    if (runTime_.writeTime())
    {
        mark(runTime_, fileName::null, "started");
        writing_ = true;
    }
    return runTime_.write();
}


// ************************************************************************* //
