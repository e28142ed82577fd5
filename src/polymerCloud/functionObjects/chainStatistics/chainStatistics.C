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

#include "chainStatistics.H"
#include "packedReduction.H"
#include "processorNeighbours.H"
#include "cellLocator.H"
#include "periodicImages.H"
#include "polymerCloud.H"
#include "checkedInput.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"
#include "maxOrNaN.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace polymer
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(chainStatistics, 0);
    addToRunTimeSelectionTable
    (
        polymerCloudFunction,
        chainStatistics,
        dictionary
    );
}
} // End namespace polymer
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::polymer::cloudFunctions::chainStatistics::openFile()
{
    const Time& runTime = cloud_.mesh().time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/cloud_.name()
       /runTime.timeName()
    );
    mkDir(dir);

    file_.reset(new OFstream(dir/"statistics.dat"));
    file_().precision(10);

    file_()
        << "# statistics of polymerCloud " << cloud_.name() << nl
        << "# time nChains Rg2 Ree2 kTkinetic kT rodError iterMean iterMax"
        << " failures subStepped collisions stalls escaped outside"
        << " rodsOutside" << endl;
}


Foam::scalar
Foam::polymer::cloudFunctions::chainStatistics::peculiarKineticEnergy
(
    const label chaini
) const
{
    const polymerChains& chains = cloud_.chains();
    const List<vector>& v = chains.velocities();
    const List<vector>& u = cloud_.flow().beadVelocity();

    // The solvent's velocity at x^n of the last step; right after chains
    // left the domain the lists differ in size until the next step
    const bool haveFluid = (u.size() == v.size());

    scalar sum = 0;
    for (label i = chains.start(chaini); i < chains.end(chaini); ++i)
    {
        sum += magSqr(haveFluid ? v[i] - u[i] : v[i]);
    }
    return 0.5*chains.type(chaini).beadMass()*sum;
}


Foam::label Foam::polymer::cloudFunctions::chainStatistics::rodsOutside() const
{
    // Both beads of a rod can be in the fluid while the rod cuts a
    // non-convex corner (a step, a post): its midpoint then lies outside
    // the mesh. Counted where walls bound the chains.
    if (!cloud_.wallsActive())
    {
        return 0;
    }

    const polymerChains& chains = cloud_.chains();
    const List<vector>& x = chains.positions();
    const fvMesh& mesh = cloud_.mesh();
    const periodicImages& periodic = periodicImages::New(mesh);
    const cellLocator& locator = cellLocator::New(mesh);

    // Midpoints this processor's mesh does not hold may be in another's.
    // Each is sought from the cell of the chain's last midpoint found, a
    // rod's length away (the tree's search when there is none, or the
    // walk stops short): the same cells hold it
    DynamicList<point> unheld;
    for (label c = 0; c < chains.nChains(); ++c)
    {
        const label first = chains.start(c);
        const label size = chains.size(c);
        label lastCell = -1;
        for (label k = 0; k < chains.type(c).nRods(); ++k)
        {
            const point middle = periodic.wrap
            (
                0.5*(x[first + k] + x[first + (k + 1) % size])
            );
            const label celli = locator.findCell(middle, lastCell);
            if (celli < 0)
            {
                unheld.append(middle);
            }
            else
            {
                lastCell = celli;
            }
        }
    }
    if (!Pstream::parRun())
    {
        return unheld.size();
    }
    const labelList owner(processorNeighbours(mesh).pointOwners(unheld));
    return std::count(owner.cbegin(), owner.cend(), -1);
}


void Foam::polymer::cloudFunctions::chainStatistics::sampleRodError()
{
    const polymerChains& chains = cloud_.chains();
    for (label c = 0; c < chains.nChains(); ++c)
    {
        largestRodError_ =
            maxOrNaN(largestRodError_, chains.maxRodLengthError(c));
    }
}


void Foam::polymer::cloudFunctions::chainStatistics::writeLine()
{
    const polymerChains& chains = cloud_.chains();

    scalar sumRg2 = 0;
    scalar sumRee2 = 0;
    label nOpen = 0;
    scalar twiceKinetic = twiceKinetic_;
    scalar dof = 0;
    scalar dofKT = 0;
    scalar rodError = largestRodError_;

    for (label c = 0; c < chains.nChains(); ++c)
    {
        const chainType& type = chains.type(c);
        sumRg2 += chains.radiusOfGyrationSqr(c);
        if (!type.ring())
        {
            sumRee2 += chains.endToEndSqr(c);
            ++nOpen;
        }
        dof += type.degreesOfFreedom();
        dofKT += type.degreesOfFreedom()*type.kT();
    }

    label nChains = chains.nChains();
    label nRodsOutside = rodsOutside();
    {
        packedReduction all;
        all.sum(nChains);
        all.sum(nOpen);
        all.max(rodError);
        all.sum(nRodsOutside);
        all.reduce();
    }
    reduce(sumRg2, sumOp<scalar>());
    reduce(sumRee2, sumOp<scalar>());
    reduce(twiceKinetic, sumOp<scalar>());
    reduce(dof, sumOp<scalar>());
    reduce(dofKT, sumOp<scalar>());

    const constraintCounters interval =
        cloud_.constraint().intervalCount().reduced();
    const constraintCounters total =
        cloud_.constraint().totalCount().reduced();
    const collisionCounters intervalCollisions =
        cloud_.collision().intervalCount().reduced();
    const collisionCounters totalCollisions =
        cloud_.collision().totalCount().reduced();
    const wallCounters totalWall = cloud_.wall().totalCount().reduced();
    const label nOutside = cloud_.nBeadsOutside();

    if (Pstream::master())
    {
        file_()
            << cloud_.mesh().time().value() << ' '
            << nChains << ' '
            << sumRg2/max(nChains, 1) << ' '
            << sumRee2/max(nOpen, 1) << ' '
            << twiceKinetic/max(dof, scalar(1)) << ' '
            << dofKT/max(dof, scalar(1)) << ' '
            << rodError << ' '
            << scalar(interval.iterations)/max(interval.solves, 1) << ' '
            << interval.maxIterations << ' '
            << total.failures << ' '
            << total.subStepped << ' '
            << intervalCollisions.events << ' '
            << totalCollisions.stalls << ' '
            << totalWall.escapedChains << ' '
            << nOutside << ' '
            << nRodsOutside << endl;
    }

    cloud_.resetIntervalCounters();
    largestRodError_ = 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::cloudFunctions::chainStatistics::chainStatistics
(
    const word& name,
    const dictionary& dict,
    const polymerCloud& cloud
)
:
    polymerCloudFunction(name, cloud),
    interval_
    (
        checkedInput::labelAtLeastOrDefault
        (
            dict, "interval", 1, 1, "<time steps between lines>"
        )
    ),
    stepsSinceLine_(0),
    twiceKinetic_(0),
    largestRodError_(0),
    file_()
{
    if (Pstream::master())
    {
        openFile();
    }

    // The state the run starts from
    for (label c = 0; c < cloud_.chains().nChains(); ++c)
    {
        twiceKinetic_ += 2*peculiarKineticEnergy(c);
    }
    sampleRodError();
    writeLine();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::cloudFunctions::chainStatistics::postConstrain
(
    const scalar deltaT
)
{
    // The solvent's velocities at the beads are those of the chains'
    // layout now; chains leaving or moving between processors later in
    // the step change it
    if (stepsSinceLine_ + 1 >= interval_)
    {
        twiceKinetic_ = 0;
        for (label c = 0; c < cloud_.chains().nChains(); ++c)
        {
            twiceKinetic_ += 2*peculiarKineticEnergy(c);
        }
    }
}


void Foam::polymer::cloudFunctions::chainStatistics::postEvolve()
{
    // Every step's end, not only the lines': a rod off for a few steps
    // between lines is still reported
    sampleRodError();

    if (++stepsSinceLine_ >= interval_)
    {
        stepsSinceLine_ = 0;
        writeLine();
    }
}


// ************************************************************************* //
