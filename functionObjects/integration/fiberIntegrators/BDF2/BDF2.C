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

#include "BDF2.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberIntegrators
{
    defineTypeNameAndDebug(BDF2, 0);
    addToRunTimeSelectionTable(fiberIntegrator, BDF2, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fiberIntegrators::BDF2::ratio
(
    const fiber& f,
    const scalar h
)
{
    if (f.hPrev() <= 0)
    {
        return 0;
    }
    const scalar rho = h/f.hPrev();
    return rho <= 2 ? rho : 0;
}


void Foam::fiberIntegrators::BDF2::historyForces
(
    const fiber& f,
    const scalar h,
    const scalar a0,
    const scalar a1,
    const scalar a2,
    const vector& V,
    const vector& Vm,
    segmentForces& out
)
{
    // m (a0 V + a1 Vn + a2 Vm) = h (F + m g + F_ext), so the fiber's
    // momentum changes by h (F + m g + F_ext) less m (history), where
    // history = (a0 - 1) V + (a1 + 1) Vn + a2 Vm (zero for an implicit
    // Euler step, and for a constant acceleration at any step ratio).  The
    // fluid gets what the fiber took: the history term joins the segments'
    // forces by their share of the mass
    const vector history
    (
        (a0 - 1)*V + (a1 + 1)*f.velocity() + a2*Vm
    );
    forAll(out.F, i)
    {
        out.F[i] -= f.segmentMass(i)*history/h;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberIntegrators::BDF2::BDF2(const dictionary&)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberIntegrators::BDF2::predict
(
    const fiber& f,
    const scalar h,
    vector& dx,
    tensor& R
) const
{
    const scalar rho = ratio(f, h);
    dx = rho*f.dxPrev();
    R = fiber::rotation(rho*f.dthetaPrev()) & f.R();
}


void Foam::fiberIntegrators::BDF2::advance
(
    fiber& f,
    const UList<fluidSample>& samples,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const scalar h,
    segmentForces* out,
    const load* ext
) const
{
    const scalar rho = ratio(f, h);

    // Implicit Euler for rho = 0: a0 = 1, a1 = -1, a2 = 0
    const scalar a0 = (1 + 2*rho)/(1 + rho);
    const scalar a1 = -(1 + rho);
    const scalar a2 = sqr(rho)/(1 + rho);

    vector dxHat;
    tensor Rhat;
    predict(f, h, dxHat, Rhat);
    const tensor I(f.inertia(Rhat));

    const vector& Vn = f.velocity();
    const vector& wn = f.omega();
    const vector Vm(rho > 0 ? f.vPrev() : Vn);
    const vector wm(rho > 0 ? f.omegaPrev() : wn);

    vector V, w;
    solve
    (
        f, samples, hydro, g, Rhat, a0/h,
        -f.mass()*(a1*Vn + a2*Vm)/h,
        -(I & (a1*wn + a2*wm))/h,
        wn + rho*(wn - wm),
        V, w, out, ext,
        (a2/a0)*f.dxPrev(), (a2/a0)*f.dthetaPrev(), h
    );
    if (out && rho > 0)
    {
        historyForces(f, h, a0, a1, a2, V, Vm, *out);
    }

    f.moveBy
    (
        (h*V + a2*f.dxPrev())/a0,
        (h*w + a2*f.dthetaPrev())/a0,
        V, w, h
    );
}


// ************************************************************************* //
