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
#include "locateBead.H"
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
    search_(mesh),
    periodic_(periodicImages::New(mesh)),
    hostCells_(),
    remoteOwners_(),
    remoteCells_(),
    unheldBead_(),
    unheldPoint_(),
    nOutside_(0),
    exchangeSeconds_(0),
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

void Foam::flowModels::fieldFlow::remoteVelocities
(
    const interpolation<vector>& interpolator,
    const UList<point>& points,
    labelList& owner,
    labelList& cell,
    vectorField& velocity
) const
{
    const label nProcs = Pstream::nProcs();
    const label myProc = Pstream::myProcNo();

    // Every processor's unheld points, with the processor and cell that
    // held each at the last step (a start for the walk), to every processor
    List<pointField> all(nProcs);
    List<labelList> allOwner(nProcs);
    List<labelList> allCell(nProcs);
    all[myProc] = points;
    allOwner[myProc] = owner;
    allCell[myProc] = cell;
    Pstream::gatherList(all);
    Pstream::scatterList(all);
    Pstream::gatherList(allOwner);
    Pstream::scatterList(allOwner);
    Pstream::gatherList(allCell);
    Pstream::scatterList(allCell);

    labelList offset(nProcs + 1, Zero);
    forAll(all, proci)
    {
        offset[proci + 1] = offset[proci] + all[proci].size();
    }

    // The lowest processor holding a point answers for it; only those whose
    // bounding box holds it look
    const boundBox& bounds = mesh_.bounds();
    labelList claim(offset[nProcs], labelMax);
    labelList found(offset[nProcs], -1);
    vectorField answer(offset[nProcs], Zero);
    forAll(all, proci)
    {
        forAll(all[proci], k)
        {
            const point& p = all[proci][k];
            if (proci == myProc || !bounds.contains(p))
            {
                continue;
            }
            const label j = offset[proci] + k;
            const label start =
                (allOwner[proci][k] == myProc) ? allCell[proci][k] : -1;
            found[j] = locateBead(search_, p, start);
            if (found[j] >= 0)
            {
                claim[j] = myProc;
            }
        }
    }
    Pstream::listCombineGather(claim, minEqOp<label>());
    Pstream::listCombineScatter(claim);

    forAll(answer, j)
    {
        if (claim[j] == myProc)
        {
            label proci = 0;
            while (offset[proci + 1] <= j)
            {
                ++proci;
            }
            const point& p = all[proci][j - offset[proci]];
            answer[j] = interpolator.interpolate(p, found[j]);
        }
        else
        {
            found[j] = -1;
        }
    }
    Pstream::listCombineGather(answer, plusEqOp<vector>());
    Pstream::listCombineScatter(answer);
    Pstream::listCombineGather(found, maxEqOp<label>());
    Pstream::listCombineScatter(found);

    velocity.setSize(points.size());
    forAll(points, k)
    {
        const label j = offset[myProc] + k;
        velocity[k] = answer[j];
        owner[k] = (claim[j] == labelMax) ? -1 : claim[j];
        cell[k] = found[j];
    }
}


void Foam::flowModels::fieldFlow::update(const polymerChains& chains)
{
    const List<vector>& x = chains.positions();
    nOutside_ = 0;
    if (x.empty() && !Pstream::parRun())
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

    labelList& hostCell = hostCells_.update(chains);
    labelList& remoteOwner = remoteOwners_.update(chains);
    labelList& remoteCell = remoteCells_.update(chains);
    beadVelocity_.setSize(x.size());

    DynamicList<label>& unheld = unheldBead_;
    DynamicList<point>& unheldPoints = unheldPoint_;
    unheld.clear();
    unheldPoints.clear();

    // A bead outside this processor's bounding box is in another's mesh,
    // or in none: no search here
    const boundBox& bounds = mesh_.bounds();
    forAll(x, i)
    {
        const point p = periodic_.wrap(x[i]);
        hostCell[i] =
            bounds.contains(p) ? locateBead(search_, p, hostCell[i]) : -1;

        if (hostCell[i] < 0)
        {
            beadVelocity_[i] = Zero;
            unheld.append(i);
            unheldPoints.append(p);
        }
        else
        {
            beadVelocity_[i] = interpolator->interpolate(p, hostCell[i]);
        }
    }

    // Beads in other processors' meshes take their velocity there
    if (Pstream::parRun())
    {
        clockTime clock;
        labelList owner(unheld.size());
        labelList cell(unheld.size());
        forAll(unheld, k)
        {
            owner[k] = remoteOwner[unheld[k]];
            cell[k] = remoteCell[unheld[k]];
        }
        vectorField velocity;
        remoteVelocities(interpolator(), unheldPoints, owner, cell, velocity);
        exchangeSeconds_ += clock.elapsedTime();

        remoteOwner = -1;
        forAll(unheld, k)
        {
            beadVelocity_[unheld[k]] = velocity[k];
            remoteOwner[unheld[k]] = owner[k];
            remoteCell[unheld[k]] = cell[k];
        }
    }
    forAll(unheld, k)
    {
        nOutside_ += (remoteOwner[unheld[k]] < 0);
    }

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
    List<DynamicList<point>> remotePoint(nProcs);
    List<DynamicList<vector>> remoteTransfer(nProcs);
    List<DynamicList<scalar>> remoteCoeff(nProcs);
    label nextUnheld = 0;

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

            const label celli = hostCells_.cells()[i];
            if (celli < 0)
            {
                // The unheld beads are listed in bead order
                while (unheldBead_[nextUnheld] != i)
                {
                    ++nextUnheld;
                }
                const label proci = remoteOwners_.cells()[i];
                if (proci >= 0)
                {
                    remotePoint[proci].append(unheldPoint_[nextUnheld]);
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
        depositRemote(remotePoint, remoteTransfer, remoteCoeff);
        exchangeSeconds_ += clock.elapsedTime();
    }
}


void Foam::flowModels::fieldFlow::depositRemote
(
    const List<DynamicList<point>>& points,
    const List<DynamicList<vector>>& transfer,
    const List<DynamicList<scalar>>& coeff
)
{
    PstreamBuffers buffers(Pstream::commsTypes::nonBlocking);
    forAll(points, proci)
    {
        if (points[proci].size())
        {
            UOPstream os(proci, buffers);
            os  << points[proci] << transfer[proci] << coeff[proci];
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
        const List<point> p(is);
        const List<vector> t(is);
        const List<scalar> c(is);
        forAll(p, k)
        {
            const label celli = search_.findCell(p[k]);
            if (celli >= 0)
            {
                momentumTransfer_[celli] += (t[k] + c[k]*U[celli])/rho_;
                momentumCoeff_[celli] += c[k]/rho_;
            }
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
