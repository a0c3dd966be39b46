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

#include "fiberHydrodynamics.H"
#include "inertialDrag.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberHydrodynamics::fiberHydrodynamics
(
    const scalar rhoFluid,
    const bool inertial,
    const scalar CD,
    const scalar autoBound,
    const bool viscous
)
:
    rho_(rhoFluid),
    viscous_(viscous),
    inertial_(inertial),
    CD_(CD),
    autoBound_(autoBound),
    nInertial_(0),
    nSkipped_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberHydrodynamics::law
(
    const fiber& f,
    const label i,
    const tensor& R,
    const fluidSample& s,
    const vector& vOld,
    const vector& omegaOld,
    segmentLaw& k
) const
{
    const vector z(f.segmentDirection(R, i));
    const tensor zz(z*z);
    const tensor Pp(tensor::I - zz);
    const scalar mu = s.mu;
    const vector Ez(s.E() & z);

    // Viscous, Eq. 10-11
    k.Kuw = Zero;
    k.Kwu = Zero;
    k.f0 = Zero;
    if (viscous_)
    {
        k.Kuu = mu*(f.kAx(i)*zz + f.kAp(i)*Pp);
        k.Kww = mu*(f.kCx(i)*zz + f.kCp(i)*Pp);
        k.t0 = (mu*f.kH(i))*(z ^ Ez);
    }
    else
    {
        k.Kuu = Zero;
        k.Kww = Zero;
        k.t0 = Zero;
    }

    if (!inertial_)
    {
        return;
    }

    // Inertial cross-flow drag, Eq. 12-13, linearised about the old state
    const vector a(Pp & (s.U - vOld));
    const vector b(((s.Omega() - omegaOld) ^ z) + (Pp & Ez));

    const scalar l = f.segmentLength(i);
    const scalar c = 0.5*rho_*CD_*f.segmentDiameter(i);

    if (autoBound_ > 0)
    {
        const scalar wMax = mag(a) + 0.5*l*mag(b);
        const scalar boundF = c*l*wMax/(mu*f.kAp(i));
        const scalar boundT = c*pow3(l)*wMax/(12*mu*f.kCp(i));
        if (max(boundF, boundT) < autoBound_)
        {
            ++nSkipped_;
            return;
        }
    }
    ++nInertial_;

    scalar M0, M1, M2;
    inertialDrag::moments(a, b, l, M0, M1, M2);

    const tensor Z(crossMatrix(z));

    k.Kuu += (c*M0)*Pp;
    k.Kww += (c*M2)*Pp;
    k.Kuw -= (c*M1)*Z;
    k.Kwu += (c*M1)*Z;
    k.f0 += (c*M1)*(Pp & Ez);
    k.t0 += (c*M2)*(z ^ Ez);
}


void Foam::fiberHydrodynamics::evaluate
(
    const segmentLaw& k,
    const fluidSample& s,
    const vector& v,
    const vector& omega,
    vector& F,
    vector& T
)
{
    const vector du(s.U - v);
    const vector dw(s.Omega() - omega);
    F = (k.Kuu & du) + (k.Kuw & dw) + k.f0;
    T = (k.Kwu & du) + (k.Kww & dw) + k.t0;
}


// ************************************************************************* //
