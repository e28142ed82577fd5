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

#include "vtkChains.H"
#include "checkedInput.H"
#include "polymerCloud.H"
#include "foamVtkOutput.H"
#include "OSspecific.H"
#include "makePolymerModel.H"

#include <fstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(polymerCloudFunction, cloudFunctions, vtkChains)


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::cloudFunctions::vtkChains::writeLines
(
    vtk::formatter& format,
    const polymerChains& chains
) const
{
    // A ring repeats its first bead to close the line
    labelList connectivity(chains.nBeads() + chains.nChains());
    labelList offsets(chains.nChains());
    label n = 0;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            connectivity[n++] = i;
        }
        if (chains.type(c).ring())
        {
            connectivity[n++] = chains.start(c);
        }
        offsets[c] = n;
    }
    connectivity.setSize(n);

    format.tag(vtk::fileTag::LINES);

    format.beginDataArray<label>(vtk::dataArrayAttr::CONNECTIVITY);
    format.writeSize(vtk::sizeofData<label>(connectivity.size()));
    vtk::writeList(format, connectivity);
    format.flush();
    format.endDataArray();

    format.beginDataArray<label>(vtk::dataArrayAttr::OFFSETS);
    format.writeSize(vtk::sizeofData<label>(offsets.size()));
    vtk::writeList(format, offsets);
    format.flush();
    format.endDataArray();

    format.endTag(vtk::fileTag::LINES);
}


void Foam::polymer::cloudFunctions::vtkChains::writeFile
(
    const fileName& file,
    const polymerChains& chains
) const
{
    const Time& runTime = cloud_.mesh().time();
    const label nBeads = chains.nBeads();

    std::ofstream os(file);
    autoPtr<vtk::formatter> format = writeOpts_.newFormatter(os);

    format()
        .xmlHeader()
        .beginVTKFile<vtk::fileTag::POLY_DATA>()
        .beginFieldData()
        .writeTimeValue(runTime.value())
        .endFieldData()
        .tag
        (
            vtk::fileTag::PIECE,
            vtk::fileAttr::NUMBER_OF_POINTS, nBeads,
            vtk::fileAttr::NUMBER_OF_LINES, chains.nChains()
        );

    format().tag(vtk::fileTag::POINTS)
        .beginDataArray<float, 3>(vtk::dataArrayAttr::POINTS);
    format().writeSize(vtk::sizeofData<float, 3>(nBeads));
    vtk::writeList(format(), chains.positions());
    format().flush();
    format().endDataArray();
    format().endTag(vtk::fileTag::POINTS);

    writeLines(format(), chains);

    labelList chainId(nBeads);
    labelList bead(nBeads);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            chainId[i] = chains.globalId(c);
            bead[i] = i - chains.start(c);
        }
    }

    format().beginPointData();

    format().beginDataArray<label>("chainId");
    format().writeSize(vtk::sizeofData<label>(nBeads));
    vtk::writeList(format(), chainId);
    format().flush();
    format().endDataArray();

    format().beginDataArray<label>("bead");
    format().writeSize(vtk::sizeofData<label>(nBeads));
    vtk::writeList(format(), bead);
    format().flush();
    format().endDataArray();

    format().beginDataArray<float, 3>("U");
    format().writeSize(vtk::sizeofData<float, 3>(nBeads));
    vtk::writeList(format(), chains.velocities());
    format().flush();
    format().endDataArray();

    format().endPointData();

    format().endPiece();
    format().endTag(vtk::fileTag::POLY_DATA).endVTKFile();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cloudFunctions::vtkChains::vtkChains
(
    const word& name,
    const dictionary& dict,
    const polymerCloud& cloud
)
:
    polymerCloudFunction(name, cloud),
    writeOpts_(vtk::formatType::INLINE_BASE64),
    series_()
{
    static const Enum<IOstream::streamFormat> formatNames
    ({
        { IOstream::ASCII, "ascii" },
        { IOstream::BINARY, "binary" },
    });
    if
    (
        checkedInput::enumOrDefault
        (
            dict, "format", formatNames, IOstream::BINARY
        )
     == IOstream::ASCII
    )
    {
        writeOpts_.ascii(true);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::cloudFunctions::vtkChains::write()
{
    // Every processor's chains, written by the master (a serial run's
    // need no copy)
    autoPtr<polymerChains> gathered;
    if (Pstream::parRun())
    {
        gathered.reset(new polymerChains(cloud_.gatherChains()));
    }
    if (!Pstream::master())
    {
        return;
    }
    const polymerChains& chains =
        gathered ? gathered() : cloud_.chains();

    const Time& runTime = cloud_.mesh().time();

    const fileName dir(runTime.globalPath()/"VTK"/cloud_.name());
    mkDir(dir);

    const fileName file
    (
        dir/cloud_.name() + "_" + Foam::name(runTime.timeIndex()) + ".vtp"
    );

    writeFile(file, chains);

    const fileName seriesName(vtk::seriesWriter::base(file));
    if (series_.empty())
    {
        series_.load(seriesName, true, runTime.value());
    }
    series_.append(runTime.value(), file);
    series_.write(seriesName);
}


// ************************************************************************* //
