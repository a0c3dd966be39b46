/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fiberTracking: rigid fibers for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fiberTracking, distributed under GPL-3.0-or-later.

\*---------------------------------------------------------------------------*/

#include "constraints.H"
#include "contact.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberContactSchemes
{
    defineTypeNameAndDebug(constraints, 0);
    addToRunTimeSelectionTable(fiberContactScheme, constraints, model);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberContactSchemes::constraints::constraints(contact& model)
:
    fiberContactScheme(model),
    solver_(model)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::fiberContactSchemes::constraints::pairsAcross() const
{
    return solver_.pairsAcross();
}


const char* Foam::fiberContactSchemes::constraints::intervalsRule() const
{
    return
        "with scheme constraints (the intervals follow the approach of"
        " pairs, maxApproach)";
}


void Foam::fiberContactSchemes::constraints::describe(Ostream& os) const
{
    os  << ", constraints per island (intervals by the approach of"
        << " pairs, at most " << model_.maxApproach_ << " diameters each)";
}


Foam::scalar Foam::fiberContactSchemes::constraints::interval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar dt,
    const scalar tLeft,
    const scalar tc
)
{
    return model_.adaptiveInterval(fibers, roles, tLeft, tc);
}


void Foam::fiberContactSchemes::constraints::loads
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar h,
    springTable& next,
    UList<fiberIntegrator::load>& loads,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    solver_.constrain(fibers, segs, cand, h, next, loads, touching, close);
}


// ************************************************************************* //
