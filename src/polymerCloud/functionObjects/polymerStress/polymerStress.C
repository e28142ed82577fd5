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

#include "polymerStress.H"
#include "polymerCloud.H"
#include "checkedInput.H"
#include "OSspecific.H"
#include "periodicImages.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(polymerCloudFunction, cloudFunctions, polymerStress)


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar
Foam::polymer::cloudFunctions::polymerStress::standardErrorXY() const
{
    const label n = blockMeansXY_.size();
    if (n < 2)
    {
        return 0;
    }
    scalar mean = 0;
    for (const scalar m : blockMeansXY_)
    {
        mean += m;
    }
    mean /= n;
    scalar var = 0;
    for (const scalar m : blockMeansXY_)
    {
        var += sqr(m - mean);
    }
    return std::sqrt(var/(n - 1)/n);
}


Foam::autoPtr<Foam::volSymmTensorField>
Foam::polymer::cloudFunctions::polymerStress::newField(const word& name) const
{
    const fvMesh& mesh = cloud_.mesh();
    return autoPtr<volSymmTensorField>::New
    (
        IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedSymmTensor(dimPressure, Zero)
    );
}


void Foam::polymer::cloudFunctions::polymerStress::addToFields
(
    const UList<symmTensor>& beadTerm
)
{
    // Each bead's term in the cell holding it at x-dagger, in whichever
    // processor's mesh
    sampler_->locate(cloud_.chains());
    symmTensorField& step = field_->primitiveFieldRef();
    step = Zero;
    sampler_->addToCells(beadTerm, step);
    step /= cloud_.mesh().V();
    field_->correctBoundaryConditions();

    fieldSum_ += step;
    fieldMean_->primitiveFieldRef() = fieldSum_/nSteps_;
    fieldMean_->correctBoundaryConditions();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cloudFunctions::polymerStress::polymerStress
(
    const word& name,
    const dictionary& dict,
    const polymerCloud& cloud
)
:
    polymerCloudFunction(name, cloud),
    start_(dict.getOrDefault<scalar>("start", 0)),
    blockSteps_
    (
        checkedInput::labelAtLeastOrDefault
        (
            dict, "blockSteps", 1000, 1, "<steps per block>"
        )
    ),
    interval_
    (
        checkedInput::labelAtLeastOrDefault
        (
            dict, "interval", 100, 1, "<flow steps between lines>"
        )
    ),
    flowSteps_(0),
    sum_(Zero),
    nSteps_(0),
    blockSum_(Zero),
    blockN_(0),
    blockMeansXY_(),
    file_(),
    positionsStar_(),
    field_(),
    fieldMean_(),
    fieldSum_(),
    sampler_()
{
    if (dict.getOrDefault<bool>("writeFields", true))
    {
        const word name(dict.getOrDefault<word>("field", "tauPolymer"));
        field_ = newField(name);
        fieldMean_ = newField(name + "Mean");
        fieldSum_.setSize(cloud.mesh().nCells(), Zero);
        sampler_.reset(new beadSampler(cloud.mesh()));
    }

    if (Pstream::master())
    {
        const Time& runTime = cloud.mesh().time();
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/cloud.name()
           /runTime.timeName()
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"polymerStress.dat"));
        file_().precision(10);
        file_()
            << "# polymer stress of " << cloud.name()
            << " (Kramers, rod tensions; domain average, time average from "
            << start_ << ")" << nl
            << "# time tauXX tauYY tauZZ tauXY tauYZ tauXZ seXY steps"
            << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::cloudFunctions::polymerStress::postIntegrate
(
    const UList<vector>& positionsOld,
    const UList<vector>& velocitiesOld,
    const UList<vector>& force,
    const scalar deltaT
)
{
    if (cloud_.mesh().time().value() > start_)
    {
        positionsStar_ = cloud_.chains().positions();
    }
}


void
Foam::polymer::cloudFunctions::polymerStress::postConstrain(const scalar deltaT)
{
    if (cloud_.mesh().time().value() <= start_)
    {
        return;
    }

    const polymerChains& chains = cloud_.chains();
    const List<vector>& x = chains.positions();
    const List<vector>& v = chains.velocities();
    const List<vector>& u = cloud_.flow().beadVelocity();
    const bool haveFluid = (u.size() == v.size());

    // Each bead's term, kept for the per-cell fields
    List<symmTensor> beadTerm(field_ ? x.size() : 0);

    symmTensor step(Zero);
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const chainType& type = chains.type(c);
        const scalar forcePerShift = type.forcePerDisplacement(deltaT);

        const vector centre = chains.centreOfMass(c);

        for (label i = chains.start(c); i < chains.end(c); ++i)
        {
            const vector constraintForce =
                forcePerShift*(x[i] - positionsStar_[i]);

            // The momentum the beads carry relative to the solvent
            const vector peculiar = haveFluid ? v[i] - u[i] : v[i];

            const symmTensor term =
              - symm((x[i] - centre)*constraintForce)
              - type.beadMass()*sqr(peculiar);
            step += term;
            if (field_)
            {
                beadTerm[i] = term;
            }
        }
    }

    reduce(step, sumOp<symmTensor>());
    step /= gSum(cloud_.mesh().V());

    sum_ += step;
    ++nSteps_;
    if (field_)
    {
        addToFields(beadTerm);
    }
    blockSum_ += step;
    if (++blockN_ == blockSteps_)
    {
        blockMeansXY_.append(blockSum_.xy()/blockN_);
        blockSum_ = Zero;
        blockN_ = 0;
    }
}


void Foam::polymer::cloudFunctions::polymerStress::postEvolve()
{
    // Lines every interval flow steps; the average is over the polymer
    // steps (more than the flow steps where the cloud sub-cycles)
    if (!nSteps_)
    {
        return;
    }
    ++flowSteps_;
    if (flowSteps_ % interval_ || !Pstream::master())
    {
        return;
    }

    const symmTensor mean = sum_/nSteps_;
    file_()
        << cloud_.mesh().time().value() << ' '
        << mean.xx() << ' ' << mean.yy() << ' ' << mean.zz() << ' '
        << mean.xy() << ' ' << mean.yz() << ' ' << mean.xz() << ' '
        << standardErrorXY() << ' ' << nSteps_ << endl;
}


// ************************************************************************* //
