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

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberInteractions::contactConstraints::contactConstraints
(
    const contact& model
)
:
    model_(model),
    islands_(),
    bodyOf_(),
    bodyFiber_(),
    bodyLocal_(),
    remoteBody_(),
    islandPairs_(),
    islandContacts_(),
    shipped_(),
    answers_(),
    warnedUnsettled_(false),
    nAcross_(0)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::fiberInteractions::contactConstraints::islandBody
(
    const fiber& f,
    const label local
)
{
    const auto it = bodyOf_.cfind(local);
    if (it.found())
    {
        return *it;
    }
    const label b = islands_.addBody(f.flexible() ? f.nSegments() : 1);
    bodyOf_.insert(local, b);
    bodyFiber_.append(f.id());
    bodyLocal_.append(local);
    return b;
}


void Foam::fiberInteractions::contactConstraints::respond(const scalar h)
{
    // Every body of this processor's fibers: its response over h (all
    // processors together: a segment on another's part is sampled there)
    if (!model_.response_)
    {
        FatalErrorInFunction
            << "Entry 'scheme constraints' of 'interactions': no cloud to"
            << " say how the fibers respond" << abort(FatalError);
    }
    DynamicList<label> fis(bodyLocal_.size());
    DynamicList<label> bs(bodyLocal_.size());
    forAll(bodyLocal_, b)
    {
        if (bodyLocal_[b] >= 0)
        {
            fis.append(bodyLocal_[b]);
            bs.append(b);
        }
    }
    List<scalarList> M;
    List<scalarList> v;
    model_.response_(fis, h, M, v);
    forAll(bs, k)
    {
        contactIslands::body& B = islands_.bodyAt(bs[k]);
        B.mobility.transfer(M[k]);
        B.vFree.transfer(v[k]);
    }
}


Foam::label Foam::fiberInteractions::contactConstraints::remoteBody
(
    const segment& S
)
{
    const auto it = remoteBody_.cfind(S.fiber);
    if (it.found())
    {
        return *it;
    }
    const label b = islands_.addBody(S.flexible ? S.nSeg : 1);
    remoteBody_.insert(S.fiber, b);
    bodyFiber_.append(S.fiber);
    bodyLocal_.append(-1);
    return b;
}


Foam::tensor Foam::fiberInteractions::contactConstraints::turnR
(
    const label turn
) const
{
    return
        turn >= 0 && model_.periodic_[turn].hasR()
      ? model_.periodic_[turn].R()
      : tensor::I;
}


bool Foam::fiberInteractions::contactConstraints::constraintOf
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
    const contact::pairGeometry g(model_.geometry(A, B));
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
    const scalar m = reducedMass(A.m, B.m);
    // The dashpots act on a pair that touches at the start; on one apart
    // at the start only the spring on the end overlap (a dashpot there
    // would push across the gap before the pair touches)
    const scalar damped = delta > 0 ? 1 : 0;
    c.n = n;
    c.delta0 = delta;
    const fiberContactLaw& law = model_.law_();
    c.kn = law.normalStiffness(delta);
    c.cn = damped*law.normalDamping(m, delta);
    c.kt = law.tangentialStiffness(delta);
    c.ct = damped*law.tangentialDamping(m, delta);
    c.mu = law.friction();
    c.fExtra = touching ? vector(-law.cohesion(delta)*n) : vector(Zero);
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberInteractions::contactConstraints::constrain
(
    const UPtrList<fiber>& fibers,
    const UList<segment>& segs,
    const UList<FixedList<label, 2>>& cand,
    const scalar h,
    springTable& next,
    UList<fiberIntegrator::load>& loads,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    // Each pair once, from the processor of the lower fiber id (a partner
    // beyond a periodic patch is an image of a fiber, of this processor or
    // another's); the partner's processor told of it
    Map<label> localOf(2*fibers.size());
    forAll(fibers, fi)
    {
        localOf.insert(fibers[fi].id(), fi);
    }
    islands_.clear();
    bodyOf_.clear();
    bodyFiber_.clear();
    bodyLocal_.clear();
    remoteBody_.clear();
    islandPairs_.clear();
    islandContacts_.clear();
    List<DynamicList<FixedList<label, 5>>> notes(Pstream::nProcs());
    for (const FixedList<label, 2>& ij : cand)
    {
        const segment& Q = segs[ij[0]];
        const segment& P = segs[ij[1]];
        // (a flexible fiber against itself, where the search lets its
        // segments touch: once, from the lower segment)
        if
        (
            Q.fiber < P.fiber ? Q.local >= 0
          : Q.fiber == P.fiber && Q.seg < P.seg && Q.local >= 0
        )
        {
            decidePair(fibers, localOf, Q, P, h, notes, touching, close);
        }
    }
    sortPending();
    if (Pstream::parRun())
    {
        labelHashSet told;
        tellPartners(fibers, localOf, notes, told, touching, close);
        respond(h);
        shipIslands(told);
    }
    else
    {
        respond(h);
        forAll(islandContacts_, i)
        {
            islandPairs_[i].slot = islands_.addContact(islandContacts_[i]);
        }
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
    collectResults();
    applyConstraints(fibers, localOf, next, loads);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fiberInteractions::contactConstraints::decidePair
(
    const UPtrList<fiber>& fibers,
    const Map<label>& localOf,
    const segment& Q,
    const segment& P,
    const scalar h,
    UList<DynamicList<FixedList<label, 5>>>& notes,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    contactIslands::contact c;
    point cp;
    bool isTouching = false;
    bool isClose = false;
    const bool acts = constraintOf(Q, P, h, c, cp, isTouching, isClose);
    const bool remote = P.local < 0 && !localOf.found(P.fiber);
    if (remote)
    {
        notes[P.proc].append
        (
            FixedList<label, 5>
            {
                P.fiber, Q.fiber, isTouching, isClose, acts && P.m > 0
            }
        );
    }
    if (isClose)
    {
        close.append(FixedList<label, 2>{Q.fiber, P.fiber});
        if (!remote)
        {
            close.append(FixedList<label, 2>{P.fiber, Q.fiber});
        }
    }
    if (isTouching)
    {
        touching.append(FixedList<label, 2>{Q.fiber, P.fiber});
        if (!remote)
        {
            touching.append(FixedList<label, 2>{P.fiber, Q.fiber});
        }
    }
    if (!acts || !(Q.m > 0 || P.m > 0))
    {
        return;
    }
    const label pLocal =
        P.local >= 0 ? P.local : remote ? -1 : localOf[P.fiber];
    addConstraint(fibers, Q, P, pLocal, h, cp, c);
    islandPairs_.append
    (
        constraintPair
        {
            {Q.fiber, Q.seg, P.fiber, P.seg}, cp, Q.local, pLocal, P.proc,
            P.turn, Q.m > 0, P.m > 0, -1, Zero, Zero
        }
    );
}


void Foam::fiberInteractions::contactConstraints::addConstraint
(
    const UPtrList<fiber>& fibers,
    const segment& Q,
    const segment& P,
    const label pLocal,
    const scalar h,
    const point& cp,
    contactIslands::contact& c
)
{
    const pairKey k{Q.fiber, Q.seg, P.fiber, P.seg};
    // The tangential spring of the pair (the lower id's), turned into the
    // contact plane with its length kept
    pairKey from(k);
    vector xi(model_.previousSpring(k, from));
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
    // into the fiber's frame.  A partner of another processor is a body
    // that stands for it (the master's solve fills it)
    const auto bodyOf = [&](const segment& S, const label local)
    {
        return
            local >= 0 ? islandBody(fibers[local], local) : remoteBody(S);
    };
    const bool qMoves = Q.m > 0;
    const segment& A = qMoves ? Q : P;
    const segment& B = qMoves ? P : Q;
    const scalar sgn = qMoves ? 1 : -1;
    c.a = bodyOf(A, qMoves ? Q.local : pLocal);
    c.pa = A.flexible ? A.seg : 0;
    c.ra = cp - A.x;
    c.b = B.m > 0 ? bodyOf(B, qMoves ? pLocal : Q.local) : -1;
    c.pb = B.flexible ? B.seg : 0;
    c.rb = cp - B.x;
    c.vB = B.v + (B.w ^ c.rb);
    const tensor R(turnR(P.turn));
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
    islandContacts_.append(c);
}


void Foam::fiberInteractions::contactConstraints::sortPending()
{
    labelList order(identity(islandPairs_.size()));
    std::sort
    (
        order.begin(), order.end(),
        [this](const label i, const label j)
        {
            return islandPairs_[i].key < islandPairs_[j].key;
        }
    );
    DynamicList<constraintPair> pairs(islandPairs_.size());
    DynamicList<contactIslands::contact> cs(islandContacts_.size());
    for (const label i : order)
    {
        pairs.append(islandPairs_[i]);
        cs.append(islandContacts_[i]);
    }
    islandPairs_.transfer(pairs);
    islandContacts_.transfer(cs);
}


void Foam::fiberInteractions::contactConstraints::applyConstraints
(
    const UPtrList<fiber>& fibers,
    const Map<label>& localOf,
    springTable& next,
    UList<fiberIntegrator::load>& loads
)
{
    // The force on the lower id (Q) of each pair, -f on its partner at the
    // same point (an image's fiber: both turned back into its frame; a
    // fiber of another processor: sent there), summed in the keys' order;
    // the springs at the end under both keys
    DynamicList<pointForce> parts;
    List<DynamicList<scalar>> out(Pstream::nProcs());
    for (const constraintPair& cp : islandPairs_)
    {
        const pairKey& k = cp.key;
        const vector fQ(cp.qMoves ? cp.f : -cp.f);
        const vector xi(cp.qMoves ? cp.xiEnd : -cp.xiEnd);
        const pairKey kr{k[2], k[3], k[0], k[1]};
        next.set(k, xi);
        if (cp.qMoves)
        {
            parts.append(pointForce{k, cp.q, k[1], fQ, cp.c});
        }
        const tensor R(turnR(cp.turn));
        const vector fP(-(R.T() & fQ));
        const point cP
        (
            cp.turn >= 0 ? model_.periodic_[cp.turn].invTransformPosition(cp.c)
          : cp.c
        );
        const vector xiP(R.T() & xi);
        if (cp.p >= 0)
        {
            next.set(kr, xiP);
            if (cp.pMoves)
            {
                parts.append(pointForce{kr, cp.p, k[3], fP, cP});
            }
            continue;
        }
        DynamicList<scalar>& o = out[cp.pProc];
        for (const label l : kr)
        {
            o.append(l);
        }
        o.append(cp.pMoves);
        for (const vector& v : {fP, vector(cP), xiP})
        {
            o.append(v.x());
            o.append(v.y());
            o.append(v.z());
        }
    }
    if (Pstream::parRun())
    {
        partnerForces(localOf, out, next, parts);
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


Foam::label Foam::fiberInteractions::contactConstraints::pairsAcross() const
{
    return returnReduce(nAcross_, sumOp<label>());
}


// ************************************************************************* //
