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

#include "freedMemory.H"
#include "debug.H"
#include "Time.H"
#include "error.H"

#include <cstdlib>
#include <cstring>
#include <malloc.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

bool Foam::polymer::freedMemory::settled_ = false;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

int Foam::polymer::freedMemory::keepSwitch(const Time& runTime)
{
    // Looked up, not registered (registerOptSwitch): a registered switch
    // raised the peak memory at exit by 4 MB in a run of 400 000 beads
    const dictionary* local =
        runTime.controlDict().findDict("OptimisationSwitches");
    const dictionary& switches =
        (local && local->found("keepFreedMemory"))
      ? *local
      : debug::optimisationSwitches();

    const int value = switches.getOrDefault<int>("keepFreedMemory", 1);
    if (value != 0 && value != 1)
    {
        FatalIOErrorInFunction(switches)
            << "OptimisationSwitches keepFreedMemory in " << switches.name()
            << " is " << value << nl
            << "    expected: keepFreedMemory 0; (malloc's own policy) or"
            << " keepFreedMemory 1; (freed memory kept for reuse)"
            << exit(FatalIOError);
    }
    return value;
}


bool Foam::polymer::freedMemory::setByEnvironment()
{
    const char* tunables = std::getenv("GLIBC_TUNABLES");

    return
        std::getenv("MALLOC_MMAP_THRESHOLD_")
     || std::getenv("MALLOC_TRIM_THRESHOLD_")
     || std::getenv("MALLOC_TOP_PAD_")
     || (tunables && std::strstr(tunables, "glibc.malloc."));
}


bool Foam::polymer::freedMemory::keep(const Time& runTime)
{
    if (settled_)
    {
        return false;
    }
    settled_ = true;

    if (!keepSwitch(runTime))
    {
        Info<< "polymerCloud: malloc's own thresholds"
            << " (OptimisationSwitches keepFreedMemory 0)" << nl;
        return false;
    }
    if (setByEnvironment())
    {
        Info<< "polymerCloud: malloc's thresholds as the environment sets"
            << " them" << nl;
        return false;
    }

    // Each call fixes its threshold (no dynamic raise); a refusal leaves
    // glibc's policy, which is only slower
    const bool set =
        mallopt(M_MMAP_THRESHOLD, mmapThreshold) == 1
     && mallopt(M_TRIM_THRESHOLD, trimThreshold) == 1;

    Info<< "polymerCloud: freed memory "
        << (set ? "kept for reuse" : "returned as malloc decides")
        << " (arrays up to " << mmapThreshold/(1024*1024)
        << " MB from the heap, the heap's free top kept up to "
        << trimThreshold/(1024*1024) << " MB;"
        << " OptimisationSwitches keepFreedMemory)" << nl;

    return set;
}


// ************************************************************************* //
