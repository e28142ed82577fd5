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

#include "polymerCoupling.H"
#include "packedReduction.H"
#include "field.H"
#include "checkedInput.H"
#include "fvmSup.H"
#include "UIListStream.H"
#include "clockTime.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The coefficients the coupling is read from: the field flow's (two-way
// coupling needs a solved flow), none for other flows
const Foam::dictionary& couplingCoeffs(const Foam::polymer::flowModel& flow)
{
    return flow.solvesFlow() ? flow.coeffDict() : Foam::dictionary::null;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::polymer::flowModels::field&
Foam::polymer::polymerCoupling::solvedFlow() const
{
    return refCast<const flowModels::field>(flow_);
}


void
Foam::polymer::polymerCoupling::checkSettings(const dictionary& coeffs) const
{
    const word coupling =
        coeffs.getOrDefault<word>("coupling", "oneWay");
    if (coupling != "oneWay" && coupling != "twoWay")
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword 'coupling' in " << coeffs.name() << " is "
            << coupling << nl
            << "    expected: coupling <oneWay | twoWay>;"
            << exit(FatalIOError);
    }

    if (predictorCorrector_ && !twoWay_)
    {
        FatalIOErrorInFunction(coeffs)
            << "Keyword 'predictorCorrector' in " << coeffs.name()
            << " is true with coupling oneWay" << nl
            << "    expected: coupling twoWay; with predictorCorrector true"
            << " (a one-way flow does not depend on the chains)"
            << exit(FatalIOError);
    }

    // OpenFOAM's CrankNicolson keeps the old time derivative between
    // steps, which the second solve of a step corrupts
    const word ddtU("ddt(" + solvedFlow().UName() + ")");
    const ITstream& ddtScheme = mesh_.ddtScheme(ddtU);
    if
    (
        predictorCorrector_ && ddtScheme.size() && ddtScheme[0].isWord()
     && ddtScheme[0].wordToken() == "CrankNicolson"
    )
    {
        FatalIOErrorInFunction(mesh_.schemesDict())
            << "ddtSchemes " << ddtU << " is CrankNicolson in "
            << mesh_.schemesDict().name() << ", with predictorCorrector"
            << " true in " << coeffs.name() << nl
            << "    expected: Euler or backward with predictorCorrector"
            << " (the flow is solved twice a step)"
            << exit(FatalIOError);
    }
}


void Foam::polymer::polymerCoupling::depositRemote
(
    const processorNeighbours& neighbours,
    const List<DynamicList<label>>& cells,
    const List<DynamicList<vector>>& transfer,
    const List<DynamicList<scalar>>& coeff
)
{
    // The beads' holders are the sampler's neighbours, which located them
    const labelList& procs = neighbours.neighbours();
    PtrList<OListStream> send(neighbours.streams());
    label nSent = 0;
    forAll(procs, k)
    {
        const label proci = procs[k];
        if (cells[proci].size())
        {
            send[k] << cells[proci] << transfer[proci] << coeff[proci];
            nSent += cells[proci].size();
        }
    }
    label nToSend = 0;
    for (const DynamicList<label>& c : cells)
    {
        nToSend += c.size();
    }
    if (nSent != nToSend)
    {
        FatalErrorInFunction
            << nToSend - nSent << " beads' momentum is for processors that"
            << " are not the sampler's neighbours " << procs
            << abort(FatalError);
    }
    List<List<char>> recv;
    neighbours.exchange(send, recv);

    const volVectorField& U =
        mesh_.lookupObject<volVectorField>(solvedFlow().UName());
    forAll(recv, k)
    {
        if (recv[k].empty())
        {
            continue;
        }
        UIListStream is(recv[k], IOstream::BINARY);
        const labelList cell(is);
        const List<vector> t(is);
        const List<scalar> c(is);
        forAll(cell, m)
        {
            momentumTransfer_[cell[m]] += (t[m] + c[m]*U[cell[m]])/rho_;
            momentumCoeff_[cell[m]] += c[m]/rho_;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::polymerCoupling::polymerCoupling
(
    const fvMesh& mesh,
    const flowModel& flow
)
:
    mesh_(mesh),
    flow_(flow),
    twoWay_
    (
        couplingCoeffs(flow).getOrDefault<word>("coupling", "oneWay")
     == "twoWay"
    ),
    rho_
    (
        twoWay_
      ? checkedInput::positiveScalar
        (
            couplingCoeffs(flow), "rho", "<solvent density>"
        )
      : 1
    ),
    semiImplicit_
    (
        couplingCoeffs(flow).getOrDefault<bool>("semiImplicit", false)
    ),
    predictorCorrector_
    (
        couplingCoeffs(flow).getOrDefault<bool>("predictorCorrector", false)
    ),
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
    ),
    exchangeSeconds_(0),
    momentumLost_(Zero),
    beadStepsLost_(0)
{
    if (flow.solvesFlow())
    {
        checkSettings(flow.coeffDict());
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::polymerCoupling::deposit
(
    const polymerChains& chains,
    const UList<vector>& velocityChange,
    const UList<vector>& force,
    const scalar deltaT,
    const bool accumulate,
    const scalar flowDeltaT
)
{
    if (!accumulate)
    {
        momentumTransfer_.field() = Zero;
        momentumCoeff_.field() = 0;
    }

    if (!twoWay_)
    {
        return;
    }

    const volVectorField& U =
        mesh_.lookupObject<volVectorField>(solvedFlow().UName());
    const beadSampler& sampler = solvedFlow().sampler();

    // Beads in other processors' meshes: their momentum goes there
    const label nProcs = Pstream::nProcs();
    List<DynamicList<label>> remoteCell(nProcs);
    List<DynamicList<vector>> remoteTransfer(nProcs);
    List<DynamicList<scalar>> remoteCoeff(nProcs);

    for (label c = 0; c < chains.nChains(); ++c)
    {
        const chainType& type = chains.type(c);
        const scalar m = type.beadMass();
        // The semi-implicit part is the flow step's sensitivity to the
        // fluid velocity, held over the step: once, over the flow step
        const scalar coeff =
            (semiImplicit_ && !accumulate)
          ? -m*std::expm1(-flowDeltaT/type.inertialTime())
          : 0;

        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            // What the solvent received: minus the beads' momentum change
            // less what external forces gave them
            vector transfer = -m*velocityChange[i];
            if (force.size())
            {
                transfer += force[i]*deltaT;
            }

            const label celli = sampler.hostTets()[i].cell();
            if (celli < 0)
            {
                const label proci = sampler.remoteOwner(i);
                if (proci >= 0)
                {
                    remoteCell[proci].append(sampler.remoteTet(i).cell());
                    remoteTransfer[proci].append(transfer);
                    remoteCoeff[proci].append(coeff);
                }
                else
                {
                    // In no mesh: no cell to take it, but not forgotten
                    momentumLost_ += transfer;
                    ++beadStepsLost_;
                }
                continue;
            }

            if (coeff == 0)
            {
                // Explicit coupling: no read of the cell's U, which is
                // half the scattered loads of a bead here
                momentumTransfer_[celli] += transfer/rho_;
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
        depositRemote
        (
            sampler.neighbours(), remoteCell, remoteTransfer, remoteCoeff
        );
        exchangeSeconds_ += clock.elapsedTime();
    }
}


Foam::tmp<Foam::fvVectorMatrix> Foam::polymer::polymerCoupling::SU
(
    volVectorField& U
) const
{
    const dimensionedScalar deltaT = mesh_.time().deltaT();
    const volScalarField::Internal Vdt(mesh_.V()*deltaT);

    if (!twoWay_)
    {
        return tmp<fvVectorMatrix>::New(U, dimVelocity*dimVolume/dimTime);
    }

    // transfer = T0 - coeff u_bead: T0 - coeff U with U implicit
    return
        momentumTransfer_/Vdt
      - fvm::Sp(momentumCoeff_/Vdt, U);
}


void Foam::polymer::polymerCoupling::writeRunTotals(dictionary& dict) const
{
    vector momentumLost = momentumLost_;
    scalar beadStepsLost = beadStepsLost_;
    packedReduction all;
    all.sum(momentumLost);
    all.sum(beadStepsLost);
    all.reduce();

    dictionary& totals = dict.subDictOrAdd("coupling");
    runTotals::add(totals, "momentumLost", momentumLost);
    runTotals::add(totals, "beadStepsLost", beadStepsLost);
}


void Foam::polymer::polymerCoupling::readRunTotals(const dictionary& dict)
{
    const dictionary* saved = dict.findDict("coupling");
    if (saved)
    {
        runTotals::read(*saved, "momentumLost", momentumLost_);
        runTotals::read(*saved, "beadStepsLost", beadStepsLost_);
    }
}


// ************************************************************************* //
