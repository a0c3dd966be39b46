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

#include "explicitSprings.H"
#include "contact.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberContactSchemes
{
    defineTypeNameAndDebug(explicitSprings, 0);
    addToRunTimeSelectionTable(fiberContactScheme, explicitSprings, model);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberContactSchemes::explicitSprings::explicitSprings(contact& model)
:
    fiberContactScheme(model)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const char* Foam::fiberContactSchemes::explicitSprings::intervalsRule() const
{
    return
        "with explicit contacts (implicit off: the intervals resolve the"
        " contact time, contactSteps)";
}


void Foam::fiberContactSchemes::explicitSprings::describe(Ostream& os) const
{
    os  << ", " << model_.contactSteps_ << " intervals per contact time";
}


Foam::scalar Foam::fiberContactSchemes::explicitSprings::interval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar dt,
    const scalar tLeft,
    const scalar tc
)
{
    // The contact time resolved by contactSteps: equal intervals over the
    // step, ended at a graze within it, so that the next interval's start
    // sees the touch
    scalar hMax = GREAT;
    if (tc < GREAT)
    {
        hMax =
            dt
           /max(1, label(std::ceil(dt*model_.contactSteps_/tc*(1 - 1e-9))));
    }
    const scalar h = contact::equalParts(hMax, tLeft);
    return model_.sweptInterval(fibers, roles, h);
}


void Foam::fiberContactSchemes::explicitSprings::loads
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
    model_.springInteract
    (
        fibers, roles, segs, cand, h, next, loads, touching, close
    );
}


// ************************************************************************* //
