/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fiberTracking: rigid fibers for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fiberTracking, distributed under GPL-3.0-or-later.

Application
    Test-fiberModel

Description
    Unit tests of the fiber model classes, without a mesh or a solver.
    Every check compares a number with an independent reference (closed
    form, limit, exact discrete solution or quadrature) and prints
    'PASS: <name> (<detail>)' or 'FAIL: <name> (<detail>)'.  The exit code
    is the number of failures.

\*---------------------------------------------------------------------------*/

#include "spheroidResistance.H"
#include "inertialDrag.H"
#include "fiber.H"
#include "fiberHydrodynamics.H"
#include "fiberIntegrator.H"
#include "fiberDispersion.H"
#include "GosmanIoannides.H"
#include "counterRandom.H"
#include "fiberSizes.H"
#include "Tuple2.H"
#include "fiberTracker.H"
#include "subStepControl.H"
#include "subStepStatistics.H"
#include "segmentDistance.H"
#include "Random.H"
#include "mathematicalConstants.H"
#include "IOstreams.H"

#include <cmath>
#include <sstream>

using namespace Foam;
using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * * * * Harness  * * * * * * * * * * * * * * * * //

static label nPass = 0;
static label nFail = 0;

void check(const std::string& name, const bool ok, const std::string& detail)
{
    Info<< (ok ? "PASS: " : "FAIL: ") << name.c_str() << " ("
        << detail.c_str() << ")" << endl;
    ok ? ++nPass : ++nFail;
}

scalar relErr(const scalar a, const scalar b)
{
    return mag(a - b)/max(mag(b), VSMALL);
}

std::string fmt(const scalar a, const scalar b, const scalar err)
{
    std::ostringstream os;
    os.precision(10);
    os << "got " << a << ", reference " << b << ", rel. error " << err;
    return os.str();
}


// * * * * * * * * * * * * * * Analytic flows  * * * * * * * * * * * * * * //

//- Linear flow u = U0 + G (x - x0) of viscosity mu
struct linearFlow
{
    vector U0;
    tensor G;
    point x0;
    scalar mu;

    void sample(const fiber& f, List<fluidSample>& s) const
    {
        List<point> pts;
        f.segmentCentres(pts);
        s.setSize(pts.size());
        forAll(pts, i)
        {
            s[i] = fluidSample(U0 + (G & (pts[i] - x0)), G, mu);
        }
    }
};


//- Simple shear u = gammaDot (y - y0) e_x
linearFlow shear(const scalar gammaDot, const scalar mu)
{
    tensor G(Zero);
    G.xy() = gammaDot;
    return linearFlow{Zero, G, Zero, mu};
}


//- Cox's r_e written out independently of the library
scalar coxRe(const scalar rc)
{
    return 1.24*rc/std::sqrt(std::log(rc));
}


//- Angle of p in the shear plane, from the gradient axis towards the flow
scalar shearAngle(const vector& p)
{
    return std::atan2(p.x(), p.y());
}


//- Integrate fiber f in the flow for nSteps of dt; return the time of the
//  first full 2 pi turn of p (linear interpolation), -1 if none
scalar period
(
    fiber& f,
    const linearFlow& flow,
    const fiberIntegrator& integ,
    const fiberHydrodynamics& hydro,
    const scalar dt,
    const label nSteps
)
{
    List<fluidSample> s;
    const scalar phi0 = shearAngle(f.orientation());
    scalar phiPrev = phi0;
    scalar unwrapped = phi0;
    scalar T = -1;
    for (label n = 1; n <= nSteps; ++n)
    {
        flow.sample(f, s);
        integ.advance(f, s, hydro, Zero, dt);
        const scalar phi = shearAngle(f.orientation());
        scalar dphi = phi - phiPrev;
        if (dphi > pi) dphi -= twoPi;
        if (dphi < -pi) dphi += twoPi;
        const scalar next = unwrapped + dphi;
        if (T < 0 && next >= phi0 + twoPi)
        {
            const scalar frac = (phi0 + twoPi - unwrapped)/dphi;
            T = (n - 1 + frac)*dt;
        }
        unwrapped = next;
        phiPrev = phi;
    }
    return T;
}


//- Period of a straight chain of N spheroid segments from the inertia-free
//  torque balance (docs/model.md): B = (N h + A S2)/(N c + A S2)
scalar chainPeriod
(
    const label N,
    const scalar L,
    const scalar d,
    const scalar gammaDot
)
{
    const scalar l = L/N;
    const scalar a = l/2;
    const spheroidResistance res(coxRe(l/d));
    const scalar A = 6*pi*a*res.YA;
    const scalar c = 8*pi*pow3(a)*res.YC;
    const scalar h = 8*pi*pow3(a)*res.YH;
    const scalar S2 = sqr(l)*N*(scalar(N)*N - 1)/12.0;
    const scalar B = (N*h + A*S2)/(N*c + A*S2);
    const scalar r = std::sqrt((1 + B)/(1 - B));
    return spheroidResistance::jefferyPeriod(r, gammaDot);
}


// * * * * * * * * * * * * * * * * * Tests  * * * * * * * * * * * * * * * * //

void testResistance()
{
    // Sphere limit: all functions -> 1, Y^H -> 0 (physics.md 1.4)
    {
        const spheroidResistance s(1 + 1e-12);
        const scalar err = max
        (
            max(mag(s.XA - 1), mag(s.YA - 1)),
            max(max(mag(s.XC - 1), mag(s.YC - 1)), mag(s.YH))
        );
        check("resistance.sphereLimit", err < 1e-10, fmt(err, 0, err));
    }

    // Series and closed form meet at e = 0.01 (absolute: the functions
    // are O(1), Y^H is O(e^2) and its change over the 2e-9 step in e is
    // 2e-11)
    {
        const scalar rBelow = 1/std::sqrt(1 - sqr(0.01 - 1e-9));
        const scalar rAbove = 1/std::sqrt(1 - sqr(0.01 + 1e-9));
        const spheroidResistance a(rBelow), b(rAbove);
        const scalar err = max
        (
            max(mag(a.XA - b.XA), mag(a.YA - b.YA)),
            max(max(mag(a.XC - b.XC), mag(a.YC - b.YC)), mag(a.YH - b.YH))
        );
        check("resistance.seriesContinuity", err < 1e-9, fmt(err, 0, err));
    }

    // Slender limit (physics.md 1.5): errors O(ln r / r^2)
    {
        const scalar r = 1e4;
        const spheroidResistance s(r);
        const scalar l2r = std::log(2*r);
        const scalar err = max
        (
            max
            (
                relErr(s.XA, (4.0/3.0)/(2*l2r - 1)),
                relErr(s.YA, (8.0/3.0)/(2*l2r + 1))
            ),
            max
            (
                max
                (
                    relErr(s.YC, (2.0/3.0)/(2*l2r - 1)),
                    relErr(s.XC, 2/(3*sqr(r)))
                ),
                relErr(s.YH/s.YC, 1)
            )
        );
        check("resistance.slenderLimit", err < 1e-6, fmt(err, 0, err));
    }

    // Worked example physics.md 8.1 (r_c = 10): Y^A, Y^C, Y^H, X^A, X^C
    {
        const spheroidResistance s(coxRe(10));
        const scalar err = max
        (
            max(relErr(s.XA, 0.286743), relErr(s.YA, 0.404356)),
            max
            (
                max(relErr(s.XC, 0.010266), relErr(s.YC, 0.145519)),
                relErr(s.YH, 0.141225)
            )
        );
        check("resistance.workedExample", err < 5e-5, fmt(err, 0, err));
    }

    // Bretherton: Y^H/Y^C = (r^2 - 1)/(r^2 + 1) exactly
    for (const scalar r : {1.5, 3.0, 10.0, 31.3466, 1000.0})
    {
        const spheroidResistance s(r);
        const scalar ref = (sqr(r) - 1)/(sqr(r) + 1);
        const scalar err = relErr(s.YH/s.YC, ref);
        std::ostringstream nm;
        nm << "resistance.brethertonRatio r=" << r;
        check(nm.str(), err < 1e-10, fmt(s.YH/s.YC, ref, err));
    }
}


void testBrethertonTorqueBalance()
{
    // One spheroid segment (l/d = 50), negligible inertia, one implicit
    // step in a general linear flow: the rotation rate must be Jeffery's
    // p' = W p + B (E p - (p.E p) p), B from Cox's r_e.
    const scalar l = 1e-3, d = 2e-5;
    const vector p0(vector(0.3, 0.8, 0.52)/mag(vector(0.3, 0.8, 0.52)));
    fiber f(fiber::straight(0, Zero, p0, 1, l, d, 1e-9));

    tensor G(1.0, 40.0, -3.0, 7.0, -2.0, 5.0, 11.0, -6.0, 1.0);
    G = 10*G;
    const linearFlow flow{Zero, G, Zero, 1.6};
    const fiberHydrodynamics hydro(1260, false, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));

    List<fluidSample> s;
    flow.sample(f, s);
    integ->advance(f, s, hydro, Zero, 1e-3);

    const vector pdot(f.omega() ^ p0);
    const symmTensor E(symm(G));
    const tensor W(skew(G));
    const scalar re = coxRe(l/d);
    const scalar B = (sqr(re) - 1)/(sqr(re) + 1);
    const vector Ep(E & p0);
    const vector ref((W & p0) + B*(Ep - (p0 & Ep)*p0));
    const scalar err = mag(pdot - ref)/mag(ref);
    check
    (
        "resistance.brethertonTorqueBalance",
        err < 1e-9,
        fmt(mag(pdot), mag(ref), err)
    );
}


scalar quadrature
(
    const vector& a,
    const vector& b,
    const scalar l,
    const label k
)
{
    // Composite Simpson, split at the point of smallest |a + s b| so each
    // piece is smooth
    const scalar h = l/2;
    List<scalar> cuts({-h, h});
    const scalar bb = magSqr(b);
    if (bb > 0)
    {
        const scalar s0 = -(a & b)/bb;
        if (s0 > -h && s0 < h)
        {
            cuts = List<scalar>({-h, s0, h});
        }
    }
    scalar sum = 0;
    const label n = 20000;
    for (label c = 0; c + 1 < cuts.size(); ++c)
    {
        const scalar lo = cuts[c], hi = cuts[c + 1];
        const scalar dx = (hi - lo)/n;
        for (label j = 0; j <= n; ++j)
        {
            const scalar s = lo + j*dx;
            const scalar w = (j == 0 || j == n) ? 1 : (j % 2 ? 4 : 2);
            sum += w*std::pow(s, k)*mag(a + s*b)*dx/3;
        }
    }
    return sum;
}


void testInertialDrag()
{
    const scalar l = 2e-4;
    struct caseAB { const char* name; vector a; vector b; };
    const List<caseAB> cases
    ({
        {"translation", vector(0.3, -0.2, 0), vector(0, 0, 0)},
        {"rotation", vector(0, 0, 0), vector(800, 300, 0)},
        {"signChangeInside", vector(0.05, 0.01, 0), vector(-900, -100, 0)},
        {"exactZeroCrossing", vector(0.04, 0, 0), vector(-1000, 0, 0)},
        {"noSignChange", vector(0.3, 0.1, 0), vector(-1500, 900, 0)},
        {"smallGradientSeries", vector(0.3, 0.1, 0), vector(200, -700, 0)},
        // |b| l/2 = 0.2494 |a|: the series at its branch limit, most terms
        {"seriesAtBranchLimit", vector(0.3, 0, 0), vector(400, 600, 200)},
        {"skew3D", vector(0.02, -0.07, 0.01), vector(300, 500, -800)}
    });

    for (const caseAB& c : cases)
    {
        scalar M[3];
        inertialDrag::moments(c.a, c.b, l, M[0], M[1], M[2]);
        const scalar scale0 = mag(c.a)*l + mag(c.b)*sqr(l);
        scalar err = 0;
        for (label k = 0; k < 3; ++k)
        {
            const scalar q = quadrature(c.a, c.b, l, k);
            err = max(err, mag(M[k] - q)/(scale0*std::pow(l, k)));
        }
        check
        (
            std::string("inertialDrag.closedFormVsQuadrature.") + c.name,
            err < 1e-9,
            fmt(err, 0, err)
        );
    }

    // The two forms meet at |b| l/2 = |a|/4: just below it Gauss-Legendre,
    // just above it the exact antiderivatives (which cancel little there;
    // b moved by 1e-14 changes the moments by less than 1e-15);
    // both must give the same moments to near round-off
    {
        const vector a(0.3, -0.1, 0.05);
        const vector bHat(vector(0.2, 0.9, -0.4)/mag(vector(0.2, 0.9, -0.4)));
        const scalar bLimit = 0.25*mag(a)/(0.5*l);
        scalar Mb[3], Ma[3];
        inertialDrag::moments
        (
            a, (1 - 1e-14)*bLimit*bHat, l, Mb[0], Mb[1], Mb[2]
        );
        inertialDrag::moments
        (
            a, (1 + 1e-14)*bLimit*bHat, l, Ma[0], Ma[1], Ma[2]
        );
        scalar err = 0;
        for (label k = 0; k < 3; ++k)
        {
            err = max(err, mag(Mb[k] - Ma[k])/(mag(a)*std::pow(l, k + 1)));
        }
        check("inertialDrag.formsMeetAtSwitch", err < 1e-13, fmt(err, 0, err));
    }

    // Pure translation and pure rotation closed forms (physics.md 3.4)
    {
        const vector a(0.3, -0.2, 0);
        scalar M0, M1, M2;
        inertialDrag::moments(a, Zero, l, M0, M1, M2);
        const scalar err = max
        (
            relErr(M0, l*mag(a)),
            max(relErr(M2, pow3(l)*mag(a)/12), mag(M1)/(sqr(l)*mag(a)))
        );
        check("inertialDrag.pureTranslation", err < 1e-12, fmt(err, 0, err));
    }
    {
        const vector b(800, 300, 0);
        scalar M0, M1, M2;
        inertialDrag::moments(Zero, b, l, M0, M1, M2);
        const scalar err = max
        (
            relErr(M0, mag(b)*sqr(l)/4),
            relErr(M2, mag(b)*pow4(l)/32)
        );
        check("inertialDrag.pureRotation", err < 1e-12, fmt(err, 0, err));
    }

    // Force of a segment in uniform cross-flow: rho C_D d l |a| a / 2
    {
        const scalar d = 2e-5, rho = 1.2, CD = 1;
        fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, d, 1380));
        const fiberHydrodynamics hydro(rho, true, CD);
        const fluidSample s(vector(3, 4, 0), Zero, 1.8e-5);
        fiberHydrodynamics::segmentLaw k;
        hydro.law(f, 0, f.R(), s, Zero, Zero, k);
        const fiberHydrodynamics viscousOnly(rho, false, CD);
        fiberHydrodynamics::segmentLaw kv;
        viscousOnly.law(f, 0, f.R(), s, Zero, Zero, kv);
        vector F, T, Fv, Tv;
        fiberHydrodynamics::evaluate(k, s, Zero, Zero, F, T);
        fiberHydrodynamics::evaluate(kv, s, Zero, Zero, Fv, Tv);
        const vector ref(0.5*rho*CD*d*l*mag(s.U)*s.U);
        const scalar err = mag((F - Fv) - ref)/mag(ref);
        check
        (
            "inertialDrag.segmentCrossFlowForce",
            err < 1e-12,
            fmt(mag(F - Fv), mag(ref), err)
        );
    }
}


void testInertialAuto()
{
    // inertialDrag auto: left out exactly when the bound is below 1e-3
    const scalar l = 2e-4, d = 2e-5, rho = 1.2, mu = 1.8e-5;
    fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, d, 1380));
    const fiberHydrodynamics on(rho, true, 1);
    const fiberHydrodynamics autoH(rho, true, 1, 1e-3);
    const fiberHydrodynamics off(rho, false, 1);
    scalar errSlow = 0, errFast = 0;
    for (const scalar slip : {1e-4, 10.0})
    {
        const fluidSample s(vector(slip, 0, 0), Zero, mu);
        fiberHydrodynamics::segmentLaw k;
        vector Fon, Fauto, Foff, T;
        on.law(f, 0, f.R(), s, Zero, Zero, k);
        fiberHydrodynamics::evaluate(k, s, Zero, Zero, Fon, T);
        autoH.law(f, 0, f.R(), s, Zero, Zero, k);
        fiberHydrodynamics::evaluate(k, s, Zero, Zero, Fauto, T);
        off.law(f, 0, f.R(), s, Zero, Zero, k);
        fiberHydrodynamics::evaluate(k, s, Zero, Zero, Foff, T);
        if (slip < 1)
        {
            // omitted, and the omitted part is below the bound
            errSlow = max(mag(Fauto - Foff)/mag(Foff),
                mag(Fon - Foff)/mag(Foff)/1e-3);
        }
        else
        {
            errFast = mag(Fauto - Fon)/mag(Fon);
        }
    }
    check
    (
        "inertialDrag.autoOmitsBelowBound",
        errSlow < 1 && autoH.nSkipped() == 1,
        fmt(errSlow, 1, errSlow) + " (omitted part / (1e-3 viscous))"
    );
    check
    (
        "inertialDrag.autoKeepsAboveBound",
        errFast < 1e-15 && autoH.nInertial() == 1,
        fmt(errFast, 0, errFast)
    );
}


void testViscousSwitch()
{
    // viscousDrag off: only the inertial cross-flow force remains,
    // rho C_D d l |a| a/2 for a broadside segment
    const scalar l = 2e-4, d = 2e-5, rho = 1.2;
    fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, d, 1380));
    const fiberHydrodynamics inertialOnly(rho, true, 1, 0, false);
    const fluidSample s(vector(3, 4, 0), Zero, 1.8e-5);
    fiberHydrodynamics::segmentLaw k;
    inertialOnly.law(f, 0, f.R(), s, Zero, Zero, k);
    vector F, T;
    fiberHydrodynamics::evaluate(k, s, Zero, Zero, F, T);
    const vector ref(0.5*rho*d*l*mag(s.U)*s.U);
    const scalar err = mag(F - ref)/mag(ref);
    check
    (
        "switch.viscousDragOff",
        err < 1e-12 && mag(T) < 1e-30,
        fmt(mag(F), mag(ref), err)
    );
}


void testInertia()
{
    const label N = 5;
    const scalar l = 2e-4, d = 2e-5, rho = 1380;
    const scalar L = N*l;
    const vector p(vector(1, 2, 3)/mag(vector(1, 2, 3)));
    fiber f(fiber::straight(0, vector(1, 2, 3), p, N, l, d, rho));

    const scalar m = rho*pi*sqr(d)/4*L;
    const scalar Iperp = m*(sqr(L)/12 + sqr(d)/16);
    const scalar Ipar = m*sqr(d)/8;
    const symmTensor ref(Ipar*sqr(p) + Iperp*(symmTensor::I - sqr(p)));
    const symmTensor I(f.inertia(f.R()));
    const scalar err = mag(I - ref)/mag(ref);
    check("inertia.straightChainVsCylinder", err < 1e-12, fmt(err, 0, err));
    check
    (
        "inertia.mass",
        relErr(f.mass(), m) < 1e-14,
        fmt(f.mass(), m, relErr(f.mass(), m))
    );
    check
    (
        "inertia.centreOfMass",
        mag(f.position() - vector(1, 2, 3)) < 1e-14,
        fmt(mag(f.position() - vector(1, 2, 3)), 0, 0)
    );
}


//- Torque-free rotation of a straight fiber in vacuum: by Euler's
//  equations an axisymmetric body keeps its spin about its axis, and its
//  rate across the axis, exactly (the gyroscopic term has no component
//  about a symmetry axis).  The inertia about the axis is 300 times less
//  than across it, so a gyroscopic term with such a component (the
//  paper's printed w_n x I w_{n-1}) turns the precession into spin: it
//  lost the whole 7 rad/s (implicit Euler) and 0.07 rad/s (BDF2).  Bound
//  1e-6 rad/s: implicit Euler turns the fiber about the new rate, which
//  keeps the spin exactly (1.5e-9: round-off amplified 300 times over
//  5000 steps); BDF2 turns it by a blend of two steps' rates, exact to
//  its truncation (w h = 2e-3: 2.8e-7)
void testFreeRotation()
{
    const label N = 5;
    const scalar l = 2e-4, d = 2e-5, rho = 2500;
    const vector p(vector(1, 2, 3)/mag(vector(1, 2, 3)));
    const vector q(normalised(p ^ vector(0, 0, 1)));
    const fiberHydrodynamics vacuum(1.2, false, 1, 0, false);
    const scalar w3 = 7, wPerp = 200, dt = 1e-5;
    for (const word scheme : {"implicitEuler", "BDF2"})
    {
        dictionary dict;
        dict.add("integrator", scheme);
        autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
        fiber f(fiber::straight(0, Zero, p, N, l, d, rho));
        f.setOmega(w3*p + wPerp*q);
        List<fluidSample> s(N, fluidSample(Zero, Zero, 1.8e-5));
        scalar errSpin = 0, errPerp = 0;
        for (label k = 0; k < 5000; ++k)
        {
            integ->advance(f, s, vacuum, Zero, dt);
            const vector e(f.orientation());
            const scalar ws = f.omega() & e;
            errSpin = max(errSpin, mag(ws - w3));
            errPerp =
                max(errPerp, mag(mag(f.omega() - ws*e) - wPerp)/wPerp);
        }
        std::ostringstream det;
        det << "5000 steps, " << 5000*dt*wPerp << " rad across the axis:"
            << " spin about the axis off by " << errSpin << " rad/s (of "
            << w3 << "), rate across it by " << errPerp << " (relative)";
        check
        (
            "freeRotation." + scheme,
            errSpin < 1e-6 && errPerp < 1e-9,
            det.str()
        );
    }
}


//- The rotation vector of a unit quaternion against the angle and axis
//  it was built from, either side of the switches between the series
//  (sin(angle/2) = 1e-3 and 1e-2: asin's, to s^4 and to s^6; atan's) and
//  from the series (small angles) to atan2 at tan(angle/2) = 0.05, and for
//  q and -q
void testRotationVector()
{
    const vector n(vector(0.3, -0.2, 1)/mag(vector(0.3, -0.2, 1)));
    scalar worst = 0;
    for
    (
        const scalar a
      : {
            1e-12, 1e-6, 1e-3, 1.999e-3, 2.001e-3, 0.01999, 0.02001, 0.05,
            0.0998, 0.1001, 0.3, 1.0, 2.5, 3.1
        }
    )
    {
        for (const scalar sgn : {1.0, -1.0})
        {
            const quaternion q(sgn*std::cos(a/2), sgn*std::sin(a/2)*n);
            const vector theta(fiber::rotationVectorOf(q));
            worst = max(worst, mag(theta - a*n)/a);
        }
    }
    check
    (
        "fiber.rotationVectorOf.seriesAndAtan2",
        worst < 1e-15,
        fmt(worst, 0, worst)
    );

    // And back: the quaternion of a rotation vector against cos and sin
    // of the half angle, either side of the series' bound (0.1)
    scalar worstQ = 0;
    for
    (
        const scalar a
      : {1e-12, 1e-6, 1e-3, 0.05, 0.0999, 0.1001, 0.3, 1.0, 2.5, 3.1}
    )
    {
        const quaternion q(fiber::rotationQuaternion(a*n));
        worstQ =
            max
            (
                worstQ,
                mag(q.w() - std::cos(a/2)) + mag(q.v() - std::sin(a/2)*n)
            );
    }
    check
    (
        "fiber.rotationQuaternion.seriesAndTrig",
        worstQ < 1e-15,
        fmt(worstQ, 0, worstQ)
    );
}


void testRelaxation()
{
    // One segment at rest released in a uniform flow (physics.md 6):
    // tau_perp = m/(3 pi mu l Y^A); implicit Euler gives exactly
    // v_n/u = 1 - (1 + dt/tau)^-n
    const scalar l = 2e-4, d = 2e-5, rho = 1380, mu = 1.8e-5;
    const vector p(0, 0, 1);
    const vector u(1, 0, 0);
    const spheroidResistance res(coxRe(l/d));
    const scalar m = rho*pi*sqr(d)/4*l;
    const scalar tau = m/(3*pi*mu*l*res.YA);

    check
    (
        "relaxation.tauWorkedExample",
        relErr(tau, 6.32e-3) < 1e-3,
        fmt(tau, 6.32e-3, relErr(tau, 6.32e-3))
    );

    const fiberHydrodynamics hydro(1.2, false, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    const linearFlow flow{u, Zero, Zero, mu};

    for (const scalar z : {1e-2, 1e-1, 1.0, 10.0, 1e2, 1e4, 1e6, 1e8})
    {
        fiber f(fiber::straight(0, Zero, p, 1, l, d, rho));
        const scalar dt = z*tau;
        const label n = max(3, label(std::ceil(1/z)));
        List<fluidSample> s;
        bool bounded = true;
        scalar prev = 0;
        for (label k = 0; k < n; ++k)
        {
            flow.sample(f, s);
            integ->advance(f, s, hydro, Zero, dt);
            const scalar v = f.velocity().x();
            bounded = bounded && v >= prev && v <= 1 + 1e-12
                && mag(f.velocity().y()) + mag(f.velocity().z()) < 1e-12
                && mag(f.omega()) < 1e-12;
            prev = v;
        }
        const scalar vx = f.velocity().x();
        const scalar exactDiscrete = 1 - std::pow(1 + z, -n);
        const scalar errDiscrete = mag(vx - exactDiscrete);
        const scalar exact = 1 - std::exp(-n*z);
        const scalar errExact = mag(vx - exact);

        std::ostringstream nm;
        nm << "relaxation.dtOverTau=" << z;
        check
        (
            nm.str() + ".exactDiscrete",
            errDiscrete < 1e-12,
            fmt(vx, exactDiscrete, errDiscrete)
        );
        check(nm.str() + ".boundedMonotone", bounded, "0 <= v <= u, no spin");
        if (z <= 0.1)
        {
            // first-order error bound |(1+z)^-n - e^-nz| <= n z^2/2
            check
            (
                nm.str() + ".vsAnalytic",
                errExact <= n*sqr(z)/2,
                fmt(vx, exact, errExact)
            );
        }
    }
}


void testGravity()
{
    // One heavy segment settling in quiescent air, oblique to gravity:
    // terminal velocity v = m A^-1 g with
    // A = 6 pi mu a (X^A pp + Y^A (I - pp)), a = l/2; no rotation
    const scalar l = 2e-4, d = 2e-5, rho = 1380, mu = 1.8e-5;
    const vector p(vector(1, 1, 1)/std::sqrt(3.0));
    const vector g(0, -9.81, 0);
    fiber f(fiber::straight(0, Zero, p, 1, l, d, rho));

    const spheroidResistance res(coxRe(l/d));
    const scalar a = l/2;
    const scalar m = rho*pi*sqr(d)/4*l;
    const vector gPar((g & p)*p);
    const vector ref
    (
        m*gPar/(6*pi*mu*a*res.XA) + m*(g - gPar)/(6*pi*mu*a*res.YA)
    );

    const fiberHydrodynamics hydro(1.2, false, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    const linearFlow still{Zero, Zero, Zero, mu};
    List<fluidSample> s;
    for (label k = 0; k < 60; ++k)
    {
        still.sample(f, s);
        integ->advance(f, s, hydro, g, 1e-2);
    }
    const scalar err = mag(f.velocity() - ref)/mag(ref);
    check
    (
        "gravity.terminalVelocityObliqueSegment",
        err < 1e-10 && mag(f.omega()) < 1e-12,
        fmt(mag(f.velocity()), mag(ref), err)
    );
}


void testResponse()
{
    // fiberIntegrator::response: the implicit Euler step of a three-segment
    // fiber in shear with inertial drag and gravity, with a load (a force
    // at a point off the axis) held over it, equals the response's free
    // velocities plus its mobility times the load (the step is linear in
    // the load: its drag is linearized about the start)
    const scalar l = 2e-4, d = 2e-5, rho = 1500, mu = 1e-3;
    const vector g(0, -9.81, 0);
    const vector p(normalised(vector(1, 2, 0.5)));
    fiber f(fiber::straight(0, point(1e-4, 2e-4, 0), p, 3, l, d, rho));
    f.setVelocity(vector(0.01, -0.02, 0.005));
    f.setOmega(vector(3, -1, 20));
    const fiberHydrodynamics hydro(1000, true, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    const linearFlow flow(shear(100, mu));
    List<fluidSample> s;
    flow.sample(f, s);
    const scalar h = 1e-4;
    scalarList mob, vFree;
    fiberIntegrator::response(f, s, hydro, g, h, mob, vFree);

    const vector F(2e-7, -1e-7, 3e-7);
    const point c(f.position() + 0.7*l*p + vector(0, 0, 0.5*d));
    fiberIntegrator::load ld;
    ld.F = F;
    ld.M = c ^ F;
    fiber moved(f);
    integ->advance(moved, s, hydro, g, h, nullptr, &ld);

    scalarList G(6);
    const vector T((c - f.position()) ^ F);
    for (label i = 0; i < 3; ++i)
    {
        G[i] = F[i];
        G[3 + i] = T[i];
    }
    vector V(Zero), w(Zero);
    for (label i = 0; i < 3; ++i)
    {
        V[i] = vFree[i];
        w[i] = vFree[3 + i];
        for (label j = 0; j < 6; ++j)
        {
            V[i] += mob[6*i + j]*G[j];
            w[i] += mob[6*(3 + i) + j]*G[j];
        }
    }
    const scalar err =
        max
        (
            mag(V - moved.velocity())/mag(moved.velocity()),
            mag(w - moved.omega())/mag(moved.omega())
        );
    check("response.implicitEulerStepWithLoad", err < 1e-12, fmt(err, 0, err));
}


void testJefferyAndRigidity()
{
    const scalar L = 1e-3, d = 2e-5, rho = 1380, mu = 1.6, gammaDot = 200;
    const linearFlow flow(shear(gammaDot, mu));
    const fiberHydrodynamics hydro(1260, false, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    const scalar dt = 1e-5;
    const label nSteps = 120000;

    // Tolerance 1e-5: the scheme is first order with gammaDot dt = 2e-3,
    // but the errors of the two symmetric half-turns cancel, leaving
    // O((gammaDot dt)^2) = 4e-6 in the period.

    // One segment: Jeffery with Cox's r_e of the whole fiber
    {
        fiber f(fiber::straight(0, Zero, vector(0, 1, 0), 1, L, d, rho));
        const scalar T = period(f, flow, integ(), hydro, dt, nSteps);
        const scalar re = coxRe(L/d);
        const scalar ref = twoPi*(re + 1/re)/gammaDot;
        check
        (
            "jeffery.analyticShear.oneSegment",
            relErr(T, ref) < 1e-5,
            fmt(T, ref, relErr(T, ref))
        );
    }

    // Five segments: chain period; then rigidity after 1e5+ steps
    {
        const label N = 5;
        const scalar l = L/N;
        fiber f(fiber::straight(0, Zero, vector(0, 1, 0), N, l, d, rho));
        const scalar T = period(f, flow, integ(), hydro, dt, nSteps);
        const scalar ref = chainPeriod(N, L, d, gammaDot);
        check
        (
            "jeffery.analyticShear.chainOfFive",
            relErr(T, ref) < 1e-5,
            fmt(T, ref, relErr(T, ref))
        );

        List<point> pts;
        f.segmentCentres(pts);
        const tensor R(f.R());
        scalar errLen = 0, errAngle = 0;
        for (label i = 0; i + 1 < N; ++i)
        {
            errLen = max(errLen, relErr(mag(pts[i + 1] - pts[i]), l));
            errAngle = max
            (
                errAngle,
                mag
                (
                    (f.segmentDirection(R, i) & f.segmentDirection(R, i + 1))
                  - 1
                )
            );
        }
        const scalar errUnit = mag(mag(f.orientation()) - 1);
        const scalar errOrth = mag((R & R.T()) - tensor::I);
        check
        (
            "rigidity.segmentLengths.120000steps",
            errLen < 1e-12,
            fmt(errLen, 0, errLen)
        );
        check
        (
            "rigidity.relativeAngles.120000steps",
            errAngle < 1e-12,
            fmt(errAngle, 0, errAngle)
        );
        check
        (
            "rigidity.unitOrientation.120000steps",
            errUnit < 1e-12 && errOrth < 1e-12,
            fmt(errUnit, errOrth, errUnit)
        );
    }

    // Stiff steps: the five-segment Jeffery fiber (tau ~ 1e-7 s) with
    // dt/tau up to 1e8 stays finite and bounded by the flow
    {
        const scalar tau = 1e-7;
        for (const scalar z : {1e-2, 1.0, 1e2, 1e4, 1e6, 1e8})
        {
            fiber f
            (
                fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho)
            );
            List<fluidSample> s;
            scalar vMax = 0, wMax = 0;
            for (label k = 0; k < 200; ++k)
            {
                flow.sample(f, s);
                integ->advance(f, s, hydro, Zero, z*tau);
                vMax = max(vMax, mag(f.velocity()));
                wMax = max(wMax, mag(f.omega()));
            }
            // centre at the zero-velocity line: |v| stays ~0; |omega| is
            // at most gammaDot (rotation + strain rate of simple shear)
            std::ostringstream nm;
            nm << "stiff.jefferyFiber.dtOverTau=" << z;
            const bool ok =
                std::isfinite(vMax) && std::isfinite(wMax)
             && vMax < 1e-9*gammaDot*L && wMax <= gammaDot*(1 + 1e-9);
            std::ostringstream det;
            det << "max|v| " << vMax << ", max|omega| " << wMax;
            check(nm.str(), ok, det.str());
        }
    }
}


void testGosmanIoannides()
{
    typedef fiberDispersions::GosmanIoannides GI;

    // Hand-computed values (calculator):
    //   0.09^0.63 = exp(0.63 ln 0.09) = exp(-1.517005728) = 0.2193677501
    //   l_e(k = 1, eps = 10) = 0.2193677501/10 = 0.02193677501 m
    //   t_e(l_e = 0.02, |u'| = 0.5) = 0.04 s
    //   t_tr(l_e = 0.02, tau = 0.01, |slip| = 4) = -0.01 ln(0.5)
    //                                             = 0.006931471806 s
    //   t_tr(l_e = 0.02, tau = 0.01, |slip| = 1): captured (l_e >= 0.01)
    {
        dictionary coeffs;
        const GI gi(coeffs);
        const scalar le = gi.eddyLength(1, 10);
        check
        (
            "dispersion.eddyLengthHand",
            relErr(le, 0.02193677501) < 1e-9,
            fmt(le, 0.02193677501, relErr(le, 0.02193677501))
        );
        const scalar te = GI::eddyLifetime(0.02, 0.5);
        check
        (
            "dispersion.eddyLifetimeHand",
            relErr(te, 0.04) < 1e-14,
            fmt(te, 0.04, relErr(te, 0.04))
        );
        const scalar ttr = GI::transitTime(0.02, 0.01, 4);
        check
        (
            "dispersion.transitTimeHand",
            relErr(ttr, 0.006931471806) < 1e-9,
            fmt(ttr, 0.006931471806, relErr(ttr, 0.006931471806))
        );
        const scalar tc = GI::transitTime(0.02, 0.01, 1);
        check
        (
            "dispersion.transitTimeCaptured",
            tc >= GREAT,
            fmt(tc, GREAT, 0)
        );
    }

    // Fluctuation statistics through the model: k = 1.5 gives
    // u' = psi, zero mean and unit variance per component
    {
        dictionary dict;
        dict.add("dispersion", "GosmanIoannides");
        autoPtr<fiberDispersion> disp(fiberDispersion::New(dict));
        const label nDraw = 200000;
        vector sum(Zero), sumSq(Zero);
        scalar sumXY = 0;
        for (label n = 0; n < nDraw; ++n)
        {
            fiber f
            (
                fiber::straight
                (
                    n % 1000, Zero, vector(0, 0, 1), 1, 2e-4, 2e-5, 1380
                )
            );
            f.nDraws() = n/1000;
            List<fluidSample> s(1, fluidSample(Zero, Zero, 1.8e-5));
            s[0].k = 1.5;
            s[0].epsilon = 10;
            disp->correct(f, s);
            sum += s[0].U;
            sumSq += cmptMultiply(s[0].U, s[0].U);
            sumXY += s[0].U.x()*s[0].U.y();
        }
        const vector mean(sum/nDraw);
        const vector var(sumSq/nDraw - cmptMultiply(mean, mean));
        // 4 standard errors: mean 4/sqrt(N), variance 4 sqrt(2/N)
        const scalar tolMean = 4/std::sqrt(scalar(nDraw));
        const scalar tolVar = 4*std::sqrt(2.0/nDraw);
        std::ostringstream det;
        det << "mean " << mean.x() << " " << mean.y() << " " << mean.z()
            << ", variance " << var.x() << " " << var.y() << " " << var.z()
            << ", <u'v'> " << sumXY/nDraw << "; reference 0 and 2k/3 = 1"
            << " within " << tolMean << " and " << tolVar;
        check
        (
            "dispersion.fluctuationZeroMean",
            cmptMax(cmptMag(mean)) < tolMean,
            det.str()
        );
        check
        (
            "dispersion.fluctuationVariance2kOver3",
            cmptMax(cmptMag(var - vector::one)) < tolVar
         && mag(sumXY/nDraw) < tolMean,
            det.str()
        );
    }

    // Same seed, same eddies; another seed, other eddies
    {
        typedef counterRandom CR;
        const vector a(CR::gaussian(3, 17, 5)), b(CR::gaussian(3, 17, 5));
        const vector c(CR::gaussian(4, 17, 5));
        check
        (
            "dispersion.reproducibleSeed",
            a == b && mag(a - c) > 1e-6,
            "seed 3 twice equal, seed 4 differs"
        );
    }

    // Dispersion in uniform k, epsilon, no mean flow: a fiber with
    // tau << t_e follows the eddies (captured: t_tr infinite), so its
    // velocity is psi sigma held for T = l_e/(|psi| sigma).  Renewal
    // theory gives <x^2>/t -> E[(u_x T)^2]/E[T] per component, with
    // E[(u_x T)^2] = l_e^2/3 and E[T] = l_e sqrt(2/pi)/sigma (chi law of
    // |psi|): D = <x^2>/(2t) = l_e sigma sqrt(pi/2)/6.  Inertia changes
    // the displacement by at most tau |v|, bounded in time.
    {
        dictionary dict;
        dict.add("dispersion", "GosmanIoannides");
        autoPtr<fiberDispersion> disp(fiberDispersion::New(dict));
        dictionary idict;
        idict.add("integrator", "implicitEuler");
        autoPtr<fiberIntegrator> integ(fiberIntegrator::New(idict));
        const fiberHydrodynamics hydro(1.2, false, 1);

        const scalar k = 1, epsilon = 1, mu = 1.8e-5;
        const scalar sigma = std::sqrt(2*k/3);
        dictionary coeffs;
        const scalar le = GI(coeffs).eddyLength(k, epsilon);
        const scalar D = le*sigma*std::sqrt(pi/2)/6;
        const scalar ET = le*std::sqrt(2/pi)/sigma;
        const scalar tEnd = 300*ET;

        const label nFib = 2000;
        scalar sumR2 = 0;
        for (label id = 0; id < nFib; ++id)
        {
            fiber f
            (
                fiber::straight
                (
                    id, Zero, vector(0, 0, 1), 1, 2e-4, 2e-5, 1380
                )
            );
            scalar t = 0;
            List<fluidSample> s(1);
            while (t < tEnd)
            {
                s[0] = fluidSample(Zero, Zero, mu);
                s[0].k = k;
                s[0].epsilon = epsilon;
                const scalar dt = min(disp->correct(f, s), tEnd - t);
                integ->advance(f, s, hydro, Zero, dt);
                disp->elapse(f, dt);
                t += dt;
            }
            sumR2 += magSqr(f.position());
        }
        const scalar Dsim = sumR2/nFib/(6*tEnd);
        // statistical error of a mean of nFib squared displacements in
        // 3 components: relative sqrt(2/(3 nFib)) = 1.8 %; 4 of them
        const scalar tol = 4*std::sqrt(2.0/(3*nFib));
        check
        (
            "dispersion.meanSquareDisplacement",
            relErr(Dsim, D) < tol,
            fmt(Dsim, D, relErr(Dsim, D)) + ", tolerance "
          + std::to_string(tol)
        );
    }
}


// Eddies far shorter than the fiber's relaxation time are merged
// (GosmanIoannides.H).  A heavy fiber (tau about 50 eddy times t_L =
// l_e/sigma) in uniform k, epsilon, no mean flow: its long-time dispersion
// D = <|x|^2>/6t with merged eddies (minEddyRatio 0.1: each stands for 5)
// must equal that with every eddy drawn (minEddyRatio 0, brute force:
// 13 000 eddies per fiber), within 4 standard errors of the difference.  The
// eddies' own rate l_e sigma sqrt(pi/2)/6 is not the reference: eddies
// that end by transit are shorter against the fiber's slip, which slows
// its relaxation (about 1.4 times that rate here); merged eddies without
// that mean give 1.13 times, and the check fails.  Then k -> 0 with
// epsilon finite: eddies of 3e-13 s must not cost a sub-step each: at
// most one per 0.1 tau on average.
void testEddyMerge()
{
    dictionary idict;
    idict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(idict));
    const fiberHydrodynamics hydro(1.2, false, 1);
    const scalar mu = 1.8e-5;
    auto newFiber = [](const label id)
    {
        return fiber
        (
            fiber::straight(id, Zero, vector(0, 0, 1), 1, 2e-4, 2e-5, 1380)
        );
    };
    // run: the fiber over tEnd in uniform k, epsilon; the eddies drawn
    auto run = [&](const fiberDispersion& disp, const scalar k,
        const scalar eps, const scalar tEnd, fiber& f,
        const vector& U = Zero)
    {
        scalar t = 0;
        List<fluidSample> s(1);
        while (t < tEnd && f.nDraws() < 100000)
        {
            s[0] = fluidSample(U, Zero, mu);
            s[0].k = k;
            s[0].epsilon = eps;
            const scalar dt = min(disp.correct(f, s), tEnd - t);
            integ->advance(f, s, hydro, Zero, dt);
            disp.elapse(f, dt);
            t += dt;
        }
        return f.nDraws();
    };
    auto model = [](const scalar ratio)
    {
        dictionary dict, coeffs;
        dict.add("dispersion", "GosmanIoannides");
        coeffs.add("minEddyRatio", ratio);
        dict.add("GosmanIoannidesCoeffs", coeffs);
        return fiberDispersion::New(dict);
    };
    const fiber f0(newFiber(0));
    const scalar tau = f0.segmentMass(0)/(mu*f0.kAp(0));
    const scalar k = 1e-2, epsilon = 21, tEnd = 200*tau;
    const label nFib = 1000;
    scalar D[2], se[2], nEddies[2];
    for (label m = 0; m < 2; ++m)
    {
        autoPtr<fiberDispersion> disp(model(m ? 0.1 : 0));
        scalar s2 = 0, s4 = 0;
        nEddies[m] = 0;
        for (label id = 0; id < nFib; ++id)
        {
            fiber f(newFiber(id));
            nEddies[m] += run(disp(), k, epsilon, tEnd, f);
            s2 += magSqr(f.position());
            s4 += sqr(magSqr(f.position()));
        }
        D[m] = s2/nFib/(6*tEnd);
        se[m] = std::sqrt((s4/nFib - sqr(s2/nFib))/nFib)/(6*tEnd);
    }
    const scalar seDiff = std::sqrt(sqr(se[0]) + sqr(se[1]));
    std::ostringstream det;
    det << "D merged " << D[1] << " (" << nEddies[1]/nFib << " eddies per"
        << " fiber) against every eddy " << D[0] << " (" << nEddies[0]/nFib
        << "), difference " << D[1] - D[0] << ", 4 standard errors "
        << 4*seDiff;
    check("dispersion.mergedEddiesKeepDispersion",
        mag(D[1] - D[0]) < 4*seDiff, det.str());

    // k -> 0: eddies of l_e/sigma = 3e-13 s (k 1e-12, epsilon 1), and
    // eddies the fiber crosses in 6e-9 s (k = epsilon = 1e-15 as
    // kkLOmega's laminar part has them, the fiber at rest in a stream of
    // 3.5 m/s); over 20 tau at most 20/0.1 = 200 eddies on average: bound
    // 2x (fails with 1e5 draws)
    autoPtr<fiberDispersion> disp(model(0.1));
    const List<vector> cases({vector(1e-12, 1, 0), vector(1e-15, 1e-15, 3.5)});
    for (const vector& kEpsU : cases)
    {
        label nMax = 0;
        for (label id = 0; id < 50; ++id)
        {
            fiber f(newFiber(id));
            nMax = max(nMax, run(disp(), kEpsU.x(), kEpsU.y(), 20*tau, f,
                vector(kEpsU.z(), 0, 0)));
        }
        std::ostringstream det;
        det << "k " << kEpsU.x() << ", epsilon " << kEpsU.y() << ", stream "
            << kEpsU.z() << " m/s: at most " << nMax << " eddies per fiber"
            << " over 20 relaxation times (bound 400)";
        check
        (
            kEpsU.z() > 0
          ? "dispersion.mergedEddiesCrossed"
          : "dispersion.mergedEddiesVanishingK",
            nMax <= 400,
            det.str()
        );
    }
}

void testJefferyCorrection()
{
    // jefferyCorrection: the chain's B equals Cox's B of the whole fiber
    // for every N with l/d >= 3 (N <= 16 for L/d = 50), and the simulated
    // period is Jeffery's within 1 % (issue 4, section 5)
    const scalar L = 1e-3, d = 2e-5, rho = 1380, mu = 1.6, gammaDot = 200;
    const scalar re = coxRe(L/d);
    const scalar Bref = (sqr(re) - 1)/(sqr(re) + 1);
    const scalar Tref = twoPi*(re + 1/re)/gammaDot;

    scalar errB = 0;
    for (label N = 1; N <= 16; ++N)
    {
        fiber f(fiber::straight(0, Zero, vector(0, 1, 0), N, L/N, d, rho));
        f.jefferyCorrection();
        errB = max(errB, relErr(f.chainBretherton(), Bref));
    }
    check
    (
        "jefferyCorrection.chainBrethertonN1to16",
        errB < 1e-12,
        fmt(errB, 0, errB)
    );

    const linearFlow flow(shear(gammaDot, mu));
    const fiberHydrodynamics hydro(1260, false, 1);
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    for (const label N : {2, 5, 10, 16})
    {
        fiber f(fiber::straight(0, Zero, vector(0, 1, 0), N, L/N, d, rho));
        f.jefferyCorrection();
        const scalar T = period(f, flow, integ(), hydro, 1e-5, 110000);
        std::ostringstream nm;
        nm << "jefferyCorrection.periodN=" << N;
        check(nm.str(), relErr(T, Tref) < 0.01, fmt(T, Tref, relErr(T, Tref)));
    }
}


//- One step in an analytic flow, sampled where the scheme evaluates its
//  forces (as fiberCloud does)
template<class Flow>
void stepIn
(
    fiber& f,
    const Flow& flow,
    const fiberIntegrator& integ,
    const fiberHydrodynamics& hydro,
    const scalar dt
)
{
    List<point> pts;
    if (integ.predicts())
    {
        integ.predictedCentres(f, dt, pts);
    }
    else
    {
        f.segmentCentres(pts);
    }
    List<fluidSample> s(pts.size());
    forAll(pts, i)
    {
        s[i] = flow(pts[i]);
    }
    integ.advance(f, s, hydro, Zero, dt);
}


struct shearFlow
{
    scalar gammaDot, mu;
    fluidSample operator()(const point& x) const
    {
        tensor G(Zero);
        G.xy() = gammaDot;
        return fluidSample(vector(gammaDot*x.y(), 0, 0), G, mu);
    }
};


//- u = (U0 sin(k y), 0, 0)
struct waveFlow
{
    scalar U0, k, mu;
    fluidSample operator()(const point& x) const
    {
        tensor G(Zero);
        G.xy() = U0*k*std::cos(k*x.y());
        return fluidSample(vector(U0*std::sin(k*x.y()), 0, 0), G, mu);
    }
};


void testOrder()
{
    const wordList schemes({"implicitEuler", "BDF2"});
    const scalarList expected({1, 2});

    forAll(schemes, si)
    {
        dictionary dict;
        dict.add("integrator", schemes[si]);
        autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));

        // (a) Relaxation in uniform flow, error at t = tau against
        //     1 - exp(-1), steps tau/10, tau/20, tau/40
        {
            const scalar l = 2e-4, d = 2e-5, mu = 1.8e-5;
            const fiberHydrodynamics hydro(1.2, false, 1);
            const spheroidResistance res(coxRe(l/d));
            const scalar tau = 1380*pi*sqr(d)/4*l/(3*pi*mu*l*res.YA);
            const linearFlow uni{vector(1, 0, 0), Zero, Zero, mu};
            scalarList err(3);
            forAll(err, k)
            {
                const label n = 10*(1 << k);
                fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, d,
                    1380));
                auto flow = [&](const point& x)
                {
                    return fluidSample(uni.U0, Zero, mu);
                };
                for (label j = 0; j < n; ++j)
                {
                    stepIn(f, flow, integ(), hydro, tau/n);
                }
                err[k] = mag(f.velocity().x() - (1 - std::exp(-1.0)));
            }
            const scalar order = std::log2(err[1]/err[2]);
            std::ostringstream det;
            det << "errors " << err[0] << " " << err[1] << " " << err[2]
                << ", observed order " << order;
            check
            (
                "order." + schemes[si] + ".relaxation",
                mag(order - expected[si]) < 0.25,
                det.str()
            );
        }

        // (a') Stiff relaxation: bounded and settled for dt/tau to 1e8
        {
            const scalar l = 2e-4, d = 2e-5, mu = 1.8e-5;
            const fiberHydrodynamics hydro(1.2, false, 1);
            const spheroidResistance res(coxRe(l/d));
            const scalar tau = 1380*pi*sqr(d)/4*l/(3*pi*mu*l*res.YA);
            bool ok = true;
            scalar worst = 0;
            for (const scalar z : {1.0, 1e2, 1e4, 1e6, 1e8})
            {
                fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, d,
                    1380));
                auto flow = [&](const point& x)
                {
                    return fluidSample(vector(1, 0, 0), Zero, mu);
                };
                for (label j = 0; j < 20; ++j)
                {
                    stepIn(f, flow, integ(), hydro, z*tau);
                    const scalar v = f.velocity().x();
                    ok = ok && std::isfinite(v) && v > -1e-12
                        && v < 1.25;
                    worst = max(worst, v);
                }
                ok = ok && mag(f.velocity().x() - 1) < (z >= 1e2 ? 1e-6 : 1e-2);
            }
            std::ostringstream det;
            det << "largest v/u " << worst << ", settled to u";
            check("stiff." + schemes[si] + ".relaxationDtOverTau1to1e8", ok,
                det.str());
        }

        // (b) Jeffery orbit of one segment, angle at t = 0.02 s against
        //     tan(phi) = r tan(gammaDot t/(r + 1/r))
        {
            const scalar L = 1e-3, d = 2e-5, gammaDot = 200;
            const fiberHydrodynamics hydro(1260, false, 1);
            const shearFlow flow{gammaDot, 1.6};
            const scalar r = coxRe(L/d);
            const scalar tEnd = 0.02;
            const scalar phiRef =
                std::atan2(r*std::sin(gammaDot*tEnd/(r + 1/r)),
                    std::cos(gammaDot*tEnd/(r + 1/r)));
            scalarList err(3);
            forAll(err, k)
            {
                const label n = 100*(1 << k);
                fiber f(fiber::straight(0, Zero, vector(0, 1, 0), 1, L, d,
                    1380));
                for (label j = 0; j < n; ++j)
                {
                    stepIn(f, flow, integ(), hydro, tEnd/n);
                }
                err[k] = mag(shearAngle(f.orientation()) - phiRef);
            }
            const scalar order = std::log2(err[1]/err[2]);
            std::ostringstream det;
            det << "angle errors " << err[0] << " " << err[1] << " "
                << err[2] << " rad, observed order " << order;
            check
            (
                "order." + schemes[si] + ".jefferyAngle",
                mag(order - expected[si]) < 0.25,
                det.str()
            );
        }

        // (c) Five-segment fiber with inertia (air) in a non-uniform flow
        //     u = (U0 sin ky, 0, 0): centre and orientation at 0.05 s
        //     against the same scheme with 16 times smaller steps
        {
            const waveFlow flow{0.5, constant::mathematical::twoPi/0.01,
                1.8e-5};
            const fiberHydrodynamics hydro(1.2, false, 1);
            const scalar tEnd = 0.05;
            auto run = [&](const label n)
            {
                fiber f(fiber::straight(0, point(0, 0.0013, 0),
                    vector(0.6, 0.8, 0), 5, 2e-4, 2e-5, 1380));
                for (label j = 0; j < n; ++j)
                {
                    stepIn(f, flow, integ(), hydro, tEnd/n);
                }
                return f;
            };
            const fiber ref(run(50*16*4));
            scalarList err(3);
            forAll(err, k)
            {
                const fiber f(run(50*(1 << k)));
                err[k] = mag(f.position() - ref.position())/2e-4
                  + mag(f.orientation() - ref.orientation());
            }
            const scalar order = std::log2(err[1]/err[2]);
            std::ostringstream det;
            det << "errors " << err[0] << " " << err[1] << " " << err[2]
                << ", observed order " << order;
            check
            (
                "order." + schemes[si] + ".nonUniformFlow",
                mag(order - expected[si]) < 0.3,
                det.str()
            );
        }
    }
}


void testExtremes()
{
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));

    // Aspect ratio and segment count: whole-fiber L/d from 3 to 1000,
    // 1 to 100 segments (segments with l/d >= 3): the chain turns with its
    // closed-form period and stays rigid
    {
        const scalar d = 2e-5, gammaDot = 200;
        const linearFlow flow(shear(gammaDot, 1.6));
        const fiberHydrodynamics hydro(1260, false, 1);
        struct shape { scalar rc; label N; };
        scalar worst = 0, worstRigid = 0;
        std::ostringstream det;
        for
        (
            const shape& sh
          : List<shape>({{3, 1}, {10, 1}, {10, 3}, {100, 1}, {100, 30},
                {1000, 1}, {1000, 10}, {1000, 100}})
        )
        {
            const scalar L = sh.rc*d;
            fiber f(fiber::straight(0, Zero, vector(0, 1, 0), sh.N, L/sh.N,
                d, 1380));
            const scalar Tref = chainPeriod(sh.N, L, d, gammaDot);
            const scalar dt = Tref/20000;
            const scalar T = period(f, flow, integ(), hydro, dt, 22000);
            const scalar e = relErr(T, Tref);
            worst = max(worst, e);
            List<point> pts;
            f.segmentCentres(pts);
            for (label i = 0; i + 1 < sh.N; ++i)
            {
                worstRigid = max
                (
                    worstRigid,
                    relErr(mag(pts[i + 1] - pts[i]), L/sh.N)
                );
            }
            det << " L/d " << sh.rc << " N " << sh.N << ": " << e << ";";
        }
        check
        (
            "extreme.aspectRatioAndSegments.period",
            worst < 1e-4 && worstRigid < 1e-12,
            "relative period errors" + det.str()
        );
    }

    // Segment Reynolds number 1e-4 to 1e5: a heavy broadside segment
    // falling through still air reaches the terminal velocity of viscous
    // plus inertial drag, m g = A v + (rho C_D d l/2) v^2, a quadratic
    // with one positive root
    {
        const scalar l = 2e-4, d = 2e-5, mu = 1.8e-5, rhoF = 1.2;
        const spheroidResistance res(coxRe(l/d));
        const scalar A = 6*pi*mu*(l/2)*res.YA;
        const scalar c = 0.5*rhoF*d*l;
        const fiberHydrodynamics hydro(rhoF, true, 1);
        const linearFlow still{Zero, Zero, Zero, mu};
        scalar worst = 0;
        std::ostringstream det;
        for (const scalar Re : {1e-4, 1e-2, 1.0, 1e2, 1e4, 1e5})
        {
            const scalar vt = Re*mu/(rhoF*d);
            const scalar m = 1380*pi*sqr(d)/4*l;
            const scalar g = (A*vt + c*sqr(vt))/m;  // gravity giving Re
            fiber f(fiber::straight(0, Zero, vector(1, 0, 0), 1, l, d,
                1380));
            const scalar tau = m/(A + c*vt);
            List<fluidSample> s;
            for (label k = 0; k < 400; ++k)
            {
                still.sample(f, s);
                integ->advance(f, s, hydro, vector(0, -g, 0), 0.1*tau);
            }
            const scalar e = relErr(-f.velocity().y(), vt);
            worst = max(worst, e);
            det << " Re " << Re << ": " << e << ";";
        }
        check
        (
            "extreme.reynolds1e-4to1e5.terminalVelocity",
            worst < 1e-8,
            "relative errors" + det.str()
        );
    }

    // Heavy fiber (density ratio 1e4 in water-like fluid) under gravity:
    // terminal velocity of a single segment (Stokes), oblique
    {
        const scalar l = 2e-4, d = 2e-5, mu = 1e-3, rhoF = 1000;
        const vector p(vector(1, 2, 0)/std::sqrt(5.0));
        fiber f(fiber::straight(0, Zero, p, 1, l, d, 1e4*rhoF));
        const spheroidResistance res(coxRe(l/d));
        const scalar a = l/2, m = 1e7*pi*sqr(d)/4*l;
        const vector g(0, -9.81, 0);
        const vector gp((g & p)*p);
        const vector ref
        (
            m*gp/(6*pi*mu*a*res.XA) + m*(g - gp)/(6*pi*mu*a*res.YA)
        );
        const fiberHydrodynamics hydro(rhoF, false, 1);
        const linearFlow still{Zero, Zero, Zero, mu};
        List<fluidSample> s;
        // tau ~ 1 s: 40 s in steps of 0.01 s
        for (label k = 0; k < 4000; ++k)
        {
            still.sample(f, s);
            integ->advance(f, s, hydro, g, 1e-2);
        }
        const scalar e = mag(f.velocity() - ref)/mag(ref);
        check
        (
            "extreme.heavyFiberDensityRatio1e4.terminalVelocity",
            e < 1e-8,
            fmt(mag(f.velocity()), mag(ref), e)
        );
    }

    // At rest in a fast flow (100 m/s, air), steps of 1e-6 s (0.2 tau ...
    // tau/100): reaches the flow velocity, no overshoot; zero shear and
    // zero velocity: nothing moves; two coincident fibers move identically
    {
        const scalar l = 2e-4, d = 2e-5, mu = 1.8e-5;
        const fiberHydrodynamics hydro(1.2, true, 1);
        const linearFlow fast{vector(100, 0, 0), Zero, Zero, mu};
        fiber a(fiber::straight(0, Zero, vector(0, 1, 0), 5, l, d, 1380));
        fiber b(fiber::straight(1, Zero, vector(0, 1, 0), 5, l, d, 1380));
        List<fluidSample> s;
        scalar vMax = 0;
        for (label k = 0; k < 20000; ++k)
        {
            fast.sample(a, s);
            integ->advance(a, s, hydro, Zero, 1e-5);
            fast.sample(b, s);
            integ->advance(b, s, hydro, Zero, 1e-5);
            vMax = max(vMax, a.velocity().x());
        }
        check
        (
            "extreme.atRestInFastFlow",
            vMax <= 100*(1 + 1e-12) && relErr(a.velocity().x(), 100) < 1e-6,
            fmt(a.velocity().x(), 100, relErr(a.velocity().x(), 100))
        );
        check
        (
            "extreme.coincidentFibers",
            mag(a.position() - b.position()) == 0
         && mag(a.orientation() - b.orientation()) == 0,
            "identical states after 20000 steps"
        );
        fiber c(fiber::straight(0, Zero, vector(0, 1, 0), 5, l, d, 1380));
        const linearFlow none{Zero, Zero, Zero, mu};
        for (label k = 0; k < 100; ++k)
        {
            none.sample(c, s);
            integ->advance(c, s, hydro, Zero, 1e-3);
        }
        check
        (
            "extreme.zeroVelocityZeroShear",
            mag(c.position()) == 0 && mag(c.velocity()) == 0
         && mag(c.omega()) == 0,
            "fiber stays at rest"
        );
    }
}


// * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

// Periodic crossing: fiber::transform moves the whole rigid state with the
// patch transform x' = R x + t (rotational cyclic: 90 degrees about an axis
// through c).  Reference: the transform applied to each segment centre, to
// the velocity, angular velocity and orientation separately.
void testPeriodicTransform()
{
    fiber f
    (
        fiber::straight(0, point(0.3, -0.2, 0.1), vector(1, 2, 3), 5, 0.1,
            0.01, 1000)
    );
    f.setVelocity(vector(0.5, -1, 2));
    f.setOmega(vector(-3, 1, 7));

    const point c(1, 2, 0);
    const tensor R(0, -1, 0, 1, 0, 0, 0, 0, 1);
    const vectorTensorTransform T((c - (R & c)), R, true);

    List<point> before, after;
    f.segmentCentres(before);
    const vector v0(f.velocity()), w0(f.omega()), p0(f.orientation());
    f.transform(T);
    f.segmentCentres(after);

    scalar err = 0;
    forAll(before, i)
    {
        err = max(err, mag(after[i] - T.transformPosition(before[i])));
    }
    err = max(err, mag(f.velocity() - (R & v0)));
    err = max(err, mag(f.omega() - (R & w0)));
    err = max(err, mag(f.orientation() - (R & p0)));
    check("periodicTransform.rotational", err < 1e-12, fmt(err, 0, err));

    // Translational crossing and back: the state returns exactly
    const vectorTensorTransform S(vector(-0.1, 0, 0));
    f.transform(S);
    f.transform(vectorTensorTransform(-S.t()));
    // x = R^T (x' - t)
    f.transform(vectorTensorTransform(-(R.T() & T.t()), R.T(), true));
    f.segmentCentres(after);
    scalar back = 0;
    forAll(before, i)
    {
        back = max(back, mag(after[i] - before[i]));
    }
    back = max(back, mag(f.velocity() - v0) + mag(f.omega() - w0));
    check("periodicTransform.roundTrip", back < 1e-12, fmt(back, 0, back));

    // Two crossings (rotations about different centres, then a shift):
    // the accumulated transform equals applying them in turn
    const point c2(-0.5, 0, 3);
    const tensor R2(1, 0, 0, 0, 0, -1, 0, 1, 0);
    const vectorTensorTransform T2((c2 - (R2 & c2)), R2, true);
    const vectorTensorTransform all
    (
        fiberTracker::after(S, fiberTracker::after(T2, T))
    );
    scalar comp = 0;
    for (const point& x : before)
    {
        const point ref
        (
            S.transformPosition(T2.transformPosition(T.transformPosition(x)))
        );
        comp = max(comp, mag(all.transformPosition(x) - ref));
    }
    check("periodicTransform.composition", comp < 1e-12, fmt(comp, 0, comp));
}


//- Advance f over dt in sub-steps chosen by ctl, as fiberCloud does (equal
//  parts of the time left at the rate asked, then the estimate); returns
//  the number of sub-steps
template<class Flow>
label controlledStep
(
    fiber& f,
    const Flow& flow,
    const fiberIntegrator& integ,
    const fiberHydrodynamics& hydro,
    const subStepControl& ctl,
    const scalar dt
)
{
    List<point> pts;
    List<fluidSample> s;
    scalar tLeft = dt;
    label n = 0;
    while (tLeft > 0)
    {
        f.segmentCentres(pts);
        s.setSize(pts.size());
        forAll(pts, i)
        {
            s[i] = flow(pts[i]);
        }
        const scalar parts = tLeft*ctl.rate(f, s, GREAT);
        const label nParts = max(1, label(std::ceil(parts*(1 - 1e-9))));
        const scalar h = tLeft/nParts;
        integ.advance(f, s, hydro, Zero, h);
        ctl.update(f, s, h);
        tLeft -= h;
        if (tLeft <= 1e-9*h)
        {
            tLeft = 0;
        }
        ++n;
    }
    return n;
}


//- Time of the first full turn of p in the shear plane under ctl, solver
//  steps of dt (linear interpolation within the sub-step); sub-steps in n
template<class Flow>
scalar controlledPeriod
(
    fiber& f,
    const Flow& flow,
    const fiberIntegrator& integ,
    const fiberHydrodynamics& hydro,
    const subStepControl& ctl,
    const scalar dt,
    label& n
)
{
    const scalar phi0 = shearAngle(f.orientation());
    scalar phiPrev = phi0, unwrapped = phi0, t = 0;
    n = 0;
    for (label k = 0; k < 1000000; ++k)
    {
        // one sub-step at a time, so the turn is caught where it happens
        const label m = controlledStep(f, flow, integ, hydro, ctl, dt);
        n += m;
        const scalar phi = shearAngle(f.orientation());
        scalar dphi = phi - phiPrev;
        if (dphi > pi) dphi -= twoPi;
        if (dphi < -pi) dphi += twoPi;
        if (unwrapped + dphi >= phi0 + twoPi)
        {
            return t + dt*(phi0 + twoPi - unwrapped)/dphi;
        }
        unwrapped += dphi;
        phiPrev = phi;
        t += dt;
    }
    return -1;
}


void testStepControl()
{
    const scalar L = 1e-3, d = 2e-5, rho = 1380, mu = 1.6, gammaDot = 200;
    const fiberHydrodynamics hydro(1260, false, 1);
    const shearFlow flow{gammaDot, mu};
    dictionary dict;
    dict.add("integrator", "implicitEuler");
    autoPtr<fiberIntegrator> integ(fiberIntegrator::New(dict));
    // The default: the tolerance control, tolerance 0.1 and maxRotation
    // 0.1 (the stability map below runs at it)
    const subStepControl tol{dictionary()};
    // The tolerance control at 3e-3, the default before ensembles judged
    dictionary fineDict;
    fineDict.add("tolerance", 3e-3);
    const subStepControl fine(fineDict);

    // The paper's rule with its c = 0.1 by default: rate = r_c gammaDot/c
    {
        fiber f(fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho));
        List<fluidSample> s(5, flow(Zero));
        dictionary pd;
        pd.add("subStepControl", "paper");
        const subStepControl paper(pd);
        const scalar rate = paper.rate(f, s, GREAT);
        const scalar ref = (L/d)*gammaDot/0.1;
        check
        (
            "stepControl.paperRuleIsEq22",
            tol.control() == subStepControl::mode::tolerance
         && tol.tolerance() == 0.1
         && tol.maxRotation() == 0.1
         && paper.control() == subStepControl::mode::paper
         && paper.shearStepFactor() == 0.1
         && relErr(rate, ref) < 1e-12,
            fmt(rate, ref, relErr(rate, ref))
        );
    }

    // Jeffery period at tolerance 3e-3: one segment against Jeffery-Cox,
    // five against the chain's closed form (target 1e-5); solver steps of
    // 0.05/gammaDot split by the control
    {
        label nTol = 0;
        fiber f1(fiber::straight(0, Zero, vector(0, 1, 0), 1, L, d, rho));
        const scalar T1 =
            controlledPeriod(f1, flow, integ(), hydro, fine, 0.05/gammaDot,
                nTol);
        const scalar re = coxRe(L/d);
        const scalar ref1 = twoPi*(re + 1/re)/gammaDot;
        check
        (
            "stepControl.tolerance.jefferyPeriod.oneSegment",
            relErr(T1, ref1) < 1e-5,
            fmt(T1, ref1, relErr(T1, ref1)) + ", "
          + std::to_string(nTol) + " sub-steps"
        );

        label n5 = 0, nPaper = 0;
        fiber f5(fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho));
        const scalar T5 =
            controlledPeriod(f5, flow, integ(), hydro, fine, 0.05/gammaDot,
                n5);
        const scalar ref5 = chainPeriod(5, L, d, gammaDot);
        dictionary pd;
        pd.add("subStepControl", "paper");
        pd.add("shearStepFactor", 0.1);
        const subStepControl paper(pd);
        fiber g5(fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho));
        const scalar Tp =
            controlledPeriod(g5, flow, integ(), hydro, paper, 0.05/gammaDot,
                nPaper);
        std::ostringstream det;
        det << fmt(T5, ref5, relErr(T5, ref5)) << ", " << n5
            << " sub-steps (paper's rule, c = 0.1: " << nPaper
            << ", period error " << relErr(Tp, ref5) << ")";
        check
        (
            "stepControl.tolerance.jefferyPeriod.chainOfFive",
            relErr(T5, ref5) < 1e-5,
            det.str()
        );

        // At the default tolerance 0.1: the error follows the tolerance
        // (below), 7.4e-6 at 3e-3 scales to 2.5e-4 at 0.1; within 1e-3
        label nDef = 0;
        fiber h5(fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho));
        const scalar Td =
            controlledPeriod(h5, flow, integ(), hydro, tol, 0.05/gammaDot,
                nDef);
        std::ostringstream detD;
        detD << fmt(Td, ref5, relErr(Td, ref5)) << ", " << nDef
             << " sub-steps (3e-3: " << n5 << ")";
        check
        (
            "stepControl.default.jefferyPeriod.chainOfFive",
            relErr(Td, ref5) < 1e-3,
            detD.str()
        );
    }

    // The error follows the tolerance: angle of one segment at
    // t = 0.02 s against Jeffery's closed form for tol 1e-2 and 1e-3; a
    // first-order scheme with error per unit step gives a ratio of 10
    // (accepted 4 to 25: the step is an integer part of the solver step)
    {
        const scalar r = coxRe(L/d);
        const scalar tEnd = 0.02;
        const scalar phiRef =
            std::atan2(r*std::sin(gammaDot*tEnd/(r + 1/r)),
                std::cos(gammaDot*tEnd/(r + 1/r)));
        scalarList err(2);
        labelList steps(2, Zero);
        const scalarList tols({1e-2, 1e-3});
        forAll(tols, k)
        {
            dictionary td;
            td.add("subStepControl", "tolerance");
            td.add("tolerance", tols[k]);
            const subStepControl ctl(td);
            fiber f(fiber::straight(0, Zero, vector(0, 1, 0), 1, L, d, rho));
            for (label j = 0; j < 20; ++j)
            {
                steps[k] += controlledStep(f, flow, integ(), hydro, ctl,
                    tEnd/20);
            }
            err[k] = mag(shearAngle(f.orientation()) - phiRef);
        }
        std::ostringstream det;
        det << "angle errors " << err[0] << " (" << steps[0] << " steps), "
            << err[1] << " (" << steps[1] << " steps): ratio "
            << err[0]/err[1];
        check
        (
            "stepControl.tolerance.errorFollowsTolerance",
            err[0]/err[1] > 4 && err[0]/err[1] < 25,
            det.str()
        );
    }

    // Stiff: a segment at rest released in uniform flow, solver steps of
    // 1 to 1e8 relaxation times; a new eddy (jump) every fifth solver step.
    // Bounded, monotone, settled, and the control does not collapse: the
    // sub-steps per solver step stay few; both schemes
    for (const word scheme : {"implicitEuler", "BDF2"})
    {
        dictionary sd;
        sd.add("integrator", scheme);
        autoPtr<fiberIntegrator> si(fiberIntegrator::New(sd));
        const scalar l = 2e-4, dd = 2e-5, muA = 1.8e-5;
        const fiberHydrodynamics air(1.2, false, 1);
        const spheroidResistance res(coxRe(l/dd));
        const scalar tau = 1380*pi*sqr(dd)/4*l/(3*pi*muA*l*res.YA);
        bool ok = true;
        label nMax = 0;
        scalar worst = 0;
        for (const scalar z : {1.0, 1e2, 1e4, 1e6, 1e8})
        {
            fiber f(fiber::straight(0, Zero, vector(0, 0, 1), 1, l, dd,
                1380));
            auto uniform = [&](const point&)
            {
                return fluidSample(vector(1, 0, 0), Zero, muA);
            };
            scalar vPrev = 0;
            for (label j = 0; j < 20; ++j)
            {
                if (j % 5 == 4)
                {
                    f.jumped() = true;
                }
                const label n =
                    controlledStep(f, uniform, si(), air, tol, z*tau);
                nMax = max(nMax, n);
                const scalar v = f.velocity().x();
                // BDF2 overshoots a relaxation (2.9 % at most with
                // constant steps, docs/numerics.md); the control's steps
                // here keep it within 0.6 %
                ok = ok && std::isfinite(v)
                    && v >= vPrev - (scheme == "BDF2" ? 6e-3 : 1e-12)
                    && v < (scheme == "BDF2" ? 1.006 : 1 + 1e-12);
                worst = max(worst, v);
                vPrev = v;
            }
            ok = ok && mag(f.velocity().x() - 1) < 1e-6;
        }
        std::ostringstream det;
        det << "largest v/u " << worst << ", settled to u; at most " << nMax
            << " sub-steps in a solver step";
        check
        (
            "stiff.default." + scheme + ".relaxationDtOverTau1to1e8",
            ok && nMax <= 100,
            det.str()
        );
    }

    // Stiff five-segment Jeffery fiber (tau ~ 1e-7 s), solver steps up to
    // 1e8 tau: bounded by the flow as under the paper's rule
    {
        const scalar tau = 1e-7;
        bool ok = true;
        std::ostringstream det;
        for (const scalar z : {1.0, 1e4, 1e8})
        {
            fiber f(fiber::straight(0, Zero, vector(0, 1, 0), 5, L/5, d, rho));
            scalar vMax = 0, wMax = 0;
            label nMax = 0;
            for (label k = 0; k < 20; ++k)
            {
                nMax = max(nMax, controlledStep(f, flow, integ(), hydro, tol,
                    min(z*tau, 0.01)));
                vMax = max(vMax, mag(f.velocity()));
                wMax = max(wMax, mag(f.omega()));
            }
            ok = ok && std::isfinite(vMax) && std::isfinite(wMax)
              && vMax < 1e-9*gammaDot*L && wMax <= gammaDot*(1 + 1e-9);
            det << "dt/tau " << z << ": max|omega| " << wMax << ", "
                << nMax << " sub-steps; ";
        }
        check("stiff.default.jefferyFiber", ok, det.str());
    }
}




// * * * * * * * * * * * * * * * Size distributions  * * * * * * * * * * * //

//- A distribution entry: type and its coefficients
dictionary distributionDict(const word& type, const dictionary& coeffs)
{
    dictionary d;
    d.add("type", type);
    d.add(word(type + "Distribution"), coeffs);
    return d;
}


dictionary rangeDict(const scalar lo, const scalar hi)
{
    dictionary c;
    c.add("minValue", lo);
    c.add("maxValue", hi);
    return c;
}


//- Sample mean and variance of n draws of entry i (0: nSegments, 1:
//  segmentLength, 2: diameter) against the distribution's (4 standard
//  errors; se of the variance from the fourth central moment mu4)
void checkMoments
(
    const std::string& name,
    const fiberSizes& sizes,
    const label i,
    const label n,
    const scalar mean,
    const scalar var,
    const scalar mu4
)
{
    scalar s = 0, s2 = 0;
    List<scalar> x(n);
    for (label k = 0; k < n; ++k)
    {
        const fiberSizes::size sz(sizes.draw(7, k));
        x[k] = (i == 0 ? scalar(sz.n) : i == 1 ? sz.l : sz.d);
        s += x[k];
    }
    const scalar m = s/n;
    for (const scalar xi : x)
    {
        s2 += sqr(xi - m);
    }
    const scalar v = s2/(n - 1);
    const scalar seMean = std::sqrt(var/n);
    const scalar seVar = std::sqrt((mu4 - sqr(var))/n);
    std::ostringstream os;
    os.precision(6);
    os  << n << " draws: mean " << m << " against " << mean << " ("
        << (m - mean)/seMean << " se), variance " << v << " against " << var
        << " (" << (v - var)/seVar << " se)";
    check
    (
        name,
        mag(m - mean) < 4*seMean && mag(v - var) < 4*seVar,
        os.str()
    );
}


void testSizes()
{
    const label n = 40000;

    // Uniform lengths on [a, b]: mean (a+b)/2, variance w^2/12, mu4 w^4/80
    {
        const scalar a = 1e-4, b = 3e-4, w = b - a;
        dictionary d;
        d.add("nSegments", 2);
        d.add("segmentLength", distributionDict("uniform", rangeDict(a, b)));
        d.add("diameter", 2e-5);
        d.add("density", 1000);
        const fiberSizes sizes(d);
        checkMoments
        (
            "sizes.uniformLength", sizes, 1, n, 0.5*(a + b), sqr(w)/12,
            pow4(w)/80
        );
        const fiberSizes::size s1(sizes.draw(3, 11)), s2(sizes.draw(3, 11));
        const fiberSizes::size s3(sizes.draw(3, 12));
        check
        (
            "sizes.sameSeedSameFiber",
            s1.l == s2.l && s1.l != s3.l && s1.n == 2 && s1.d == 2e-5,
            "draw (seed 3, fiber 11) twice equal, fiber 12 differs"
        );
    }

    // OpenFOAM v1912's normal: 'variance' is sqrt(2) sigma; truncated to
    // [min, max] = mu -+ 2 sigma here.  Truncated normal moments, with
    // alpha = -2, beta = 2, Z = Phi(2) - Phi(-2):
    //   mean mu, variance sigma^2 (1 - 2 beta phi(beta)/Z),
    //   mu4 sigma^4 (3 - (2 beta^3 + 6 beta) phi(beta)/Z)
    {
        const scalar mu = 2e-5, sigma = 2e-6;
        dictionary c(rangeDict(mu - 2*sigma, mu + 2*sigma));
        c.add("expectation", mu);
        c.add("variance", std::sqrt(2.0)*sigma);
        dictionary d;
        d.add("nSegments", 1);
        d.add("segmentLength", 2e-4);
        d.add("diameter", distributionDict("normal", c));
        d.add("density", 1000);
        const fiberSizes sizes(d);
        const scalar beta = 2;
        const scalar phi = std::exp(-0.5*sqr(beta))/std::sqrt(twoPi);
        const scalar Z = std::erf(beta/std::sqrt(2.0));
        checkMoments
        (
            "sizes.normalDiameter", sizes, 2, n, mu,
            sqr(sigma)*(1 - 2*beta*phi/Z),
            pow4(sigma)*(3 - (2*pow3(beta) + 6*beta)*phi/Z)
        );
    }

    // A table (general): triangular pdf on [a, b] = c -+ h, mode c:
    // mean c, variance h^2/6, mu4 h^4/15
    {
        const scalar c = 2e-4, h = 1e-4;
        List<Tuple2<scalar, scalar>> table
        ({
            Tuple2<scalar, scalar>(c - h, 0),
            Tuple2<scalar, scalar>(c, 1),
            Tuple2<scalar, scalar>(c + h, 0)
        });
        dictionary coeffs;
        coeffs.add("distribution", table);
        dictionary d;
        d.add("nSegments", 1);
        d.add("segmentLength", distributionDict("general", coeffs));
        d.add("diameter", 2e-5);
        d.add("density", 1000);
        const fiberSizes sizes(d);
        checkMoments
        (
            "sizes.tableLength", sizes, 1, n, c, sqr(h)/6, pow4(h)/15
        );
    }

    // nSegments uniform on [0.5, 5.5), rounded: 1..5 equally likely,
    // mean 3, variance 2, mu4 (1/5) sum (k - 3)^4 = 6.8
    {
        dictionary d;
        d.add("nSegments", distributionDict("uniform", rangeDict(0.5, 5.5)));
        d.add("segmentLength", 2e-4);
        d.add("diameter", 2e-5);
        d.add("density", 1000);
        const fiberSizes sizes(d);
        checkMoments("sizes.roundedSegments", sizes, 0, n, 3, 2, 6.8);
    }

    // A distribution that can give a segment of l/d < 3 is refused
    {
        dictionary d;
        d.add("nSegments", 1);
        d.add
        (
            "segmentLength",
            distributionDict("uniform", rangeDict(5e-5, 3e-4))
        );
        d.add("diameter", 2e-5);
        d.add("density", 1000);
        std::string msg("no error");
        try
        {
            const fiberSizes sizes(d);
        }
        catch (const Foam::IOerror& err)
        {
            msg = err.message();
        }
        check
        (
            "sizes.refusedAspectRatio",
            msg.find("min(segmentLength)/max(diameter)") != std::string::npos,
            msg.substr(0, 80)
        );
    }
}


// * * * * * * * * * * * * What bound the sub-steps  * * * * * * * * * * * //

void testSubStepStatistics()
{
    // Lengths 10^u, u uniform on a grid of 1e5 points in [-9, -3]: the
    // median is 1e-6 and the 10 % quantile 10^-8.4 exactly; the histogram
    // gives each within half a bin (a factor 10^(1/40), 5.9 %).  Limits
    // cycled 0, 1, 2, 3, 4, so each has a fifth; the smallest is the
    // first, 1e-9 (rule).
    subStepStatistics a, b;
    const label n = 100000;
    for (label k = 0; k < n; ++k)
    {
        const scalar u = -9 + 6*(k + 0.5)/n;
        // The own limits' share: a break cut every fifth sub-step to a
        // quarter of what the limits allowed, the others are whole
        (k % 2 ? a : b).add
        (
            k % subStepStatistics::nLimits, std::pow(10, u),
            k % 5 == 4 ? 0.25 : 1
        );
    }
    a += b;
    a.addRebound();
    const scalar half = std::pow(10, 0.5/subStepStatistics::binsPerDecade);
    const scalar eMed = mag(std::log(a.median()/1e-6));
    const scalar eQ = mag(std::log(a.quantile(0.1)/std::pow(10, -8.4)));
    check
    (
        "subStepStatistics.quantilesWithinHalfABin",
        eMed <= std::log(half)*1.0001 && eQ <= std::log(half)*1.0001,
        fmt(a.median(), 1e-6, eMed)
    );
    bool shares = (a.n() == n);
    for (label l = 0; l < subStepStatistics::nLimits; ++l)
    {
        shares = shares && a.n(l) == n/subStepStatistics::nLimits;
    }
    check
    (
        "subStepStatistics.countsByLimit",
        shares && a.nRebounds() == 1,
        fmt(a.n(0), n/subStepStatistics::nLimits, a.n() - n)
    );
    check
    (
        "subStepStatistics.smallest",
        relErr(a.hMin(), std::pow(10, -9 + 3.0/n)) < 1e-12
     && a.hMinLimit() == subStepStatistics::rule,
        fmt(a.hMin(), std::pow(10, -9 + 3.0/n), a.hMinLimit())
    );
    check
    (
        "subStepStatistics.ownLimits",
        relErr(a.nOwn(), 0.8*n + 0.2*n*0.25) < 1e-12,
        fmt(a.nOwn(), 0.85*n, a.nOwn() - 0.85*n)
    );
    a.clear();
    check
    (
        "subStepStatistics.clear",
        a.n() == 0 && a.median() == 0 && a.hMin() == 0 && a.nOwn() == 0,
        fmt(a.n(), 0, a.hMin())
    );
}


// * * * * * * * * * * * * * * Segment distance * * * * * * * * * * * * * * //

//- The least distance of [p1, q1] and [p2, q2] by sampling: a grid of
//  (s, t), then grids of shrinking size around the best point
scalar sampledDistance
(
    const point& p1,
    const point& q1,
    const point& p2,
    const point& q2
)
{
    scalar s0 = 0.5, t0 = 0.5, half = 0.5, best = GREAT;
    for (label level = 0; level < 12; ++level)
    {
        const label n = 40;
        scalar bs = s0, bt = t0;
        for (label i = 0; i <= n; ++i)
        {
            for (label j = 0; j <= n; ++j)
            {
                const scalar s = min(max(s0 - half + 2*half*i/n, 0.0), 1.0);
                const scalar t = min(max(t0 - half + 2*half*j/n, 0.0), 1.0);
                const scalar d =
                    mag((p1 + s*(q1 - p1)) - (p2 + t*(q2 - p2)));
                if (d < best)
                {
                    best = d;
                    bs = s;
                    bt = t;
                }
            }
        }
        s0 = bs;
        t0 = bt;
        half *= 0.2;
    }
    return best;
}


void testSegmentDistance()
{
    struct pairCase
    {
        const char* name;
        point p1, q1, p2, q2;
    };
    const List<pairCase> cases
    ({
        {"crossed", {0, 0, 0}, {1, 0, 0}, {0.5, -0.5, 0.2}, {0.5, 0.5, 0.2}},
        {"skew", {0, 0, 0}, {1, 0.3, 0}, {0.2, 1, 1}, {0.9, -1, 0.5}},
        {"parallel", {0, 0, 0}, {1, 0, 0}, {0.4, 0.1, 0}, {1.8, 0.1, 0}},
        {"parallelDisjoint", {0, 0, 0}, {1, 0, 0}, {1.5, 0.1, 0},
            {2.5, 0.1, 0}},
        {"collinear", {0, 0, 0}, {1, 0, 0}, {0.3, 0, 0}, {0.6, 0, 0}},
        {"endToEnd", {0, 0, 0}, {1, 0, 0}, {1.2, 0, 0}, {2, 0, 0}},
        {"endToEndReversed", {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {1.2, 0, 0}},
        {"touchingEnds", {0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}},
        {"tJunction", {0, 0, 0}, {1, 0, 0}, {0.5, 0.2, 0}, {0.5, 1, 0}},
        {"pointAndSegment", {0.3, 0.4, 0}, {0.3, 0.4, 0}, {0, 0, 0},
            {1, 0, 0}},
        {"twoPoints", {0, 0, 0}, {0, 0, 0}, {0, 3, 4}, {0, 3, 4}},
        {"nearlyParallel", {0, 0, 0}, {1, 0, 0}, {0.2, 0.1, 0},
            {1.2, 0.1 + 1e-9, 0}}
    });
    for (const pairCase& c : cases)
    {
        const segmentDistance::result r =
            segmentDistance::closest(c.p1, c.q1, c.p2, c.q2);
        const scalar ref = sampledDistance(c.p1, c.q1, c.p2, c.q2);
        const scalar got = std::sqrt(r.distSqr);
        // The points on their segments and their distance the one given
        const bool consistent =
            r.s >= 0 && r.s <= 1 && r.t >= 0 && r.t <= 1
         && mag(r.a - (c.p1 + r.s*(c.q1 - c.p1))) < 1e-14
         && mag(r.b - (c.p2 + r.t*(c.q2 - c.p2))) < 1e-14;
        // Nearly parallel (below 1e-7 rad) the pair is taken as parallel,
        // the point in the middle of the overlap: off the least distance
        // by at most half the length times the angle
        const vector u1(c.q1 - c.p1), u2(c.q2 - c.p2);
        const scalar sinA =
            mag(u1) > 0 && mag(u2) > 0
          ? mag(u1 ^ u2)/(mag(u1)*mag(u2)) : 1;
        const scalar tol =
            1e-12 + 1e-9*ref + (sinA < 1e-7 ? 0.5*mag(u2)*sinA : 0);
        check
        (
            std::string("segmentDistance.") + c.name,
            consistent && mag(got - ref) < tol,
            fmt(got, ref, mag(got - ref))
        );
    }

    // Parallel overlapping segments: the point is the middle of the overlap
    {
        const segmentDistance::result r = segmentDistance::closest
        (
            point(0, 0, 0), point(1, 0, 0), point(0.4, 0.1, 0),
            point(1.8, 0.1, 0)
        );
        check
        (
            "segmentDistance.parallelMiddleOfOverlap",
            mag(r.s - 0.7) < 1e-14 && mag(r.a.x() - r.b.x()) < 1e-14,
            fmt(r.s, 0.7, mag(r.s - 0.7))
        );
    }

    // 2000 random pairs (lengths 0 to 1, some nearly parallel)
    Random rnd(3);
    scalar worst = 0;
    for (label k = 0; k < 2000; ++k)
    {
        auto rp = [&rnd]()
        {
            return point
            (
                rnd.sample01<scalar>(), rnd.sample01<scalar>(),
                rnd.sample01<scalar>()
            );
        };
        const point p1(rp());
        const point q1(k % 7 == 0 ? p1 : rp());
        const point p2(rp());
        const point q2(k % 5 == 0 ? p2 + (q1 - p1)*0.7 : rp());
        const scalar got =
            std::sqrt(segmentDistance::closest(p1, q1, p2, q2).distSqr);
        const scalar ref = sampledDistance(p1, q1, p2, q2);
        // The exact minimum is never above a sampled distance
        worst = max(worst, max(got - ref, mag(got - ref) - 1e-9));
    }
    check
    (
        "segmentDistance.random2000",
        worst < 1e-12,
        fmt(worst, 0, worst)
    );
}


// Flexible chains: testFlexibleChain.C
void testFlexibleCantilever();
void testFlexibleElastica();
void testFlexibleTwistAndMoment();
void testFlexibleVibration();
void testFlexibleStiffLimit();
void testFlexibleState();
void testFlexibleSegmentLoads();
void testFlexibleLinks();
void testFlexibleBuckling();
void testFlexibleResponse();
void testContactIslands();
void testSegmentPairSearch();
void testContactLaws();
void testMatStore();
void testMatSheet();


int main()
{
    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    try
    {
        testResistance();
        testBrethertonTorqueBalance();
        testInertialDrag();
        testInertia();
        testFreeRotation();
        testRotationVector();
        testInertialAuto();
        testViscousSwitch();
        testRelaxation();
        testGravity();
        testResponse();
        testGosmanIoannides();
        testEddyMerge();
        testJefferyCorrection();
        testOrder();
        testExtremes();
        testJefferyAndRigidity();
        testPeriodicTransform();
        testStepControl();
        testSizes();
        testSubStepStatistics();
        testSegmentDistance();
        testFlexibleCantilever();
        testFlexibleElastica();
        testFlexibleTwistAndMoment();
        testFlexibleVibration();
        testFlexibleStiffLimit();
        testFlexibleState();
        testFlexibleSegmentLoads();
        testFlexibleLinks();
        testFlexibleBuckling();
        testFlexibleResponse();
        testContactIslands();
        testSegmentPairSearch();
        testMatStore();
        testMatSheet();
        testContactLaws();
    }
    catch (const Foam::error& err)
    {
        Info<< "FAIL: unexpected OpenFOAM error: " << err.message().c_str()
            << endl;
        ++nFail;
    }

    Info<< "Test-fiberModel: " << nPass << " passed, " << nFail << " failed"
        << endl;

    return nFail;
}


// ************************************************************************* //
