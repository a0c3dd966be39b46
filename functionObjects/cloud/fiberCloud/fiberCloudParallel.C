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
    fiberCloud: the rounds of the fibers that need a neighbour's data,
    and the transfer of fibers between processors.

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"
#include "processorPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberCloud::sampleWaiting
(
    const labelUList& waiting,
    const labelUList& offset,
    const scalarList* h,
    UList<fluidSample>& out
)
{
    DynamicList<fluidSampler::request> reqs;
    DynamicList<remoteSegment> remote;
    for (const label fi : waiting)
    {
        if (step_[fi].st != status::waiting)
        {
            continue;
        }
        const fiber& f = fibers_[fi];
        SubList<fluidSample> sf(out, f.nSegments(), offset[fi]);
        vector dx(Zero);
        tensor R(f.R());
        if (h)
        {
            integrator_->predict(f, (*h)[fi], dx, R);
        }
        sampleSegments(fi, dx, R, sf, &reqs, &remote);
    }

    // Exchange, bring the answers into the fibers' frames
    List<fluidSample> answers(reqs.size());
    sampler_.exchange(reqs, answers);
    forAll(remote, k)
    {
        fluidSampler::toStartFrame(remote[k].h, answers[k]);
        out[offset[remote[k].fiber] + remote[k].segment] = answers[k];
    }
}


void Foam::fiberCloud::round()
{
    // Stage 1: the current configuration of every waiting fiber
    labelList waiting(step_.size());
    label nWaiting = 0;
    labelList offset(step_.size() + 1, 0);
    forAll(step_, fi)
    {
        offset[fi + 1] = offset[fi];
        if (step_[fi].st == status::waiting)
        {
            waiting[nWaiting++] = fi;
            offset[fi + 1] += fibers_[fi].nSegments();
        }
    }
    waiting.setSize(nWaiting);

    List<fluidSample> s(offset.last());
    List<fluidSample> s2(offset.last());
    scalarList h(step_.size(), Zero);
    labelList why(step_.size(), Zero);

    sampleWaiting(waiting, offset, nullptr, s);

    // Stage 2: the configuration the integrator evaluates its forces in
    for (const label fi : waiting)
    {
        SubList<fluidSample> sf(s, fibers_[fi].nSegments(), offset[fi]);
        prepare(fi, sf, h[fi], why[fi]);
    }

    if (integrator_->predicts())
    {
        sampleWaiting(waiting, offset, &h, s2);
    }

    for (const label fi : waiting)
    {
        if (step_[fi].st != status::waiting)
        {
            continue;
        }
        step_[fi].st = status::running;
        fiber& f = fibers_[fi];
        if (integrator_->predicts() && !f.flexible())
        {
            SubList<fluidSample> sf(s2, f.nSegments(), offset[fi]);
            if (dispersion_->active())
            {
                dispersion_->correct(f, sf);
            }
            constraint_.constrain(sf);
            finish(fi, sf, h[fi], why[fi]);
        }
        else
        {
            finish
            (
                fi,
                SubList<fluidSample>(s, f.nSegments(), offset[fi]),
                h[fi],
                why[fi]
            );
        }
    }
}


void Foam::fiberCloud::transfer()
{
    List<DynamicList<label>> send(Pstream::nProcs());
    forAll(step_, fi)
    {
        if (step_[fi].st == status::moving)
        {
            send[step_[fi].toProc].append(fi);
        }
    }
    forAll(send, proci)
    {
        if (send[proci].empty())
        {
            continue;
        }
        autoPtr<UOPstream> osPtr(neighbours_.sendStream(proci));
        UOPstream& os = osPtr();
        os << send[proci].size();
        for (const label fi : send[proci])
        {
            const stepState& st = step_[fi];
            os  << st.toPatch << token::SPACE << st.toFace
                << token::SPACE << st.tLeft << token::SPACE << st.nSub
                << token::SPACE << st.unfollowed
                << token::SPACE << st.load
                << token::SPACE << fibers_[fi];
            if (interactions_->active())
            {
                os << token::SPACE;
                interactions_->writeFiber(fibers_[fi].id(), os);
            }
            step_[fi].st = status::gone;
            ++nSentStep_;
        }
    }
    neighbours_.exchange();

    for (const label proci : neighbours_.neighbours())
    {
        if (neighbours_.received(proci))
        {
            receive(proci);
        }
    }
}


void Foam::fiberCloud::receive(const label proci)
{
    autoPtr<UIPstream> isPtr(neighbours_.recvStream(proci));
    UIPstream& is = isPtr();
    const label n = readLabel(is);
    for (label k = 0; k < n; ++k)
    {
        const label patch = readLabel(is);
        const label face = readLabel(is);
        const scalar tLeft = readScalar(is);
        const label nSub = readLabel(is);
        const scalar unfollowed = readScalar(is);
        fiberIntegrator::load load;
        is >> load;
        autoPtr<fiber> fPtr(new fiber(is));
        if (interactions_->active())
        {
            interactions_->readFiber(is);
        }

        const processorPolyPatch& pp = tracker_.processorPatch(patch);
        // processorCyclic: into this side's frame
        const vectorTensorTransform T(fiberTracker::receiving(pp, face));
        fPtr->transform(T);
        load.transform(T);

        const label fi = fibers_.size();
        fibers_.append(fPtr.ptr());
        step_.append
        (
            stepState
            {
                tLeft > tStopLeft_ ? status::running : status::done,
                tLeft, nSub, unfollowed, -1, -1, -1, load, inIntervals_, 0
            }
        );

        fiber& f = fibers_[fi];
        const label seed = pp.faceCells()[face];
        fiberTracker::hit c =
            tracker_.locate(f.position(), f.location(), seed);
        if
        (
            c.where == fiberTracker::stop::processor
         && mag(c.left) < 1e-9*f.length()
        )
        {
            // A centre on the processor face itself (round-off): it stays
            // here rather than going back and forth
            c.where = fiberTracker::stop::none;
        }
        centreMoved(fi, c);
        if (step_[fi].st == status::moving)
        {
            // On into a third processor's part
            ++nOnwardStep_;
        }
    }
}

// ************************************************************************* //
