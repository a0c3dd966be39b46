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
    The fibers engaged in a window: those of a pair whose gap could close
    within it, or is within a tenth of a diameter (a pair close at the last
    interval stays one: collisions are counted with that hysteresis).  Only
    an engaged fiber feels contacts in the window, so only it can be
    kicked: a pair closes by a kick more only where one of its fibers is
    engaged, and the engaged fibers grow until no such pair is left (the
    least such set: the same on any number of processors; a periodic
    image's or another processor's fiber is known engaged by its id,
    exchanged until no processor finds more).  Two engaged fibers meet in
    the intervals' search.

\*---------------------------------------------------------------------------*/

#include "contactWindows.H"
#include "contact.H"
#include "openfoamCompat.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::label Foam::fiberInteractions::contactWindows::localOf
(
    const segment& S
) const
{
    // A periodic image of a fiber of this processor stands for that fiber
    // (a pair across a periodic patch may be found from one side only:
    // engaging the image engages the fiber)
    if (S.local >= 0)
    {
        return S.local;
    }
    const auto it = present_->cfind(S.fiber);
    return it.found() ? *it : label(-1);
}


bool Foam::fiberInteractions::contactWindows::engageBoth
(
    const segment& A,
    const segment& B,
    List<bool>& eng
) const
{
    bool grew = false;
    for (const segment* sg : {&A, &B})
    {
        const label li = localOf(*sg);
        if (li >= 0 && sg->m > 0 && !eng[li])
        {
            eng[li] = true;
            grew = true;
        }
    }
    return grew;
}


bool Foam::fiberInteractions::contactWindows::isEngaged
(
    const segment& S,
    const List<bool>& eng
) const
{
    const label li = localOf(S);
    return S.m > 0 && (li >= 0 ? eng[li] : engagedIds_.found(S.fiber));
}


Foam::scalar Foam::fiberInteractions::contactWindows::engageNear
(
    const scalar H,
    const label jH,
    List<bool>& eng,
    label& nMissed
)
{
    const UList<segment>& segs = *segs_;
    scalar meetKick = 0;
    forAll(near_, k)
    {
        const nearPair& np = near_[k];
        const bound& bd = bounds_[np.bi];
        const segment* A;
        const segment* B;
        ordered(segs[bd.i], segs[bd.j], A, B);
        const scalar c0 =
            jH >= 0 ? np.c[jH] : closing(bd.i, bd.j, np.du, np.dv, H);
        if
        (
            np.g < 0 && A->fiber != B->fiber && A->local >= 0
         && !A->later && !B->later
         && ((A->m > 0 && !A->was) || (B->m > 0 && !B->was))
        )
        {
            // Touching, though one of them ran through the last window on
            // its own: the window's bounds failed (counted once, where the
            // first of the pair is)
            ++nMissed;
        }
        if (np.g <= max(c0, 0.1*min(A->d, B->d)))
        {
            engageBoth(*A, *B, eng);
            if (A->fiber != B->fiber)
            {
                meetKick = max(meetKick, relSpeed(*A, *B));
            }
        }
        else if (np.g <= c0 + kick_*H && A->m > 0 && B->m > 0)
        {
            kickOnly_.append(k);
        }
    }
    return meetKick;
}


void Foam::fiberInteractions::contactWindows::grow
(
    const UPtrList<fiber>& fibers,
    List<bool>& eng
)
{
    const UList<segment>& segs = *segs_;
    const bool exchange = Pstream::parRun() || model_.periodic_.size();
    while (true)
    {
        for (bool grew = true; grew; )
        {
            grew = false;
            for (const label k : kickOnly_)
            {
                const bound& bd = bounds_[near_[k].bi];
                const segment* A;
                const segment* B;
                ordered(segs[bd.i], segs[bd.j], A, B);
                if (isEngaged(*A, eng) || isEngaged(*B, eng))
                {
                    grew = engageBoth(*A, *B, eng) || grew;
                }
            }
        }
        if (!exchange)
        {
            break;
        }
        List<labelList> ids(Pstream::nProcs());
        DynamicList<label> mine;
        forAll(fibers, fi)
        {
            if (eng[fi] && !engagedIds_.found(fibers[fi].id()))
            {
                mine.append(fibers[fi].id());
            }
        }
        ids[Pstream::myProcNo()] = std::move(mine);
        fiberCompat::allGatherList(ids);
        label nNew = 0;
        for (const labelList& l : ids)
        {
            for (const label id : l)
            {
                nNew += engagedIds_.insert(id);
            }
        }
        if (nNew == 0)
        {
            break;
        }
    }
}


Foam::scalar Foam::fiberInteractions::contactWindows::engage
(
    const UPtrList<fiber>& fibers,
    const List<bool>& owes,
    const scalar H,
    const label jH,
    List<bool>& eng,
    label& nMissed
)
{
    eng = owes;
    nMissed = 0;
    kickOnly_.clear();
    engagedIds_.clear();
    scalar meetKick = engageNear(H, jH, eng, nMissed);
    grow(fibers, eng);
    const UList<segment>& segs = *segs_;
    for (const label k : kickOnly_)
    {
        const bound& bd = bounds_[near_[k].bi];
        const segment* A;
        const segment* B;
        ordered(segs[bd.i], segs[bd.j], A, B);
        if
        (
            (isEngaged(*A, eng) || isEngaged(*B, eng))
         && A->fiber != B->fiber
        )
        {
            meetKick = max(meetKick, relSpeed(*A, *B));
        }
    }
    return returnReduce(meetKick, maxOp<scalar>());
}


Foam::label Foam::fiberInteractions::contactWindows::nEngaged
(
    const UList<role>& roles,
    const List<bool>& eng
)
{
    label n = 0;
    forAll(roles, fi)
    {
        n += roles[fi] == role::free && eng[fi];
    }
    return returnReduce(n, sumOp<label>());
}


// ************************************************************************* //
