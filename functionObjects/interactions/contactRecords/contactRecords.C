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

#include "contactRecords.H"
#include "token.H"
#include "Istream.H"
#include "Ostream.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Whether the next token is the word w (else put back)
bool nextIs(Foam::Istream& is, const Foam::word& w)
{
    Foam::token t(is);
    if (t.isWord() && t.wordToken() == w)
    {
        return true;
    }
    if (t.good())
    {
        is.putBack(t);
    }
    return false;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::contactRecords::readSpring(Istream& is)
{
    pairKey k;
    vector xi;
    label mode;
    is >> k >> xi >> mode;
    springs_.set(k, xi);
    if (mode > 0)
    {
        sliding_.set(k, mode);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::fiberInteractions::contactRecords::writeFiber
(
    const label id,
    Ostream& os
) const
{
    // The fiber's tangential springs and (implicit) its contacts of the
    // interval; nothing is pending within an interval
    label n = 0;
    forAllConstIters(springs_, iter)
    {
        n += (iter.key()[0] == id);
    }
    os << n;
    forAllConstIters(springs_, iter)
    {
        if (iter.key()[0] == id)
        {
            os  << token::SPACE << iter.key() << token::SPACE << iter.val()
                << token::SPACE << sliding_.lookup(iter.key(), 0);
        }
    }
    n = 0;
    forAllConstIters(records_, iter)
    {
        n += (iter.key()[0] == id);
    }
    os << token::SPACE << n;
    forAllConstIters(records_, iter)
    {
        if (iter.key()[0] == id)
        {
            const pairRecord& p = iter.val();
            os  << token::SPACE << iter.key() << token::SPACE << p.F
                << token::SPACE << p.K << token::SPACE << p.C
                << token::SPACE << p.vp << token::SPACE << p.rThis
                << token::SPACE << p.rOther << token::SPACE << p.n
                << token::SPACE << p.sticks << token::SPACE << p.xi
                << token::SPACE << p.xiMax << token::SPACE << p.vt0;
        }
    }
    n = 0;
    for (const FixedList<label, 2>& k : recent_)
    {
        n += (k[0] == id);
    }
    os << token::SPACE << n;
    for (const FixedList<label, 2>& k : recent_)
    {
        if (k[0] == id)
        {
            os << token::SPACE << k;
        }
    }
}


void Foam::fiberInteractions::contactRecords::readFiber(Istream& is)
{
    const label n = readLabel(is);
    for (label i = 0; i < n; ++i)
    {
        readSpring(is);
    }
    const label nRec = readLabel(is);
    for (label i = 0; i < nRec; ++i)
    {
        pairKey k;
        pairRecord p;
        is  >> k >> p.F >> p.K >> p.C >> p.vp >> p.rThis >> p.rOther >> p.n
            >> p.sticks >> p.xi >> p.xiMax
            >> p.vt0;
        records_.set(k, p);
    }
    const label nRecent = readLabel(is);
    for (label i = 0; i < nRecent; ++i)
    {
        FixedList<label, 2> k;
        is >> k;
        recent_.insert(k);
    }
}


void Foam::fiberInteractions::contactRecords::writeSprings
(
    Ostream& os
) const
{
    os << nl << "contactSprings " << springs_.size();
    forAllConstIters(springs_, iter)
    {
        os  << nl << iter.key() << token::SPACE << iter.val()
            << token::SPACE << sliding_.lookup(iter.key(), 0);
    }
}


void Foam::fiberInteractions::contactRecords::writePending
(
    Ostream& os
) const
{
    os << nl << "contactPending " << pending_.size();
    forAllConstIters(pending_, iter)
    {
        os  << nl << iter.key() << token::SPACE << iter.val()[0]
            << token::SPACE << iter.val()[1];
    }
}


void Foam::fiberInteractions::contactRecords::writeRecent
(
    Ostream& os
) const
{
    os  << nl << "contactRecent " << recent_.size();
    for (const fiberPair& k : recent_.sortedToc())
    {
        os  << nl << k;
    }
}


bool Foam::fiberInteractions::contactRecords::readSprings(Istream& is)
{
    if (!nextIs(is, "contactSprings"))
    {
        return false;
    }
    const label n = readLabel(is);
    for (label i = 0; i < n; ++i)
    {
        readSpring(is);
    }
    return true;
}


bool Foam::fiberInteractions::contactRecords::readPending(Istream& is)
{
    if (!nextIs(is, "contactPending"))
    {
        return false;
    }
    const label nP = readLabel(is);
    for (label i = 0; i < nP; ++i)
    {
        fiberPair to;
        FixedList<vector, 2> J;
        is >> to >> J[0] >> J[1];
        pending_.set(to, J);
    }
    return true;
}


bool Foam::fiberInteractions::contactRecords::readRecent(Istream& is)
{
    // (written since collisions are counted on them; older files: none)
    if (!nextIs(is, "contactRecent"))
    {
        return false;
    }
    const label nR = readLabel(is);
    for (label i = 0; i < nR; ++i)
    {
        fiberPair k;
        is >> k;
        recent_.insert(k);
    }
    return true;
}


// ************************************************************************* //
