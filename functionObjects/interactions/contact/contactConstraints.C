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
    The contacts as constraints solved per island (scheme constraints):
    the pairs of an interval, each once, as contactIslands' contacts.

\*---------------------------------------------------------------------------*/

#include "contact.H"
#include "segmentDistance.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A force on a fiber of this processor at a point, by pair key (summed
//  in the key's order)
struct pointForce
{
    fiberInteractions::contact::pairKey key;
    label local;
    label seg;
    vector F;
    point c;
};

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::fiberInteractions::contact::islandBody
(
    const segment& S,
    const label local,
    const scalar h
)
{
    const auto it = bodyOf_.cfind(local);
    if (it.found())
    {
        return *it;
    }
    const label b = islands_.addBody(S.flexible ? S.nSeg : 1);
    contactIslands::body& B = islands_.bodyAt(b);
    if (!response_ || !response_(local, h, B.mobility, B.vFree))
    {
        FatalErrorInFunction
            << "Entry 'scheme constraints' of 'interactions': fiber "
            << S.fiber << " in contact cannot say how it responds over the"
            << " interval (a segment on another processor's part): the"
            << " constraint form takes serial runs only so far"
            << exit(FatalError);
    }
    bodyOf_.insert(local, b);
    return b;
}


Foam::point Foam::fiberInteractions::contact::ownCentre
(
    const fiber& f,
    const segment& P
)
{
    // The centre P.x stands for: the fiber's, or a flexible fiber's
    // segment's (which moves as a body of its own)
    return
        P.flexible
      ? f.position() + f.segmentOffset(f.R(), P.seg)
      : f.position();
}


Foam::vectorTensorTransform Foam::fiberInteractions::contact::imageOf
(
    const fiber& f,
    const segment& P
) const
{
    // The periodic transform that puts the fiber's centre where the
    // image's is and its segment along the image's (the translation of a
    // periodic patch, or its rotation and translation)
    const vector z(f.segmentDirection(f.R(), P.seg));
    const vector zP(normalised(P.b - P.a));
    const point x(ownCentre(f, P));
    const scalar tol = 1e-9*max(f.length(), mag(P.x));
    for (const vectorTensorTransform& T : periodic_)
    {
        const vector zT(T.hasR() ? (T.R() & z) : z);
        if
        (
            mag(T.transformPosition(x) - P.x) <= tol
         && mag(zT - zP) <= 1e-9
        )
        {
            return T;
        }
    }
    FatalErrorInFunction
        << "Entry 'scheme constraints' of 'interactions': fiber " << P.fiber
        << " has an image at " << P.x << " that no periodic transform of"
        << " the mesh puts there (from " << x << ")"
        << exit(FatalError);
    return vectorTensorTransform::I;
}


bool Foam::fiberInteractions::contact::constraintOf
(
    const segment& A,
    const segment& B,
    const scalar h,
    contactIslands::contact& c,
    point& cp,
    bool& touching,
    bool& close
)
{
    // The pair from the lower fiber id (A), as pairForce sees it
    const pairGeometry g(geometry(A, B));
    const scalar delta = g.delta;
    const bool owns = g.owns;
    const vector& n = g.n;
    touching = g.touching;
    close = g.close;
    cp = g.c;

    // A pair that could touch within the interval at the speeds it has
    // (twice over), or that attracts: a constraint (the law pushes only
    // where the end overlap would be positive)
    const vector vA(A.v + (A.w ^ (cp - A.x)));
    const vector vB(B.v + (B.w ^ (cp - B.x)));
    if (!owns || !(delta + 2*h*mag(vA - vB) > 0 || touching))
    {
        return false;
    }
    const scalar m =
        A.m > 0 && B.m > 0 ? A.m*B.m/(A.m + B.m) : max(A.m, B.m);
    // The dashpots act on a pair that touches at the start; on one apart
    // at the start only the spring on the end overlap (a dashpot there
    // would push across the gap before the pair touches)
    const scalar damped = delta > 0 ? 1 : 0;
    c.n = n;
    c.delta0 = delta;
    c.kn = kn_;
    c.cn = damped*2*zeta_*std::sqrt(m*kn_);
    c.kt = ktRatio_*kn_;
    c.ct = damped*2*zeta_*std::sqrt(m*c.kt);
    c.mu = mu_;
    c.fExtra =
        !(cohesion_ > 0) || !touching ? vector(Zero)
      : delta > 0 ? -cohesion_*n
      : -cohesion_*(1 + delta/range_)*n;
    return true;
}


void Foam::fiberInteractions::contact::constrain
(
    const PtrList<fiber>& fibers,
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar h,
    springTable& next,
    UList<fiberIntegrator::load>& loads,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    // Each pair once, from the side of the lower fiber id, where that
    // fiber is this processor's (a partner beyond a periodic patch is an
    // image of one of its fibers: serial, so every fiber is here)
    Map<label> localOf(2*fibers.size());
    forAll(fibers, fi)
    {
        localOf.insert(fibers[fi].id(), fi);
    }
    islands_.clear();
    bodyOf_.clear();
    islandPairs_.clear();
    for (const FixedList<label, 2>& ij : cand)
    {
        const segment& Q = segs[ij[0]];
        const segment& P = segs[ij[1]];
        // (a flexible fiber against itself, where the search lets its
        // segments touch: once, from the lower segment)
        if
        (
            Q.fiber > P.fiber || Q.local < 0
         || (Q.fiber == P.fiber && !(Q.seg < P.seg))
        )
        {
            continue;
        }
        contactIslands::contact c;
        point cp;
        bool isTouching = false;
        bool isClose = false;
        const bool acts =
            constraintOf(Q, P, h, c, cp, isTouching, isClose);
        if (isClose)
        {
            close.append(FixedList<label, 2>{Q.fiber, P.fiber});
            close.append(FixedList<label, 2>{P.fiber, Q.fiber});
        }
        if (isTouching)
        {
            touching.append(FixedList<label, 2>{Q.fiber, P.fiber});
            touching.append(FixedList<label, 2>{P.fiber, Q.fiber});
        }
        if (!acts || !(Q.m > 0 || P.m > 0))
        {
            continue;
        }
        // A partner beyond a periodic patch: its fiber's frame turns into
        // the image's by the patch's rotation R, x_fiber = R^T (x - x_P)
        // + the fiber's centre
        const label pLocal = P.local >= 0 ? P.local : localOf[P.fiber];
        const fiber& fP = fibers[pLocal];
        const tensor R
        (
            P.local >= 0 ? tensor::I : imageOf(fP, P).R()
        );
        const pairKey k{Q.fiber, Q.seg, P.fiber, P.seg};
        addConstraint(Q, P, pLocal, R, h, cp, c);
        islandPairs_.append
        (
            constraintPair
            {
                k, cp, Q.local, pLocal, R,
                ownCentre(fP, P) - (R.T() & P.x), Q.m > 0
            }
        );
    }
    islands_.solve(h);
    const contactIslands::statistics& st = islands_.stats();
    if (st.unconverged > 0 && !warnedUnsettled_)
    {
        // Said once: the forces of the last sweep are used
        warnedUnsettled_ = true;
        WarningInFunction
            << "Contacts as constraints: " << st.unconverged << " of "
            << st.islands << " islands did not settle within 500 sweeps"
            << " (largest residual of the law " << st.residual << "); the"
            << " forces of the last sweep are used.  Said once per run"
            << endl;
    }
    applyConstraints(fibers, next, loads);
}


void Foam::fiberInteractions::contact::addConstraint
(
    const segment& Q,
    const segment& P,
    const label pLocal,
    const tensor& R,
    const scalar h,
    const point& cp,
    contactIslands::contact& c
)
{
    const pairKey k{Q.fiber, Q.seg, P.fiber, P.seg};
    // The tangential spring of the pair (the lower id's), turned into the
    // contact plane with its length kept
    pairKey from(k);
    vector xi(previousSpring(k, from));
    const scalar len = mag(xi);
    xi -= (xi & c.n)*c.n;
    if (mag(xi) > 0)
    {
        xi *= len/mag(xi);
    }

    // The island's A is the moving side: the lower id, or its partner
    // where the lower id is fixed (then the normal, spring and force
    // turn).  A partner beyond a periodic patch (an image) moves as its
    // fiber, turned by R: its lever from the image's centre turned back
    // into the fiber's frame
    const bool qMoves = Q.m > 0;
    const segment& A = qMoves ? Q : P;
    const segment& B = qMoves ? P : Q;
    const scalar sgn = qMoves ? 1 : -1;
    c.a = islandBody(A, qMoves ? Q.local : pLocal, h);
    c.pa = A.flexible ? A.seg : 0;
    c.ra = cp - A.x;
    c.b = B.m > 0 ? islandBody(B, qMoves ? pLocal : Q.local, h) : -1;
    c.pb = B.flexible ? B.seg : 0;
    c.rb = cp - B.x;
    c.vB = B.v + (B.w ^ c.rb);
    if (qMoves)
    {
        c.Rb = R;
        c.rb = R.T() & c.rb;
    }
    else
    {
        c.Ra = R;
        c.ra = R.T() & c.ra;
    }
    c.n *= sgn;
    c.fExtra *= sgn;
    c.xi0 = sgn*xi;
    islands_.addContact(c);
}


void Foam::fiberInteractions::contact::applyConstraints
(
    const PtrList<fiber>& fibers,
    springTable& next,
    UList<fiberIntegrator::load>& loads
)
{
    // The force on the lower id (Q) of each pair, -f on its partner at the
    // same point (an image's fiber: both turned back into its frame),
    // summed in the keys' order; the springs at the end under both keys
    DynamicList<pointForce> parts;
    forAll(islandPairs_, i)
    {
        const constraintPair& cp = islandPairs_[i];
        const contactIslands::contact& c = islands_.contactAt(i);
        const pairKey& k = cp.key;
        const vector fQ(cp.qMoves ? c.f : -c.f);
        const vector xi(cp.qMoves ? c.xiEnd : -c.xiEnd);
        const pairKey kr{k[2], k[3], k[0], k[1]};
        next.set(k, xi);
        next.set(kr, cp.R.T() & xi);
        if (cp.qMoves)
        {
            parts.append(pointForce{k, cp.q, k[1], fQ, cp.c});
        }
        if (c.b >= 0 || !cp.qMoves)
        {
            parts.append
            (
                pointForce
                {
                    kr, cp.p, k[3], -(cp.R.T() & fQ),
                    (cp.R.T() & cp.c) + cp.shift
                }
            );
        }
    }
    std::sort
    (
        parts.begin(), parts.end(),
        [](const pointForce& a, const pointForce& b)
        {
            return a.key < b.key;
        }
    );
    for (const pointForce& p : parts)
    {
        // The interval resolves the contact (its law holds at the end of
        // the fiber's implicit Euler step of the interval): marked as
        // under contact, the sub-steps skip their error estimate, as
        // under implicit springs (zero springs: the step is unchanged)
        loads[p.local].addForce(fibers[p.local], p.seg, p.F, p.c);
        loads[p.local].implicit = true;
    }
}


// ************************************************************************* //
