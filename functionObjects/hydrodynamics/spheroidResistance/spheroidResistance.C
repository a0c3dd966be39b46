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

#include "spheroidResistance.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::scalar Foam::spheroidResistance::rcMin = 3;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::spheroidResistance::spheroidResistance(const scalar r)
{
    if (!(r >= 1))
    {
        FatalErrorInFunction
            << "prolate spheroid needs an aspect ratio >= 1, not " << r
            << abort(FatalError);
    }

    const scalar e2 = 1 - 1/(r*r);
    const scalar e = std::sqrt(e2);

    if (e < 1e-2)
    {
        // Series about the sphere (physics.md 1.4)
        const scalar e4 = e2*e2;
        XA = 1 - 0.4*e2 - 17.0/175.0*e4;
        YA = 1 - 0.3*e2 - 57.0/700.0*e4;
        XC = 1 - 1.2*e2 + 27.0/175.0*e4;
        YC = 1 - 0.9*e2 + 18.0/175.0*e4;
        YH = 0.5*e2 - 0.2*e4;
        return;
    }

    const scalar e3 = e2*e;
    const scalar L = std::log1p(e) - std::log1p(-e);
    const scalar D = -2*e + (1 + e2)*L;

    XA = (8.0/3.0)*e3/D;
    YA = (16.0/3.0)*e3/(2*e + (3*e2 - 1)*L);
    XC = (4.0/3.0)*e3*(1 - e2)/(2*e - (1 - e2)*L);
    YC = (4.0/3.0)*e3*(2 - e2)/D;
    YH = (4.0/3.0)*e3*e2/D;
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::spheroidResistance::coxAspectRatio(const scalar rc)
{
    return 1.24*rc/std::sqrt(std::log(rc));
}


Foam::scalar Foam::spheroidResistance::bretherton(const scalar r)
{
    return (r*r - 1)/(r*r + 1);
}


Foam::scalar Foam::spheroidResistance::jefferyPeriod
(
    const scalar r,
    const scalar gammaDot
)
{
    return constant::mathematical::twoPi*(r + 1/r)/gammaDot;
}


// ************************************************************************* //
