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
    Unit tests of the contacts solved per island (contactIslands), without
    fibers: bodies given by their mass, inertia and a linear drag, so that
    their response over an interval is an implicit Euler step in closed
    form.  Part of Test-fiberModel.
    - the law at the end, checked from the bodies' end velocities
      recomputed from the forces (not from the solver's own updates);
    - linear and angular momentum of random islands kept to round-off;
    - a block on an incline: sticks without creep for tan a < mu, slides
      at g (sin a - mu cos a) otherwise (Coulomb exactly);
    - islands solved apart or together, bodies stored in any order: the
      same forces bit for bit.

\*---------------------------------------------------------------------------*/

#include "contactIslands.H"
#include "point.H"
#include "mathematicalConstants.H"
#include "transform.H"
#include "IOstreams.H"

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <sstream>

using namespace Foam;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);
std::string fmt(const scalar a, const scalar b, const scalar err);

namespace
{

//- A rigid body: centre, velocities, mass, inertia (world), drag
struct rigid
{
    point x;
    vector V;
    vector w;
    scalar m;
    tensor I;
    tensor Dt;
    tensor Dr;
};


//- The implicit Euler step of the body over h as an island's body: with
//  A = M/h + D, the mobility A^-1 and the free end velocities
//  A^-1 (M v0/h + m g) (a fluid at rest)
void fill
(
    contactIslands::body& B,
    const rigid& r,
    const vector& g,
    const scalar h
)
{
    Eigen::Matrix<double, 6, 6> A(Eigen::Matrix<double, 6, 6>::Zero());
    Eigen::Matrix<double, 6, 1> b;
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            A(i, j) = (i == j ? r.m/h : 0) + r.Dt(i, j);
            A(3 + i, 3 + j) = r.I(i, j)/h + r.Dr(i, j);
        }
        b(i) = r.m*r.V[i]/h + r.m*g[i];
        b(3 + i) = (r.I & r.w)[i]/h;
    }
    const Eigen::Matrix<double, 6, 6> Ai(A.inverse());
    const Eigen::Matrix<double, 6, 1> v(Ai*b);
    for (label i = 0; i < 6; ++i)
    {
        B.vFree[i] = v(i);
        for (label j = 0; j < 6; ++j)
        {
            B.mobility[6*i + j] = Ai(i, j);
        }
    }
}


//- A random unit vector
vector randomDir(std::mt19937& gen)
{
    std::normal_distribution<double> N(0, 1);
    return normalised(vector(N(gen), N(gen), N(gen)));
}


//- A random island problem: n rigid rods (length L, diameter d) without
//  drag (so momentum is kept), each crossing the next: a chain of
//  contacts, each at the crossing (the normal across both axes, the point
//  on both surfaces, at random along both axes), with random overlaps,
//  springs and velocities
void randomProblem
(
    contactIslands& P,
    List<rigid>& bodies,
    const label n,
    const scalar mu,
    const scalar h,
    std::mt19937& gen,
    const bool tree = false
)
{
    std::uniform_real_distribution<double> U(0, 1);
    const scalar L = 1e-3;
    const scalar d = 2e-5;
    bodies.setSize(n);
    List<vector> axis(n);
    P.clear();
    forAll(bodies, i)
    {
        rigid& r = bodies[i];
        axis[i] = randomDir(gen);
        r.V = 0.01*randomDir(gen);
        r.w = 10*randomDir(gen);
        r.m = 3e-10*(1 + U(gen));
        const tensor ee(sqr(axis[i]));
        r.I = r.m*(sqr(L)/12*(tensor::I - ee) + sqr(d)/8*ee);
        r.Dt = Zero;
        r.Dr = Zero;
        r.x = Zero;
        if (i > 0)
        {
            // B = i crosses A, the last rod or (a tree) any before it
            const label a =
                tree
              ? std::uniform_int_distribution<label>(0, i - 1)(gen)
              : i - 1;
            contactIslands::contact c;
            c.a = a;
            c.b = i;
            c.n = normalised(axis[a] ^ axis[i]);
            c.ra = (U(gen) - 0.5)*L*axis[a] - 0.5*d*c.n;
            c.rb = (U(gen) - 0.5)*L*axis[i] + 0.5*d*c.n;
            r.x = bodies[a].x + c.ra - c.rb;
            c.delta0 = 1e-6*(U(gen) - 0.3);
            c.xi0 = 1e-7*randomDir(gen);
            c.kn = 0.1;
            c.cn = 2*0.2*std::sqrt(r.m*c.kn);
            c.kt = c.kn*2/7;
            c.ct = 2*0.2*std::sqrt(r.m*c.kt);
            c.mu = mu;
            c.fExtra = U(gen) < 0.3 ? -1e-8*c.n : vector(Zero);
            P.addContact(c);
        }
        fill(P.bodyAt(P.addBody(1)), r, Zero, h);
    }
}


//- The bodies' end velocities from the forces alone: v_free plus the
//  mobility times each body's generalized force (an independent check of
//  the solver's own updates)
List<scalarList> endVelocities(const contactIslands& P)
{
    List<scalarList> v(P.nBodies());
    List<scalarList> G(P.nBodies());
    forAll(v, i)
    {
        v[i] = P.bodyAt(i).vFree;
        G[i] = scalarList(v[i].size(), scalar(0));
    }
    for (label ci = 0; ci < P.nContacts(); ++ci)
    {
        const contactIslands::contact& c = P.contactAt(ci);
        const vector Ta(c.ra ^ c.f);
        for (label k = 0; k < 3; ++k)
        {
            G[c.a][6*c.pa + k] += c.f[k];
            G[c.a][6*c.pa + 3 + k] += Ta[k];
        }
        if (c.b >= 0)
        {
            const vector Tb(c.rb ^ c.f);
            for (label k = 0; k < 3; ++k)
            {
                G[c.b][6*c.pb + k] -= c.f[k];
                G[c.b][6*c.pb + 3 + k] -= Tb[k];
            }
        }
    }
    forAll(v, i)
    {
        const label n = v[i].size();
        for (label r = 0; r < n; ++r)
        {
            for (label s = 0; s < n; ++s)
            {
                v[i][r] += P.bodyAt(i).mobility[n*r + s]*G[i][s];
            }
        }
    }
    return v;
}


vector velocityAt(const scalarList& v, const label p, const vector& r)
{
    const label o = 6*p;
    return
        vector(v[o], v[o + 1], v[o + 2])
      + (vector(v[o + 3], v[o + 4], v[o + 5]) ^ r);
}


//- The largest violation of the law at the end, relative to the force
scalar lawResidual(const contactIslands& P, const scalar h)
{
    const List<scalarList> v(endVelocities(P));
    scalar worst = 0;
    for (label ci = 0; ci < P.nContacts(); ++ci)
    {
        const contactIslands::contact& c = P.contactAt(ci);
        vector u(velocityAt(v[c.a], c.pa, c.ra));
        u -= c.b >= 0 ? velocityAt(v[c.b], c.pb, c.rb) : c.vB;
        const vector F(c.f - c.fExtra);
        const scalar fn = F & c.n;
        const vector ft(F - fn*c.n);
        const scalar un = u & c.n;
        const vector ut(u - un*c.n);
        const scalar law = c.kn*(c.delta0 - h*un) - c.cn*un;
        const scalar scale = max(mag(F), c.kn*mag(c.delta0)) + VSMALL;
        scalar err = 0;
        if (fn > 0)
        {
            err = mag(fn - law);
            const vector xi(c.xi0 - (c.xi0 & c.n)*c.n);
            const vector stick(-c.kt*(xi + h*ut) - c.ct*ut);
            if (mag(ft) < c.mu*fn*(1 - 1e-9))
            {
                err = max(err, mag(ft - stick));
            }
            else if (c.mu > 0)
            {
                // Sliding: at the bound, along the force it would take
                // sticking, which exceeds the bound
                err = max(err, mag(mag(ft) - c.mu*fn));
                err = max(err, max(c.mu*fn - mag(stick), 0));
                err = max(err, mag(ft - c.mu*fn*stick/mag(stick)));
            }
        }
        else
        {
            // Apart: no force, and the law would pull
            err = mag(F) + max(law, 0);
        }
        worst = max(worst, err/scale);
    }
    return worst;
}

} // End anonymous namespace


void testContactIslandsLaw()
{
    // Chains of 6 rods, trees of 12 and of 80 (the sparse solve), with and
    // without friction: by default (sweeps, then active sets), by sweeps
    // alone, and by active sets after a single sweep (without friction:
    // with it, the active sets' Newton on the slip direction settles only
    // 19 of these 30 islands within its 10 passes; the sweeps take over)
    std::mt19937 gen(7);
    const scalar h = 1e-4;
    const FixedList<std::string, 3> mode{"default", "sweeps", "activeSets"};
    forAll(mode, k)
    {
        for (const scalar mu : {0.0, 0.3})
        {
            if (k == 2 && mu > 0)
            {
                continue;
            }
            scalar worst = 0;
            label unconverged = 0;
            label iterations = 0;
            for (label trial = 0; trial < 30; ++trial)
            {
                contactIslands P(1e-13, k == 2 ? 1 : 20000, k != 1);
                List<rigid> bodies;
                const label n = trial < 10 ? 6 : trial < 25 ? 12 : 80;
                randomProblem(P, bodies, n, mu, h, gen, trial >= 10);
                P.solve(h);
                worst = max(worst, lawResidual(P, h));
                unconverged += P.stats().unconverged;
                iterations = max(iterations, P.stats().iterations);
            }
            std::ostringstream nm, det;
            nm  << "contactIslands.lawAtEnd." << mode[k] << ".mu" << mu;
            det << "largest residual " << worst << ", most passes and sweeps "
                << iterations << ", unconverged " << unconverged;
            check(nm.str(), worst < 1e-8 && unconverged == 0, det.str());
        }
    }
}


void testContactIslandsMomentum()
{
    // Random islands without drag or gravity: the contacts' forces are
    // equal and opposite at shared points, so m V and x ^ m V + I w summed
    // over the bodies do not change
    std::mt19937 gen(11);
    const scalar h = 1e-4;
    scalar errP = 0;
    scalar errL = 0;
    for (label trial = 0; trial < 20; ++trial)
    {
        contactIslands P;
        List<rigid> bodies;
        randomProblem(P, bodies, 8, 0.5, h, gen);
        P.solve(h);
        vector P0(Zero), P1(Zero), L0(Zero), L1(Zero);
        scalar pScale = 0, lScale = 0;
        forAll(bodies, i)
        {
            const rigid& r = bodies[i];
            const scalarList& v = P.bodyAt(i).vEnd;
            const vector V(v[0], v[1], v[2]);
            const vector w(v[3], v[4], v[5]);
            P0 += r.m*r.V;
            P1 += r.m*V;
            L0 += (r.x ^ (r.m*r.V)) + (r.I & r.w);
            L1 += (r.x ^ (r.m*V)) + (r.I & w);
            pScale += r.m*mag(V - r.V);
            lScale += mag(r.I & (w - r.w)) + mag(r.x)*r.m*mag(V - r.V);
        }
        errP = max(errP, mag(P1 - P0)/pScale);
        errL = max(errL, mag(L1 - L0)/lScale);
    }
    check
    (
        "contactIslands.linearMomentum", errP < 1e-12, fmt(errP, 0, errP)
    );
    check
    (
        "contactIslands.angularMomentum", errL < 1e-12, fmt(errL, 0, errL)
    );
}


namespace
{

//- A block (rotation locked) pressed on a fixed plane by gravity tilted by
//  alpha from the normal: its displacement along the plane from 0.5 s to
//  1 s, and its acceleration there
void incline
(
    const scalar alpha,
    const scalar mu,
    scalar& creep,
    scalar& accel
)
{
    const scalar h = 1e-3;
    const scalar g = 9.81;
    const vector n(0, 1, 0);
    const vector t(1, 0, 0);
    const vector gv(g*std::sin(alpha)*t - g*std::cos(alpha)*n);
    rigid r{Zero, Zero, Zero, 1e-6, 1e-12*tensor::I, Zero, Zero};
    scalar y = 0;
    scalar s = 0;
    scalar sHalf = 0;
    scalar vHalf = 0;
    vector xi(Zero);
    contactIslands P;
    for (label step = 0; step < 1000; ++step)
    {
        P.clear();
        contactIslands::body& B = P.bodyAt(P.addBody(1));
        fill(B, r, gv, h);
        for (label k = 3; k < 6; ++k)
        {
            B.vFree[k] = 0;
            for (label j = 0; j < 6; ++j)
            {
                B.mobility[6*k + j] = 0;
                B.mobility[6*j + k] = 0;
            }
        }
        contactIslands::contact c;
        c.a = 0;
        c.n = n;
        c.delta0 = -y;
        c.xi0 = xi;
        c.kn = 10;
        c.cn = 2*0.3*std::sqrt(r.m*c.kn);
        c.kt = c.kn*2/7;
        c.ct = 2*0.3*std::sqrt(r.m*c.kt);
        c.mu = mu;
        P.addContact(c);
        P.solve(h);
        const scalarList& v = P.bodyAt(0).vEnd;
        r.V = vector(v[0], v[1], v[2]);
        y += h*(r.V & n);
        s += h*(r.V & t);
        xi = P.contactAt(0).xiEnd;
        if (step == 499)
        {
            sHalf = s;
            vHalf = r.V & t;
        }
    }
    creep = s - sHalf;
    accel = ((r.V & t) - vHalf)/0.5;
}

} // End anonymous namespace


void testContactIslandsIncline()
{
    const scalar deg = constant::mathematical::pi/180;
    const scalar mu = 0.5;
    scalar creep = 0, accel = 0;
    incline(20*deg, mu, creep, accel);
    // Diameters of 20 um: less than 1e-3 of one in 0.5 s
    check
    (
        "contactIslands.incline.sticks", mag(creep) < 1e-3*20e-6,
        fmt(creep, 0, creep)
    );
    incline(40*deg, mu, creep, accel);
    const scalar ref = 9.81*(std::sin(40*deg) - mu*std::cos(40*deg));
    const scalar err = mag(accel - ref)/ref;
    check("contactIslands.incline.slides", err < 1e-6, fmt(accel, ref, err));
}


void testContactIslandsOrder()
{
    // Two random islands solved together, each alone, and with the bodies
    // stored in reverse: the same forces bit for bit
    std::mt19937 gen(3);
    const scalar h = 1e-4;
    contactIslands A, B;
    List<rigid> ba, bb;
    randomProblem(A, ba, 5, 0.4, h, gen);
    randomProblem(B, bb, 4, 0.4, h, gen);

    contactIslands AB;
    contactIslands R;
    const label nA = A.nBodies();
    const label nB = B.nBodies();
    for (label i = 0; i < nA; ++i)
    {
        AB.bodyAt(AB.addBody(1)) = A.bodyAt(i);
    }
    for (label i = 0; i < nB; ++i)
    {
        AB.bodyAt(AB.addBody(1)) = B.bodyAt(i);
    }
    for (label i = nA + nB - 1; i >= 0; --i)
    {
        R.bodyAt(R.addBody(1)) = AB.bodyAt(i);
    }
    for (label ci = 0; ci < B.nContacts(); ++ci)
    {
        contactIslands::contact c(B.contactAt(ci));
        c.a += nA;
        c.b += nA;
        AB.addContact(c);
    }
    for (label ci = 0; ci < A.nContacts(); ++ci)
    {
        AB.addContact(A.contactAt(ci));
    }
    for (label ci = 0; ci < AB.nContacts(); ++ci)
    {
        contactIslands::contact c(AB.contactAt(ci));
        c.a = nA + nB - 1 - c.a;
        c.b = nA + nB - 1 - c.b;
        R.addContact(c);
    }
    A.solve(h);
    B.solve(h);
    AB.solve(h);
    R.solve(h);
    label differ = 0;
    for (label ci = 0; ci < AB.nContacts(); ++ci)
    {
        const vector& f = AB.contactAt(ci).f;
        const vector& fAlone =
            ci < B.nContacts()
          ? B.contactAt(ci).f
          : A.contactAt(ci - B.nContacts()).f;
        differ += f != fAlone;
        differ += f != R.contactAt(ci).f;
    }
    check
    (
        "contactIslands.independentOfOthersAndStorage",
        differ == 0 && AB.stats().islands == 2,
        fmt(differ, 0, differ)
    );
}


void testContactIslandsTurned()
{
    // The same island with some bodies given in turned frames (as a
    // partner beyond a rotational periodic patch is): each such body's
    // velocities, mobility and levers in its own frame, turned into the
    // contact's by R.  The forces in the contacts' frame and the end
    // velocities (turned back) must be those of the island as it is
    std::mt19937 gen(11);
    const scalar h = 1e-4;
    contactIslands P;
    List<rigid> bodies;
    randomProblem(P, bodies, 8, 0.5, h, gen, true);
    contactIslands T;
    List<tensor> R(P.nBodies(), tensor::I);
    for (label i = 0; i < P.nBodies(); ++i)
    {
        if (i % 2)
        {
            R[i] = rotationTensor(randomDir(gen), randomDir(gen));
        }
        contactIslands::body B(P.bodyAt(i));
        const tensor& Ri = R[i];
        for (label k = 0; k < 2; ++k)
        {
            const vector v(B.vFree[3*k], B.vFree[3*k + 1], B.vFree[3*k + 2]);
            const vector vt(Ri.T() & v);
            for (label j = 0; j < 3; ++j)
            {
                B.vFree[3*k + j] = vt[j];
            }
        }
        // M' = diag(R^T) M diag(R)
        Eigen::Matrix<double, 6, 6> M, D(Eigen::Matrix<double, 6, 6>::Zero());
        for (label r = 0; r < 6; ++r)
        {
            for (label s = 0; s < 6; ++s)
            {
                M(r, s) = B.mobility[6*r + s];
            }
        }
        for (label r = 0; r < 3; ++r)
        {
            for (label s = 0; s < 3; ++s)
            {
                D(r, s) = Ri(r, s);
                D(3 + r, 3 + s) = Ri(r, s);
            }
        }
        const Eigen::Matrix<double, 6, 6> Mt(D.transpose()*M*D);
        for (label r = 0; r < 6; ++r)
        {
            for (label s = 0; s < 6; ++s)
            {
                B.mobility[6*r + s] = Mt(r, s);
            }
        }
        T.bodyAt(T.addBody(1)) = B;
    }
    for (label ci = 0; ci < P.nContacts(); ++ci)
    {
        contactIslands::contact c(P.contactAt(ci));
        c.Ra = R[c.a];
        c.ra = R[c.a].T() & c.ra;
        c.Rb = R[c.b];
        c.rb = R[c.b].T() & c.rb;
        T.addContact(c);
    }
    P.solve(h);
    T.solve(h);
    scalar fMax = 0, df = 0, dv = 0, vMax = 0;
    for (label ci = 0; ci < P.nContacts(); ++ci)
    {
        fMax = max(fMax, mag(P.contactAt(ci).f));
        df = max(df, mag(P.contactAt(ci).f - T.contactAt(ci).f));
    }
    for (label i = 0; i < P.nBodies(); ++i)
    {
        const scalarList& v = P.bodyAt(i).vEnd;
        const scalarList& w = T.bodyAt(i).vEnd;
        for (label k = 0; k < 2; ++k)
        {
            const vector a(v[3*k], v[3*k + 1], v[3*k + 2]);
            const vector b(w[3*k], w[3*k + 1], w[3*k + 2]);
            vMax = max(vMax, mag(a));
            dv = max(dv, mag(a - (R[i] & b)));
        }
    }
    label sticking = 0;
    for (label ci = 0; ci < P.nContacts(); ++ci)
    {
        sticking += P.contactAt(ci).sticks;
    }
    check
    (
        "contactIslands.turnedFrames",
        df < 1e-9*fMax && dv < 1e-9*vMax && fMax > 0,
        fmt(max(df/fMax, dv/vMax), 0, max(df/fMax, dv/vMax))
      + " (forces and end velocities, 4 of 8 bodies turned, "
      + std::to_string(sticking) + " of 7 contacts sticking)"
    );
}


void testContactIslands()
{
    testContactIslandsLaw();
    testContactIslandsMomentum();
    testContactIslandsIncline();
    testContactIslandsOrder();
    testContactIslandsTurned();
}


// ************************************************************************* //
