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

#include "implicitSprings.H"
#include "contact.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberContactSchemes
{
    defineTypeNameAndDebug(implicitSprings, 0);
    addToRunTimeSelectionTable(fiberContactScheme, implicitSprings, model);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberContactSchemes::implicitSprings::implicitSprings(contact& model)
:
    fiberContactScheme(model)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const char* Foam::fiberContactSchemes::implicitSprings::intervalsRule() const
{
    return
        "with implicit on (the intervals follow the approach of pairs,"
        " maxApproach)";
}


void Foam::fiberContactSchemes::implicitSprings::describe(Ostream& os) const
{
    os  << ", implicit: intervals by the approach of pairs, at most "
        << model_.maxApproach_ << " diameters each (collisions inelastic"
        << " where the intervals exceed the contact time)";
}


Foam::scalar Foam::fiberContactSchemes::implicitSprings::interval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar dt,
    const scalar tLeft,
    const scalar tc
)
{
    model_.warnFlexible(fibers, roles);
    return model_.adaptiveInterval(fibers, roles, tLeft, tc);
}


void Foam::fiberContactSchemes::implicitSprings::loads
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
    // The springs' loads, and the impulses the last interval's balance
    // left to pay back
    model_.springInteract
    (
        fibers, roles, segs, cand, h, next, loads, touching, close
    );
}


void Foam::fiberContactSchemes::implicitSprings::settle
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<fiberIntegrator::load>& loads
)
{
    model_.settleSprings(fibers, roles, loads);
}


// ************************************************************************* //
