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

#include "boxInjection.H"
#include "randomWalk.H"
#include "checkedInput.H"
#include "makePolymerModel.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

makePolymerModel(injectionModel, injectionModels, boxInjection)


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::polymer::injectionModels::boxInjection::boxInjection
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    injectionModel(typeName, dict, mesh),
    chainTypeName_
    (
        checkedInput::required<word>
        (
            coeffDict_, "chainType", "<a chain type of chainTypes>"
        )
    ),
    box_
    (
        checkedInput::required<point>
        (
            coeffDict_, "min", "(<x> <y> <z>), the box's lower corner"
        ),
        checkedInput::required<point>
        (
            coeffDict_, "max", "(<x> <y> <z>), the box's upper corner"
        )
    ),
    rate_
    (
        checkedInput::positiveScalar
        (
            coeffDict_, "rate", "<chains per unit time>"
        )
    ),
    start_(coeffDict_.getOrDefault<scalar>("start", 0)),
    end_(coeffDict_.getOrDefault<scalar>("end", GREAT))
{
    if (!box_.valid())
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keywords 'min' and 'max' in " << coeffDict_.name()
            << " make an empty box" << nl
            << "    expected: min (x y z); max (X Y Z); with X >= x, ..."
            << exit(FatalIOError);
    }
    if (!(end_ > start_))
    {
        FatalIOErrorInFunction(coeffDict_)
            << "Keywords 'start' " << start_ << " and 'end' " << end_
            << " in " << coeffDict_.name() << " leave no time to inject"
            << nl << "    expected: end > start (times)"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::polymer::injectionModels::boxInjection::checkTypes
(
    const PtrList<chainType>& types
) const
{
    initialisationModel::findType
    (
        types, chainTypeName_, coeffDict_, "chainType"
    );
}


Foam::scalar Foam::polymer::injectionModels::boxInjection::dueBy
(
    const scalar t
) const
{
    // A scalar: with end GREAT the count by end is beyond a label
    return std::floor(rate_*(min(t, end_) - start_) + 1e-9);
}


bool Foam::polymer::injectionModels::boxInjection::finished
(
    const scalar time
) const
{
    return time > start_ && dueBy(time) >= dueBy(end_);
}


Foam::label Foam::polymer::injectionModels::boxInjection::inject
(
    polymerChains& chains,
    const label seed,
    label& nextGlobalId,
    const scalar time
)
{
    // Chains due by the end of the step, and by its start: the difference
    const scalar dt = mesh_.time().deltaTValue();
    const label nNew =
        (time <= start_)
      ? 0
      : label(dueBy(time)) - max(label(dueBy(time - dt)), label(0));

    // Every processor draws the same chains, each those it may own (the
    // cloud keeps each on the processor holding its reference bead)
    if (nNew <= 0)
    {
        return 0;
    }

    const label typei = initialisationModel::findType
    (
        chains.types(), chainTypeName_, coeffDict_, "chainType"
    );
    const chainType& type = chains.types()[typei];

    const List<List<point>> x = initialisationModels::randomWalk::walksInside
    (
        type, box_, seed, nextGlobalId, nNew, mesh_, coeffDict_
    );
    forAll(x, k)
    {
        if (x[k].size())
        {
            chains.append
            (
                typei, nextGlobalId, x[k], List<vector>(x[k].size(), Zero)
            );
        }
        ++nextGlobalId;
    }

    return nNew;
}


// ************************************************************************* //
