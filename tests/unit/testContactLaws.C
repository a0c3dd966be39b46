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
    Unit tests of the contact laws (fiberContactLaw, linear), against a
    head-on collision integrated here (m x'' = -F_spring(x) - c x', fourth
    order Runge-Kutta at a thousandth of the contact time, global error
    about (omega h)^4 ~ 1e-10, tolerance 1e-8): it must end
    (the overlap back to zero) at the law's contact time and leave with
    the restitution; cohesion's closed form; an unknown law refused.
    Part of Test-fiberModel.

\*---------------------------------------------------------------------------*/

#include "fiberContactLaw.H"
#include "IStringStream.H"

#include <cmath>
#include <sstream>

using namespace Foam;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);
std::string fmt(const scalar a, const scalar b, const scalar err);

namespace
{

//- A head-on collision of reduced mass m at speed v0 under the law: the
//  time until the overlap is zero again and the speed then
void collide
(
    const fiberContactLaw& law,
    const scalar m,
    const scalar v0,
    scalar& tEnd,
    scalar& vEnd
)
{
    const scalar h = 1e-3*law.contactTime(m);
    // (the law over the whole step, also at the stages just beyond the
    // overlap's ends: the contact lasts from zero overlap to zero overlap)
    auto acc = [&](const scalar x, const scalar v)
    {
        return (-law.springForce(x) - law.normalDamping(m, x)*v)/m;
    };
    // One fourth-order Runge-Kutta step of dt from (x, v)
    auto rk4 = [&](scalar& x, scalar& v, const scalar dt)
    {
        const scalar k1x = v;
        const scalar k1v = acc(x, v);
        const scalar k2x = v + 0.5*dt*k1v;
        const scalar k2v = acc(x + 0.5*dt*k1x, k2x);
        const scalar k3x = v + 0.5*dt*k2v;
        const scalar k3v = acc(x + 0.5*dt*k2x, k3x);
        const scalar k4x = v + dt*k3v;
        const scalar k4v = acc(x + dt*k3x, k4x);
        x += dt/6*(k1x + 2*k2x + 2*k3x + k4x);
        v += dt/6*(k1v + 2*k2v + 2*k3v + k4v);
    };
    scalar x = 0;
    scalar v = v0;
    scalar t = 0;
    while (t < 10*law.contactTime(m))
    {
        scalar xn = x;
        scalar vn = v;
        rk4(xn, vn, h);
        if (xn <= 0 && t > 0)
        {
            // Back at zero overlap within this step: Newton on the step
            // from its start (dx/dt = v)
            scalar dt = h*x/(x - xn);
            for (label it = 0; it < 20; ++it)
            {
                xn = x;
                vn = v;
                rk4(xn, vn, dt);
                dt -= xn/vn;
            }
            tEnd = t + dt;
            vEnd = vn;
            return;
        }
        x = xn;
        v = vn;
        t += h;
    }
    tEnd = GREAT;
    vEnd = 0;
}

} // End anonymous namespace


void testContactLaws()
{
    const scalar m = 2.4e-10;
    for (const scalar e : {0.1, 0.5, 0.9, 1.0})
    {
        std::ostringstream src;
        src << "stiffness 0.1; restitution " << e << "; friction 0.5;"
            << " cohesion { strength 2e-7; range 2e-6; }";
        const dictionary dict(IStringStream(src.str())());
        autoPtr<fiberContactLaw> law(fiberContactLaw::New(dict));
        scalar tEnd = 0;
        scalar vEnd = 0;
        collide(law(), m, 1e-3, tEnd, vEnd);
        const scalar tc = law->contactTime(m);
        const scalar errT = mag(tEnd - tc)/tc;
        const scalar errE = mag(-vEnd/1e-3 - e);
        std::ostringstream nm;
        nm << "contactLaw.linear.e" << e;
        check
        (
            nm.str() + ".contactTime", errT < 1e-8, fmt(tEnd, tc, errT)
        );
        check
        (
            nm.str() + ".restitution", errE < 1e-8, fmt(-vEnd/1e-3, e, errE)
        );
    }

    // Cohesion: the strength touching, falling linearly to zero at range
    {
        const dictionary dict
        (
            IStringStream
            (
                "stiffness 0.1; restitution 0.5;"
                " cohesion { strength 2e-7; range 2e-6; }"
            )()
        );
        autoPtr<fiberContactLaw> law(fiberContactLaw::New(dict));
        const scalar err =
            mag(law->cohesion(1e-7) - 2e-7)
          + mag(law->cohesion(-0.5e-6) - 1.5e-7)
          + mag(law->cohesion(-2e-6)) + mag(law->cohesion(-3e-6));
        check("contactLaw.cohesion.linearRamp", err < 1e-20, fmt(err, 0, err));
    }

    // An unknown law: refused, naming the entry
    {
        const dictionary dict
        (
            IStringStream("law hertz; stiffness 0.1; restitution 0.5;")()
        );
        bool refused = false;
        std::string what;
        try
        {
            autoPtr<fiberContactLaw> law(fiberContactLaw::New(dict));
        }
        catch (const Foam::IOerror& err)
        {
            refused = true;
            what = err.message();
            for (char& c : what)
            {
                c = (c == '\n' ? ' ' : c);
            }
        }
        check
        (
            "contactLaw.unknownRefused",
            refused && what.find("law") != std::string::npos,
            what.substr(0, 60)
        );
    }
}


// ************************************************************************* //
