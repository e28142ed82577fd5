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

#include "faultInjectingFileOperation.H"
#include "addToRunTimeSelectionTable.H"
#include "OSspecific.H"
#include "IOstreams.H"

#include <cstdlib>
#include <unistd.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fileOperations
{
    defineTypeNameAndDebug(faultInjectingFileOperation, 0);
    addToRunTimeSelectionTable
    (
        fileOperation,
        faultInjectingFileOperation,
        word
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fileOperations::faultInjectingFileOperation::faultInjectingFileOperation
(
    bool verbose
)
:
    uncollatedFileOperation(verbose),
    stopAfterFile_
    (
        getEnv("POLYMER_FAULT_STOP_AFTER_FILE").empty()
      ? 0
      : readLabel(getEnv("POLYMER_FAULT_STOP_AFTER_FILE"))
    ),
    cut_(getEnv("POLYMER_FAULT_CUT") == "1"),
    nFiles_(0),
    lastFile_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::Ostream>
Foam::fileOperations::faultInjectingFileOperation::NewOFstream
(
    const fileName& pathname,
    IOstream::streamFormat format,
    IOstream::versionNumber version,
    IOstream::compressionType compression,
    const bool valid
) const
{
    if (stopAfterFile_ > 0 && nFiles_ == stopAfterFile_)
    {
        if (cut_)
        {
            const off_t size = Foam::fileSize(lastFile_);
            if (::truncate(lastFile_.c_str(), size/2) != 0)
            {
                Pout<< "faultInjecting: cannot cut " << lastFile_ << endl;
            }
        }
        Pout<< "faultInjecting: stopped after file " << nFiles_ << ", "
            << lastFile_ << (cut_ ? ", cut to half its length" : "")
            << endl;
        std::_Exit(1);
    }

    ++nFiles_;
    lastFile_ = pathname;
    Pout<< "faultInjecting: file " << nFiles_ << ": " << pathname << endl;

    return uncollatedFileOperation::NewOFstream
    (
        pathname, format, version, compression, valid
    );
}


// ************************************************************************* //
