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

#include "linear.H"
#include "keywordCheck.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberContactLaws
{
    defineTypeNameAndDebug(linear, 0);
    addToRunTimeSelectionTable(fiberContactLaw, linear, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberContactLaws::linear::linear(const dictionary& dict)
:
    fiberContactLaw(dict),
    kn_(keywordCheck::positive(dict, "stiffness")),
    e_(dict.get<scalar>("restitution")),
    zeta_(0),
    ktRatio_(keywordCheck::positive(dict, "tangentialStiffness", 2.0/7.0))
{
    if (!(e_ > 0) || e_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'restitution' must lie in (0, 1], not " << e_
            << exit(FatalIOError);
    }
    const scalar lnE = std::log(e_);
    zeta_ = -lnE/std::sqrt(sqr(constant::mathematical::pi) + sqr(lnE));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::wordList Foam::fiberContactLaws::linear::keywords() const
{
    return wordList({"stiffness", "restitution", "tangentialStiffness"});
}


Foam::scalar Foam::fiberContactLaws::linear::springForce
(
    const scalar delta
) const
{
    return kn_*delta;
}


Foam::scalar Foam::fiberContactLaws::linear::normalStiffness
(
    const scalar
) const
{
    return kn_;
}


Foam::scalar Foam::fiberContactLaws::linear::normalDamping
(
    const scalar m,
    const scalar
) const
{
    return 2*zeta_*std::sqrt(m*kn_);
}


Foam::scalar Foam::fiberContactLaws::linear::tangentialStiffness
(
    const scalar
) const
{
    return ktRatio_*kn_;
}


Foam::scalar Foam::fiberContactLaws::linear::tangentialDamping
(
    const scalar m,
    const scalar
) const
{
    return 2*zeta_*std::sqrt(m*(ktRatio_*kn_));
}


Foam::scalar Foam::fiberContactLaws::linear::contactTime
(
    const scalar m
) const
{
    return
        constant::mathematical::pi
       /std::sqrt(kn_/m*(1 - sqr(zeta_)));
}


Foam::scalar Foam::fiberContactLaws::linear::releaseSpeed
(
    const scalar m,
    const scalar delta
) const
{
    return std::sqrt(kn_/m)*max(delta, 0);
}


void Foam::fiberContactLaws::linear::describe(Ostream& os) const
{
    os  << "k_n " << kn_ << " N/m, restitution " << e_ << " (damping ratio "
        << zeta_ << "), friction " << friction() << ", k_t/k_n " << ktRatio_;
}


// ************************************************************************* //
