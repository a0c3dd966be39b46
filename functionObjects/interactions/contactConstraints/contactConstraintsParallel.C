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
    The contacts as constraints in parallel.  A pair is decided once, by
    the processor of its lower fiber id, which tells the partner's
    processor (its fiber's touches, and that its body joins the solve).
    An island whose bodies are all of one processor is solved there; one
    that reaches across processors (a body standing for another's fiber,
    or one told of) is sent to the master with its bodies' responses
    (each by its own processor), solved there with the master's own, in
    the keys' order (the serial order), and its forces sent back.  The
    force on a partner of another processor is sent to it with the
    pair's spring.  One exchange to the partners, one to the master and
    back, one of forces per interval.

\*---------------------------------------------------------------------------*/

#include "contact.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void putVector(DynamicList<scalar>& o, const vector& v)
{
    o.append(v.x());
    o.append(v.y());
    o.append(v.z());
}


vector getVector(const UList<scalar>& in, label& k)
{
    const vector v(in[k], in[k + 1], in[k + 2]);
    k += 3;
    return v;
}


void putTensor(DynamicList<scalar>& o, const tensor& T)
{
    for (direction i = 0; i < tensor::nComponents; ++i)
    {
        o.append(T[i]);
    }
}


tensor getTensor(const UList<scalar>& in, label& k)
{
    tensor T;
    for (direction i = 0; i < tensor::nComponents; ++i)
    {
        T[i] = in[k++];
    }
    return T;
}


//- A contact by its key and its bodies' fiber ids (b: -1 fixed)
void packContact
(
    const FixedList<label, 4>& key,
    const label aId,
    const label bId,
    const contactIslands::contact& c,
    DynamicList<scalar>& o
)
{
    for (const label l : key)
    {
        o.append(l);
    }
    o.append(aId);
    o.append(c.pa);
    putVector(o, c.ra);
    o.append(bId);
    o.append(c.pb);
    putVector(o, c.rb);
    putVector(o, c.vB);
    putTensor(o, c.Ra);
    putTensor(o, c.Rb);
    putVector(o, c.n);
    o.append(c.delta0);
    putVector(o, c.xi0);
    for (const scalar s : {c.kn, c.cn, c.kt, c.ct, c.mu})
    {
        o.append(s);
    }
    putVector(o, c.fExtra);
}


//- The contact at k of in (its bodies' fiber ids in a and b)
void unpackContact
(
    const UList<scalar>& in,
    label& k,
    FixedList<label, 4>& key,
    contactIslands::contact& c
)
{
    for (label& l : key)
    {
        l = label(in[k++]);
    }
    c.a = label(in[k++]);
    c.pa = label(in[k++]);
    c.ra = getVector(in, k);
    c.b = label(in[k++]);
    c.pb = label(in[k++]);
    c.rb = getVector(in, k);
    c.vB = getVector(in, k);
    c.Ra = getTensor(in, k);
    c.Rb = getTensor(in, k);
    c.n = getVector(in, k);
    c.delta0 = in[k++];
    c.xi0 = getVector(in, k);
    c.kn = in[k++];
    c.cn = in[k++];
    c.kt = in[k++];
    c.ct = in[k++];
    c.mu = in[k++];
    c.fExtra = getVector(in, k);
}


void sendScalars(UOPstream& os, const UList<scalar>& o)
{
    os << o.size();
    os.write
    (
        reinterpret_cast<const char*>(o.cdata()),
        std::streamsize(o.size()*sizeof(scalar))
    );
}


void receiveScalars(UIPstream& is, DynamicList<scalar>& in)
{
    in.resize(readLabel(is));
    is.read
    (
        reinterpret_cast<char*>(in.data()),
        std::streamsize(in.size()*sizeof(scalar))
    );
}


//- The root of i (halving the paths)
label rootOf(labelList& up, label i)
{
    while (up[i] != i)
    {
        up[i] = up[up[i]];
        i = up[i];
    }
    return i;
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::fiberInteractions::contactConstraints::tellPartners
(
    const UPtrList<fiber>& fibers,
    const Map<label>& localOf,
    const UList<DynamicList<FixedList<label, 5>>>& notes,
    labelHashSet& told,
    DynamicList<FixedList<label, 2>>& touching,
    DynamicList<FixedList<label, 2>>& close
)
{
    // A note: the partner's fiber (here), the deciding side's, touching,
    // close, the partner's body joins the solve
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(notes, proci)
    {
        if (proci != Pstream::myProcNo())
        {
            UOPstream os(proci, pBufs);
            os << notes[proci];
        }
    }
    pBufs.finishedSends();
    forAll(notes, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        const List<FixedList<label, 5>> in(is);
        for (const FixedList<label, 5>& n : in)
        {
            const label local = localOf.lookup(n[0], -1);
            if (local < 0)
            {
                FatalErrorInFunction
                    << "Processor " << proci << " decided a pair with fiber "
                    << n[0] << ", which is not here" << abort(FatalError);
            }
            if (n[2])
            {
                touching.append(FixedList<label, 2>{n[0], n[1]});
            }
            if (n[3])
            {
                close.append(FixedList<label, 2>{n[0], n[1]});
            }
            if (n[4])
            {
                told.insert(islandBody(fibers[local], local));
            }
        }
    }
}


void Foam::fiberInteractions::contactConstraints::shipIslands
(
    const labelHashSet& told
)
{
    // The islands of this processor's pending contacts; those with a body
    // of another's fiber, or one of this processor's told of, reach
    // across processors
    const label nB = islands_.nBodies();
    labelList up(identity(nB));
    for (const contactIslands::contact& c : islandContacts_)
    {
        if (c.b >= 0)
        {
            up[rootOf(up, c.a)] = rootOf(up, c.b);
        }
    }
    boolList across(nB, false);
    forAllConstIters(remoteBody_, iter)
    {
        across[rootOf(up, *iter)] = true;
    }
    for (const label b : told)
    {
        across[rootOf(up, b)] = true;
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    shipped_.clear();
    if (!Pstream::master())
    {
        DynamicList<scalar> o;
        forAll(islandContacts_, i)
        {
            const contactIslands::contact& c = islandContacts_[i];
            if (!across[rootOf(up, c.a)])
            {
                islandPairs_[i].slot = islands_.addContact(c);
                continue;
            }
            islandPairs_[i].slot = -1;
            shipped_.append(i);
            packContact
            (
                islandPairs_[i].key, bodyFiber_[c.a],
                c.b >= 0 ? bodyFiber_[c.b] : label(-1), c, o
            );
        }
        nAcross_ += shipped_.size();
        UOPstream os(Pstream::masterNo(), pBufs);
        sendScalars(os, o);
        // The bodies of this processor's fibers in those islands
        o.clear();
        for (label b = 0; b < nB; ++b)
        {
            const contactIslands::body& B = islands_.bodyAt(b);
            if (across[rootOf(up, b)] && !remoteBody_.found(bodyFiber_[b]))
            {
                o.append(bodyFiber_[b]);
                o.append(B.pieces);
                o.append(B.vFree);
                o.append(B.mobility);
            }
        }
        sendScalars(os, o);
    }
    pBufs.finishedSends();
    if (Pstream::master())
    {
        receiveIslands(pBufs);
    }
}


void Foam::fiberInteractions::contactConstraints::receiveBodies
(
    const UList<scalar>& in,
    Map<label>& byId
)
{
    for (label k = 0; k < in.size(); )
    {
        const label id = label(in[k++]);
        const label pieces = label(in[k++]);
        label b = byId.lookup(id, -1);
        if (b < 0)
        {
            b = islands_.addBody(pieces);
            bodyFiber_.append(id);
            bodyLocal_.append(-1);
            byId.insert(id, b);
        }
        contactIslands::body& B = islands_.bodyAt(b);
        B.pieces = pieces;
        B.vFree = SubList<scalar>(in, 6*pieces, k);
        k += 6*pieces;
        B.mobility = SubList<scalar>(in, 36*pieces*pieces, k);
        k += 36*pieces*pieces;
    }
}


void Foam::fiberInteractions::contactConstraints::receiveIslands
(
    PstreamBuffers& pBufs
)
{
    // The bodies first (standing-in ones filled, new ones added), then
    // every contact, the master's and the received, in the keys' order
    Map<label> byId(2*bodyFiber_.size() + 16);
    forAll(bodyFiber_, b)
    {
        byId.insert(bodyFiber_[b], b);
    }
    struct entry
    {
        pairKey key;
        label proc;
        label i;
    };
    DynamicList<entry> all(islandContacts_.size());
    forAll(islandContacts_, i)
    {
        all.append(entry{islandPairs_[i].key, Pstream::masterNo(), i});
    }
    List<DynamicList<contactIslands::contact>> got(Pstream::nProcs());
    DynamicList<scalar> in;
    for (label proci = 1; proci < Pstream::nProcs(); ++proci)
    {
        UIPstream is(proci, pBufs);
        DynamicList<scalar> cin;
        receiveScalars(is, cin);
        receiveScalars(is, in);
        receiveBodies(in, byId);
        for (label k = 0; k < cin.size(); )
        {
            pairKey key;
            contactIslands::contact c;
            unpackContact(cin, k, key, c);
            c.a = byId[c.a];
            c.b = c.b >= 0 ? byId[c.b] : label(-1);
            all.append(entry{key, proci, got[proci].size()});
            got[proci].append(c);
        }
    }
    forAllConstIters(remoteBody_, iter)
    {
        if (islands_.bodyAt(*iter).vFree.empty())
        {
            FatalErrorInFunction
                << "Fiber " << iter.key() << " of another processor is in an"
                << " island here, but its processor did not send its body"
                << abort(FatalError);
        }
    }
    std::sort
    (
        all.begin(), all.end(),
        [](const entry& a, const entry& b) { return a.key < b.key; }
    );
    answers_.setSize(Pstream::nProcs());
    for (DynamicList<label>& a : answers_)
    {
        a.clear();
    }
    for (const entry& e : all)
    {
        if (e.proc == Pstream::masterNo())
        {
            islandPairs_[e.i].slot = islands_.addContact(islandContacts_[e.i]);
        }
        else
        {
            answers_[e.proc].append(islands_.addContact(got[e.proc][e.i]));
        }
    }
}


void Foam::fiberInteractions::contactConstraints::collectResults()
{
    for (constraintPair& cp : islandPairs_)
    {
        if (cp.slot >= 0)
        {
            const contactIslands::contact& c = islands_.contactAt(cp.slot);
            cp.f = c.f;
            cp.xiEnd = c.xiEnd;
        }
    }
    if (!Pstream::parRun())
    {
        return;
    }
    // The master's answers, in the order each processor sent its contacts
    // (answers_ were filled in that order for each processor)
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    if (Pstream::master())
    {
        for (label proci = 1; proci < Pstream::nProcs(); ++proci)
        {
            DynamicList<scalar> o(6*answers_[proci].size());
            for (const label s : answers_[proci])
            {
                putVector(o, islands_.contactAt(s).f);
                putVector(o, islands_.contactAt(s).xiEnd);
            }
            UOPstream os(proci, pBufs);
            sendScalars(os, o);
        }
    }
    pBufs.finishedSends();
    if (!Pstream::master())
    {
        UIPstream is(Pstream::masterNo(), pBufs);
        DynamicList<scalar> in;
        receiveScalars(is, in);
        label k = 0;
        for (const label i : shipped_)
        {
            islandPairs_[i].f = getVector(in, k);
            islandPairs_[i].xiEnd = getVector(in, k);
        }
    }
}


void Foam::fiberInteractions::contactConstraints::partnerForces
(
    const Map<label>& localOf,
    const UList<DynamicList<scalar>>& out,
    springTable& next,
    DynamicList<pointForce>& parts
)
{
    // Per pair: its key from the partner, whether the partner moves, the
    // force, point and spring in the partner's frame
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(out, proci)
    {
        if (proci != Pstream::myProcNo())
        {
            UOPstream os(proci, pBufs);
            sendScalars(os, out[proci]);
        }
    }
    pBufs.finishedSends();
    DynamicList<scalar> in;
    forAll(out, proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        receiveScalars(is, in);
        for (label k = 0; k < in.size(); )
        {
            pairKey kr;
            for (label& l : kr)
            {
                l = label(in[k++]);
            }
            const bool moves = in[k++] != 0;
            const vector F(getVector(in, k));
            const point c(getVector(in, k));
            const vector xi(getVector(in, k));
            next.set(kr, xi);
            if (moves)
            {
                parts.append(pointForce{kr, localOf[kr[0]], kr[1], F, c});
            }
        }
    }
}


// ************************************************************************* //
