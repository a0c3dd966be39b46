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

#include "fiber.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiber::fiber(Istream& is)
:
    id_(readLabel(is)),
    setIndex_(readLabel(is)),
    s0_(is),
    z0_(is),
    l_(is),
    d_(is),
    rho_(is),
    p0_(is),
    mSeg_(),
    m_(0),
    I0_(Zero),
    alpha_(readScalar(is)),
    x_(is),
    q_(is),
    v_(is),
    omega_(is),
    dxPrev_(is),
    dthetaPrev_(is),
    vPrev_(is),
    omegaPrev_(is),
    hPrev_(readScalar(is)),
    hNext_(readScalar(is)),
    jumped_(readBool(is)),
    psi_(is),
    eddyTime_(readScalar(is)),
    nDraws_(readLabel(is)),
    nSubSteps_(is),
    E_(readScalar(is)),
    G_(readScalar(is)),
    z0Rest_(),
    Q_(),
    vSeg_(),
    wSeg_(),
    matPatch_(-1),
    landTime_(0),
    restSince_(-1),
    restEnds_(point::zero),
    location_(),
    segmentLocations_(l_.size())
{
    if (E_ > 0)
    {
        is >> z0Rest_ >> Q_ >> vSeg_ >> wSeg_;
    }
    is >> matPatch_ >> landTime_ >> restSince_ >> restEnds_;
    is.check(FUNCTION_NAME);
    calcProperties();
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const fiber& f)
{
    os  << f.id_ << token::SPACE
        << f.setIndex_ << token::SPACE
        << f.s0_ << token::SPACE
        << f.z0_ << token::SPACE
        << f.l_ << token::SPACE
        << f.d_ << token::SPACE
        << f.rho_ << token::SPACE
        << f.p0_ << token::SPACE
        << f.alpha_ << token::SPACE
        << f.x_ << token::SPACE
        << f.q_ << token::SPACE
        << f.v_ << token::SPACE
        << f.omega_ << token::SPACE
        << f.dxPrev_ << token::SPACE
        << f.dthetaPrev_ << token::SPACE
        << f.vPrev_ << token::SPACE
        << f.omegaPrev_ << token::SPACE
        << f.hPrev_ << token::SPACE
        << f.hNext_ << token::SPACE
        << f.jumped_ << token::SPACE
        << f.psi_ << token::SPACE
        << f.eddyTime_ << token::SPACE
        << f.nDraws_ << token::SPACE
        << f.nSubSteps_ << token::SPACE
        << f.E_ << token::SPACE
        << f.G_;
    if (f.E_ > 0)
    {
        os  << token::SPACE << f.z0Rest_ << token::SPACE << f.Q_
            << token::SPACE << f.vSeg_ << token::SPACE << f.wSeg_;
    }
    os  << token::SPACE << f.matPatch_ << token::SPACE << f.landTime_
        << token::SPACE << f.restSince_ << token::SPACE << f.restEnds_;

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
