/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | polymerCloud: bead-rod chains in OpenFOAM flows
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of polymerCloud, an extension of OpenFOAM (GPL v3+).

Description
    Reading and writing the chains in the time directories:
    lagrangian/<cloud>/positions (OpenFOAM's v1706 positions format, which
    ParaView's OpenFOAM reader shows as points), position (the same as a
    field), U, chainId, bead and chainType (index into chainTypes).
    Every file follows the case's writeFormat and writeCompression
    (positions in binary as OpenFOAM's particles write it: each point and
    its cell as one raw block). Positions and velocities are written with
    17 significant digits in ASCII so that a restart continues bit for
    bit.

    In a parallel run each processor writes its own chains whole, beads
    in its neighbours' sub-domains included. reconstructPar joins the
    processors' fields (position, U, chainId, bead, chainType) into the
    case's time directory, from which a serial run restarts; it makes no
    positions file there (OpenFOAM's particles must lie in their
    processor's mesh, a chain's beads need not), so the position field is
    read first.

\*---------------------------------------------------------------------------*/

#include "polymerCloud.H"
#include "asciiBlockWriter.H"
#include "checkedInput.H"
#include "writeStatus.H"
#include "runTotals.H"
#include "IOField.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "fileOperation.H"
#include "OSspecific.H"
#include "particle.H"
#include "isFinite.H"

#include <cstddef>
#include <cstring>
#include <vector>

// * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * * //

namespace
{
    // The bytes of a binary positions entry, as particle::writePosition
    // writes them: the point and its cell
    const std::streamsize binaryEntrySize =
        offsetof(Foam::particle::positionsCompat1706, facei)
      - offsetof(Foam::particle::positionsCompat1706, position);
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::IOobject Foam::polymer::polymerCloud::fieldIOobject
(
    const word& fieldName,
    const IOobject::readOption r
) const
{
    return IOobject
    (
        fieldName,
        mesh_.time().timeName(),
        *this,
        r,
        IOobject::NO_WRITE,
        false
    );
}


bool Foam::polymer::polymerCloud::savedCloudExists(const fileName& dir)
{
    return isFile(dir/"position") || isFile(dir/"positions");
}


Foam::fileName Foam::polymer::polymerCloud::savedCloudDir() const
{
    return mesh_.time().timePath()/cloud::prefix/name();
}


bool Foam::polymer::polymerCloud::savedCloudIsComplete() const
{
    const fileName dir(savedCloudDir());
    const bool saved = savedCloudExists(dir);
    const word status(saved ? writeStatus::status(dir) : word::null);
    const bool incomplete = saved && !status.empty() && status != "complete";

    if (returnReduce(incomplete, orOp<bool>()))
    {
        WarningInFunction
            << "The chains saved in "
            << mesh_.time().timeName()/cloud::prefix/name()
            << " at the start of an earlier run were not completely written"
            << " (the run was stopped while writing them): starting them"
            << " anew with the initialisation, as they were" << endl;
        return false;
    }
    return returnReduce(saved, orOp<bool>());
}


Foam::fileName Foam::polymer::polymerCloud::undecomposedCloudDir() const
{
    const Time& runTime = mesh_.time();
    return runTime.globalPath()/runTime.timeName()/cloud::prefix/name();
}


Foam::fileName Foam::polymer::polymerCloud::outputPropertiesFile
(
    const fileName& timeDir
) const
{
    return
        timeDir/"uniform"/cloud::prefix/name()/(name() + "OutputProperties");
}


Foam::dictionary Foam::polymer::polymerCloud::readOutputProperties
(
    const fileName& timeDir
) const
{
    IFstream is(outputPropertiesFile(timeDir));
    return is.good() ? dictionary(is) : dictionary();
}


Foam::label Foam::polymer::polymerCloud::readNextChainId
(
    const dictionary& outputProperties
) const
{
    return checkedInput::labelAtLeastOrDefault
    (
        outputProperties, "nextChainId", -1, 0, "<the next chain's id>"
    );
}


void Foam::polymer::polymerCloud::readRunTotals
(
    const dictionary& outputProperties
)
{
    const dictionary* saved = outputProperties.findDict("runTotals");
    if (!saved)
    {
        return;
    }
    runTotals::read(*saved, "injected", nInjected_);
    for (polymerSubModel& model : models_)
    {
        model.readRunTotals(*saved);
    }
    stepper_->readRunTotals(*saved);
    distribution_->readRunTotals(*saved);
    coupling_->readRunTotals(*saved);
    if (contactProjection_)
    {
        contactProjection_->readRunTotals(*saved);
    }
}


void Foam::polymer::polymerCloud::writeOutputProperties() const
{
    IOdictionary outputProperties
    (
        IOobject
        (
            name() + "OutputProperties",
            mesh_.time().timeName(),
            "uniform"/cloud::prefix/name(),
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    outputProperties.add("nextChainId", nextChainId_);

    // The run's totals, for a restart to continue them (collective)
    dictionary totals;
    runTotals::add
    (
        totals, "injected", returnReduce(nInjected_, sumOp<label>())
    );
    for (const polymerSubModel& model : models_)
    {
        model.writeRunTotals(totals);
    }
    stepper_->writeRunTotals(totals);
    distribution_->writeRunTotals(totals);
    coupling_->writeRunTotals(totals);
    if (contactProjection_)
    {
        contactProjection_->writeRunTotals(totals);
    }
    outputProperties.add("runTotals", totals);

    outputProperties.regIOobject::write();
}


Foam::List<Foam::point>
Foam::polymer::polymerCloud::readPositions(const IOobject& io)
{
    IFstream is(io.objectPath());

    IOobject header(io);
    if (!is.good() || !header.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the header of " << io.objectPath()
            << exit(FatalIOError);
    }

    const label n = readLabel(is);
    List<point> positions(n);

    is.readBegin("positions");
    if (is.format() == IOstream::ASCII)
    {
        for (point& p : positions)
        {
            label celli;
            is >> p >> celli;
        }
    }
    else
    {
        // Raw blocks of this build's point and label: a file written with
        // other sizes (its header's arch) cannot be read so
        if
        (
            is.labelByteSize() != sizeof(label)
         || is.scalarByteSize() != sizeof(scalar)
        )
        {
            FatalIOErrorInFunction(is)
                << "The binary positions file " << io.objectPath()
                << " has " << is.labelByteSize() << "-byte labels and "
                << is.scalarByteSize() << "-byte scalars (its header's arch)"
                << nl << "    expected: " << sizeof(label) << "-byte labels"
                << " and " << sizeof(scalar) << "-byte scalars, as this"
                << " build writes them (or an ASCII file)"
                << exit(FatalIOError);
        }
        particle::positionsCompat1706 entry;
        for (point& p : positions)
        {
            is.read(reinterpret_cast<char*>(&entry.position), binaryEntrySize);
            p = entry.position;
        }
    }
    is.readEnd("positions");
    is.check(FUNCTION_NAME);

    return positions;
}


Foam::List<Foam::point> Foam::polymer::polymerCloud::readSavedPositions
(
    const IOobject& io
)
{
    // The position field where there is one: reconstructPar writes no
    // positions file for the beads, which need not be in a processor's
    // mesh, but joins the processors' position fields
    IOobject field(io, "position");
    field.readOpt() = IOobject::MUST_READ;
    if (isFile(field.objectPath()))
    {
        return List<point>(IOField<point>(field));
    }
    return readPositions(IOobject(io, "positions"));
}


void Foam::polymer::polymerCloud::readChains(const fileName& dir)
{
    auto io = [&](const word& fieldName)
    {
        return IOobject
        (
            dir/fieldName, mesh_, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        );
    };

    const List<point> positions(readSavedPositions(io("positions")));
    const IOField<vector> U(io("U"));
    const IOField<label> chainId(io("chainId"));
    const IOField<label> bead(io("bead"));
    const IOField<label> typeIndex(io("chainType"));

    const label n = positions.size();
    if (U.size() != n || chainId.size() != n || bead.size() != n
     || typeIndex.size() != n)
    {
        FatalIOErrorInFunction(properties_)
            << "The saved cloud in " << U.path() << " has fields of"
            << " different sizes: positions " << n << ", U " << U.size()
            << ", chainId " << chainId.size() << ", bead " << bead.size()
            << ", chainType " << typeIndex.size()
            << exit(FatalIOError);
    }

    // Beads of a chain are consecutive, in bead order
    for (label first = 0; first < n; )
    {
        const label typei = typeIndex[first];
        if (typei < 0 || typei >= types_.size())
        {
            FatalIOErrorInFunction(properties_)
                << "Bead " << first << " in " << U.path() << " has chainType "
                << typei << nl << "    expected: an index into chainTypes"
                << " (0 to " << types_.size() - 1 << ")"
                << exit(FatalIOError);
        }

        const label size = types_[typei].nBeads();
        for (label k = 0; k < size; ++k)
        {
            const label i = first + k;
            if (i < n && !(isFinite(positions[i]) && isFinite(U[i])))
            {
                FatalIOErrorInFunction(properties_)
                    << "Chain " << chainId[first] << ", bead " << k << ", in "
                    << U.path() << " has position " << positions[i]
                    << " and velocity " << U[i] << nl
                    << "    expected: finite values (no NaN or inf)"
                    << exit(FatalIOError);
            }
            if
            (
                i >= n || bead[i] != k || chainId[i] != chainId[first]
             || typeIndex[i] != typei
            )
            {
                FatalIOErrorInFunction(properties_)
                    << "Chain " << chainId[first] << " in " << U.path()
                    << " is not a run of " << size << " beads numbered 0 to "
                    << size - 1 << " (type " << types_[typei].name() << ")"
                    << exit(FatalIOError);
            }
        }

        chains_.append
        (
            typei,
            chainId[first],
            SubList<point>(positions, size, first),
            SubList<vector>(U, size, first)
        );
        first += size;
    }

    checkRods(U.path());
}


void Foam::polymer::polymerCloud::writePositions
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp
) const
{
    const IOobject io(fieldIOobject("positions", IOobject::NO_READ));
    mkDir(io.path());

    // Through the file handler, as the cloud's fields are
    autoPtr<Ostream> osPtr
    (
        fileHandler().NewOFstream(io.objectPath(), fmt, ver, cmp)
    );
    Ostream& os = osPtr();
    io.writeHeader(os, "Cloud<passiveParticle>");

    const List<vector>& x = chains_.positions();

    // The v1706 format's host cell: -1, not searched for (a tree search
    // per bead and write); readers locate the points themselves, and
    // chains need not be in the mesh
    os  << x.size() << nl << token::BEGIN_LIST << nl;
    if (os.format() == IOstream::ASCII)
    {
        asciiBlockWriter out(os);
        for (const point& p : x)
        {
            out << p << char(token::SPACE) << label(-1) << char(token::NL);
        }
    }
    else
    {
        // particle::writePosition's binary entry: the point and the cell
        // as one raw block, which OpenFOAM's readers take, in parentheses
        // (OSstream::write) and followed by a newline. The same bytes are
        // gathered in blocks of entries and written at once: four stream
        // calls a bead were half the write of a large cloud
        const std::streamsize entrySize = binaryEntrySize + 3;
        const label entriesPerBlock = 2048;
        std::vector<char> block(entriesPerBlock*entrySize);
        particle::positionsCompat1706 entry;
        entry.celli = -1;
        for (label first = 0; first < x.size(); first += entriesPerBlock)
        {
            const label last = min(first + entriesPerBlock, x.size());
            char* out = block.data();
            for (label i = first; i < last; ++i)
            {
                entry.position = x[i];
                *out++ = token::BEGIN_LIST;
                std::memcpy(out, &entry.position, binaryEntrySize);
                out += binaryEntrySize;
                *out++ = token::END_LIST;
                *out++ = token::NL;
            }
            os.writeRaw(block.data(), out - block.data());
        }
    }
    os  << token::END_LIST << nl;

    IOobject::writeEndDivider(os);
}


bool Foam::polymer::polymerCloud::writeVectorField
(
    const IOField<vector>& field,
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp
) const
{
    const IOobject& io = field;
    const UList<vector>& values = field;
    if
    (
        fmt != IOstream::ASCII
     || values.size() <= Detail::ListPolicy::short_length<vector>::value
     || values.uniform()
    )
    {
        return field.writeObject(fmt, ver, cmp, true);
    }

    // The file IOField::writeObject writes (through the file handler, its
    // header, UList::writeList's layout of a long list that is not
    // uniform, the end divider), its numbers formatted in blocks
    mkDir(io.path());
    autoPtr<Ostream> osPtr
    (
        fileHandler().NewOFstream(io.objectPath(), fmt, ver, cmp)
    );
    Ostream& os = osPtr();
    if (!os.good())
    {
        return false;
    }
    field.writeHeader(os);
    os  << nl << values.size() << nl << token::BEGIN_LIST << nl;
    {
        asciiBlockWriter out(os);
        for (const vector& v : values)
        {
            out << v << char(token::NL);
        }
    }
    os  << token::END_LIST << nl;
    IOobject::writeEndDivider(os);
    return os.good();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::polymer::polymerCloud::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
{
    pathTimes_.start();
    stepper_->checkFinite("at the write of time");
    const unsigned int oldPrecision =
        IOstream::defaultPrecision(max(17u, IOstream::defaultPrecision()));

    writePositions(fmt, ver, cmp);

    const label n = chains_.nBeads();
    IOField<point> position
    (
        fieldIOobject("position", IOobject::NO_READ),
        chains_.positions()
    );
    IOField<vector> U
    (
        fieldIOobject("U", IOobject::NO_READ),
        chains_.velocities()
    );
    IOField<label> chainId(fieldIOobject("chainId", IOobject::NO_READ), n);
    IOField<label> bead(fieldIOobject("bead", IOobject::NO_READ), n);
    IOField<label> typeIndex
    (
        fieldIOobject("chainType", IOobject::NO_READ),
        n
    );

    for (label c = 0; c < chains_.nChains(); ++c)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            chainId[i] = chains_.globalId(c);
            bead[i] = i - chains_.start(c);
            typeIndex[i] = chains_.typeIndex(c);
        }
    }

    const bool ok =
        writeVectorField(position, fmt, ver, cmp)
     && writeVectorField(U, fmt, ver, cmp)
     && chainId.writeObject(fmt, ver, cmp, true)
     && bead.writeObject(fmt, ver, cmp, true)
     && typeIndex.writeObject(fmt, ver, cmp, true);

    writeOutputProperties();
    IOstream::defaultPrecision(oldPrecision);

    for (polymerCloudFunction& function : functions_)
    {
        function.write();
    }

    const bool written = ok && cloud::writeObject(fmt, ver, cmp, valid);
    pathTimes_.lap(pathTimes::write);
    pathTimes_.stop();
    return written;
}


void Foam::polymer::polymerCloud::writeObjects(objectRegistry& obr) const
{
    IOField<point>& position =
        cloud::createIOField<point>("position", chains_.nBeads(), obr);
    position = chains_.positions();

    IOField<vector>& U =
        cloud::createIOField<vector>("U", chains_.nBeads(), obr);
    U = chains_.velocities();

    IOField<label>& chainId =
        cloud::createIOField<label>("chainId", chains_.nBeads(), obr);
    for (label c = 0; c < chains_.nChains(); ++c)
    {
        for (label i = chains_.start(c); i < chains_.end(c); ++i)
        {
            chainId[i] = chains_.globalId(c);
        }
    }
}


// ************************************************************************* //
