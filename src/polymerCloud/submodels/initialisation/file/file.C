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

#include "file.H"
#include "IOdictionary.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(initialisationModel, initialisationModels, file)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::initialisationModels::file::file
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    initialisationModel(typeName, dict, mesh),
    fileName_(coeffDict_.getOrDefault<word>("file", "polymerChains")),
    tolerance_
    (
        checkedInput::positiveScalarOrDefault
        (
            coeffDict_, "tolerance", 1e-6, "<relative rod-length mismatch>"
        )
    )
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::initialisationModels::file::check
(
    const chainType& type,
    const List<point>& x,
    const dictionary& chainDict,
    const label chaini
) const
{
    if (x.size() != type.nBeads())
    {
        FatalIOErrorInFunction(chainDict)
            << "Chain " << chaini << " in " << chainDict.name()
            << ": keyword 'positions' has " << x.size() << " points" << nl
            << "    expected: positions (<" << type.nBeads()
            << " points>); for chain type " << type.name()
            << exit(FatalIOError);
    }

    const label n = x.size();
    for (label k = 0; k < type.nRods(); ++k)
    {
        const scalar length = mag(x[(k + 1) % n] - x[k]);
        if (mag(length - type.rodLength()) > tolerance_*type.rodLength())
        {
            FatalIOErrorInFunction(chainDict)
                << "Chain " << chaini << " in " << chainDict.name()
                << ": keyword 'positions' has rod " << k << " (beads " << k
                << " and " << (k + 1) % n << ") of length " << length << nl
                << "    expected: positions with every rod of length a = "
                << type.rodLength() << " (chain type " << type.name()
                << ") to a relative " << tolerance_
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::polymer::initialisationModels::file::create
(
    polymerChains& chains,
    const label seed
) const
{
    const label nBefore = chains.nChains();
    IOobject io
    (
        fileName_,
        mesh_.time().constant(),
        mesh_,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(false))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'file' in " << coeffDict_.name() << " names "
            << io.objectPath() << ", which does not exist" << nl
            << "    expected: file <the name of a chains file in constant/>;"
            << " (default polymerChains)"
            << exit(FatalIOError);
    }
    const IOdictionary chainsFile(io);

    if (!chainsFile.found("chains", keyType::LITERAL))
    {
        FatalIOErrorInFunction(chainsFile)
            << "Missing keyword 'chains' in " << chainsFile.name() << nl
            << "    expected: chains ( { chainType <name>; positions"
            << " ( (x y z) ... ); } ... );"
            << exit(FatalIOError);
    }

    const List<dictionary> chainDicts(chainsFile.lookup("chains"));

    forAll(chainDicts, chaini)
    {
        dictionary chainDict(chainDicts[chaini]);
        chainDict.name() = chainsFile.name() + "/chains/" + Foam::name(chaini);

        const label typei = lookupType(chains.types(), chainDict, "chainType");
        const chainType& type = chains.types()[typei];

        if (!chainDict.found("positions", keyType::LITERAL))
        {
            FatalIOErrorInFunction(chainDict)
                << "Missing keyword 'positions' in " << chainDict.name() << nl
                << "    expected: positions ( (x y z) ... );"
                << exit(FatalIOError);
        }

        const List<point> x(chainDict.get<List<point>>("positions"));
        check(type, x, chainDict, chaini);

        chains.append
        (
            typei,
            chains.nChains(),
            x,
            List<vector>(x.size(), Zero)
        );
    }
    return chains.nChains() - nBefore;
}


// ************************************************************************* //
