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
    contact: the search for pairs (segments, periodic images, the segments
    of other processors within reach, the grid).

\*---------------------------------------------------------------------------*/

#include "contact.H"
#include "openfoamCompat.H"
#include "fiberTracker.H"
#include "periodicImages.H"
#include "PstreamBuffers.H"
#include "segmentDistance.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
typedef fiberInteractions::contact::segment segment;

//- Scalars per segment in a processor's message (packSegment)
const label nPacked = 59;

//- Segment s into buf from position k on (labels and bools as exact
//  scalars): one contiguous block per message, not a stream of tokens
void packSegment(const segment& s, UList<scalar>& buf, label& k)
{
    const auto put = [&buf, &k](const vector& v)
    {
        buf[k++] = v.x();
        buf[k++] = v.y();
        buf[k++] = v.z();
    };
    buf[k++] = s.fiber;
    buf[k++] = s.seg;
    buf[k++] = s.nSeg;
    put(s.a);
    put(s.b);
    buf[k++] = s.d;
    put(s.zPrev);
    buf[k++] = s.s0;
    buf[k++] = s.flexible;
    put(s.x);
    put(s.v);
    put(s.w);
    buf[k++] = s.m;
    put(s.sX);
    put(s.sTheta);
    put(s.sV);
    put(s.sW);
    buf[k++] = s.sTau;
    buf[k++] = s.H;
    put(s.dX);
    put(s.dTheta);
    put(s.u);
    buf[k++] = s.gradU;
    buf[k++] = s.slip;
    buf[k++] = s.slack;
    buf[k++] = s.tauLo;
    buf[k++] = s.tauHi;
    buf[k++] = s.g;
    buf[k++] = s.wall;
    buf[k++] = s.later;
    buf[k++] = s.was;
    buf[k++] = s.proc;
    buf[k++] = s.turn;
}


//- The segment packed at position k of buf (another processor's)
void unpackSegment(const UList<scalar>& buf, label& k, segment& s)
{
    const auto get = [&buf, &k]()
    {
        const vector v(buf[k], buf[k + 1], buf[k + 2]);
        k += 3;
        return v;
    };
    s.fiber = label(buf[k++]);
    s.seg = label(buf[k++]);
    s.nSeg = label(buf[k++]);
    s.a = get();
    s.b = get();
    s.d = buf[k++];
    s.zPrev = get();
    s.s0 = buf[k++];
    s.flexible = buf[k++] != 0;
    s.x = get();
    s.v = get();
    s.w = get();
    s.m = buf[k++];
    s.sX = get();
    s.sTheta = get();
    s.sV = get();
    s.sW = get();
    s.sTau = buf[k++];
    s.H = buf[k++];
    s.dX = get();
    s.dTheta = get();
    s.u = get();
    s.gradU = buf[k++];
    s.slip = buf[k++];
    s.slack = buf[k++];
    s.tauLo = buf[k++];
    s.tauHi = buf[k++];
    s.g = buf[k++];
    s.wall = buf[k++];
    s.later = buf[k++] != 0;
    s.was = buf[k++] != 0;
    s.proc = label(buf[k++]);
    s.turn = label(buf[k++]);
    s.local = -1;
}


//- The segment moved by T, the mesh's periodic transform turn (an image
//  across periodic patches)
segment image
(
    const segment& s,
    const vectorTensorTransform& T,
    const label turn
)
{
    segment i(s);
    i.turn = turn;
    i.a = T.transformPosition(s.a);
    i.b = T.transformPosition(s.b);
    i.x = T.transformPosition(s.x);
    if (T.hasR())
    {
        const tensor& R = T.R();
        i.zPrev = R & s.zPrev;
        i.v = R & s.v;
        i.w = R & s.w;
        i.sX = R & s.sX;
        i.sTheta = R & s.sTheta;
        i.sV = R & s.sV;
        i.sW = R & s.sW;
        i.dX = R & s.dX;
        i.dTheta = R & s.dTheta;
        i.u = R & s.u;
    }
    i.local = -1;
    return i;
}


//- The bounding box of a segment's axis, grown by r
boundBox segmentBox(const segment& s, const scalar r)
{
    boundBox bb(min(s.a, s.b), max(s.a, s.b));
    bb.min() -= vector::uniform(r);
    bb.max() += vector::uniform(r);
    return bb;
}


//- A lower bound on the distance of the segments ab and cd, without their
//  closest points: the largest of the centres' distance less the half
//  lengths, the gap of their boxes along any axis, and the distance of
//  their lines (most candidate pairs cross at an angle)
scalar axesApart
(
    const point& a,
    const point& b,
    const point& c,
    const point& d
)
{
    const vector dc(0.5*(a + b - c - d));
    const vector hAB(0.5*(b - a));
    const vector hCD(0.5*(d - c));
    scalar low = mag(dc) - mag(hAB) - mag(hCD);
    const vector box(cmptMag(dc) - cmptMag(hAB) - cmptMag(hCD));
    low = max(low, cmptMax(box));
    const vector n(hAB ^ hCD);
    const scalar nn = magSqr(n);
    if (nn > SMALL*magSqr(hAB)*magSqr(hCD))
    {
        low = max(low, mag(dc & n)/std::sqrt(nn));
    }
    return low;
}


//- Of two axes whose ends (p: A's two, then B's) move straight at their
//  velocities v from time 0, surfaces touching at a distance touch: the
//  time of their closest approach in (0, h) where they touch then but are
//  apart at 0 and at h (a graze), h where there is none (touches: set
//  where they touch at 0 or at h).  Golden section
//  to a thousandth of h on the gap (convex in time for rigid
//  translations, close to it over an interval)
scalar grazeTime
(
    const FixedList<point, 4>& p,
    const FixedList<vector, 4>& v,
    const scalar touch,
    const scalar h,
    bool* touches = nullptr
)
{
    const auto gap = [&](const scalar t)
    {
        const segmentDistance::result r =
            segmentDistance::closest
            (
                p[0] + t*v[0], p[1] + t*v[1], p[2] + t*v[2], p[3] + t*v[3]
            );
        return mag(r.a - r.b) - touch;
    };
    const scalar g0 = gap(0);
    const scalar gh = g0 > 0 ? gap(h) : 0;
    if (!(gh > 0))
    {
        // Touching at the start or at the end: seen there
        if (touches)
        {
            *touches = true;
        }
        return h;
    }

    // Points of the axes move at most at the largest relative speed of
    // two ends: the gap stays above (g0 + gh - vMax h)/2
    const scalar vMax =
        max
        (
            max(mag(v[0] - v[2]), mag(v[0] - v[3])),
            max(mag(v[1] - v[2]), mag(v[1] - v[3]))
        );
    if (g0 + gh > vMax*h)
    {
        return h;
    }

    // The closest approach: golden section to a thousandth of h
    const scalar phi = 0.5*(std::sqrt(5.0) - 1);
    scalar lo = 0, hi = h;
    scalar t1 = hi - phi*(hi - lo), t2 = lo + phi*(hi - lo);
    scalar f1 = gap(t1), f2 = gap(t2);
    while (hi - lo > 1e-3*h)
    {
        if (f1 < f2)
        {
            hi = t2;
            t2 = t1;
            f2 = f1;
            t1 = hi - phi*(hi - lo);
            f1 = gap(t1);
        }
        else
        {
            lo = t1;
            t1 = t2;
            f1 = f2;
            t2 = lo + phi*(hi - lo);
            f2 = gap(t2);
        }
        if (min(f1, f2) < 0)
        {
            break;
        }
    }
    return f1 < f2 ? (f1 < 0 ? t1 : h) : (f2 < 0 ? t2 : h);
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::contact::findPeriodic()
{
    label nBase = 0;
    periodic_ = periodicImages::transforms(mesh_, nBase);
    if (periodic_.size())
    {
        Info<< "    Fiber contacts across " << nBase
            << " periodic transforms (" << periodic_.size()
            << " images with their compositions)" << endl;
    }
}


Foam::scalar Foam::fiberInteractions::contact::reach
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles
) const
{
    scalar r = 0;
    forAll(fibers, fi)
    {
        if (roles[fi] == role::absent)
        {
            continue;
        }
        const fiber& f = fibers[fi];
        for (label i = 0; i < f.nSegments(); ++i)
        {
            r = max(r, f.segmentLength(i) + f.segmentDiameter(i));
        }
    }
    return returnReduce(r, maxOp<scalar>()) + range_;
}


void Foam::fiberInteractions::contact::localSegments
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    DynamicList<segment>& segs,
    const UList<fiberIntegrator::load>* loads,
    const UList<flow>* flows
) const
{
    const fiberIntegrator::load none;
    forAll(fibers, fi)
    {
        if (roles[fi] == role::absent)
        {
            continue;
        }
        const fiber& f = fibers[fi];
        const fiberIntegrator::load& lf = loads ? (*loads)[fi] : none;
        const tensor R(f.R());
        const bool flex = f.flexible();
        vector zPrev(f.segmentDirection(R, 0));
        scalar s0 = 0;
        for (label i = 0; i < f.nSegments(); ++i)
        {
            // A flexible fiber's segment moves as a body of its own (with
            // its own load and record of its motion)
            const fiberIntegrator::load& l =
                !flex ? lf : lf.seg.size() ? lf.seg[i] : none;
            const point c(f.position() + f.segmentOffset(R, i));
            const vector z(f.segmentDirection(R, i));
            const vector half((0.5*f.segmentLength(i))*z);
            const vector v(flex ? f.segmentVelocity(R, i) : f.velocity());
            const vector w(f.segmentOmega(i));

            // The flow at the segment's centre (linear about the fiber's)
            // and the slip of the segment's centre from it
            vector u(Zero);
            scalar gradU = 0;
            scalar slip = 0;
            flow fl{Zero, Zero, 0, GREAT, GREAT, 0, GREAT, false, true};
            if (flows)
            {
                fl = (*flows)[fi];
                u = fl.U + (fl.G & (c - f.position()));
                gradU = mag(fl.G);
                slip = mag((flex ? v : v + (w ^ (c - f.position()))) - u);
            }
            segs.append
            (
                segment
                {
                    f.id(), i, f.nSegments(), c - half, c + half,
                    f.segmentDiameter(i), zPrev, s0, flex,
                    flex ? c : f.position(), v, w,
                    roles[fi] == role::fixed ? 0 : f.mass(), fi,
                    l.sX, l.sTheta, l.sV, l.sW, l.sTau, l.H, l.dX, l.dTheta,
                    u, gradU, slip, fl.slack, fl.tauLo, fl.tauHi, fl.g,
                    fl.wall, fl.later, fl.engaged, Pstream::myProcNo(), -1
                }
            );
            zPrev = z;
            s0 += f.segmentLength(i);
        }
    }
}


Foam::scalar Foam::fiberInteractions::contact::gather
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    DynamicList<segment>& segs,
    const UList<fiberIntegrator::load>* loads,
    const scalar skin,
    const UList<flow>* flows
) const
{
    localSegments(fibers, roles, segs, loads, flows);
    const scalar r = reach(fibers, roles) + skin;
    addImages(segs, r);
    addGhosts(segs, r);
    return r;
}


Foam::scalar Foam::fiberInteractions::contact::slideLimit
(
    const segment& A,
    const segment& B,
    const vector& n,
    const scalar delta,
    const vector& vr
) const
{
    // A sliding contact: friction changes the sliding speed by at most a
    // tenth in the interval, or the interval is a contact time (where it
    // stops: it sticks at the next)
    const pairKey kA{A.fiber, A.seg, B.fiber, B.seg};
    const pairKey kB{B.fiber, B.seg, A.fiber, A.seg};
    const scalar FtMax = law_->friction()*law_->springForce(max(delta, 0));
    const contactRecords::slidingTable& sliding = rec_.sliding();
    if (!(FtMax > 0) || (!sliding.found(kA) && !sliding.found(kB)))
    {
        return GREAT;
    }
    const scalar vt = mag(vr - (vr & n)*n);
    const scalar m = reducedMass(A.m, B.m);
    return max(0.1*vt*m/FtMax, contactTime(m));
}


Foam::scalar Foam::fiberInteractions::contact::sweepLimit
(
    const segment& P,
    const segment& Q,
    const scalar h
) const
{
    // In one order, the lower fiber id (then segment) first, so that every
    // side of a pair gets the same number to the last bit
    const bool pFirst =
        P.fiber < Q.fiber || (P.fiber == Q.fiber && P.seg < Q.seg);
    const segment& A = pFirst ? P : Q;
    const segment& B = pFirst ? Q : P;

    // The ends of both axes move at their velocities (straight paths over
    // the interval); along them the surfaces' gap is convex in time for
    // rigid translations, close to it over an interval
    const vector vA0(A.v + (A.w ^ (A.a - A.x)));
    const vector vA1(A.v + (A.w ^ (A.b - A.x)));
    const vector vB0(B.v + (B.w ^ (B.a - B.x)));
    const vector vB1(B.v + (B.w ^ (B.b - B.x)));
    return
        grazeTime
        (
            {A.a, A.b, B.a, B.b}, {vA0, vA1, vB0, vB1},
            0.5*(A.d + B.d) + range_, h
        );
}


Foam::scalar Foam::fiberInteractions::contact::pairLimit
(
    const segment& A,
    const segment& B,
    const scalar h,
    label& why
) const
{
    const scalar s = mag(0.5*(A.a + A.b - B.a - B.b));
    const scalar lA = mag(A.b - A.a);
    const scalar lB = mag(B.b - B.a);
    const scalar vc =
        mag
        (
            A.v - B.v + (A.w ^ (0.5*(A.a + A.b) - A.x))
          - (B.w ^ (0.5*(B.a + B.b) - B.x))
        );

    // A pair that cannot limit the interval (its gap at least that of the
    // centres less the half lengths, its speed at most that of the centres
    // plus the turning ends) needs no closest points (it does not touch,
    // so it does not slide)
    const scalar gLow =
        s - 0.5*(lA + lB + A.d + B.d) - range_ + maxApproach_*min(A.d, B.d);
    const scalar vUp =
        vc + 0.5*(mag(A.w ^ (A.b - A.a)) + mag(B.w ^ (B.b - B.a)));
    if (gLow > 0 && vUp*h <= gLow)
    {
        return h;
    }

    // The surfaces' gap g closes at the normal relative speed of the
    // closest points (any speed where the axes cross); the interval lets
    // it reach an overlap of maxApproach diameters
    const segmentDistance::result r =
        segmentDistance::closest(A.a, A.b, B.a, B.b);
    const vector vr
    (
        (A.v + (A.w ^ (r.a - A.x))) - (B.v + (B.w ^ (r.b - B.x)))
    );
    const scalar dist = mag(r.a - r.b);
    const scalar g = max(dist - 0.5*(A.d + B.d) - range_, 0);
    const scalar allowed = g + maxApproach_*min(A.d, B.d);
    const scalar vn =
        dist > SMALL*(A.d + B.d)
      ? max(-(vr & (r.a - r.b))/dist, 0)
      : mag(vr);
    scalar hp = h;
    if (vn*h > allowed)
    {
        hp = allowed/vn;
        why = g > 0 ? limit::approaching : limit::touching;
    }
    if (implicit_ && g <= 0 && law_->friction() > 0)
    {
        const vector n((r.a - r.b)/max(dist, VSMALL));
        const scalar hs =
            slideLimit(A, B, n, 0.5*(A.d + B.d) - dist, vr);
        if (hs < hp)
        {
            hp = hs;
            why = limit::sliding;
        }
    }
    return hp;
}


Foam::scalar Foam::fiberInteractions::contact::approachLimit
(
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar lambdaPairs,
    const scalar r,
    const scalar skin,
    const scalar hMax,
    scalar& vFar,
    label& why
) const
{
    // The candidates.  The velocity gradient at the scale of the pairs
    // beyond the search, lambda: the largest relative speed of the centres
    // per distance of the pairs the search saw at least a reach (r - skin)
    // apart (lambdaPairs: a near pair's speed per distance of centres
    // measures its contact or its turning, not the flow, and a crossing
    // pair's diverges), or the largest rate at which a segment's axis
    // turns (a spin about a segment's own axis, as where fibers roll on
    // each other, moves no point of the axis)
    scalar h = hMax;
    scalar lambda = lambdaPairs;
    why = -1;
    for (const FixedList<label, 2>& ij : cand)
    {
        // Both local: the pair once (the local segments come first, and
        // the first of a candidate is local: its partner is local where
        // it comes before it)
        if (!(ij[1] < ij[0]))
        {
            h = pairLimit(segs[ij[0]], segs[ij[1]], h, why);
        }
    }

    // Any other pair has centres more than reach + skin apart and surfaces
    // more than skin: where the velocity varies smoothly over a reach, it
    // closes at most at lambda times the centres' distance, and never
    // faster than the range of all the segments' end velocities
    vector vMin(vector::uniform(GREAT));
    vector vMax(vector::uniform(-GREAT));
    for (const segment& s : segs)
    {
        if (s.local < 0)
        {
            continue;
        }
        const scalar l = mag(s.b - s.a);
        lambda = max(lambda, l > 0 ? mag(s.w ^ (s.b - s.a))/l : mag(s.w));
        for (const point& e : {s.a, s.b})
        {
            const vector ve(s.v + (s.w ^ (e - s.x)));
            vMin = min(vMin, ve);
            vMax = max(vMax, ve);
        }
    }
    reduce(vMin, minOp<vector>());
    reduce(vMax, maxOp<vector>());
    reduce(lambda, maxOp<scalar>());
    vFar = vMax.x() < vMin.x() ? 0 : min(mag(vMax - vMin), lambda*r);
    if (vFar*h > skin)
    {
        h = skin/vFar;
        why = limit::far;
    }

    // The reason of the processor whose limit is the global one
    const scalar hAll = returnReduce(h, minOp<scalar>());
    why = returnReduce(h == hAll ? why : label(-1), maxOp<label>());
    return hAll;
}


Foam::scalar Foam::fiberInteractions::contact::sweptInterval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar h
)
{
    // The range of the velocities of the segments' ends: no pair closes
    // faster, so the search within reach and a skin of that times h holds
    // every pair that can touch within the interval (the skin at most a
    // reach; the interval then so short that the skin covers it)
    vector vMin(vector::uniform(GREAT));
    vector vMax(vector::uniform(-GREAT));
    forAll(fibers, fi)
    {
        if (roles[fi] == role::absent)
        {
            continue;
        }
        const fiber& f = fibers[fi];
        const tensor R(f.R());
        for (label i = 0; i < f.nSegments(); ++i)
        {
            const vector v(f.segmentVelocity(R, i));
            const vector dw
            (
                f.segmentOmega(i)
              ^ ((0.5*f.segmentLength(i))*f.segmentDirection(R, i))
            );
            vMin = min(vMin, min(v + dw, v - dw));
            vMax = max(vMax, max(v + dw, v - dw));
        }
    }
    reduce(vMin, minOp<vector>());
    reduce(vMax, maxOp<vector>());
    const scalar vRange = vMax.x() < vMin.x() ? 0 : mag(vMax - vMin);
    const scalar r0 = reach(fibers, roles);
    scalar hs = vRange*h > r0 ? r0/vRange : h;

    DynamicList<segment>& segs = near_.segs;
    DynamicList<FixedList<label, 2>>& cand = near_.cand;
    segs.clear();
    cand.clear();
    near_.inReach.clear();
    near_.skin = vRange*hs;
    near_.r = gather(fibers, roles, segs, nullptr, near_.skin);
    candidates(segs, near_.r, cand, near_.skin, &near_.inReach);
    near_.valid = true;
    // Every pair over the same interval, so that the result does not
    // depend on the pairs' order (serial and parallel alike)
    const scalar H = hs;
    for (const FixedList<label, 2>& ij : cand)
    {
        if (!(ij[1] < ij[0]) && segs[ij[0]].fiber != segs[ij[1]].fiber)
        {
            hs = min(hs, sweepLimit(segs[ij[0]], segs[ij[1]], H));
        }
    }
    return returnReduce(hs, minOp<scalar>());
}


bool Foam::fiberInteractions::contact::grazed
(
    const FixedList<label, 2>& ij,
    const UList<FixedList<vector, 2>>& move,
    const UList<scalar>& moveMax,
    const UList<scalar>& bend,
    bool& touches
) const
{
    const sweptSegment& P = sweptSegs_[ij[0]];
    const sweptSegment& Q = sweptSegs_[ij[1]];

    // On the straight paths no point of one axis moves against one
    // of the other by more than the largest relative motion of
    // their ends, dRel (the relative motion is bilinear along the
    // axes: its largest at two ends).  The axes' distance at time
    // t of the interval is at least g0 - t dRel and g1 - (1 - t)
    // dRel (g0, g1: at its start and end), so at least (g0 + g1
    // - dRel)/2: a pair farther apart than that and the touch
    // cannot have met (most pairs move together in the flow)
    const scalar touch = 0.5*(P.d + Q.d) + range_;
    const scalar gMax = moveMax[ij[0]] + moveMax[ij[1]] + touch;
    const scalar g0 = axesApart(P.a, P.b, Q.a, Q.b);
    if (g0 > gMax)
    {
        return false;
    }
    const FixedList<vector, 2>& mP = move[ij[0]];
    const FixedList<vector, 2>& mQ = move[ij[1]];
    const scalar dRel =
        std::sqrt
        (
            max
            (
                max(magSqr(mP[0] - mQ[0]), magSqr(mP[0] - mQ[1])),
                max(magSqr(mP[1] - mQ[0]), magSqr(mP[1] - mQ[1]))
            )
        );
    if
    (
        g0 > dRel + touch
     || 0.5*(g0 + axesApart
         (
             P.a + mP[0], P.b + mP[1], Q.a + mQ[0], Q.b + mQ[1]
         ) - dRel) > touch
    )
    {
        return false;
    }
    const FixedList<point, 4> p{P.a, P.b, Q.a, Q.b};
    const FixedList<vector, 4> m{mP[0], mP[1], mQ[0], mQ[1]};

    // A graze along the straight paths that is deeper than the
    // paths can stray from them: certain (a shallower one may be
    // an artefact of the straight paths)
    const scalar margin = bend[ij[0]] + bend[ij[1]];
    if
    (
        grazeTime(p, m, touch, 1, &touches) < 1
     && (margin < SMALL*touch || grazeTime(p, m, touch - margin, 1) < 1)
    )
    {
        return true;
    }
    return false;
}


void Foam::fiberInteractions::contact::missedGrazes
(
    const scalar t,
    const scalar h,
    const UList<segment>& segs,
    DynamicList<FixedList<label, 2>>& cand
)
{
    // The last interval's candidates, where it ends now (over more than
    // one interval the ends' motion is not one straight path)
    if (sweptCand_.size() && mag(t - sweptEnd_) <= 1e-6*sweptH_)
    {
        List<FixedList<vector, 2>> move;
        List<scalar> moveMax;
        List<scalar> bend;
        sweptMotion(segs, move, moveMax, bend);

        // The pairs of different fibers, the lower id first and of this
        // processor (each pair on one processor); by fiber pair, those
        // that grazed and those that touched at either end (seen there)
        HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> pairs;
        DynamicList<FixedList<label, 2>> seen;

        countJumped(moveMax);
        for (const FixedList<label, 2>& ij : sweptCand_)
        {
            // (the compact ids first: most candidates end here)
            const label fP = sweptFiber_[ij[0]];
            const label fQ = sweptFiber_[ij[1]];
            if
            (
                fP < 0 || !(fP < (fQ < 0 ? -1 - fQ : fQ))
             || moveMax[ij[0]] < 0 || moveMax[ij[1]] < 0
            )
            {
                continue;
            }
            const sweptSegment& P = sweptSegs_[ij[0]];
            const sweptSegment& Q = sweptSegs_[ij[1]];
            bool touches = false;
            if (grazed(ij, move, moveMax, bend, touches))
            {
                pairs.insert(FixedList<label, 2>{P.fiber, Q.fiber});
            }
            if (touches)
            {
                seen.append(FixedList<label, 2>{P.fiber, Q.fiber});
            }
        }

        // A graze of fibers touching at the interval's start or end by
        // other segments (a contact that moved across a joint) was seen
        if (pairs.size())
        {
            for (const FixedList<label, 2>& f : seen)
            {
                pairs.erase(f);
            }
            nMissed_ += pairs.size();
        }
    }

    keepSwept(t, h, segs, cand);
}


void Foam::fiberInteractions::contact::countJumped
(
    const UList<scalar>& moveMax
)
{
    // The fibers of this processor put where they are by other than their
    // motion (their pairs are left out: their paths are not known)
    labelHashSet jumped;
    forAll(moveMax, j)
    {
        if (moveMax[j] < -1.5 && sweptFiber_[j] >= 0)
        {
            jumped.insert(sweptSegs_[j].fiber);
        }
    }
    nJumped_ += jumped.size();
}


void Foam::fiberInteractions::contact::keepSwept
(
    const scalar t,
    const scalar h,
    const UList<segment>& segs,
    DynamicList<FixedList<label, 2>>& cand
)
{
    // The buffers swapped, kept for their capacity
    sweptCand_.swap(cand);
    sweptSegs_.resize(segs.size());
    sweptFiber_.resize(segs.size());
    forAll(segs, i)
    {
        const segment& s = segs[i];
        sweptSegs_[i] =
            sweptSegment
            {
                s.fiber, s.seg, s.a, s.b,
                s.v + (s.w ^ (s.a - s.x)), s.v + (s.w ^ (s.b - s.x)), s.d
            };
        sweptFiber_[i] = s.local >= 0 ? s.fiber : -1 - s.fiber;
    }
    sweptEnd_ = t + h;
    sweptH_ = h;
}


Foam::fiberInteractions::contact::segment
Foam::fiberInteractions::contact::unwrapped
(
    const segment& s,
    const point& a0
) const
{
    // A copy found a period away from where the segment was (it crossed a
    // periodic patch and no image of it is near there): its image nearest
    // to there (a path through the domain would sweep across every pair)
    segment best(s);
    if (magSqr(s.a - a0) > sqr(near_.r))
    {
        forAll(periodic_, ti)
        {
            const vectorTensorTransform& T = periodic_[ti];
            const point a(T.transformPosition(s.a));
            if (magSqr(a - a0) < magSqr(best.a - a0))
            {
                best = image(s, T, ti);
            }
        }
    }
    return best;
}


void Foam::fiberInteractions::contact::sweptMotion
(
    const UList<segment>& segs,
    List<FixedList<vector, 2>>& move,
    List<scalar>& moveMax,
    List<scalar>& bend
) const
{
    const List<label> now(sweptNow(segs));
    move.setSize(now.size());
    moveMax.setSize(now.size());
    bend.setSize(now.size());
    forAll(now, j)
    {
        moveMax[j] = -1;
        bend[j] = 0;
        if (now[j] >= 0)
        {
            const sweptSegment& o = sweptSegs_[j];
            const segment s(unwrapped(segs[now[j]], o.a));
            move[j][0] = s.a - o.a;
            move[j][1] = s.b - o.b;
            moveMax[j] = max(mag(move[j][0]), mag(move[j][1]));
            const vector va(s.v + (s.w ^ (s.a - s.x)));
            const vector vb(s.v + (s.w ^ (s.b - s.x)));
            bend[j] = 0.25*sweptH_*max(mag(va - o.va), mag(vb - o.vb));

            // Where the velocity of an end moves between its values at the
            // two ends of the interval, the end moves at most h times the
            // larger speed
            const scalar vMax =
                max(max(mag(va), mag(vb)), max(mag(o.va), mag(o.vb)));
            if (moveMax[j] > 2*sweptH_*vMax + SMALL*o.d)
            {
                moveMax[j] = -2;
            }
        }
    }
}


Foam::List<Foam::label> Foam::fiberInteractions::contact::sweptNow
(
    const UList<segment>& segs
) const
{
    // Where the fibers are the same, a segment is at its index of then
    // (local segments in the fibers' order, then the images and other
    // processors'): a fiber's own segment is its only copy of its own (a
    // period away where it crossed a periodic patch: unwrapped), an image
    // or another's within the search distance of where it was (another
    // copy is a period away)
    List<label> now(sweptSegs_.size(), -1);
    const scalar r2 = sqr(near_.r);
    bool all = true;
    bool localAll = true;
    forAll(sweptSegs_, j)
    {
        const sweptSegment& s = sweptSegs_[j];
        if
        (
            j < segs.size() && segs[j].fiber == s.fiber
         && segs[j].seg == s.seg
         && (sweptFiber_[j] >= 0 || magSqr(segs[j].a - s.a) < r2)
        )
        {
            now[j] = j;
        }
        else
        {
            all = false;
            localAll = localAll && sweptFiber_[j] < 0;
        }
    }
    if (all)
    {
        return now;
    }

    // Where every segment of this processor's fibers is at its index of
    // then (the usual case: the images, which follow them, change with
    // the skin), only the copies that are not this processor's own, then
    // the own segments of images that are gone
    label i0 = 0;
    if (localAll)
    {
        while (i0 < segs.size() && segs[i0].local >= 0)
        {
            ++i0;
        }
    }
    if (!nearestCopies(segs, i0, now) && i0 > 0)
    {
        ownCopies(segs, i0, now);
    }
    return now;
}


bool Foam::fiberInteractions::contact::nearestCopies
(
    const UList<segment>& segs,
    const label i0,
    List<label>& now
) const
{
    // The copies of each segment now from i0 on (its own, its images,
    // another processor's) as a list from the first, by fiber and segment
    HashTable<label, FixedList<label, 2>, FixedList<label, 2>::Hash<>>
        first(2*(segs.size() - i0) + 1);
    List<label> next(segs.size(), -1);
    for (label i = i0; i < segs.size(); ++i)
    {
        const FixedList<label, 2> key{segs[i].fiber, segs[i].seg};
        auto it = first.find(key);
        if (it.found())
        {
            next[i] = *it;
            *it = i;
        }
        else
        {
            first.insert(key, i);
        }
    }

    // Of each segment then not found at its index, the copy nearest to
    // where it was (an image where it crossed a periodic patch, or where
    // it was an image)
    bool found = true;
    forAll(sweptSegs_, j)
    {
        if (now[j] >= 0)
        {
            continue;
        }
        const sweptSegment& s = sweptSegs_[j];
        const auto it = first.cfind(FixedList<label, 2>{s.fiber, s.seg});
        scalar dBest = GREAT;
        for (label i = it.found() ? *it : -1; i >= 0; i = next[i])
        {
            if (magSqr(segs[i].a - s.a) < dBest)
            {
                dBest = magSqr(segs[i].a - s.a);
                now[j] = i;
            }
        }
        found = found && now[j] >= 0;
    }
    return found;
}


void Foam::fiberInteractions::contact::ownCopies
(
    const UList<segment>& segs,
    const label i0,
    List<label>& now
) const
{
    // An image that is gone (its segment farther from the periodic patch
    // than the search's reach now): its fiber's own segment, a period away
    // (unwrapped), by the first segment of each fiber
    Map<label> firstOf(i0/2 + 16);
    for (label i = 0; i < i0; ++i)
    {
        if (segs[i].seg == 0)
        {
            firstOf.insert(segs[i].fiber, i);
        }
    }
    forAll(sweptSegs_, j)
    {
        const auto it = firstOf.cfind(sweptSegs_[j].fiber);
        const label i = it.found() ? *it + sweptSegs_[j].seg : -1;
        if
        (
            now[j] < 0 && i >= 0 && i < i0
         && segs[i].fiber == sweptSegs_[j].fiber
         && segs[i].seg == sweptSegs_[j].seg
        )
        {
            now[j] = i;
        }
    }
}


void Foam::fiberInteractions::contact::owedImpulses
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    Map<label>& present,
    UList<bool>& engaged
)
{
    // The impulses due to fibers that are gone (escaped, deposited):
    // nothing to pay back to
    forAll(fibers, fi)
    {
        if (roles[fi] != role::absent)
        {
            present.insert(fibers[fi].id(), fi);
        }
    }
    for (const FixedList<label, 2>& k : rec_.pending().toc())
    {
        const auto it = present.cfind(k[0]);
        if (!it.found())
        {
            rec_.pending().erase(k);
        }
        else
        {
            engaged[*it] = true;
        }
    }
}


Foam::scalar Foam::fiberInteractions::contact::nextWindow
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<flow>& flows,
    const scalar dt,
    const scalar tLeft,
    UList<bool>& engaged
)
{
    // The shortest contact time, for the window's intervals (the fibers
    // of the step, those a feed releases in it included, are all there)
    tcWindow_ = shortestContactTime(fibers);
    if (!(tLeft > 0))
    {
        engaged = false;
        return tLeft;
    }

    // The fibers present (by id); a fiber owed an impulse is engaged
    engaged = false;
    Map<label> present(2*fibers.size() + 16);
    owedImpulses(fibers, roles, present, engaged);

    // Implicit contacts: no windows.  What an implicit contact does
    // depends on how long its intervals are (stable at any length,
    // dissipative where they exceed the contact time), and the windows
    // change that: on the TJunction feed (air, random walk, cohesion) the
    // collisions in 0.04 s fell from 285 to 192 with windows, and the soft
    // strike of tests/contacts kept its angular momentum to 8.8e-3 instead
    // of 1.7e-4 at maxApproach 0.01 (the defect between flexible fibers,
    // docs/model.md section 7).  And where the last window of this step
    // engaged most fibers (a dense suspension), the rest of the step is
    // one window with every fiber engaged, without the window's search
    // (the next step looks again)
    if
    (
        implicit_
     || (tLeft < (1 - 1e-9)*dt && windows_.denseFraction() > 0.8)
    )
    {
        engaged = true;
        return tLeft;
    }

    // The pairs within reach and the windows' skin (half a reach or more,
    // adaptive: below), with the flow at every segment
    DynamicList<segment>& segs = near_.segs;
    DynamicList<FixedList<label, 2>>& cand = near_.cand;
    segs.clear();
    cand.clear();
    near_.valid = false;
    const scalar r0 = reach(fibers, roles);
    const scalar skin = windows_.skin()*r0;
    const scalar r = gather(fibers, roles, segs, nullptr, skin, &flows);
    candidates(segs, r, cand, skin);

    // The window's length and the fibers engaged in it (contactWindows)
    label nMissed = 0;
    const scalar H =
        windows_.choose
        (
            fibers, roles, segs, cand, present, r, skin, tLeft, engaged,
            nMissed
        );
    nMissed_ += nMissed;
    segs.clear();
    cand.clear();
    return H;
}


void Foam::fiberInteractions::contact::addImages
(
    DynamicList<segment>& segs,
    const scalar r
) const
{
    if (periodic_.empty())
    {
        return;
    }
    boundBox domain(mesh_.bounds());
    reduce(domain.min(), minOp<point>());
    reduce(domain.max(), maxOp<point>());
    domain.min() -= vector::uniform(r);
    domain.max() += vector::uniform(r);

    // The image's axis first: most images lie beyond the domain, and the
    // whole segment is copied only for those that do not
    const label n = segs.size();
    for (label i = 0; i < n; ++i)
    {
        forAll(periodic_, ti)
        {
            const vectorTensorTransform& T = periodic_[ti];
            const point a(T.transformPosition(segs[i].a));
            const point b(T.transformPosition(segs[i].b));
            if (domain.overlaps(boundBox(min(a, b), max(a, b))))
            {
                segs.append(image(segs[i], T, ti));
            }
        }
    }
}


void Foam::fiberInteractions::contact::receiveGhosts
(
    DynamicList<segment>& segs,
    PstreamBuffers& pBufs
) const
{
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        const label n = readLabel(is);
        DynamicList<scalar>& rbuf = ghostRecv_;
        rbuf.resize(nPacked*n);
        is.read
        (
            reinterpret_cast<char*>(rbuf.data()),
            std::streamsize(rbuf.size()*sizeof(scalar))
        );
        segs.reserve(segs.size() + n);
        label k = 0;
        for (label j = 0; j < n; ++j)
        {
            segment s;
            unpackSegment(rbuf, k, s);
            segs.append(s);
        }
    }
}


void Foam::fiberInteractions::contact::addGhosts
(
    DynamicList<segment>& segs,
    const scalar r
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // Each processor's box of its segments (its own and their images):
    // another's segment is sent where its box grown by r overlaps it.
    // (Not the mesh's bounds: polyMesh::bounds() is the whole mesh's in a
    // parallel run, which sent every segment to every processor.)
    List<boundBox> parts(Pstream::nProcs());
    boundBox& own = parts[Pstream::myProcNo()];
    own = boundBox::invertedBox;
    for (const segment& s : segs)
    {
        own.add(s.a);
        own.add(s.b);
    }
    fiberCompat::allGatherList(parts);

    if (!ghostBufs_)
    {
        ghostBufs_.reset
        (
            new PstreamBuffers(Pstream::commsTypes::nonBlocking)
        );
    }
    PstreamBuffers& pBufs = *ghostBufs_;
    pBufs.clear();
    DynamicList<scalar>& buf = ghostSend_;
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        buf.clear();
        label n = 0, k = 0;
        forAll(segs, i)
        {
            if (parts[proci].overlaps(segmentBox(segs[i], r)))
            {
                buf.resize(k + nPacked);
                packSegment(segs[i], buf, k);
                ++n;
            }
        }
        if (k != nPacked*n)
        {
            FatalErrorInFunction
                << "Packed " << k << " scalars for " << n << " segments, not "
                << nPacked << " each" << abort(FatalError);
        }
        UOPstream os(proci, pBufs);
        os << n;
        os.write
        (
            reinterpret_cast<const char*>(buf.cdata()),
            std::streamsize(buf.size()*sizeof(scalar))
        );
    }
    pBufs.finishedSends();
    receiveGhosts(segs, pBufs);
}


void Foam::fiberInteractions::contact::candidates
(
    const UList<segment>& segs,
    const scalar r,
    DynamicList<FixedList<label, 2>>& cand,
    const scalar skin,
    DynamicList<FixedList<label, 2>>* inReach,
    scalar* lambda
) const
{
    search_.pairs(segs, r, range_, skin, cand, inReach, lambda);
}


// ************************************************************************* //
