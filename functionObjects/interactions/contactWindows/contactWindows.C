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

#include "contactWindows.H"
#include "contact.H"
#include "openfoamCompat.H"
#include "segmentDistance.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::fiberInteractions::contactWindows::contactWindows(const contact& model)
:
    model_(model),
    skin_(0.5),
    denseFraction_(0),
    segs_(nullptr),
    far_(),
    kick_(0),
    present_(nullptr)
{}


// * * * * * * * * * * * * * * A segment's terms  * * * * * * * * * * * * * //

Foam::scalar Foam::fiberInteractions::contactWindows::turning
(
    const segment& S
)
{
    const scalar l = mag(S.b - S.a);
    return max(mag(S.w ^ (S.b - S.a)), S.gradU*l);
}


Foam::scalar Foam::fiberInteractions::contactWindows::turnNow
(
    const segment& S
)
{
    return mag(S.w ^ (S.b - S.a));
}


Foam::scalar Foam::fiberInteractions::contactWindows::turnAccel
(
    const segment& S
)
{
    return
        S.tauLo > 0
      ? (mag(S.w) + S.gradU)*mag(S.b - S.a)/S.tauLo
      : GREAT/4;
}


Foam::scalar Foam::fiberInteractions::contactWindows::accel
(
    const segment& S
)
{
    return S.tauLo > 0 ? (S.slip + S.slack)/S.tauLo + S.g : GREAT;
}


Foam::scalar Foam::fiberInteractions::contactWindows::dFluid
(
    const scalar slip,
    const scalar slack,
    const scalar tauHi,
    const scalar g,
    const scalar H
)
{
    return slip*min(H, tauHi) + slack*H + g*min(tauHi*H, 0.5*sqr(H));
}


void Foam::fiberInteractions::contactWindows::ordered
(
    const segment& Q,
    const segment& P,
    const segment*& A,
    const segment*& B
)
{
    const bool qFirst =
        Q.fiber < P.fiber || (Q.fiber == P.fiber && Q.seg < P.seg);
    A = qFirst ? &Q : &P;
    B = qFirst ? &P : &Q;
}


Foam::scalar Foam::fiberInteractions::contactWindows::relSpeed
(
    const segment& A,
    const segment& B
)
{
    return
        mag(centreVelocity(A) - centreVelocity(B))
      + 0.5*(turnNow(A) + turnNow(B));
}


// * * * * * * * * * * * * * * * * * Bounds  * * * * * * * * * * * * * * * //

void Foam::fiberInteractions::contactWindows::makeBounds
(
    const UList<FixedList<label, 2>>& cand
)
{
    const UList<segment>& segs = *segs_;
    bounds_.clear();
    bounds_.setCapacity(cand.size());
    for (const FixedList<label, 2>& ij : cand)
    {
        if (ij[1] < ij[0])
        {
            continue;
        }
        const segment& Q = segs[ij[0]];
        const segment& P = segs[ij[1]];
        if (!(Q.m > 0) && !(P.m > 0))
        {
            continue;
        }
        const segment* A;
        const segment* B;
        ordered(Q, P, A, B);
        bounds_.append
        (
            bound
            {
                ij[0], ij[1],
                mag(0.5*(A->a + A->b - B->a - B->b))
              - 0.5*(mag(A->b - A->a) + mag(B->b - B->a) + A->d + B->d)
              - model_.range_
            }
        );
    }
}


Foam::scalar Foam::fiberInteractions::contactWindows::contactKick() const
{
    // A fiber that touches another may leave the contact at most at the
    // pair's relative speed plus what the overlap and the cohesion can
    // give it (their energy), m the reduced mass
    const UList<segment>& segs = *segs_;
    const fiberContactLaw& law = model_.law_();
    const scalar range = model_.range_;
    scalar kick = 0;
    for (const bound& bd : bounds_)
    {
        const segment& Q = segs[bd.i];
        const segment& P = segs[bd.j];
        if (bd.gLow > 0.1*min(Q.d, P.d) || Q.fiber == P.fiber)
        {
            continue;
        }
        const segment* pA;
        const segment* pB;
        ordered(Q, P, pA, pB);
        const segment& A = *pA;
        const segment& B = *pB;
        const segmentDistance::result cp =
            segmentDistance::closest(A.a, A.b, B.a, B.b);
        const scalar delta = 0.5*(A.d + B.d) - mag(cp.a - cp.b);
        if (delta + range < 0)
        {
            continue;
        }
        const scalar m = reducedMass(A.m, B.m);
        kick =
            max
            (
                kick,
                relSpeed(A, B) + law.releaseSpeed(m, delta)
              + std::sqrt(2*law.cohesionStrength()*range/m)
            );
    }
    return returnReduce(kick, maxOp<scalar>());
}


void Foam::fiberInteractions::contactWindows::makeTerms()
{
    const UList<segment>& segs = *segs_;
    ts_.setSize(segs.size());
    forAll(segs, i)
    {
        const segment& S = segs[i];
        ts_[i] =
            segTerms
            {
                centreVelocity(S), turning(S), turnNow(S),
                min(turnAccel(S), GREAT/4), min(accel(S), GREAT/4),
                mag(S.u) + S.slip + S.slack, mag(centreVelocity(S))
            };
    }
}


Foam::scalar Foam::fiberInteractions::contactWindows::speed
(
    const label i,
    const scalar H
) const
{
    const segTerms& t = ts_[i];
    return
        min
        (
            t.fluidSpeed + (*segs_)[i].g*H + 0.5*t.turning,
            t.magVc + t.accel*H + 0.5*(t.turnNow + t.turnAccel*H)
        );
}


Foam::scalar Foam::fiberInteractions::contactWindows::rebound
(
    const label i,
    const scalar H
) const
{
    // A fiber whose gap to a wall or symmetry plane is less than spd H may
    // rebound off it, which turns its velocity by up to twice its speed
    const scalar spd = speed(i, H);
    return (*segs_)[i].wall < spd*H ? 2*spd*H : 0;
}


Foam::scalar Foam::fiberInteractions::contactWindows::closing
(
    const label i,
    const label j,
    const scalar du,
    const scalar dv,
    const scalar H
) const
{
    const segment& A = (*segs_)[i];
    const segment& B = (*segs_)[j];
    const scalar viaFluid =
        du*H
      + dFluid(A.slip, A.slack, A.tauHi, A.g, H)
      + dFluid(B.slip, B.slack, B.tauHi, B.g, H)
      + 0.5*(ts_[i].turning + ts_[j].turning)*H;
    const scalar straight =
        dv*H
      + 0.5*(ts_[i].accel + ts_[j].accel)*sqr(H)
      + 0.5*(ts_[i].turnNow + ts_[j].turnNow)*H
      + 0.25*min(ts_[i].turnAccel + ts_[j].turnAccel, GREAT/4)*sqr(H);
    return min(viaFluid, straight) + rebound(i, H) + rebound(j, H);
}


void Foam::fiberInteractions::contactWindows::farMaxima
(
    const scalar r,
    const scalar skin
)
{
    // |u_A - u_B| at most the largest velocity gradient times the
    // distance, or the range of the fluid's velocities; |v_A - v_B| at
    // most the range of the segments' velocities
    farTerms& f = far_;
    f = farTerms{0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    scalar gradMax = 0;
    vector uMin(vector::uniform(GREAT));
    vector uMax(vector::uniform(-GREAT));
    vector vMin(vector::uniform(GREAT));
    vector vMax(vector::uniform(-GREAT));
    for (const segment& sg : *segs_)
    {
        if (sg.local < 0)
        {
            continue;
        }
        gradMax = max(gradMax, sg.gradU);
        f.slip = max(f.slip, sg.slip);
        f.slack = max(f.slack, sg.slack);
        f.tauHi = max(f.tauHi, sg.tauHi);
        f.g = max(f.g, sg.g);
        f.accel = max(f.accel, min(accel(sg), GREAT/4));
        f.turn = max(f.turn, turning(sg));
        f.turnNow = max(f.turnNow, turnNow(sg));
        f.turnAccel = max(f.turnAccel, min(turnAccel(sg), GREAT/4));
        uMin = min(uMin, sg.u);
        uMax = max(uMax, sg.u);
        vMin = min(vMin, centreVelocity(sg));
        vMax = max(vMax, centreVelocity(sg));
    }
    reduce(gradMax, maxOp<scalar>());
    for
    (
        scalar* s
      : {&f.slip, &f.slack, &f.tauHi, &f.g, &f.accel, &f.turn, &f.turnNow,
         &f.turnAccel}
    )
    {
        reduce(*s, maxOp<scalar>());
    }
    reduce(uMin, minOp<vector>());
    reduce(uMax, maxOp<vector>());
    reduce(vMin, minOp<vector>());
    reduce(vMax, maxOp<vector>());
    const bool none = uMax.x() < uMin.x();
    f.du = none ? 0 : min(mag(uMax - uMin), gradMax*(r + skin));
    f.dv = none ? 0 : mag(vMax - vMin);
}


void Foam::fiberInteractions::contactWindows::wallHits(const scalar tLeft)
{
    // A segment may reach a wall or symmetry plane no sooner than its gap
    // over its speed bound for the rest of the step; of all processors'
    // segments, those faster than every one that may hit sooner
    const UList<segment>& segs = *segs_;
    hits_.clear();
    forAll(segs, i)
    {
        if (segs[i].local >= 0 && rebound(i, tLeft) > 0)
        {
            const scalar spd = speed(i, tLeft);
            hits_.push_back({max(segs[i].wall, 0)/max(spd, VSMALL), spd});
        }
    }
    const auto envelope = [](std::vector<hitSpeed>& h)
    {
        std::sort(h.begin(), h.end());
        std::vector<hitSpeed> e;
        for (const hitSpeed& x : h)
        {
            if (e.empty() || x.second > e.back().second)
            {
                e.push_back(x);
            }
        }
        h.swap(e);
    };
    envelope(hits_);
    if (!Pstream::parRun())
    {
        return;
    }
    List<List<scalar>> all(Pstream::nProcs());
    List<scalar>& mine = all[Pstream::myProcNo()];
    mine.setSize(2*hits_.size());
    forAll(hits_, k)
    {
        mine[2*k] = hits_[k].first;
        mine[2*k + 1] = hits_[k].second;
    }
    fiberCompat::allGatherList(all);
    hits_.clear();
    for (const List<scalar>& l : all)
    {
        for (label k = 0; k + 1 < l.size(); k += 2)
        {
            hits_.push_back({l[k], l[k + 1]});
        }
    }
    envelope(hits_);
}


Foam::scalar Foam::fiberInteractions::contactWindows::wallFast
(
    const scalar H
) const
{
    // The last of the envelope that may hit within H (the fastest)
    const auto it =
        std::lower_bound(hits_.begin(), hits_.end(), hitSpeed(H, -GREAT));
    return it == hits_.begin() ? 0 : std::prev(it)->second;
}


Foam::scalar Foam::fiberInteractions::contactWindows::farClosing
(
    const scalar H
) const
{
    const farTerms& f = far_;
    return
        min
        (
            f.du*H + 2*dFluid(f.slip, f.slack, f.tauHi, f.g, H) + f.turn*H,
            f.dv*H + f.accel*sqr(H) + f.turnNow*H + 0.5*f.turnAccel*sqr(H)
        )
      + kick_*H + 2*wallFast(H)*H;
}


Foam::scalar Foam::fiberInteractions::contactWindows::longest
(
    const scalar tLeft,
    const scalar skin
) const
{
    // The closing grows with H: bisection
    scalar H = tLeft;
    if (farClosing(H) > skin)
    {
        scalar lo = 0;
        for (label iter = 0; iter < 50; ++iter)
        {
            const scalar mid = 0.5*(lo + H);
            (farClosing(mid) > skin ? H : lo) = mid;
        }
        H = max(lo, 1e-9*tLeft);
        H = tLeft/std::ceil(tLeft/H*(1 - 1e-9));
    }
    return H;
}


void Foam::fiberInteractions::contactWindows::nearPairs
(
    const FixedList<scalar, nW>& Hw,
    const scalar skin
)
{
    // Any window here lets a kick move a fiber at most the skin
    const UList<segment>& segs = *segs_;
    near_.clear();
    near_.setCapacity(bounds_.size());
    forAll(bounds_, bi)
    {
        const bound& bd = bounds_[bi];
        const segment& Q = segs[bd.i];
        const segment& P = segs[bd.j];
        const segment* A;
        const segment* B;
        ordered(Q, P, A, B);
        const scalar du = mag(Q.u - P.u);
        const scalar dv = mag(ts_[bd.i].vc - ts_[bd.j].vc);
        const scalar within =
            max
            (
                closing(bd.i, bd.j, du, dv, Hw[0]) + skin,
                0.1*min(A->d, B->d)
            );
        if (bd.gLow > within)
        {
            continue;
        }
        const segmentDistance::result cp =
            segmentDistance::closest(A->a, A->b, B->a, B->b);
        const scalar g =
            mag(cp.a - cp.b) - 0.5*(A->d + B->d) - model_.range_;
        if (g > within)
        {
            continue;
        }
        nearPair np{bi, g, du, dv, FixedList<scalar, nW>()};
        for (label j = 0; j < nW; ++j)
        {
            np.c[j] = closing(bd.i, bd.j, du, dv, Hw[j]);
        }
        near_.append(np);
    }
}


void Foam::fiberInteractions::contactWindows::adaptSkin
(
    const label jBest,
    const scalar Hs,
    const scalar tLeft,
    const label nCand
)
{
    // Twice as thick where the longest window was the cheapest and did
    // not reach the step's end (while the search finds at most 8 pairs
    // per segment), half as thick where one at most a quarter as long was
    // (pairs over all processors: the same on any number of them)
    label nSeg = 0;
    for (const segment& sg : *segs_)
    {
        nSeg += sg.local >= 0;
    }
    const scalar pairsPerSeg =
        scalar(returnReduce(nCand, sumOp<label>()))
       /max(returnReduce(nSeg, sumOp<label>()), 1);
    if (jBest == 0 && Hs < (1 - 1e-9)*tLeft && pairsPerSeg < 8)
    {
        skin_ = min(2*skin_, 16.0);
    }
    else if (jBest >= 2 || pairsPerSeg > 32)
    {
        skin_ = max(0.5*skin_, 0.5);
    }
}


// * * * * * * * * * * * * * * * * The window  * * * * * * * * * * * * * * //

Foam::scalar Foam::fiberInteractions::contactWindows::choose
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const Map<label>& present,
    const scalar r,
    const scalar skin,
    const scalar tLeft,
    UList<bool>& engaged,
    label& nMissed
)
{
    segs_ = &segs;
    present_ = &present;
    makeBounds(cand);
    kick_ = contactKick();
    makeTerms();
    farMaxima(r, skin);
    wallHits(tLeft);

    // The longest window, Hs, and its halves to a 32nd; the pairs that
    // could close within Hs with a kick
    const scalar Hs = longest(tLeft, skin);
    FixedList<scalar, nW> Hw;
    for (label j = 0; j < nW; ++j)
    {
        Hw[j] = tLeft/std::ceil(tLeft/(Hs/pow(2.0, j))*(1 - 1e-9));
    }
    nearPairs(Hw, skin);

    // Every fiber ends a sub-step at a window's end, and an engaged fiber
    // at each of its intervals, about contactSteps per contact time: of
    // the windows Hw the one with the fewest such stops per unit time,
    // (moving fibers + engaged ones x intervals in it)/H
    const List<bool> owes(engaged);
    label nMove = 0;
    for (const role rl : roles)
    {
        nMove += rl == role::free;
    }
    reduce(nMove, sumOp<label>());
    const scalar hc = model_.tcWindow_/model_.contactSteps_;
    label jBest = 0;
    scalar costBest = GREAT;
    List<bool> eng(engaged.size());
    for (label j = 0; j < nW; ++j)
    {
        label n = 0;
        engage(fibers, owes, Hw[j], j, eng, n);
        const scalar cost =
            (nMove + nEngaged(roles, eng)*max(1, Hw[j]/hc))/Hw[j];
        if (cost < costBest)
        {
            costBest = cost;
            jBest = j;
        }
    }

    // The pairs that may meet within the window may kick their fibers at
    // up to their relative speed: where that is more than the kicks
    // allowed for, the window is taken again with it (at most twice)
    scalar H = 0;
    for (label pass = 0; pass < 3; ++pass)
    {
        H = min(Hw[jBest], longest(tLeft, skin));
        label n = 0;
        const scalar meetKick =
            engage(fibers, owes, H, H == Hw[jBest] ? jBest : -1, eng, n);
        if (meetKick <= kick_ || pass == 2)
        {
            nMissed = n;
            break;
        }
        kick_ = meetKick;
    }
    forAll(engaged, fi)
    {
        engaged[fi] = eng[fi];
    }

    adaptSkin(jBest, Hs, tLeft, cand.size());
    denseFraction_ = nMove > 0 ? scalar(nEngaged(roles, eng))/nMove : 0;
    segs_ = nullptr;
    present_ = nullptr;
    return H;
}


// ************************************************************************* //
