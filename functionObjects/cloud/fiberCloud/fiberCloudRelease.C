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
    fiberCloud: the fibers placed at the start (located, checked, kept
    by the processor that holds their centre) and those the feeds release
    in a step.

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"
#include "openfoamCompat.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberCloud::locateInjected
(
    PtrList<fiber>& all,
    const labelUList& offset,
    labelList& owner,
    labelList& segFound,
    List<trackedPoint>& centre
) const
{
    const label myProc = Pstream::myProcNo();

    // Centres by the cell tree; segments by tracks from the centre, the
    // cell tree only for those a track does not reach (another
    // processor's part, or around a corner)
    forAll(all, fi)
    {
        constraint_.constrain(all[fi]);
        const fiber& f = all[fi];
        const label c = mesh_.findCell(f.position());
        if (c < 0)
        {
            continue;
        }
        owner[fi] = myProc;
        tracker_.locate(f.position(), centre[fi], c);
        const tensor R(f.R());
        for (label i = 0; i < f.nSegments(); ++i)
        {
            trackedPoint tp(centre[fi]);
            const fiberTracker::hit h =
                tracker_.track(tp, f.segmentOffset(R, i));
            if (h.where == fiberTracker::stop::none)
            {
                segFound[offset[fi] + i] = 1;
            }
        }
    }
    fiberCompat::listCombineReduce(segFound, maxEqOp<label>());

    List<point> pts;
    forAll(all, fi)
    {
        all[fi].segmentCentres(pts);
        forAll(pts, i)
        {
            if
            (
                !segFound[offset[fi] + i]
             && periodicImages::inside(mesh_, images_, pts[i])
            )
            {
                segFound[offset[fi] + i] = 1;
            }
        }
    }

    fiberCompat::listCombineReduce(owner, minEqOp<label>());
    fiberCompat::listCombineReduce(segFound, maxEqOp<label>());
}


void Foam::fiberCloud::checkInjected
(
    const dictionary& injectionDict,
    const PtrList<fiber>& all,
    const List<fiberInjection::origin>& origins,
    const labelUList& offset,
    const labelUList& owner,
    const labelUList& segFound
) const
{
    const label nProcs = Pstream::nProcs();
    List<point> pts;
    forAll(all, fi)
    {
        const fiberInjection::origin& o = origins[fi];
        if (!constraint_.inPlane(all[fi]))
        {
            FatalIOErrorInFunction(injectionDict)
                << "Fiber " << o.index << " of set '" << o.set
                << "' (id " << all[fi].id() << ") does not lie in the"
                << " solution plane of this 2-D case (free directions "
                << constraint_.freeDirections() << ")." << nl
                << "    Give its 'direction' in the plane"
                << exit(FatalIOError);
        }
        if (owner[fi] == nProcs)
        {
            FatalIOErrorInFunction(injectionDict)
                << "Fiber " << o.index << " of set '" << o.set
                << "' (id " << all[fi].id() << "): its centre "
                << all[fi].position() << " is outside the mesh."
                << nl << "    Move it inside the domain "
                << mesh_.bounds() << exit(FatalIOError);
        }
        all[fi].segmentCentres(pts);
        forAll(pts, i)
        {
            if (!segFound[offset[fi] + i])
            {
                FatalIOErrorInFunction(injectionDict)
                    << "Fiber " << o.index << " of set '" << o.set
                    << "' (id " << all[fi].id() << "): segment " << i
                    << " at " << pts[i] << " is outside the mesh."
                    << nl << "    Move the fiber, shorten it or turn it so"
                    << " that all segments lie in the domain"
                    << exit(FatalIOError);
            }
        }
    }
}


void Foam::fiberCloud::distribute
(
    const dictionary& injectionDict,
    PtrList<fiber>& all,
    const List<fiberInjection::origin>& origins
)
{
    const label myProc = Pstream::myProcNo();

    // Owner: the lowest processor whose mesh holds the centre; segments
    // found somewhere (flattened, per fiber offset)
    labelList owner(all.size(), Pstream::nProcs());
    labelList offset(all.size() + 1, 0);
    forAll(all, fi)
    {
        offset[fi + 1] = offset[fi] + all[fi].nSegments();
    }
    labelList segFound(offset.last(), 0);
    List<trackedPoint> centre(all.size());

    locateInjected(all, offset, owner, segFound, centre);
    checkInjected(injectionDict, all, origins, offset, owner, segFound);

    label nMine = 0;
    forAll(all, fi)
    {
        if (owner[fi] == myProc)
        {
            ++nMine;
        }
    }
    fibers_.setSize(nMine);
    nMine = 0;
    forAll(all, fi)
    {
        if (owner[fi] == myProc)
        {
            fiber* fPtr = all.set(fi, nullptr).ptr();
            fPtr->location() = centre[fi];
            fibers_.set(nMine++, fPtr);
        }
    }
}


Foam::label Foam::fiberCloud::placeFeed
(
    fiberPatchInjection& feed,
    const label k0,
    PtrList<fiber>& placed,
    labelList& owner,
    List<trackedPoint>& centre
)
{
    // Fiber k0 + j keeps its size; its place is drawn again until the
    // whole fiber lies in the mesh (so the sizes released follow the
    // distribution).  Every processor draws the same candidates and the
    // location is combined.
    const label nNew = placed.size();
    labelList pending(identity(nNew));
    labelList attempt(nNew, 0);
    label nRedrawn = 0;
    const label maxRedrawn = 1000*nNew + 10000;
    while (pending.size())
    {
        if (nRedrawn > maxRedrawn)
        {
            FatalErrorInFunction
                << "Fiber set '" << feed.name() << "': "
                << nNew - pending.size() << " of " << nNew
                << " fibers placed after " << nRedrawn << " candidates"
                << " with a segment outside the mesh: no place just"
                << " inside patch '"
                << mesh_.boundaryMesh()[feed.patch()].name()
                << "' holds the whole fiber. Use shorter fibers or"
                << " another patch" << exit(FatalError);
        }
        const label nTry = pending.size();
        PtrList<fiber> cand(nTry);
        labelList offset(nTry + 1, 0);
        forAll(cand, j)
        {
            const label slot = pending[j];
            cand.set
            (
                j,
                new fiber(feed.candidate(-1, k0 + slot, attempt[slot]++))
            );
            offset[j + 1] = offset[j] + cand[j].nSegments();
        }
        labelList candOwner(nTry, Pstream::nProcs());
        labelList segFound(offset.last(), 0);
        List<trackedPoint> candCentre(nTry);
        locateInjected(cand, offset, candOwner, segFound, candCentre);

        DynamicList<label> still;
        forAll(cand, j)
        {
            bool inside = candOwner[j] < Pstream::nProcs();
            for (label i = offset[j]; i < offset[j + 1]; ++i)
            {
                inside = inside && segFound[i];
            }
            if (!inside)
            {
                ++nRedrawn;
                still.append(pending[j]);
                continue;
            }
            const label slot = pending[j];
            owner[slot] = candOwner[j];
            centre[slot] = candCentre[j];
            placed.set(slot, cand.set(j, nullptr));
        }
        pending.transfer(still);
    }
    return nRedrawn;
}


void Foam::fiberCloud::release
(
    const scalar t0,
    const scalar t1,
    DynamicList<scalar>& tLeft
)
{
    const label myProc = Pstream::myProcNo();
    for (fiberPatchInjection& feed : feeds_)
    {
        const label k0 = feed.nReleased();
        const label nNew = feed.nDue(t1) - k0;
        if (nNew <= 0)
        {
            continue;
        }
        feed.prepare(mesh_);

        PtrList<fiber> placed(nNew);
        labelList owner(nNew, Pstream::nProcs());
        List<trackedPoint> centre(nNew);
        const label nRedrawn = placeFeed(feed, k0, placed, owner, centre);

        // In release order: the next ids, the release times
        forAll(placed, slot)
        {
            const scalar tRel = max(feed.releaseTime(k0 + slot), t0);
            const label id = counters_.injected(feed.setIndex());
            if (owner[slot] != myProc)
            {
                continue;
            }
            fiber* fPtr = placed.set(slot, nullptr).ptr();
            fPtr->setId(id);
            fiber& f = *fPtr;
            bend(f);
            if (jeffery_)
            {
                f.jefferyCorrection();
            }
            f.location() = centre[slot];
            if (feed.velocity())
            {
                f.setVelocity(constraint_.constrain(*feed.velocity()));
            }
            else
            {
                fluidSample s;
                sampler_.interpolate(f.location(), s);
                f.setVelocity(constraint_.constrain(s.U));
            }
            makeFlexible(f);
            events_.record(f, tRel, fiberEventLog::injected, feed.patch());
            fibers_.append(fPtr);
            tLeft.append(max(t1 - tRel, scalar(0)));
        }
        feed.released(nNew, nRedrawn);
    }
}

// ************************************************************************* //
