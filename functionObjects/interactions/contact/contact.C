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

#include <algorithm>

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

//- A pair's force and moment on this side's fiber, with the pair's key
//  (this side's fiber and segment, the other's) for a fixed order
struct contribution
{
    fiberInteractions::contact::pairKey key;
    label local;
    vector F;
    vector M;
};


//- The reduced mass of two fibers (mass 0: fixed, infinite)
inline scalar reducedMass(const scalar a, const scalar b)
{
    if (a > 0 && b > 0)
    {
        return a*b/(a + b);
    }
    return a > 0 ? a : b;
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberInteractions::contact::contact
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    mesh_(mesh),
    kn_(0),
    e_(1),
    zeta_(0),
    mu_(0),
    ktRatio_(2.0/7.0),
    contactSteps_(20),
    cohesion_(0),
    range_(0),
    periodic_(),
    springs_(),
    pairs_(),
    touching_(),
    nCollisions_(0)
{
    read(dict);
    findPeriodic();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::contact::read(const dictionary& dict)
{
    keywordCheck::warnUnknown
    (
        dict,
        wordList
        ({
            "type", "stiffness", "restitution", "friction",
            "tangentialStiffness", "contactSteps", "cohesion"
        }),
        "interactions (contact)"
    );
    kn_ = keywordCheck::positive(dict, "stiffness");
    e_ = dict.get<scalar>("restitution");
    if (!(e_ > 0) || e_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'restitution' must lie in (0, 1], not " << e_
            << exit(FatalIOError);
    }
    const scalar lnE = std::log(e_);
    zeta_ = -lnE/std::sqrt(sqr(constant::mathematical::pi) + sqr(lnE));
    mu_ = dict.getOrDefault<scalar>("friction", 0);
    if (mu_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'friction' must not be negative, not " << mu_
            << exit(FatalIOError);
    }
    ktRatio_ = keywordCheck::positive(dict, "tangentialStiffness", 2.0/7.0);
    contactSteps_ = dict.getOrDefault<label>("contactSteps", 20);
    if (contactSteps_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'contactSteps' must be at least 1, not "
            << contactSteps_ << exit(FatalIOError);
    }
    if (dict.found("cohesion"))
    {
        const dictionary& c = dict.subDict("cohesion");
        keywordCheck::warnUnknown
        (
            c,
            wordList({"strength", "range"}),
            "interactions/cohesion"
        );
        cohesion_ = keywordCheck::positive(c, "strength");
        range_ = keywordCheck::positive(c, "range");
    }

    Info<< "    Fiber contacts: k_n " << kn_ << " N/m, restitution " << e_
        << " (damping ratio " << zeta_ << "), friction " << mu_
        << ", k_t/k_n " << ktRatio_ << ", " << contactSteps_
        << " intervals per contact time";
    if (cohesion_ > 0)
    {
        Info<< ", cohesion " << cohesion_ << " N within " << range_ << " m";
    }
    Info<< endl;
}


Foam::vector Foam::fiberInteractions::contact::tangential
(
    const vector& n,
    const vector& vt,
    const scalar Fn,
    const scalar m,
    const pairKey& k,
    const scalar h,
    springTable& springs
) const
{
    // The spring of the contact, turned into the present contact plane
    // (its length kept), and stretched by the tangential motion over the
    // interval
    vector xi(springs_.lookup(k, Zero));
    const scalar len = mag(xi);
    xi -= (xi & n)*n;
    const scalar lenT = mag(xi);
    if (lenT > 0)
    {
        xi *= len/lenT;
    }
    xi += vt*h;

    const scalar kt = ktRatio_*kn_;
    const scalar ct = 2*zeta_*std::sqrt(m*kt);
    vector Ft(-kt*xi - ct*vt);
    const scalar FtMax = mu_*mag(Fn);
    if (mag(Ft) > FtMax)
    {
        // Sliding: Coulomb's force along the spring, which is reset to
        // hold it
        Ft *= FtMax/mag(Ft);
        xi = -Ft/kt;
    }
    springs.set(k, xi);
    return Ft;
}


bool Foam::fiberInteractions::contact::pairForce
(
    const segment& A,
    const segment& B,
    const pairKey& k,
    const scalar h,
    springTable& springs,
    vector& F,
    point& c,
    bool& touching
) const
{
    const segmentDistance::result r =
        segmentDistance::closest(A.a, A.b, B.a, B.b);
    const scalar dist = std::sqrt(r.distSqr);
    const scalar delta = 0.5*(A.d + B.d) - dist;
    touching = delta > 0 || (cohesion_ > 0 && -delta < range_);
    if (!touching)
    {
        return false;
    }

    // Normal from B to A; axes that meet: normal to both
    vector n;
    if (dist > 1e-12*(A.d + B.d))
    {
        n = (r.a - r.b)/dist;
    }
    else
    {
        const vector cr((A.b - A.a) ^ (B.b - B.a));
        n = mag(cr) > 0 ? normalised(cr) : normalTo(A.b - A.a);
    }
    c = 0.5*((r.a - 0.5*A.d*n) + (r.b + 0.5*B.d*n));

    const vector vrel
    (
        (A.v + (A.w ^ (c - A.x))) - (B.v + (B.w ^ (c - B.x)))
    );
    const scalar vn = vrel & n;
    const scalar m = reducedMass(A.m, B.m);

    scalar Fn = 0;
    F = Zero;
    if (delta > 0)
    {
        Fn = kn_*delta - 2*zeta_*std::sqrt(m*kn_)*vn;
        if (mu_ > 0)
        {
            F = tangential(n, vrel - vn*n, Fn, m, k, h, springs);
        }
    }
    if (cohesion_ > 0)
    {
        Fn -= delta > 0 ? cohesion_ : cohesion_*(1 + delta/range_);
    }
    F += Fn*n;
    return true;
}


void Foam::fiberInteractions::contact::count
(
    const DynamicList<FixedList<label, 2>>& touching
)
{
    // Distinct fiber pairs, the other fibers each touches
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> seen;
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> before;
    for (const FixedList<label, 2>& p : pairs_)
    {
        before.insert(p);
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
        touching_(t[0]) = touching_.lookup(t[0], 0) + 1;
        if (t[0] < t[1])
        {
            pairs_.append(t);
            if (!before.found(t))
            {
                ++nNew;
            }
        }
    }
    nCollisions_ += returnReduce(nNew, sumOp<label>());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fiberInteractions::contact::contactTime
(
    const scalar m
) const
{
    return
        constant::mathematical::pi
       /std::sqrt(kn_/m*(1 - sqr(zeta_)));
}


Foam::label Foam::fiberInteractions::contact::nIntervals
(
    const PtrList<fiber>& fibers,
    const scalar dt
) const
{
    scalar mMin = GREAT;
    for (const fiber& f : fibers)
    {
        mMin = min(mMin, f.mass());
    }
    reduce(mMin, minOp<scalar>());
    if (!(mMin < GREAT) || !(dt > 0))
    {
        return 1;
    }
    const scalar tc = contactTime(mMin/8);
    return max(1, label(std::ceil(dt*contactSteps_/tc*(1 - 1e-9))));
}


void Foam::fiberInteractions::contact::interact
(
    const PtrList<fiber>& fibers,
    const UList<role>& roles,
    const scalar t,
    const scalar h,
    UList<fiberIntegrator::load>& loads
)
{
    DynamicList<segment> segs;
    localSegments(fibers, roles, segs);
    const scalar r = reach(segs);
    addImages(segs, r);
    addGhosts(segs, r);
    DynamicList<FixedList<label, 2>> cand;
    candidates(segs, r, cand);

    springTable next(2*springs_.size() + 16);
    DynamicList<FixedList<label, 2>> touching;

    // The forces on this processor's fibers, summed in an order that does
    // not depend on the decomposition: by fiber, then partner and segments
    DynamicList<contribution> parts;
    for (const FixedList<label, 2>& ij : cand)
    {
        const segment& Q = segs[ij[0]];
        const segment& P = segs[ij[1]];

        // The pair from this side, always in one order: the lower fiber
        // id first
        const bool qFirst = Q.fiber < P.fiber;
        const segment& A = qFirst ? Q : P;
        const segment& B = qFirst ? P : Q;
        const pairKey k{Q.fiber, Q.seg, P.fiber, P.seg};
        vector F;
        point c;
        bool touch;
        if (!pairForce(A, B, k, h, next, F, c, touch))
        {
            continue;
        }
        touching.append(FixedList<label, 2>{Q.fiber, P.fiber});
        if (Q.m > 0)
        {
            const vector FQ(qFirst ? F : -F);
            parts.append(contribution{k, Q.local, FQ, c ^ FQ});
        }
    }
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
        loads[cp.local].F += cp.F;
        loads[cp.local].M += cp.M;
    }
    springs_.transfer(next);
    count(touching);
}


void Foam::fiberInteractions::contact::writeFiber
(
    const label id,
    Ostream& os
) const
{
    label n = 0;
    forAllConstIters(springs_, iter)
    {
        if (iter.key()[0] == id)
        {
            ++n;
        }
    }
    os << n;
    forAllConstIters(springs_, iter)
    {
        if (iter.key()[0] == id)
        {
            os << token::SPACE << iter.key() << token::SPACE << iter.val();
        }
    }
}


void Foam::fiberInteractions::contact::readFiber(Istream& is)
{
    const label n = readLabel(is);
    for (label i = 0; i < n; ++i)
    {
        pairKey k;
        vector xi;
        is >> k >> xi;
        springs_.set(k, xi);
    }
}


void Foam::fiberInteractions::contact::writeRestart(Ostream& os) const
{
    os << nl << "contactSprings " << springs_.size();
    forAllConstIters(springs_, iter)
    {
        os << nl << iter.key() << token::SPACE << iter.val();
    }
}


void Foam::fiberInteractions::contact::readRestart(Istream& is)
{
    // A file written without contacts has none
    token t(is);
    if (!t.isWord() || t.wordToken() != "contactSprings")
    {
        if (t.good())
        {
            is.putBack(t);
        }
        return;
    }
    readFiber(is);
}


// ************************************************************************* //
