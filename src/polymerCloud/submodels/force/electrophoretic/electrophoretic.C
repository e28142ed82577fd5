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

#include "electrophoretic.H"
#include "checkedInput.H"
#include "fvm.H"
#include "fvc.H"
#include "makePolymerModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(forceModel, forceModels, electrophoretic)


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::IOobject Foam::polymer::forceModels::electrophoretic::potentialIO
(
    const fvMesh& mesh
) const
{
    IOobject io
    (
        coeffDict_.getOrDefault<word>("field", "phiE"),
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::AUTO_WRITE
    );
    if (!io.typeHeaderOk<volScalarField>(true))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keyword 'field' in " << coeffDict_.name() << " names "
            << io.name() << ", which is no potential field (volScalarField)"
            << " in " << mesh.time().timeName() << "/" << nl
            << "    expected: field <the electric potential's name>;"
            << " (default phiE)"
            << exit(FatalIOError);
    }
    return io;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::forceModels::electrophoretic::electrophoretic
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    forceModel(typeName, dict),
    charge_
    (
        checkedInput::required<scalar>
        (
            coeffDict_, "charge", "<a bead's charge, force per unit field>"
        )
    ),
    potential_(potentialIO(mesh), mesh),
    field_
    (
        IOobject
        (
            "E",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            coeffDict_.getOrDefault<bool>("writeField", true)
          ? IOobject::AUTO_WRITE
          : IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(potential_.dimensions()/dimLength, Zero)
    ),
    pointField_(),
    sampler_(mesh),
    beadField_()
{
    Info<< "electrophoretic: solving laplacian(" << potential_.name()
        << ") = 0 for the electric field" << endl;

    // From a zero guess: the field read is a guess only, and at a restart
    // it is the written solution, whose guess would end the solve
    // elsewhere within its tolerance; from zero, a restart solves the
    // same system from the same start and continues bit for bit
    potential_.primitiveFieldRef() = Zero;
    fvScalarMatrix laplace(fvm::laplacian(potential_));
    const solverPerformance solved(laplace.solve());
    if (!solved.converged())
    {
        FatalIOErrorInFunction(mesh.solverDict(potential_.name()))
            << "The potential " << potential_.name() << " did not converge:"
            << " residual " << solved.finalResidual() << " after "
            << solved.nIterations() << " iterations (solver "
            << solved.solverName() << ")" << nl
            << "    expected: solvers { " << potential_.name()
            << " { tolerance <t>; maxIter <n>; } } in fvSolution, with"
            << " maxIter enough to reach the tolerance"
            << exit(FatalIOError);
    }

    field_ = -fvc::grad(potential_);

    pointField_ = beadSampler::pointValues(field_);

    Info<< "    |E| from " << gMin(mag(field_)().primitiveField())
        << " to " << gMax(mag(field_)().primitiveField()) << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::forceModels::electrophoretic::addForce
(
    const polymerChains& chains,
    UList<vector>& force
) const
{
    sampler_.locate(chains);
    beadField_.setSize(chains.nBeads());
    sampler_.sample(field_, pointField_(), beadField_);
    forAll(beadField_, i)
    {
        force[i] += charge_*beadField_[i];
    }
}


// ************************************************************************* //
