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

#include "fieldFlow.H"
#include "PstreamBuffers.H"
#include "clockTime.H"
#include "volFields.H"
#include "interpolation.H"
#include "fvmSup.H"
#include "checkedInput.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace flowModels
{
    defineTypeNameAndDebug(fieldFlow, 0);
    addToRunTimeSelectionTable(flowModel, fieldFlow, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flowModels::fieldFlow::fieldFlow
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    flowModel(typeName, dict, mesh),
    UName_(coeffDict_.getOrDefault<word>("U", "U")),
    interpolationScheme_
    (
        coeffDict_.getOrDefault<word>("interpolation", "cellPoint")
    ),
    sampler_(mesh),
    depositSeconds_(0),
    twoWay_
    (
        coeffDict_.getOrDefault<word>("coupling", "oneWay") == "twoWay"
    ),
    rho_
    (
        twoWay_
      ? checkedInput::positiveScalar(coeffDict_, "rho", "<solvent density>")
      : 1
    ),
    semiImplicit_(coeffDict_.getOrDefault<bool>("semiImplicit", false)),
    predictorCorrector_
    (
        coeffDict_.getOrDefault<bool>("predictorCorrector", false)
    ),
    velocityStart_(),
    momentumTransfer_
    (
        IOobject
        (
            "polymerMomentumTransfer",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedVector(dimVelocity*dimVolume, Zero)
    ),
    momentumCoeff_
    (
        IOobject
        (
            "polymerMomentumCoeff",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedScalar(dimVolume, Zero)
    )
{
    const word coupling =
        coeffDict_.getOrDefault<word>("coupling", "oneWay");
    if (coupling != "oneWay" && coupling != "twoWay")
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'coupling' in " << coeffDict_.name() << " is "
            << coupling << nl
            << "    expected: coupling <oneWay | twoWay>;"
            << exit(FatalIOError);
    }

    if (predictorCorrector_ && !twoWay_)
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'predictorCorrector' in " << coeffDict_.name()
            << " is true with coupling oneWay" << nl
            << "    expected: coupling twoWay; with predictorCorrector true"
            << " (a one-way flow does not depend on the chains)"
            << exit(FatalIOError);
    }

    // OpenFOAM's CrankNicolson keeps the old time derivative between
    // steps, which the second solve of a step corrupts
    const word ddtU("ddt(" + UName_ + ")");
    const ITstream& ddtScheme = mesh.ddtScheme(ddtU);
    if
    (
        predictorCorrector_ && ddtScheme.size() && ddtScheme[0].isWord()
     && ddtScheme[0].wordToken() == "CrankNicolson"
    )
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "ddtSchemes " << ddtU << " is CrankNicolson in "
            << mesh.schemesDict().name() << ", with predictorCorrector"
            << " true in " << coeffDict_.name() << nl
            << "    expected: Euler or backward with predictorCorrector"
            << " (the flow is solved twice a step)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::flowModels::fieldFlow::update(const polymerChains& chains)
{
    if (chains.positions().empty() && !Pstream::parRun())
    {
        // No interpolation to set up (cellPoint interpolates U to the
        // points): a scene without chains pays nothing
        beadVelocity_.clear();
        velocityStart_.clear();
        return;
    }

    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    autoPtr<interpolation<vector>> interpolator
    (
        interpolation<vector>::New(interpolationScheme_, U)
    );

    sampler_.locate(chains);
    beadVelocity_.setSize(chains.nBeads());
    sampler_.sample(interpolator(), beadVelocity_);

    // The corrector's flow: the mean of the step's start and the predicted
    // end (beads injected since have no start value)
    const label nStart = min(velocityStart_.size(), beadVelocity_.size());
    for (label i = 0; i < nStart; ++i)
    {
        beadVelocity_[i] = 0.5*(velocityStart_[i] + beadVelocity_[i]);
    }
    velocityStart_.clear();
}


void Foam::flowModels::fieldFlow::storePredictor()
{
    velocityStart_ = beadVelocity_;
}


void Foam::flowModels::fieldFlow::depositMomentum
(
    const polymerChains& chains,
    const UList<vector>& velocityChange,
    const UList<vector>& force,
    const scalar deltaT
)
{
    momentumTransfer_.field() = Zero;
    momentumCoeff_.field() = 0;

    if (!twoWay_)
    {
        return;
    }

    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);

    // Beads in other processors' meshes: their momentum goes there
    const label nProcs = Pstream::nProcs();
    List<DynamicList<label>> remoteCell(nProcs);
    List<DynamicList<vector>> remoteTransfer(nProcs);
    List<DynamicList<scalar>> remoteCoeff(nProcs);

    for (label c = 0; c < chains.nChains(); ++c)
    {
        const chainType& type = chains.type(c);
        const scalar m = type.beadMass();
        const scalar coeff =
            semiImplicit_ ? -m*std::expm1(-deltaT/type.inertialTime()) : 0;

        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            // What the solvent received: minus the beads' momentum change
            // less what external forces gave them
            vector transfer = -m*velocityChange[i];
            if (force.size())
            {
                transfer += force[i]*deltaT;
            }

            const label celli = sampler_.hostTets()[i].cell();
            if (celli < 0)
            {
                const label proci = sampler_.remoteOwners()[i];
                if (proci >= 0)
                {
                    remoteCell[proci].append
                    (
                        sampler_.remoteTets()[i].cell()
                    );
                    remoteTransfer[proci].append(transfer);
                    remoteCoeff[proci].append(coeff);
                }
                continue;
            }

            // The implicit part's explicit counterpart: the cell's U now,
            // so that in a steady flow the two cancel (at the bead's
            // interpolated U they would leave a spurious force wherever
            // it differs from the cell's, as next to walls)
            momentumTransfer_[celli] += (transfer + coeff*U[celli])/rho_;
            momentumCoeff_[celli] += coeff/rho_;
        }
    }

    if (Pstream::parRun())
    {
        clockTime clock;
        depositRemote(remoteCell, remoteTransfer, remoteCoeff);
        depositSeconds_ += clock.elapsedTime();
    }
}


void Foam::flowModels::fieldFlow::depositRemote
(
    const List<DynamicList<label>>& cells,
    const List<DynamicList<vector>>& transfer,
    const List<DynamicList<scalar>>& coeff
)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(cells, proci)
    {
        if (cells[proci].size())
        {
            UOPstream os(proci, buffers);
            os  << cells[proci] << transfer[proci] << coeff[proci];
        }
    }
    labelList recvSizes;
    buffers.finishedSends(recvSizes);

    const volVectorField& U = mesh_.lookupObject<volVectorField>(UName_);
    forAll(recvSizes, proci)
    {
        if (!recvSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, buffers);
        const labelList cell(is);
        const List<vector> t(is);
        const List<scalar> c(is);
        forAll(cell, k)
        {
            momentumTransfer_[cell[k]] += (t[k] + c[k]*U[cell[k]])/rho_;
            momentumCoeff_[cell[k]] += c[k]/rho_;
        }
    }
}


Foam::tmp<Foam::fvVectorMatrix> Foam::flowModels::fieldFlow::SU
(
    volVectorField& U
) const
{
    const dimensionedScalar deltaT = mesh_.time().deltaT();
    const volScalarField::Internal Vdt(mesh_.V()*deltaT);

    if (!twoWay_)
    {
        return flowModel::SU(U);
    }

    // transfer = T0 - coeff u_bead: T0 - coeff U with U implicit
    return
        momentumTransfer_/Vdt
      - fvm::Sp(momentumCoeff_/Vdt, U);
}


// ************************************************************************* //
