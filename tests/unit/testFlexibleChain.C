/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fiberTracking: rigid fibers for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fiberTracking, distributed under GPL-3.0-or-later.

Description
    Unit tests of the flexible chain (flexibleChain) against closed forms:
    the discrete cantilever (tip and uniform load), the elastica (Bisshopp
    & Drucker), the free-free beam's first frequency, energy and joint
    gaps over long runs, and the rigid chain's Jeffery period in the stiff
    limit.  Part of Test-fiberModel.

\*---------------------------------------------------------------------------*/

#include "flexibleChain.H"
#include "fiberHydrodynamics.H"
#include "fluidSample.H"
#include "spheroidResistance.H"
#include "mathematicalConstants.H"
#include "IOstreams.H"
#include "IStringStream.H"
#include "OStringStream.H"

#include <cmath>
#include <sstream>

using namespace Foam;
using namespace Foam::constant::mathematical;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);
scalar relErr(const scalar a, const scalar b);
std::string fmt(const scalar a, const scalar b, const scalar err);
scalar chainPeriod
(
    const label N,
    const scalar L,
    const scalar d,
    const scalar gammaDot
);


// * * * * * * * * * * * * * * * * Helpers * * * * * * * * * * * * * * * * //

namespace
{

// A beam of length 1 along x with EI = 1 and mass 1 per length
// (d = L/1000: the cross-section's rotary inertia, which the segments keep
// (Eq. 4), shifts the first frequency by 1.5e-6 only)
const scalar beamL = 1, beamD = 1e-3, beamEI = 1, beamRhoA = 1;

scalar beamE()
{
    return beamEI/(pi*pow4(beamD)/64);
}

scalar beamRho()
{
    return beamRhoA/(pi*sqr(beamD)/4);
}

flexibleChain beam(const label N, const scalar nu = 0.3)
{
    const fiber f
    (
        fiber::straight
        (
            0, point(0.5*beamL, 0, 0), vector(1, 0, 0), N, beamL/N, beamD,
            beamRho()
        )
    );
    return flexibleChain(f, beamE(), beamE()/(2*(1 + nu)));
}


//- Static equilibrium of a clamped chain under dead loads (a tip force
//  -tipLoad e_y, a line load -lineLoad e_y, a tip couple M): implicit
//  steps with a light damping until the motion stops; the tip's y, and
//  the last segment's rotation vector from its start into rot if given
scalar cantileverTip
(
    const label N,
    const scalar tipLoad,
    const scalar lineLoad,
    label& nSteps,
    const vector& M = Zero,
    vector* rot = nullptr
)
{
    flexibleChain c(beam(N));
    c.clamp();
    const quaternion q0(c.rotations()[N - 1]);
    const scalar l = beamL/N;
    List<flexibleChain::segmentLoad> loads(N);
    forAll(loads, i)
    {
        loads[i].f = vector(0, -lineLoad*l, 0);
        // damping: a time scale of the first mode
        loads[i].A = (beamRhoA*l*10)*tensor::I;
        loads[i].D = (beamRhoA*pow3(l)*10)*tensor::I;
    }
    const scalar h = 0.05;
    auto state = [&]()
    {
        return
            c.end().y()
          + mag(fiber::rotationVectorOf(conjugate(q0)*c.rotations()[N - 1]));
    };
    scalar tip = state();
    for (nSteps = 1; nSteps < 200000; ++nSteps)
    {
        // the tip load is dead (fixed direction) at the moving tip
        const vector P(0, -tipLoad, 0);
        loads[N - 1].f = vector(0, -lineLoad*l, 0) + P;
        loads[N - 1].t = ((0.5*l*c.direction(N - 1)) ^ P) + M;
        c.step(loads, h);
        const scalar tipNew = state();
        if (mag(tipNew - tip) < 1e-15*mag(tipNew) && nSteps > 10)
        {
            break;
        }
        tip = tipNew;
    }
    if (rot)
    {
        *rot = fiber::rotationVectorOf(conjugate(q0)*c.rotations()[N - 1]);
    }
    return c.end().y();
}

//- The hydrodynamic loads of chain c (segments of fiber f) in the linear
//  flow u = G x of viscosity mu
void linearFlowLoads
(
    const fiber& f,
    const flexibleChain& c,
    const fiberHydrodynamics& hydro,
    const tensor& G,
    const scalar mu,
    UList<flexibleChain::segmentLoad>& loads
)
{
    forAll(loads, i)
    {
        const point& r = c.centres()[i];
        const fluidSample s((G & r), G, mu);
        fiberHydrodynamics::segmentLaw k;
        hydro.law
        (
            f, i, c.rotations()[i].R(), s, c.velocities()[i], c.omegas()[i],
            k
        );
        flexibleChain::segmentLoad& ld = loads[i];
        ld.f = (k.Kuu & s.U) + (k.Kuw & s.Omega()) + k.f0;
        ld.A = k.Kuu;
        ld.B = k.Kuw;
        ld.t = (k.Kwu & s.U) + (k.Kww & s.Omega()) + k.t0;
        ld.C = k.Kwu;
        ld.D = k.Kww;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * * //

void testFlexibleCantilever()
{
    // Small deflection (load 1e-8 EI/L^2: geometric nonlinearity 1e-16)
    // against the exact discrete chain of N joints (clamp + N - 1),
    // k_b = EI/l: tip load  v = P L^3/(3 EI) (N+1)(2N+1)/(2 N^2),
    // uniform load v = w L^4/(8 EI) ((N+1)/N)^2
    const scalar P = 1e-8, w = 1e-8;
    scalar errTipPrev = GREAT, errLinePrev = GREAT;
    bool convTip = true, convLine = true;
    for (const label N : {1, 2, 5, 10, 20, 40})
    {
        label n1 = 0, n2 = 0;
        const scalar vTip = -cantileverTip(N, P, 0, n1);
        const scalar vLine = -cantileverTip(N, 0, w, n2);
        const scalar refTip = P/3*(N + 1)*(2*N + 1)/(2.0*N*N);
        const scalar refLine = w/8*sqr((N + 1.0)/N);
        std::ostringstream nm;
        nm << "flexible.cantilever.N=" << N;
        check
        (
            nm.str() + ".tipLoad.discrete",
            relErr(vTip, refTip) < 1e-9,
            fmt(vTip, refTip, relErr(vTip, refTip))
        );
        check
        (
            nm.str() + ".uniformLoad.discrete",
            relErr(vLine, refLine) < 1e-9,
            fmt(vLine, refLine, relErr(vLine, refLine))
        );
        const scalar eT = relErr(vTip, P/3), eL = relErr(vLine, w/8);
        convTip = convTip && eT < errTipPrev;
        convLine = convLine && eL < errLinePrev;
        errTipPrev = eT;
        errLinePrev = eL;
    }
    std::ostringstream det;
    det << "error against the continuum at N = 40: tip " << errTipPrev
        << ", uniform " << errLinePrev;
    check
    (
        "flexible.cantilever.convergesToContinuum",
        convTip && convLine && errTipPrev < 0.04 && errLinePrev < 0.06,
        det.str()
    );
}


void testFlexibleTwistAndMoment()
{
    // A tip couple: every joint (clamp + N - 1) carries it whole, so the
    // discrete chain is exact for any N and any angle about a fixed axis:
    // twist about the axis T L/(G J) (G J = EI/(1 + nu) here), bending
    // about z a tip rotation M L/EI with the tip deflection
    // M L^2 (N + 1)/(2 N EI) (small) or the arc's (1 - cos(ML/EI))/(M/EI)
    // discrete: sum over joints of l sin(j M l/EI)
    const label N = 10;
    const scalar nu = 0.3;
    for (const scalar T : {1e-6, 1.0})
    {
        label n = 0;
        vector rot;
        cantileverTip(N, 0, 0, n, vector(T, 0, 0), &rot);
        const scalar ref = T*beamL*(1 + nu)/beamEI;
        std::ostringstream nm;
        nm << "flexible.cantilever.twist.T=" << T;
        check
        (
            nm.str(),
            relErr(rot.x(), ref) < 1e-9 && mag(rot.y()) + mag(rot.z()) < 1e-12,
            fmt(rot.x(), ref, relErr(rot.x(), ref))
        );
    }
    for (const scalar M : {1e-6, 1.0})
    {
        label n = 0;
        vector rot;
        const scalar v = cantileverTip(N, 0, 0, n, vector(0, 0, M), &rot);
        const scalar l = beamL/N, a = M*l/beamEI;
        scalar vRef = 0;
        for (label j = 1; j <= N; ++j)
        {
            vRef += l*std::sin(j*a);
        }
        const scalar e =
            max(relErr(rot.z(), M*beamL/beamEI), relErr(v, vRef));
        std::ostringstream nm, det;
        nm << "flexible.cantilever.tipMoment.M=" << M;
        det << "tip rotation " << rot.z() << " (" << M*beamL/beamEI
            << "), deflection " << v << " (" << vRef << "), rel. error "
            << e;
        check(nm.str(), e < 1e-9, det.str());
    }
}


void testFlexibleElastica()
{
    // Large deflection under a dead tip load: Bisshopp & Drucker (1945),
    // v/L = 0.30172 (PL^2/EI = 1) and 0.49346 (2).  The discrete chain's
    // error is O(1/N) (the clamp joint sits at the wall): Richardson's
    // extrapolation of N = 40 and 80 removes it.
    const scalar ref[2] = {0.30172, 0.49346};
    for (label k = 0; k < 2; ++k)
    {
        const scalar P = k + 1;
        label n = 0;
        const scalar v40 = -cantileverTip(40, P, 0, n);
        const scalar v80 = -cantileverTip(80, P, 0, n);
        const scalar vR = 2*v80 - v40;
        std::ostringstream nm, det;
        nm << "flexible.elastica.PL2overEI=" << P;
        det << "N=40 " << v40 << ", N=80 " << v80 << ", extrapolated "
            << vR << ", reference " << ref[k] << ", rel. error "
            << relErr(vR, ref[k]);
        // the reference has 5 digits
        check
        (
            nm.str(),
            relErr(vR, ref[k]) < 2e-4
         && mag(v80 - ref[k]) < mag(v40 - ref[k]),
            det.str()
        );
    }
}


namespace
{

// The free-free beam's first mode: beta_1 L, sigma and the mode shape
const scalar beta1L = 4.73004074;

scalar modeSigma()
{
    return
        (std::cosh(beta1L) - std::cos(beta1L))
       /(std::sinh(beta1L) - std::sin(beta1L));
}

scalar modePhi(const scalar x)
{
    const scalar b = beta1L*x/beamL;
    return
        std::cosh(b) + std::cos(b)
      - modeSigma()*(std::sinh(b) + std::sin(b));
}

scalar modeSlope(const scalar x)
{
    const scalar b = beta1L*x/beamL;
    return beta1L/beamL
       *(std::sinh(b) - std::sin(b) - modeSigma()*(std::cosh(b) + std::cos(b)));
}


//- The free-free chain of N segments started with the continuum mode's
//  velocity (amplitude 1e-6: linear), nPer steps per period Tref: the
//  period of the upward zero crossings of the modal coordinate
//  sum m_i phi(x_i) y_i, and the energy lost over 5 periods
scalar freeFreePeriod
(
    const label N,
    const label nPer,
    const scalar Tref,
    scalar& loss
)
{
    flexibleChain c(beam(N));
    const scalar eps = 1e-6;
    forAll(c.centres(), i)
    {
        const point r(c.centres()[i]);
        c.set
        (
            i, r, c.rotations()[i], vector(0, eps*modePhi(r.x()), 0),
            vector(0, 0, eps*modeSlope(r.x()))
        );
    }
    const List<flexibleChain::segmentLoad> loads(N);
    const scalar h = Tref/nPer;
    const scalar m = beamRhoA*beamL/N;
    auto modal = [&]()
    {
        scalar q = 0;
        forAll(c.centres(), i)
        {
            q += m*modePhi((i + 0.5)*beamL/N)*c.centres()[i].y();
        }
        return q;
    };

    // the energy after the first step (the constraint projection of the
    // initial velocities)
    c.step(loads, h);
    const scalar e0 = c.kineticEnergy() + c.elasticEnergy();
    scalar qPrev = modal();
    DynamicList<scalar> up;
    for (label n = 2; n <= 5*nPer + nPer/2; ++n)
    {
        c.step(loads, h);
        const scalar q = modal();
        if (qPrev < 0 && q >= 0)
        {
            up.append((n - 1 + qPrev/(qPrev - q))*h);
        }
        qPrev = q;
    }
    loss = 1 - (c.kineticEnergy() + c.elasticEnergy())/e0;
    return up.size() > 1 ? (up.last() - up.first())/(up.size() - 1) : -1;
}

} // End anonymous namespace


void testFlexibleVibration()
{
    // Free-free beam, first bending mode: omega_1 = (beta_1 L)^2
    // sqrt(EI/(rho A L^4)), beta_1 L = 4.73004
    const scalar omegaRef =
        sqr(beta1L)*std::sqrt(beamEI/(beamRhoA*pow4(beamL)));
    const scalar Tref = twoPi/omegaRef;
    auto run = [&](const label N, const label nPer, scalar& loss)
    {
        return freeFreePeriod(N, nPer, Tref, loss);
    };

    // The chain's error falls fast with N down to the floor of what the
    // chain does not discretise: the step's period error (omega h)^2/3 =
    // 8e-7 and the rotary inertia of the cross-section (Rayleigh beam),
    // 1e-6; both below 3e-6
    scalar loss = 0;
    scalar err[4];
    std::ostringstream det;
    det << "period rel. error";
    const label Ns[4] = {5, 10, 20, 40};
    for (label k = 0; k < 4; ++k)
    {
        const scalar T = run(Ns[k], 4000, loss);
        err[k] = (T - Tref)/Tref;
        det << ", N=" << Ns[k] << ": " << err[k];
    }
    check
    (
        "flexible.vibration.freeFree.firstFrequencyConverges",
        mag(err[1]) < mag(err[0]) && mag(err[2]) < mag(err[1])
     && mag(err[2]) < 3e-6 && mag(err[3]) < 3e-6,
        det.str()
    );

    // Energy of the undamped chain: implicit Euler damps an oscillation
    // by (1 + omega^2 h^2)^(-1/2) per step, so the decay exponent
    // -ln(E/E0) over 5 periods is first order in h and vanishes as h -> 0
    // (halves with h, to O(omega^2 h^2) = 4e-5)
    scalar loss1 = 0, loss2 = 0, loss3 = 0;
    run(10, 1000, loss1);
    run(10, 2000, loss2);
    run(10, 4000, loss3);
    const scalar r1 = -std::log(1 - loss1), r2 = -std::log(1 - loss2);
    const scalar r3 = -std::log(1 - loss3);
    std::ostringstream detE;
    detE << "energy decay exponent over 5 periods at 1000, 2000, 4000 steps"
        << " per period: " << r1 << ", " << r2 << ", " << r3;
    check
    (
        "flexible.vibration.energyConservedAsStepVanishes",
        r3 > 0 && mag(r1/r2 - 2) < 2e-3 && mag(r2/r3 - 2) < 2e-3,
        detE.str()
    );
}


void testFlexibleStiffLimit()
{
    // The stiff chain in simple shear (no inertial drag) turns with the
    // rigid chain's Jeffery period (chainPeriod, which the rigid scheme
    // matches to 1e-5); and the joints stay closed: the linearised step
    // opens them by l (h omega)^2/2 (4e-6 l here), the projection closes
    // them to round-off, so no gap grows over 120000 steps
    const scalar L = 1e-3, d = 2e-5, rho = 1380, mu = 1.6, gammaDot = 200;
    const label N = 5;
    const fiberHydrodynamics hydro(1260, false, 1);
    tensor G(Zero);
    G.xy() = gammaDot;
    const scalar dt = 1e-5;
    const fiber f(fiber::straight(0, Zero, vector(0, 1, 0), N, L/N, d, rho));
    const scalar Tref = chainPeriod(N, L, d, gammaDot);

    for (const scalar E : {1e16, 1e20})
    {
        flexibleChain c(f, E, E/2.6);
        List<flexibleChain::segmentLoad> loads(N);
        auto angle = [&]()
        {
            const vector p(c.end() - c.start());
            return std::atan2(p.x(), p.y());
        };
        const scalar phi0 = angle();
        scalar phiPrev = phi0, unwrapped = phi0, T = -1;
        scalar gapEarly = 0, gapLate = 0;
        const label nSteps = 120000;
        for (label n = 1; n <= nSteps; ++n)
        {
            linearFlowLoads(f, c, hydro, G, mu, loads);
            c.step(loads, dt);
            (n <= nSteps/10 ? gapEarly : gapLate) =
                max(n <= nSteps/10 ? gapEarly : gapLate, c.maxGap());
            const scalar phi = angle();
            scalar dphi = phi - phiPrev;
            if (dphi > pi) dphi -= twoPi;
            if (dphi < -pi) dphi += twoPi;
            const scalar next = unwrapped + dphi;
            if (T < 0 && next >= phi0 + twoPi)
            {
                T = (n - 1 + (phi0 + twoPi - unwrapped)/dphi)*dt;
            }
            unwrapped = next;
            phiPrev = phi;
        }
        std::ostringstream nm, det;
        nm << "flexible.stiffLimit.E=" << E;
        det << fmt(T, Tref, relErr(T, Tref)) << "; max joint gap/l, first"
            << " tenth " << gapEarly/(L/N) << ", rest " << gapLate/(L/N);
        check(nm.str() + ".jefferyPeriod", relErr(T, Tref) < 1e-4, det.str());
        check
        (
            nm.str() + ".jointGapNoDrift",
            gapLate < 1e-12*L/N && gapEarly < 1e-12*L/N,
            det.str()
        );
    }
}


void testFlexibleState()
{
    // A flexible fiber's state through the chain and back (writeBack),
    // and through a stream (processor transfer, restart): unchanged to
    // round-off; a rigidly moving chain gives the fiber its rigid
    // velocities
    fiber f
    (
        fiber::straight(7, point(1, 2, 3), vector(1, 1, 0), 4, 0.25, 0.01, 1e3)
    );
    f.setVelocity(vector(0.1, -0.2, 0.3));
    f.setOmega(vector(0, 0, 2));
    f.makeFlexible(1e9, 4e8);

    // bend it: one implicit step under opposite tip forces
    {
        flexibleChain c(f);
        List<flexibleChain::segmentLoad> loads(4);
        loads[0].f = vector(0, 0, 1);
        loads[3].f = vector(0, 0, -1);
        c.step(loads, 1e-3);
        c.writeBack(f, 1e-3);
    }
    const flexibleChain a(f);

    OStringStream os;
    os.precision(17);
    os << f;
    IStringStream is(os.str());
    const fiber g(is);
    const flexibleChain b(g);

    scalar err = 0;
    forAll(a.centres(), i)
    {
        err = max(err, mag(a.centres()[i] - b.centres()[i]));
        err = max(err, mag(a.velocities()[i] - b.velocities()[i]));
        err = max(err, mag(a.omegas()[i] - b.omegas()[i]));
        err = max(err, mag(a.direction(i) - b.direction(i)));
    }
    check
    (
        "flexible.state.streamRoundTrip",
        g.flexible() && err < 1e-12,
        fmt(err, 0, err)
    );

    // Rigid motion: the chain of a rigid fiber written back
    fiber r
    (
        fiber::straight(8, point(0, 0, 0), vector(0, 1, 1), 5, 0.2, 0.01, 1e3)
    );
    r.setVelocity(vector(1, 0, 0));
    r.setOmega(vector(0.5, -1, 2));
    const vector v0(r.velocity()), w0(r.omega());
    const point x0(r.position());
    r.makeFlexible(1e9, 4e8);
    flexibleChain(r).writeBack(r, 0);
    const scalar e =
        mag(r.velocity() - v0) + mag(r.omega() - w0) + mag(r.position() - x0);
    check
    (
        "flexible.state.rigidMotionWrittenBack",
        e < 1e-12,
        fmt(e, 0, e)
    );
}


// * * * * * * * * * * * * Loads of the interactions  * * * * * * * * * * //

namespace
{

//- A load written with 17 digits and read back
fiberIntegrator::load streamed(const fiberIntegrator::load& l)
{
    OStringStream os;
    os.precision(17);
    os << l;
    IStringStream is(os.str());
    fiberIntegrator::load r;
    is >> r;
    return r;
}

} // End anonymous namespace


void testFlexibleSegmentLoads()
{
    // The interactions' explicit loads by segment (contacts): a pair of
    // opposite forces across the tips of a flexible fiber at rest in a
    // fluid without viscosity (a couple, as a self-contact gives): after
    // one step h the chain's momentum is zero and its angular momentum
    // about the origin h sum c x F, to O(h^3) (the segments' inertia
    // turns within the step: the relative error falls as h^2); the load
    // turns and moves with a periodic transform and streams unchanged; a
    // rigid fiber's load has no segment loads.  The load bends the chain: a
    // tip turns against the middle segment (not against the other tip,
    // which the load's point symmetry turns alike), far above the
    // round-off of a unit vector (1e-16)
    const label N = 5;
    auto straight = [&]()
    {
        fiber f
        (
            fiber::straight
            (
                3, point(1, 2, 3), vector(1, 0, 0), N, 2e-4, 2e-5, 1e3
            )
        );
        f.makeFlexible(1e9, 4e8);
        return f;
    };
    fiber f(straight());
    const tensor R(f.R());
    const point c0(f.position() + f.segmentOffset(R, 0));
    const point c4(f.position() + f.segmentOffset(R, N - 1));
    const vector F(0, 1e-6, 2e-7);
    fiberIntegrator::load l;
    l.addForce(f, 0, F, c0 + vector(0, 1e-5, 0));
    l.addForce(f, N - 1, -F, c4 + vector(0, -1e-5, 0));
    const vector M(l.M);

    const fiberHydrodynamics hydro(1000, false, 1);
    const List<fluidSample> s(N, fluidSample(Zero, Zero, 0));
    FixedList<scalar, 2> eP, eL;
    const FixedList<scalar, 2> h({1e-8, 1e-9});
    scalar turn = 0;
    for (label k = 0; k < 2; ++k)
    {
        fiber g(straight());
        flexibleChain work;
        work.advance(g, s, hydro, Zero, h[k], nullptr, &l);
        const flexibleChain c(g);
        eP[k] = mag(c.momentum())/(mag(F)*h[k]);
        eL[k] = mag(c.angularMomentum() - h[k]*M)/mag(h[k]*M);
        turn = mag(c.direction(0) - c.direction(N/2));
    }
    std::ostringstream det;
    det << "momentum " << max(eP[0], eP[1]) << " of h |F|, angular "
        << "momentum against h sum c x F: relative difference " << eL[0]
        << " (h = " << h[0] << " s), " << eL[1] << " (h = " << h[1]
        << " s); a tip turned against the middle segment by " << turn;
    check
    (
        "flexible.segmentLoads.applied",
        label(l.seg.size()) == N && mag(l.F) == 0 && max(eP[0], eP[1]) < 1e-12
     && eL[1] < 1e-9 && eL[0] > 30*eL[1] && turn > 1e-13,
        det.str()
    );

    // An implicit spring K and dashpot C along the axis on the middle
    // segment's centre, with the spring's force F0 at the start: the
    // chain moves as one body, by backward Euler V = h F0/(m + h C + h^2 K)
    {
        const label N3 = 3;
        fiber g
        (
            fiber::straight(5, Zero, vector(1, 0, 0), N3, 2e-4, 2e-5, 1e3)
        );
        g.makeFlexible(1e9, 4e8);
        const scalar K = 0.3, C = 2e-6, F0 = 1e-6, hs = 1e-5;
        fiberIntegrator::load li;
        li.addForce(g, 1, vector(F0, 0, 0), g.position());
        li.addSpring
        (
            g, 1, K*sqr(vector(1, 0, 0)), C*sqr(vector(1, 0, 0)), Zero, Zero
        );
        flexibleChain work;
        const List<fluidSample> s3(N3, fluidSample(Zero, Zero, 0));
        work.advance(g, s3, hydro, Zero, hs, nullptr, &li);
        const scalar Vref = hs*F0/(g.mass() + hs*C + sqr(hs)*K);
        scalar eV = 0;
        for (label i = 0; i < N3; ++i)
        {
            eV = max(eV, mag(work.velocities()[i] - vector(Vref, 0, 0)));
        }
        check
        (
            "flexible.segmentLoads.implicitSpring",
            li.implicit && eV < 1e-12*Vref,
            fmt(work.velocities()[0].x(), Vref, eV/Vref)
        );
    }

    // Transformed: c' = Q c + t, F' = Q F, M' = c' x F'
    const tensor Q(fiber::rotationQuaternion(vector(0.3, -0.2, 1)).R());
    const vector t(0.5, -1, 2);
    fiberIntegrator::load lt(l);
    lt.transform(vectorTensorTransform(t, Q, true));
    const point c0t((Q & (c0 + vector(0, 1e-5, 0))) + t);
    const scalar eT =
        mag(lt.seg[0].F - (Q & F)) + mag(lt.seg[0].M - (c0t ^ (Q & F)))
      + mag(lt.seg[1].F) + mag(lt.seg[1].M);

    const fiberIntegrator::load lr(streamed(lt));
    scalar eS = 0;
    for (size_t i = 0; i < lr.seg.size(); ++i)
    {
        eS += mag(lr.seg[i].F - lt.seg[i].F) + mag(lr.seg[i].M - lt.seg[i].M);
    }

    fiber r
    (
        fiber::straight(4, Zero, vector(0, 1, 0), N, 2e-4, 2e-5, 1e3)
    );
    fiberIntegrator::load lrigid;
    lrigid.addForce(r, 2, F, point(0, 1e-4, 0));
    std::ostringstream det2;
    det2 << "transformed " << eT << ", streamed " << eS << " ("
         << lr.seg.size() << " segments), rigid fiber: "
         << lrigid.seg.size() << " segment loads";
    check
    (
        "flexible.segmentLoads.transformAndStream",
        eT < 1e-15*mag(F)*(1 + mag(t) + mag(c0)) && label(lr.seg.size()) == N
     && eS < 1e-20 && lrigid.seg.empty() && mag(lrigid.F - F) == 0,
        det2.str()
    );
}


// * * * * * * * * * * * * * Self-contact links  * * * * * * * * * * * * * //

void testFlexibleLinks()
{
    // A self-contact's spring and dashpot between segments 0 and 3 of a
    // spinning flexible chain, with the contact's explicit force pair:
    //  - solved with the step (the low-rank update of the block
    //    tridiagonal system), the solution is the fixed point of the
    //    one-sided springs each segment takes against its partner's
    //    velocity: given the partner's contact-point velocity from the
    //    linked step, the plain step with one-sided springs (separately
    //    checked, flexible.segmentLoads.implicitSpring) gives the same
    //    velocities;
    //  - without fluid (no viscosity) the step keeps the momentum (the
    //    pair is internal);
    //  - a stiff link holds the contact: the points' relative velocity
    //    falls as 1/(h^2 K) against the step without the spring;
    //  - the link turns with a periodic transform and streams unchanged
    const label N = 6;
    const scalar l = 2e-4;
    auto chain = [&]()
    {
        fiber f
        (
            fiber::straight
            (
                7, point(1, 2, 3), vector(1, 0, 0), N, l, 2e-5, 1e3
            )
        );
        f.setVelocity(vector(0.1, -0.2, 0.05));
        f.setOmega(vector(3, 20, -5));
        f.makeFlexible(1e7, 4e6);
        return f;
    };
    const fiber f0(chain());
    const tensor R(f0.R());
    const point xA(f0.position() + f0.segmentOffset(R, 0));
    const point xB(f0.position() + f0.segmentOffset(R, 3));
    const point c(0.5*(xA + xB) + vector(0, 2e-5, -1e-5));
    const vector rA(c - xA), rB(c - xB);
    const vector n(normalised(vector(0.3, 1, 0.2)));
    const vector F(2e-6*n);
    const scalar h = 1e-5;

    // Link stiffness: normal and tangential, and dashpots.  For the fixed
    // point, of the order of the segments' own inertia (h^2 K ~ h C ~ m,
    // m = 6.3e-11 kg): a link far stiffer than that dominates both
    // systems, and their difference is the round-off of their condition
    // (1e-8 at h^2 K = 80 m)
    auto springs = [&](const scalar kn, tensor& K, tensor& C)
    {
        K = kn*sqr(n) + 0.3*kn*(tensor::I - sqr(n));
        C = 2e-4*std::sqrt(kn)*sqr(n) + 1e-6*(tensor::I - sqr(n));
    };
    tensor K(0.5*sqr(n) + 0.2*(tensor::I - sqr(n)));
    tensor C(5e-6*sqr(n) + 2e-6*(tensor::I - sqr(n)));

    const fiberHydrodynamics hydro(1000, false, 1);
    const List<fluidSample> still(N, fluidSample(Zero, Zero, 0));
    const List<fluidSample> water(N, fluidSample(Zero, Zero, 1e-6));
    auto pointVelocity =
        [](const flexibleChain& w, const label i, const vector& r)
    {
        return w.velocities()[i] + (w.omegas()[i] ^ r);
    };
    auto pairLoad = [&](fiberIntegrator::load& ld)
    {
        ld.addForce(f0, 0, F, c);
        ld.addForce(f0, 3, -F, c);
    };

    // One step h of a fresh chain in fluid s under load ld
    auto stepped =
        [&](const fiberIntegrator::load& ld, const List<fluidSample>& s)
    {
        fiber g(chain());
        flexibleChain w;
        w.advance(g, s, hydro, Zero, h, nullptr, &ld);
        return w;
    };

    // Linked, in water
    fiberIntegrator::load ll;
    pairLoad(ll);
    ll.addLink(f0, 0, 3, rA, rB, K, C);
    const flexibleChain w1(stepped(ll, water));
    const vector uA(pointVelocity(w1, 0, rA)), uB(pointVelocity(w1, 3, rB));

    // One-sided springs against the partner's velocity from the linked
    // step (the contact's form: explicit F + C vp, spring on own motion),
    // and again with that velocity changed by a few ulp (1e-15): the
    // round-off the system amplifies, the scale of the test's tolerance
    auto oneSided = [&](const scalar eps)
    {
        const vector vB(uB*(1 + eps)), vA(uA*(1 - eps));
        fiberIntegrator::load lo;
        lo.addForce(f0, 0, F + (C & vB), c);
        lo.addForce(f0, 3, -F + (C & vA), c);
        lo.addSpring(f0, 0, K, C, rA, vB);
        lo.addSpring(f0, 3, K, C, rB, vA);
        return stepped(lo, water);
    };
    auto differ = [&](const flexibleChain& a, const flexibleChain& b)
    {
        scalar e = 0;
        for (label i = 0; i < N; ++i)
        {
            e = max(e, mag(a.velocities()[i] - b.velocities()[i]));
            e = max(e, l*mag(a.omegas()[i] - b.omegas()[i]));
        }
        return e;
    };
    const flexibleChain w2(oneSided(0));
    const scalar eFix = differ(w1, w2);
    const scalar eUlp = differ(w2, oneSided(1e-15));
    scalar vScale = 0;
    for (label i = 0; i < N; ++i)
    {
        vScale = max(vScale, mag(w1.velocities()[i]));
    }
    std::ostringstream detFix;
    detFix
        << "velocities differ by " << eFix << " m/s of " << vScale
        << " (" << eFix/vScale << "); a change of the partner's velocity "
        << "by 1e-15 changes them by " << eUlp << "; contact points' "
        << "relative velocity " << mag(uA - uB);
    check
    (
        "flexible.links.pairSolved",
        ll.implicit && eFix < 10*eUlp && eFix < 1e-8*vScale
     && mag(uA - uB) > 0,
        detFix.str()
    );

    // Momentum in still fluid without viscosity
    {
        const vector P0(f0.mass()*f0.velocity());
        const flexibleChain w(stepped(ll, still));
        const scalar eP = mag(w.momentum() - P0)/mag(P0);
        check
        (
            "flexible.links.momentum",
            eP < 1e-12,
            fmt(mag(w.momentum()), mag(P0), eP)
        );
    }

    // A stiff link holds the contact: relative velocity of the points
    // against the step without the spring (the force pair alone)
    scalar ratio[2];
    const scalar kns[2] = {1e4, 1e6};
    scalar vFree = 0;
    {
        fiberIntegrator::load lf;
        pairLoad(lf);
        const flexibleChain w(stepped(lf, still));
        vFree = mag(pointVelocity(w, 0, rA) - pointVelocity(w, 3, rB));
    }
    for (label k = 0; k < 2; ++k)
    {
        tensor Ks, Cs;
        springs(kns[k], Ks, Cs);
        fiberIntegrator::load ls;
        pairLoad(ls);
        ls.addLink(f0, 0, 3, rA, rB, Ks, Cs);
        const flexibleChain w(stepped(ls, still));
        ratio[k] =
            mag(pointVelocity(w, 0, rA) - pointVelocity(w, 3, rB))/vFree;
    }
    std::ostringstream det;
    det << "relative velocity / without spring: " << ratio[0] << " (kn "
        << kns[0] << "), " << ratio[1] << " (kn " << kns[1] << ")";
    check
    (
        "flexible.links.stiffHolds",
        ratio[0] < 0.1 && ratio[1] < 0.02*ratio[0] && ratio[1] > 0,
        det.str()
    );

    // Transformed and streamed
    const tensor Q(fiber::rotationQuaternion(vector(0.3, -0.2, 1)).R());
    fiberIntegrator::load lt(ll);
    lt.transform(vectorTensorTransform(vector(1, 2, 3), Q, true));
    const fiberIntegrator::load lr(streamed(lt));
    const fiberIntegrator::link& a = lt.links[0];
    const fiberIntegrator::link& b = lr.links[0];
    const scalar eT =
        mag(a.rA - (Q & rA)) + mag(a.rB - (Q & rB))
      + mag(a.K - (Q & K & Q.T()))/mag(K);
    const scalar eS =
        mag(a.rA - b.rA) + mag(a.rB - b.rB) + mag(a.K - b.K) + mag(a.C - b.C);
    check
    (
        "flexible.links.transformAndStream",
        lr.links.size() == 1 && b.i == 0 && b.j == 3 && eT < 1e-15
     && eS < 1e-20,
        fmt(eT, eS, eT + eS)
    );
}


// * * * * * * * * * * * * * * Buckling in shear  * * * * * * * * * * * * * //

namespace
{



//- A straight chain (L = 1 mm, d = 20 um, N segments) in simple shear
//  (glycerol-like, 200 1/s, no inertial drag), started 5 degrees from the
//  flow direction in the shear plane with its joints bent by eps (an arc
//  in the shear plane) and, a second chain, by -eps, turned through the
//  compressional quadrant to 60 degrees: the largest half-difference of
//  their joint angles over the passage, over eps (the growth of the
//  perturbation; the chain's own bending by the flow, the same in both,
//  drops out)
scalar bucklingAmplification(const label N, const scalar E)
{
    const scalar L = 1e-3, d = 2e-5, rho = 1380, mu = 1.6, gammaDot = 200;
    const scalar eps = 1e-7;
    const fiberHydrodynamics hydro(1260, false, 1);
    tensor G(Zero);
    G.xy() = gammaDot;
    const scalar th0 = 175*pi/180;
    const vector p(std::cos(th0), std::sin(th0), 0);
    const fiber f(fiber::straight(0, Zero, p, N, L/N, d, rho));
    flexibleChain ca(f, E, E/2.6), cb(f, E, E/2.6);

    // bent: segment i turned by delta_i about z, every joint by eps
    const scalar l = L/N;
    for (const label sgn : {1, -1})
    {
        flexibleChain& c = sgn > 0 ? ca : cb;
        point end(c.start());
        scalar delta = 0;
        for (label i = 0; i < N; ++i)
        {
            delta += sgn*(i == 0 ? 0 : eps);
            const quaternion q
            (
                fiber::rotationQuaternion(vector(0, 0, delta))
               *c.rotations()[i]
            );
            const vector z(q.R() & f.bodyDirection(i));
            c.set(i, end + 0.5*l*z, q, Zero, Zero);
            end += l*z;
        }
    }

    List<flexibleChain::segmentLoad> loads(N);
    auto shear = [&](const flexibleChain& c)
    {
        linearFlowLoads(f, c, hydro, G, mu, loads);
    };
    auto angle = [](const flexibleChain& c, const label j)
    {
        return
            fiber::rotationVectorOf
            (
                conjugate(c.rotations()[j])*c.rotations()[j + 1]
            );
    };

    const scalar dt = 1e-5;
    scalar Amax = 0;
    for (label n = 0; n < 200000; ++n)
    {
        shear(ca);
        ca.step(loads, dt);
        shear(cb);
        cb.step(loads, dt);
        for (label j = 0; j + 1 < N; ++j)
        {
            Amax = max(Amax, 0.5*mag(angle(ca, j) - angle(cb, j)));
        }
        const vector e(ca.end() - ca.start());
        const scalar th = std::atan2(e.y(), e.x());
        if (th > 0 && th < pi/3)
        {
            break;
        }
    }
    return Amax/eps;
}

} // End anonymous namespace


void testFlexibleBuckling()
{
    // Onset of buckling in shear: the modulus below which the arc
    // perturbation more than doubles in the compressional passage, by
    // bisection in log E, against
    //  - Forgacs & Mason (1959): buckles for E (ln 2 r_p - 1.75)/
    //    (2 eta gammaDot r_p^4) < 1;
    //  - Becker & Shelley (2001): buckles for mu = 8 pi eta gammaDot L^4/
    //    (E I c) > 306.4, c = -ln(eps^2 e), eps = d/(2 L) (slender-body
    //    theory; the definition of eps as radius over length is assumed).
    // The chain's segments carry their own spheroid resistance (no
    // slender-body coupling along the fiber), so the onset is expected
    // between the two estimates within a factor 3 (they differ by 3.4)
    const scalar L = 1e-3, d = 2e-5, eta = 1.6, gammaDot = 200;
    const scalar rp = L/d;
    const scalar EFM =
        2*eta*gammaDot*pow4(rp)/(std::log(2*rp) - 1.75);
    const scalar I = pi*pow4(d)/64;
    const scalar c = -std::log(sqr(d/(2*L))*std::exp(1.0));
    const scalar EBS = 8*pi*eta*gammaDot*pow4(L)/(306.4*I*c);

    for (const label N : {10, 15})
    {
        scalar lo = std::log(1e7), hi = std::log(1e10);
        const scalar Glo = bucklingAmplification(N, std::exp(lo));
        const scalar Ghi = bucklingAmplification(N, std::exp(hi));
        for (label k = 0; k < 12; ++k)
        {
            const scalar mid = 0.5*(lo + hi);
            (bucklingAmplification(N, std::exp(mid)) > 2 ? lo : hi) = mid;
        }
        const scalar Ec = std::exp(0.5*(lo + hi));
        std::ostringstream det;
        det.precision(3);
        det << "onset E = " << Ec << " Pa (growth " << Glo << " at 1e7 Pa, "
            << Ghi << " at 1e10 Pa); Forgacs-Mason " << EFM
            << " Pa (ratio " << Ec/EFM << "), Becker-Shelley " << EBS
            << " Pa (ratio " << Ec/EBS << ")";
        check
        (
            "flexible.buckling.onset.N=" + std::to_string(N),
            Glo > 100 && Ghi < 1.5 && Ec > EBS/3 && Ec < 3*EFM,
            det.str()
        );
    }
}


void testFlexibleResponse()
{
    // flexibleChain::response: the chain's step of h with loads held over
    // it (two forces at points off the axes, on segments 1 and 4, as
    // contacts as constraints give them) equals the response's free
    // velocities plus its mobility times the segments' forces and moments.
    // The joints' closing after the step gives back the angular momentum
    // it moved by a rigid rotation of the velocities (by 2e-7 of them
    // here) but under implicit springs: a spring of 1e-200 N/m, of no
    // other effect, compares the step itself
    const label N = 6;
    const scalar l = 2e-4, h = 1e-5;
    fiber f0
    (
        fiber::straight
        (
            3, point(1, 2, 3), normalised(vector(1, 0.2, 0)), N, l, 2e-5,
            1500
        )
    );
    f0.setVelocity(vector(0.1, -0.2, 0.05));
    f0.setOmega(vector(3, 20, -5));
    f0.makeFlexible(1e7, 4e6);
    const fiberHydrodynamics hydro(1000, true, 1);
    List<fluidSample> s(N, fluidSample(Zero, Zero, 1e-6));
    forAll(s, i)
    {
        s[i] = fluidSample(vector(0.05*i, 0.01, 0), Zero, 1e-6);
    }
    const vector g(0, -9.81, 0);

    flexibleChain r;
    scalarList mob, vFree;
    r.response(f0, s, hydro, g, h, mob, vFree);

    const tensor R(f0.R());
    const FixedList<label, 2> segs({1, 4});
    const FixedList<vector, 2> F
    ({
        vector(2e-7, -1e-7, 3e-7), vector(-1e-7, 4e-7, 0)
    });
    fiberIntegrator::load ld;
    ld.implicit = true;
    scalarList G(6*N, scalar(0));
    forAll(segs, k)
    {
        const label i = segs[k];
        const point x(f0.position() + f0.segmentOffset(R, i));
        const point c
        (
            x + 0.3*l*f0.segmentDirection(R, i) + vector(0, 0, 1e-5)
        );
        ld.addForce(f0, i, F[k], c);
        const vector T((c - x) ^ F[k]);
        for (label j = 0; j < 3; ++j)
        {
            G[6*i + j] += F[k][j];
            G[6*i + 3 + j] += T[j];
        }
    }
    ld.addSpring
    (
        f0, 2, 1e-200*tensor::I, tensor::zero, Zero, Zero
    );
    fiber f(f0);
    flexibleChain w;
    w.advance(f, s, hydro, g, h, nullptr, &ld);

    scalar err = 0, scale = 0;
    for (label i = 0; i < N; ++i)
    {
        vector V(Zero), W(Zero);
        for (label k = 0; k < 3; ++k)
        {
            V[k] = vFree[6*i + k];
            W[k] = vFree[6*i + 3 + k];
            for (label j = 0; j < 6*N; ++j)
            {
                V[k] += mob[6*N*(6*i + k) + j]*G[j];
                W[k] += mob[6*N*(6*i + 3 + k) + j]*G[j];
            }
        }
        err =
            max(err, mag(V - w.velocities()[i]) + l*mag(W - w.omegas()[i]));
        scale = max(scale, mag(w.velocities()[i]));
    }
    check
    (
        "flexibleChain.response.stepWithLoads",
        err < 1e-10*scale,
        fmt(err/scale, 0, err/scale)
    );
}
