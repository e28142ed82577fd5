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

#include "pathTimes.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::FixedList<const char*, Foam::polymer::pathTimes::nPaths>
Foam::polymer::pathTimes::names
({
    "inject",
    "interpolate the flow",
    "locate and sample",
    "integrate",
    "constrain",
    "couple",
    "collide",
    "reproject",
    "bookkeep",
    "functions",
    "write"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::pathTimes::pathTimes()
:
    seconds_(Zero),
    last_(std::clock()),
    started_(last_),
    open_(false),
    lapLast_(lapClock::now()),
    lapTimes_(lapClock::duration::zero())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::polymer::pathTimes::stop()
{
    last_ = std::clock();
    const scalar cpuSeconds = scalar(last_ - started_)/CLOCKS_PER_SEC;
    if (!open_)
    {
        return cpuSeconds;
    }
    open_ = false;

    lapClock::duration lapped = lapClock::duration::zero();
    for (const lapClock::duration& t : lapTimes_)
    {
        lapped += t;
    }
    if (lapped.count() > 0)
    {
        const scalar perTick = cpuSeconds/lapped.count();
        for (label p = 0; p < nPaths; ++p)
        {
            seconds_[p] += perTick*lapTimes_[p].count();
        }
    }
    return cpuSeconds;
}


void Foam::polymer::pathTimes::writeReport(Ostream& os) const
{
    FixedList<scalar, nPaths> total(seconds_);
    scalar sum = 0;
    for (scalar& s : total)
    {
        reduce(s, sumOp<scalar>());
        sum += s;
    }

    // Milliseconds: three significant digits whatever the run's precision
    const int oldPrecision = os.precision(3);
    os  << "    CPU by path, s (share), all processors:";
    label nListed = 0;
    for (label p = 0; p < nPaths; ++p)
    {
        if (total[p] >= 5e-4)
        {
            os  << (nListed++ ? ", " : " ") << names[p] << ' '
                << total[p] << " (" << label(100*total[p]/sum + 0.5)
                << "%)";
        }
    }
    if (!nListed)
    {
        os  << " none above a millisecond";
    }
    os  << nl;
    os.precision(oldPrecision);
}


// ************************************************************************* //
