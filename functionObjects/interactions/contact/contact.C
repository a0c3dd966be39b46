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

#include "contact.H"
#include "segmentDistance.H"
#include "keywordCheck.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"
#include "HashSet.H"
#include "Switch.H"

#include <algorithm>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberInteractions
{
    defineTypeNameAndDebug(contact, 0);
    addToRunTimeSelectionTable(fiberInteraction, contact, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A pair's load on this side's fiber (contact::contribution)
typedef fiberInteractions::contact::contribution contribution;


//- The contributions added to the loads
void applyLoads
(
    const UPtrList<fiber>& fibers,
    DynamicList<contribution>& parts,
    UList<fiberIntegrator::load>& loads
)
{
    // Summed in an order that does not depend on the decomposition: by
    // fiber, then partner and segments
    std::sort
    (
        parts.begin(),
        parts.end(),
        [](const contribution& a, const contribution& b)
        {
            return a.key < b.key;
        }
    );
    for (const contribution& cp : parts)
    {
        // The explicit force with the dashpot's part C vp, at the contact
        // point (of a flexible fiber: on its segment)
        fiberIntegrator::load& l = loads[cp.local];
        const fiber& f = fibers[cp.local];
        l.addForce(f, cp.key[1], cp.F + (cp.C & cp.vp), cp.c);
        if (!(magSqr(cp.K) > 0))
        {
            continue;
        }
        if (cp.key[0] != cp.key[2])
        {
            l.addSpring(f, cp.key[1], cp.K, cp.C, cp.r, cp.vp);
        }
        else if (cp.key[1] < cp.key[3])
        {
            // A self-contact: one spring between the two segments, coupled
            // in the chain's step
            l.addLink
            (
                f, cp.key[1], cp.key[3], cp.r, cp.rOther, cp.K, cp.C
            );
        }
    }
}


//- Whether a pair's key is from the side that comes first (the lower
//  fiber id; of one fiber, the lower segment)
inline bool firstSide(const fiberInteractions::contact::pairKey& k)
{
    return k[0] < k[2] || (k[0] == k[2] && k[1] < k[3]);
}


//- A unit vector normal to v
vector normalTo(const vector& v)
{
    const vector e
    (
        mag(v.x()) < 0.9*mag(v) ? vector(1, 0, 0) : vector(0, 1, 0)
    );
    return normalised(v ^ e);
}

} // End anonymous namespace


const Foam::scalar
Foam::fiberInteractions::contact::maxIntervalsPerStep = 1e6;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberInteractions::contact::contact
(
    const dictionary& dict,
    const polyMesh& mesh,
    const scalar rhoFluid
)
:
    mesh_(mesh),
    law_(),
    contactSteps_(20),
    range_(0),
    implicit_(false),
    scheme_(),
    maxApproach_(0.25),
    hLast_(0),
    warnedFlexible_(false),
    skinNext_(-1),
    periodic_(),
    rec_(),
    pairs_(),
    touching_(),
    onFixed_(),
    nCollisions_(0),
    windows_(*this),
    tcWindow_(-1),
    nMissed_(0),
    nJumped_(0),
    sweptEnd_(-GREAT),
    sweptH_(0),
    nLimited_(Zero)
{
    read(dict, rhoFluid);
    findPeriodic();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::contact::read
(
    const dictionary& dict,
    const scalar rhoFluid
)
{
    law_ = fiberContactLaw::New(dict);
    range_ = law_->range();
    wordList known
    ({
        "type", "contactSteps", "implicit", "maxApproach", "scheme"
    });
    known.append(fiberContactLaw::commonKeywords());
    known.append(law_->keywords());
    keywordCheck::warnUnknown(dict, known, "interactions (contact)");
    contactSteps_ = dict.getOrDefault<label>("contactSteps", 20);
    if (contactSteps_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'contactSteps' must be at least 1, not "
            << contactSteps_ << exit(FatalIOError);
    }
    readScheme(dict, rhoFluid);
    maxApproach_ = keywordCheck::positive(dict, "maxApproach", 0.25);
    keywordCheck::noEffect
    (
        dict, implicit_ ? "contactSteps" : "maxApproach",
        scheme_->intervalsRule()
    );
    // A two-dimensional case (empty or wedge patches) holds every fiber in
    // one plane: two fibers that cross there meet axis to axis, and the
    // contact's normal (across both axes) points out of that plane
    if (mesh_.nGeometricD() < 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'interactions' (type contact): the case is"
            << " two-dimensional (" << mesh_.nGeometricD()
            << " geometric directions: empty or wedge patches).  Its"
            << " fibers all lie in one plane, where two fibers that cross"
            << " meet axis to axis and the contact would push them out of"
            << " the plane the case holds them in.  Fiber contacts need a"
            << " three-dimensional case (interactions { type none; } here)."
            << exit(FatalIOError);
    }

    Info<< "    Fiber contacts: ";
    law_->describe(Info);
    scheme_->describe(Info);
    if (law_->cohesionStrength() > 0)
    {
        Info<< ", cohesion " << law_->cohesionStrength() << " N within "
            << range_ << " m";
    }
    Info<< endl;
}


void Foam::fiberInteractions::contact::readScheme
(
    const dictionary& dict,
    const scalar rhoInf
)
{
    // 'scheme' explicit, implicit or constraints; 'implicit on' is
    // 'scheme implicit' (the entry before 'scheme' was).  By default
    // constraints in a liquid (the fiberTracking entry's rhoInf at least
    // 100 kg/m3: the fluid damps collisions, and the form is cheap and
    // exact there), explicit in a gas (fibers bounce: exact restitution)
    const bool implicitOn = dict.getOrDefault<Switch>("implicit", false);
    const word byDefault
    (
        implicitOn ? "implicit" : rhoInf >= 100 ? "constraints" : "explicit"
    );
    const word scheme(dict.getOrDefault<word>("scheme", byDefault));
    if (!dict.found("scheme") && !implicitOn)
    {
        Info<< "    Fiber contacts: scheme " << scheme << " (the default "
            << (rhoInf >= 100 ? "in a liquid" : "in a gas") << ", rhoInf "
            << rhoInf << " kg/m3; "
            << (
                   rhoInf >= 100
                 ? "'scheme explicit' for fibers that bounce)"
                 : "'scheme constraints' for contacts solved per island)"
               )
            << endl;
    }
    if (!fiberContactScheme::found(scheme))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'scheme' must be explicit (springs resolved in time:"
            << " bouncing, exact restitution), implicit (implicit springs"
            << " on each fiber) or constraints (the contacts of fibers that"
            << " touch solved together per island), not '" << scheme << "'"
            << " (schemes: "
            << fiberContactScheme::modelConstructorTablePtr_->sortedToc()
            << ")" << exit(FatalIOError);
    }
    if (dict.found("implicit") && dict.found("scheme") && implicitOn)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'implicit on' and 'scheme " << scheme << "' both"
            << " given: 'implicit on' is 'scheme implicit'; keep one"
            << exit(FatalIOError);
    }
    scheme_ = fiberContactScheme::New(scheme, dict, *this);
    implicit_ = scheme_->adaptive();
}


Foam::vector Foam::fiberInteractions::contact::previousSpring
(
    const pairKey& k,
    pairKey& from
) const
{
    // The contact's own, or one that moved to it from a neighbouring
    // segment of either fiber (across a joint)
    from = k;
    const auto it = rec_.springs().cfind(k);
    if (it.found() || rec_.springs().empty())
    {
        return it.found() ? *it : vector(Zero);
    }
    for (label a = -1; a <= 1; ++a)
    {
        for (label b = -1; b <= 1; ++b)
        {
            const pairKey n{k[0], k[1] + a, k[2], k[3] + b};
            const auto jt = rec_.springs().cfind(n);
            if (jt.found())
            {
                from = n;
                return *jt;
            }
        }
    }
    return Zero;
}


Foam::vector Foam::fiberInteractions::contact::tangential
(
    const vector& n,
    const vector& vt,
    const scalar Fn,
    const scalar delta,
    const scalar m,
    const pairKey& k,
    const scalar h,
    springTable& springs,
    bool& sticks,
    vector& xiStart,
    scalar& cSlide
) const
{
    // The spring of the contact, turned into the present contact plane
    // (its length kept), and stretched by the tangential motion over the
    // interval
    pairKey from(k);
    vector xi(previousSpring(k, from));
    const scalar len = mag(xi);
    xi -= (xi & n)*n;
    const scalar lenT = mag(xi);
    if (lenT > 0)
    {
        xi *= len/lenT;
    }
    xiStart = xi;
    const scalar kt = law_->tangentialStiffness(delta);
    const scalar ct = law_->tangentialDamping(m, delta);
    const scalar FtMax = law_->friction()*mag(Fn);

    if (implicit_)
    {
        // Sticking: the spring's force at the start, its stretch and the
        // dashpot implicit.  Sliding (where settle() found the spring
        // beyond Coulomb's bound, or a new contact that slides by more
        // than the spring can hold in the interval): the spring held at
        // the bound along the sliding and Coulomb's force; where the
        // sliding slowed down in the last interval and friction alone
        // could stop it within this one, Coulomb's force as an implicit
        // dashpot, F = -mu F_n v_t/max(|v_t|, mu F_n h/m) at the present
        // speed (no overshoot as the sliding stops)
        const label mode = rec_.sliding().lookup(from, 0);
        const bool slid =
            mode > 0 || (!rec_.springs().found(from) && kt*mag(vt)*h > FtMax);
        sticks = !slid;
        cSlide = 0;
        if (sticks)
        {
            springs.set(k, xi);
            return -kt*xi;
        }
        const vector dir(mode > 0 && mag(xi) > 0 ? xi : vt);
        const scalar ld = mag(dir);
        xi = ld > 0 ? vector((FtMax/kt/ld)*dir) : vector(Zero);
        xiStart = xi;
        springs.set(k, xi);
        if (mode == 2 && mag(vt) < 4*FtMax*h/m)
        {
            // Slowing down, slowly enough for friction alone to stop it
            // within the interval: the dashpot, so that it does not
            // overshoot
            cSlide = FtMax/max(mag(vt), max(FtMax*h/m, VSMALL));
            return Zero;
        }
        return -kt*xi;
    }

    const vector xiEnd(xi + vt*h);
    vector Ft(-kt*xiEnd - ct*vt);
    sticks = mag(Ft) <= FtMax;
    if (!sticks)
    {
        // Sliding: Coulomb's force along the spring, which is reset to
        // hold it
        Ft *= FtMax/mag(Ft);
        springs.set(k, -Ft/kt);
        return Ft;
    }
    springs.set(k, xiEnd);
    return Ft;
}


bool Foam::fiberInteractions::contact::ownsContact
(
    const segment& A,
    const scalar s,
    const vector& d
)
{
    // A closest point at a joint belongs to the segment on the side where
    // the axis comes closer (d from the other's closest point), to the one
    // after the joint if neither does (the partner beyond the joint on
    // both segments' axes: beside a straight chain, or outside the bend of
    // a bent one); one at a free end or inside, to this one
    const scalar tol = 1e-9*mag(d);
    if (s >= 1 && A.seg < A.nSeg - 1)
    {
        return (d & (A.b - A.a)/max(mag(A.b - A.a), VSMALL)) > tol;
    }
    if (s <= 0 && A.seg > 0)
    {
        return (d & A.zPrev) <= tol;
    }
    return true;
}


void Foam::fiberInteractions::contact::implicitSprings
(
    const segment& A,
    const segment& B,
    const vector& vA,
    const vector& vB,
    const vector& n,
    const scalar m,
    const scalar delta,
    const bool sticks,
    const scalar cSlide,
    pairLoad& p
) const
{
    // Each side moves against the partner's predicted velocity as if the
    // partner moved oppositely (a free pair: twice the spring on one
    // side's motion) or not at all (a fixed one).  Two segments of one
    // fiber (a self-contact): the spring itself on their relative motion,
    // which the chain's step solves (fiberIntegrator::link)
    const bool self = A.fiber == B.fiber;
    const bool free = A.m > 0 && B.m > 0 && !self;
    const scalar phi = free ? 2 : 1;
    p.vp =
        self ? vector(Zero) : free ? 0.5*(vA + vB) : (A.m > 0 ? vB : vA);
    const tensor nn(sqr(n));
    p.K = (phi*law_->normalStiffness(delta))*nn;
    p.C = (phi*law_->normalDamping(m, delta))*nn;
    if (sticks)
    {
        p.K += (phi*law_->tangentialStiffness(delta))*(tensor::I - nn);
        p.C += (phi*law_->tangentialDamping(m, delta))*(tensor::I - nn);
    }
    else
    {
        p.C += (phi*cSlide)*(tensor::I - nn);
    }
}


Foam::fiberInteractions::contact::pairGeometry
Foam::fiberInteractions::contact::geometry
(
    const segment& A,
    const segment& B
) const
{
    const segmentDistance::result r =
        segmentDistance::closest(A.a, A.b, B.a, B.b);
    const scalar dist = std::sqrt(r.distSqr);
    pairGeometry g;
    g.delta = 0.5*(A.d + B.d) - dist;
    g.owns =
        ownsContact(A, r.s, r.a - r.b) && ownsContact(B, r.t, r.b - r.a);
    g.touching =
        (
            g.delta > 0
         || (law_->cohesionStrength() > 0 && -g.delta < range_)
        )
     && g.owns;
    g.close = g.owns && -g.delta < range_ + 0.1*min(A.d, B.d);

    // Normal from B to A; axes that meet: normal to both
    if (dist > 1e-12*(A.d + B.d))
    {
        g.n = (r.a - r.b)/dist;
    }
    else
    {
        const vector cr((A.b - A.a) ^ (B.b - B.a));
        g.n = mag(cr) > 0 ? normalised(cr) : normalTo(A.b - A.a);
    }
    g.c = 0.5*((r.a - 0.5*A.d*g.n) + (r.b + 0.5*B.d*g.n));
    return g;
}


bool Foam::fiberInteractions::contact::pairForce
(
    const segment& A,
    const segment& B,
    const pairKey& k,
    const scalar h,
    springTable& springs,
    pairLoad& p
) const
{
    const pairGeometry g(geometry(A, B));
    const scalar delta = g.delta;
    p.touching = g.touching;
    p.close = g.close;
    p.F = Zero;
    p.K = Zero;
    p.C = Zero;
    p.vp = Zero;
    p.sticks = false;
    p.xi = Zero;
    p.xiMax = 0;
    p.vt0 = 0;
    if (!p.touching)
    {
        return false;
    }
    const vector& n = g.n;
    p.n = n;
    p.c = g.c;

    const vector vA(A.v + (A.w ^ (p.c - A.x)));
    const vector vB(B.v + (B.w ^ (p.c - B.x)));
    const vector vrel(vA - vB);
    const scalar vn = vrel & n;
    const scalar m = reducedMass(A.m, B.m);

    scalar Fn = 0;
    if (delta > 0)
    {
        const fiberContactLaw& law = law_();
        const scalar cn = law.normalDamping(m, delta);
        const scalar Fs = law.springForce(delta);
        Fn = Fs - cn*vn;
        bool sticks = false;
        scalar cSlide = 0;
        if (law.friction() > 0)
        {
            p.F =
                tangential
                (
                    n, vrel - vn*n, implicit_ ? Fs : Fn, delta, m, k, h,
                    springs, sticks, p.xi, cSlide
                );
            p.sticks = sticks;
            p.vt0 = mag(vrel - vn*n);
            p.xiMax =
                law.friction()*(implicit_ ? Fs : mag(Fn))
               /law.tangentialStiffness(delta);
        }
        if (implicit_)
        {
            implicitSprings
            (
                A, B, vA, vB, n, m, delta, sticks, cSlide, p
            );
            Fn = Fs;
        }
    }
    Fn -= law_->cohesion(delta);
    p.F += Fn*n;
    return true;
}


void Foam::fiberInteractions::contact::count
(
    const DynamicList<FixedList<label, 2>>& touching,
    const DynamicList<FixedList<label, 2>>& close
)
{
    // Distinct fiber pairs, the other fibers each touches; a collision is
    // a pair that touches and has not touched since it was last apart
    // (more than a tenth of a diameter beyond touching): a pair that rests
    // at a touch, on and off, is one, and one that closes slowly is one
    // when it touches (it was counted only if it had not been within the
    // tenth at the last interval, so slow approaches were missed)
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> seen;
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> closeNow;
    for (const FixedList<label, 2>& c : close)
    {
        closeNow.insert(c);
    }
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> next;
    for (const FixedList<label, 2>& k : rec_.recent())
    {
        if (closeNow.found(k))
        {
            next.insert(k);
        }
    }
    touching_.clear();
    pairs_.clear();
    label nNew = 0;
    for (const FixedList<label, 2>& t : touching)
    {
        if (!seen.insert(t))
        {
            continue;
        }
        next.insert(t);
        touching_(t[0]) = touching_.lookup(t[0], 0) + 1;
        if (t[0] < t[1])
        {
            pairs_.append(t);
            if (!rec_.recent().found(t))
            {
                ++nNew;
            }
        }
    }
    rec_.recent().transfer(next);
    nCollisions_ += returnReduce(nNew, sumOp<label>());
}


void Foam::fiberInteractions::contact::recordFixedTouches
(
    const UList<segment>& segs,
    const DynamicList<FixedList<label, 2>>& touching
)
{
    onFixed_.clear();
    if (touching.empty())
    {
        return;
    }
    labelHashSet partners(2*touching.size());
    for (const FixedList<label, 2>& t : touching)
    {
        partners.insert(t[1]);
    }
    Map<vector> fixedV;
    for (const segment& s : segs)
    {
        if (!(s.m > 0) && partners.found(s.fiber))
        {
            fixedV.set(s.fiber, s.v);
        }
    }
    for (const FixedList<label, 2>& t : touching)
    {
        const auto it = fixedV.cfind(t[1]);
        if (it.found())
        {
            onFixed_.set(t[0], *it);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fiberInteractions::contact::contactTime
(
    const scalar m
) const
{
    return law_->contactTime(m);
}


void Foam::fiberInteractions::contact::checkCost
(
    const dictionary& dict,
    const scalar m,
    const scalar dt
) const
{
    if (implicit_ || !(m < GREAT) || !(dt > 0))
    {
        return;
    }
    const scalar tc = contactTime(m/8);
    const scalar n = std::ceil(dt*contactSteps_/tc*(1 - 1e-9));
    // (the linear law's stiffness; a law whose stiffness grows with the
    // overlap: at touching)
    const scalar kn = law_->normalStiffness(0);
    Info<< "    Explicit contacts: contact time " << tc << " s (lightest"
        << " body " << m << " kg, k_n " << kn << " N/m): a step of " << dt
        << " s takes " << n << " intervals of the fibers that touch"
        << endl;
    if (n > maxIntervalsPerStep)
    {
        // The stiffness that gives the limit, to two digits
        std::ostringstream kMax;
        kMax << std::setprecision(2) << kn*sqr(maxIntervalsPerStep/n);
        FatalIOErrorInFunction(dict)
            << "Entry 'stiffness' " << kn << " N/m: the contact time of"
            << " the lightest pair (body of " << m << " kg) is " << tc
            << " s, and 'contactSteps' " << contactSteps_ << " intervals"
            << " per contact time make " << n << " intervals in one step"
            << " of " << dt << " s wherever fibers touch (the limit is "
            << maxIntervalsPerStep << ", already some ten seconds of CPU"
            << " per step for a single pair).  Lower 'stiffness' (the"
            << " intervals go with its square root: " << kMax.str().c_str()
            << " N/m gives the limit), lower 'contactSteps', or use"
            << " 'scheme constraints' (intervals set by how fast pairs"
            << " approach, not by the contact time; collisions inelastic)"
            << exit(FatalIOError);
    }
}


Foam::scalar Foam::fiberInteractions::contact::shortestContactTime
(
    const UPtrList<fiber>& fibers
) const
{
    scalar mMin = GREAT;
    for (const fiber& f : fibers)
    {
        mMin = min(mMin, f.mass());
        for (label i = 0; f.flexible() && i < f.nSegments(); ++i)
        {
            mMin = min(mMin, f.segmentMass(i));
        }
    }
    reduce(mMin, minOp<scalar>());
    return mMin < GREAT ? contactTime(mMin/8) : GREAT;
}


void Foam::fiberInteractions::contact::warnFlexible
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles
)
{
    if (warnedFlexible_)
    {
        return;
    }
    bool flexible = false;
    forAll(fibers, fi)
    {
        flexible =
            flexible
         || (fibers[fi].flexible() && roles[fi] == role::free);
    }
    if (returnReduce(flexible, orOp<bool>()))
    {
        warnedFlexible_ = true;
        WarningInFunction
            << "Implicit contacts with flexible fibers: contacts"
            << " between two flexible fibers have a known defect (the"
            << " two sides' impulses need not cancel, and what is paid"
            << " back can build up and kick the chains; docs/model.md,"
            << " section 7).  Use implicit off where flexible fibers"
            << " touch each other and their impulses matter." << endl;
    }
}


Foam::scalar Foam::fiberInteractions::contact::approachInterval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar tc,
    const scalar tLeft,
    scalar& vFar
)
{
    label why = -1;
    // Pairs within reach and a skin: how fast they close (adaptive:
    // every interval), growing at most twofold from one interval to
    // the next, from the contact time at the start (kept for the
    // interval's interact, at the same time).  The skin: three times
    // what the far pairs could close in the last interval (the next
    // may be twice as long), within a twentieth and a half of the
    // reach; half the reach at the start.  Where it is thin the search
    // and the interval limit test fewer pairs; the interval never
    // lets a far pair close more than the skin
    DynamicList<segment>& segs = near_.segs;
    DynamicList<FixedList<label, 2>>& cand = near_.cand;
    segs.clear();
    cand.clear();
    near_.inReach.clear();
    near_.lambda = 0;
    const scalar r0 = reach(fibers, roles);
    near_.skin =
        skinNext_ < 0 ? 0.5*r0 : min(max(skinNext_, 0.05*r0), 0.5*r0);
    near_.r = gather(fibers, roles, segs, nullptr, near_.skin);
    candidates
    (
        segs, near_.r, cand, near_.skin, &near_.inReach, &near_.lambda
    );
    near_.valid = true;
    const scalar hMax =
        approachLimit
        (
            segs, cand, near_.lambda, near_.r, near_.skin,
            min(hLast_ > 0 ? 2*hLast_ : tc, tLeft), vFar, why
        );
    if (why < 0)
    {
        const scalar cap = hLast_ > 0 ? 2*hLast_ : tc;
        why =
            tLeft <= cap ? limit::stepEnd
          : hLast_ > 0 ? limit::growth
          : limit::first;
    }
    ++nLimited_[why];
    return hMax;
}


Foam::scalar Foam::fiberInteractions::contact::equalParts
(
    const scalar hMax,
    const scalar tLeft
)
{
    return
        hMax < tLeft*(1 - 1e-9)
      ? tLeft/std::ceil(tLeft/hMax*(1 - 1e-9))
      : tLeft;
}


Foam::scalar Foam::fiberInteractions::contact::adaptiveInterval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar tLeft,
    const scalar tc
)
{
    // The longest interval the approach allows; the rest of the step split
    // into equal parts no longer than that; the next skin from what the
    // far pairs could close in it
    scalar vFar = 0;
    const scalar hMax = approachInterval(fibers, roles, tc, tLeft, vFar);
    const scalar h = equalParts(hMax, tLeft);
    skinNext_ = 3*vFar*h;
    return h;
}


Foam::scalar Foam::fiberInteractions::contact::nextInterval
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar dt,
    const scalar tLeft
)
{
    if (!(tLeft > 0))
    {
        return tLeft;
    }

    // The contact time of the lightest fiber, or of a flexible fiber's
    // lightest segment (the body a contact strikes)
    const scalar tc = tcWindow_ > 0 ? tcWindow_ : shortestContactTime(fibers);
    return scheme_->interval(fibers, roles, dt, tLeft, tc);
}


void Foam::fiberInteractions::contact::payBack
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar h,
    UList<fiberIntegrator::load>& loads
)
{
    if (rec_.pending().empty() || !(h > 0))
    {
        return;
    }
    forAll(fibers, fi)
    {
        if (roles[fi] == role::absent)
        {
            continue;
        }
        const fiber& f = fibers[fi];
        const tensor R(f.R());
        for (label i = -1; i < (f.flexible() ? f.nSegments() : 0); ++i)
        {
            const auto it =
                rec_.pending().cfind(FixedList<label, 2>{f.id(), i});
            if (!it.found())
            {
                continue;
            }
            // The impulse and its moment about the centre (of a flexible
            // fiber: of the segment), over h (implicit: the sub-steps do
            // not count it as their error)
            const vector F((*it)[0]/h);
            const point c
            (
                f.position() + (i < 0 ? vector(Zero) : f.segmentOffset(R, i))
            );
            fiberIntegrator::load& l = loads[fi];
            l.implicit = true;
            l.F += F;
            l.M += (c ^ F) + (*it)[1]/h;
            if (i >= 0)
            {
                fiberIntegrator::load& s = l.segment(f, i);
                s.F += F;
                s.M += (c ^ F) + (*it)[1]/h;
            }
            rec_.pending().erase(FixedList<label, 2>{f.id(), i});
        }
    }
}


void Foam::fiberInteractions::contact::pairsInReach
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    DynamicList<segment>& segs,
    DynamicList<FixedList<label, 2>>& cand
)
{
    if (near_.valid)
    {
        // The search of nextInterval at this time: its pairs within reach
        segs.transfer(near_.segs);
        cand.transfer(near_.inReach);
        near_.cand.clear();
        near_.valid = false;
        return;
    }
    const scalar r = gather(fibers, roles, segs);
    candidates(segs, r, cand);
}


void Foam::fiberInteractions::contact::springLoads
(
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar h,
    springTable& next,
    DynamicList<contribution>& parts,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    for (const FixedList<label, 2>& ij : cand)
    {
        const segment& Q = segs[ij[0]];
        const segment& P = segs[ij[1]];

        // The pair from this side, always in one order: the lower fiber
        // id first (of one fiber: the lower segment)
        const bool self = Q.fiber == P.fiber;
        const bool qFirst = Q.fiber < P.fiber || (self && Q.seg < P.seg);
        const pairKey k{Q.fiber, Q.seg, P.fiber, P.seg};
        pairLoad pl;
        const bool acts =
            pairForce(qFirst ? Q : P, qFirst ? P : Q, k, h, next, pl);
        if (pl.close && !self)
        {
            close.append(FixedList<label, 2>{Q.fiber, P.fiber});
        }
        if (!acts)
        {
            continue;
        }
        if (!self)
        {
            touching.append(FixedList<label, 2>{Q.fiber, P.fiber});
        }
        if (Q.m > 0)
        {
            const vector FQ(qFirst ? pl.F : -pl.F);
            parts.append
            (
                contribution
                {
                    k, Q.local, FQ, pl.c, pl.c - Q.x, pl.c - P.x, pl.K,
                    pl.C, pl.vp
                }
            );
            if (implicit_ && magSqr(pl.K) > 0)
            {
                rec_.records().set
                (
                    k,
                    pairRecord
                    {
                        FQ, pl.K, pl.C, pl.vp, pl.c - Q.x, pl.c - P.x,
                        pl.n, pl.sticks, pl.xi, pl.xiMax, pl.vt0
                    }
                );
            }
        }
    }
}


void Foam::fiberInteractions::contact::springInteract
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar h,
    springTable& next,
    UList<fiberIntegrator::load>& loads,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    // The loads on this processor's fibers, by pair, and the impulses to
    // pay back (implicit)
    DynamicList<contribution> parts;
    springLoads(segs, cand, h, next, parts, touching, close);
    applyLoads(fibers, parts, loads);
    payBack(fibers, roles, h, loads);
}


void Foam::fiberInteractions::contact::interact
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar t,
    const scalar h,
    UList<fiberIntegrator::load>& loads
)
{
    hLast_ = h;
    if (near_.valid)
    {
        missedGrazes(t, h, near_.segs, near_.cand);
    }
    else
    {
        sweptCand_.clear();
    }
    DynamicList<segment> segs;
    DynamicList<FixedList<label, 2>> cand;
    pairsInReach(fibers, roles, segs, cand);

    springTable next(2*rec_.springs().size() + 16);
    DynamicList<FixedList<label, 2>> touching;
    DynamicList<FixedList<label, 2>> close;
    rec_.records().clear();

    // The scheme's loads (fiberContactScheme)
    scheme_->loads(fibers, roles, segs, cand, h, next, loads, touching, close);
    rec_.springs().transfer(next);
    if (rec_.sliding().size())
    {
        // Contacts that ended
        for (const pairKey& k : rec_.sliding().toc())
        {
            if (!rec_.springs().found(k))
            {
                rec_.sliding().erase(k);
            }
        }
    }
    count(touching, close);
    recordFixedTouches(segs, touching);

    // The buffers back, for the next interval's search (their capacity)
    segs.clear();
    cand.clear();
    near_.segs.transfer(segs);
    near_.inReach.transfer(cand);
}


Foam::vector Foam::fiberInteractions::contact::impulse
(
    const pairRecord& p,
    const vector& F,
    const vector& r,
    const segment& s
)
{
    // Over the sub-steps h (ends): F + C vp - K (dX + dTheta x r - vp tau)
    // - C (V + w x r)
    return
        (F + (p.C & p.vp))*s.H
      - (p.K & (s.sX + (s.sTheta ^ r) - p.vp*s.sTau))
      - (p.C & (s.sV + (s.sW ^ r)));
}


void Foam::fiberInteractions::contact::settleFriction
(
    const pairKey& k,
    const pairRecord& p,
    const segment& Q,
    const segment& O
)
{
    // A sticking contact's spring is stretched by the relative tangential
    // displacement of the contact point (lower fiber id first); beyond
    // Coulomb's bound it slides from the next interval on, held at the
    // bound.  A sliding contact goes on sliding while its tangential
    // velocity keeps the direction
    const scalar sgn = firstSide(k) ? 1 : -1;
    if (p.sticks)
    {
        const vector u
        (
            sgn
           *(
                (Q.dX + (Q.dTheta ^ p.rThis))
              - (O.dX + (O.dTheta ^ p.rOther))
            )
        );
        vector xi(p.xi + u - (u & p.n)*p.n);
        if (mag(xi) > p.xiMax)
        {
            xi *= p.xiMax/mag(xi);
            rec_.sliding().set(k, 1);
        }
        rec_.springs().set(k, xi);
        return;
    }
    const vector v
    (
        sgn*((Q.v + (Q.w ^ p.rThis)) - (O.v + (O.w ^ p.rOther)))
    );
    const vector vt(v - (v & p.n)*p.n);
    if ((vt & p.xi) > 0)
    {
        rec_.springs().set(k, (p.xiMax/mag(vt))*vt);
        rec_.sliding().set(k, mag(vt) < p.vt0 ? 2 : 1);
    }
    else
    {
        rec_.sliding().erase(k);
    }
}


void Foam::fiberInteractions::contact::balancePair
(
    const UPtrList<fiber>& fibers,
    const UList<fiberIntegrator::load>& loads,
    const pairKey& k,
    const pairRecord& p,
    const segment& Q,
    const segment& O
)
{
    // A fixed partner, or one that did not move in the interval, or a
    // self-contact (solved as a pair in the chain's step): no pair to
    // balance
    if (!(O.m > 0) || !(O.H > 0) || !(Q.H > 0) || k[0] == k[2])
    {
        return;
    }
    const vector JQ(impulse(p, p.F, p.rThis, Q));
    const vector JO(impulse(p, -p.F, p.rOther, O));
    const vector J(-0.5*(firstSide(k) ? JQ + JO : JO + JQ));
    const FixedList<label, 2> to{k[0], Q.flexible ? k[1] : -1};
    if (!rec_.pending().found(to))
    {
        rec_.pending().insert(to, FixedList<vector, 2>(vector::zero));
    }
    FixedList<vector, 2>& back = rec_.pending()[to];
    back[0] += J;

    // Its moment, save the component about the body's axis of least
    // inertia (a straight fiber's own axis, a segment's): what is paid
    // back is the two sides' numerical mismatch, and about that axis
    // the inertia is (L/d)^2 times smaller than across it.  With
    // friction the mismatch is tangential, at the surface: paid back
    // about the axis, it spun heavy fibers in a liquid (pipeCyclic,
    // Stokes number 0.4) to 10^4 rad/s and 5 m/s in a 1.4 m/s flow
    const fiberIntegrator::load& l = loads[Q.local];
    const vector e
    (
        Q.flexible && k[1] < label(l.seg.size())
      ? normalised(Q.b - Q.a)
      : fibers[Q.local].R() & l.axisBody
    );
    const vector MJ(p.rThis ^ J);
    back[1] += MJ - e*(e & MJ);
}


void Foam::fiberInteractions::contact::settle
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<fiberIntegrator::load>& loads
)
{
    scheme_->settle(fibers, roles, loads);
}


void Foam::fiberInteractions::contact::settleSprings
(
    const UPtrList<fiber>& fibers,
    const UList<role>& roles,
    const UList<fiberIntegrator::load>& loads
)
{

    // Each implicit contact's two sides took impulses J_A and J_B of
    // which the sum is not zero where the partners did not move as each
    // side predicted: each gets -(J_A + J_B)/2 back at the contact point
    // at the next interval, so the pair's impulses are equal and opposite
    // Only the fibers of a contact of the interval take part, and the
    // fixed ones (each moving side of a pair has its record, a fixed one
    // none: so a partner on another processor is there too, within reach
    // of this one's fibers that take part)
    labelHashSet inContact(2*rec_.records().size() + 16);
    forAllConstIters(rec_.records(), iter)
    {
        inContact.insert(iter.key()[0]);
        inContact.insert(iter.key()[2]);
    }
    settleRoles_.setSize(roles.size());
    forAll(roles, fi)
    {
        settleRoles_[fi] =
            roles[fi] == role::fixed || inContact.found(fibers[fi].id())
          ? roles[fi]
          : role::absent;
    }
    DynamicList<segment>& segs = settleSegs_;
    segs.clear();
    gather(fibers, settleRoles_, segs, &loads);
    HashTable<label, FixedList<label, 2>, FixedList<label, 2>::Hash<>>
        where(2*segs.size());
    forAll(segs, i)
    {
        where.insert(FixedList<label, 2>{segs[i].fiber, segs[i].seg}, i);
    }
    for (const pairKey& k : rec_.records().sortedToc())
    {
        const auto q = where.cfind(FixedList<label, 2>{k[0], k[1]});
        const auto o = where.cfind(FixedList<label, 2>{k[2], k[3]});
        if (!q.found() || !o.found() || segs[*q].local < 0)
        {
            continue;
        }
        const pairRecord& p = rec_.records()[k];
        const segment& Q = segs[*q];
        const segment& O = segs[*o];

        if (law_->friction() > 0)
        {
            settleFriction(k, p, Q, O);
        }

        balancePair(fibers, loads, k, p, Q, O);
    }
    rec_.records().clear();
}


void Foam::fiberInteractions::contact::writeFiber
(
    const label id,
    Ostream& os
) const
{
    // The fiber's tangential springs and (implicit) its contacts of the
    // interval (nothing is pending within an interval), its recent pairs
    rec_.writeFiber(id, os);
}


void Foam::fiberInteractions::contact::readFiber(Istream& is)
{
    rec_.readFiber(is);
}


void Foam::fiberInteractions::contact::writeRestart(Ostream& os) const
{
    // Between steps: the springs, and the impulses to pay back (implicit)
    rec_.writeSprings(os);
    rec_.writePending(os);
    os  << nl << "contactInterval " << hLast_ << token::SPACE << skinNext_
        << token::SPACE << windows_.skin();
    rec_.writeRecent(os);
}


void Foam::fiberInteractions::contact::readRestart(Istream& is)
{
    // A file written without contacts has none; each part after the
    // springs only where the file has it (older files: not)
    if (!rec_.readSprings(is) || !rec_.readPending(is))
    {
        return;
    }
    token h(is);
    if (h.isWord() && h.wordToken() == "contactInterval")
    {
        hLast_ = readScalar(is);

        // The skin (written since the skin adapts; older files: none)
        token s(is);
        if (s.isNumber())
        {
            skinNext_ = s.number();

            // The windows' skin (written since it adapts)
            token w(is);
            if (w.isNumber())
            {
                windows_.setSkin(w.number());
            }
            else if (w.good())
            {
                is.putBack(w);
            }
        }
        else if (s.good())
        {
            is.putBack(s);
        }
    }
    else if (h.good())
    {
        is.putBack(h);
    }
    rec_.readRecent(is);
}


// ************************************************************************* //
