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
    fiberCloud: the local stepping of one fiber (sampling, the sub-step,
    integration, the centre's move, the boundary rules).

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fiberTracker::hit Foam::fiberCloud::locateSegment
(
    fiber& f,
    const label i,
    const vector& d,
    const bool store,
    trackedPoint& tp
) const
{
    typedef fiberTracker::stop stop;
    const fiberTracker::hit here
    {
        stop::none, -1, Zero, false, vectorTensorTransform::I, false
    };
    const trackedPoint& centre = f.location();
    trackedPoint& cached = f.segmentLocations()[i];

    // A segment at the centre: the centre's location
    if (magSqr(d) == 0)
    {
        tp = centre;
        return here;
    }

    // From where the segment was (a short walk), else from the centre
    fiberTracker::hit h(here);
    bool found = false;
    if (cached.located())
    {
        tp = cached;
        h = tracker_.track(tp, f.position() + d - tracker_.position(tp));
        found = (h.where == stop::none && !h.crossed);
    }
    if (!found)
    {
        tp = centre;
        h = tracker_.track(tp, d);
    }
    if (store)
    {
        cached =
            (h.where == stop::none && !h.crossed) ? tp : trackedPoint();
    }
    return h;
}


bool Foam::fiberCloud::sampleSegments
(
    const label fi,
    const vector& dx,
    const tensor& R,
    UList<fluidSample>& s,
    DynamicList<fluidSampler::request>* reqs,
    DynamicList<remoteSegment>* remote
)
{
    fiber& f = fibers_[fi];
    fluidSampler::request req;
    bool allLocal = true;
    const bool current = (magSqr(dx) == 0);

    for (label i = 0; i < f.nSegments(); ++i)
    {
        trackedPoint tp;
        const fiberTracker::hit h =
            locateSegment(f, i, dx + f.segmentOffset(R, i), current, tp);

        if (sampler_.sample(tp, h, s[i], req))
        {
            continue;
        }
        if (!reqs)
        {
            return false;
        }
        allLocal = false;
        reqs->append(req);
        remote->append(remoteSegment{fi, i, h});
    }
    return allLocal;
}


void Foam::fiberCloud::fiberResponses
(
    const labelUList& fis,
    const scalar h,
    List<scalarList>& mobility,
    List<scalarList>& vFree
)
{
    // The flow at every segment now (a segment on another processor's
    // part asked of it), then each fiber's step without and with loads
    labelList offset(fis.size() + 1, 0);
    forAll(fis, k)
    {
        offset[k + 1] = offset[k] + fibers_[fis[k]].nSegments();
    }
    List<fluidSample> s(offset.last());
    DynamicList<fluidSampler::request> reqs;
    DynamicList<remoteSegment> remote;
    labelList at(fibers_.size(), -1);
    forAll(fis, k)
    {
        const fiber& f = fibers_[fis[k]];
        at[fis[k]] = k;
        SubList<fluidSample> sf(s, f.nSegments(), offset[k]);
        sampleSegments(fis[k], Zero, f.R(), sf, &reqs, &remote);
    }
    List<fluidSample> answers(reqs.size());
    sampler_.exchange(reqs, answers);
    forAll(remote, r)
    {
        fluidSampler::toStartFrame(remote[r].h, answers[r]);
        s[offset[at[remote[r].fiber]] + remote[r].segment] = answers[r];
    }
    mobility.setSize(fis.size());
    vFree.setSize(fis.size());
    forAll(fis, k)
    {
        const fiber& f = fibers_[fis[k]];
        const SubList<fluidSample> sf(s, f.nSegments(), offset[k]);
        const vector g(gravityOn(f));
        if (f.flexible())
        {
            // The chain's own implicit Euler step (flexibleChain), which
            // it takes over an interval under contact forces
            flexWork_.response(f, sf, hydro_, g, h, mobility[k], vFree[k]);
        }
        else
        {
            fiberIntegrator::response
            (
                f, sf, hydro_, g, h, mobility[k], vFree[k]
            );
        }
    }
}


bool Foam::fiberCloud::wallContact
(
    const label fi,
    const UList<fluidSample>& s
)
{
    fiber& f = fibers_[fi];

    // Wall contact: the deepest segment beyond a wall (or beyond an
    // outlet that holds a mat)
    label iWall = -1;
    forAll(s, i)
    {
        const bool beyond =
            s[i].beyondWall()
         || (s[i].beyondOutlet() && rules_->isMat(s[i].patch));
        if (beyond && (iWall < 0 || s[i].dWall > s[iWall].dWall))
        {
            iWall = i;
        }
    }
    if (iWall < 0)
    {
        return true;
    }
    const wallRule rule =
        s[iWall].mirror ? wallRule::rebound : rules_->ruleOf(s[iWall].patch);
    if (rule == wallRule::deposit)
    {
        deposit(fi);
        return false;
    }
    if (rule == wallRule::mat)
    {
        // The wire's plane: where the deepest segment's centre (at its
        // offset from the fiber's) went through it
        const tensor R(f.R());
        const point c(f.position() + f.segmentOffset(R, iWall));
        land
        (
            fi, s[iWall].patch, s[iWall].nWall,
            c - s[iWall].dWall*s[iWall].nWall
        );
        return false;
    }
    // Back inside, then the step goes on with these samples, taken on the
    // wall face (a fiber pressed onto a wall slides along it); the
    // centre's location moves along
    stepStats_.addRebound();
    const vector shift
    (
        rebound
        (
            f,
            s[iWall].nWall,
            s[iWall].dWall,
            s[iWall].mirror ? 1 : restitution_
        )
    );
    const status before = step_[fi].st;
    centreMoved(fi, tracker_.track(f.location(), shift));
    return step_[fi].st == before;
}


Foam::scalar Foam::fiberCloud::subStepRate
(
    const label fi,
    const UList<fluidSample>& s,
    label& why
) const
{
    const fiber& f = fibers_[fi];

    // The rate the step control asks for on the mean flow (Eq. 22 or the
    // error estimate, and the cell limit).  A flexible fiber under
    // implicit contact springs takes the interval in one implicit step
    // (the cell limit aside): the springs act against the partners'
    // motion predicted over the interval, which the interval's length
    // resolves (maxApproach), not sub-steps that would resolve the
    // chain's response to a spring held at that prediction
    const bool oneStep =
        f.flexible() && interactions_->active() && step_[fi].load.implicit;
    scalar rate =
        control_.rate(f, s, cellLength_[f.location().celli], &why, oneStep);

    // Gravity can speed a fiber up within the sub-step beyond the speeds
    // the cell limit sees (a fiber from rest in a long step): keep
    // (speed + |g| h) h within maxCo cell lengths
    const scalar magG = mag(g_);
    if (magG > 0)
    {
        scalar speed = mag(f.velocity()) + 0.5*mag(f.omega())*f.length();
        for (const fluidSample& si : s)
        {
            speed = max(speed, mag(si.U));
        }
        const scalar dx = control_.maxCo()*cellLength_[f.location().celli];
        const scalar hMax =
            2*dx/(speed + std::sqrt(sqr(speed) + 4*magG*dx));
        if (1/hMax > rate)
        {
            rate = 1/hMax;
            why = subStepStatistics::cell;
        }
    }
    return rate;
}


void Foam::fiberCloud::tooManySubSteps
(
    const label fi,
    const scalar parts,
    const scalar T,
    const label why
) const
{
    const fiber& f = fibers_[fi];
    FatalErrorInFunction
        << "Fiber " << f.id() << " needs " << parts
        << " sub-steps over " << T << " s, at " << f.position()
        << " in cell " << f.location().celli << " (speed "
        << mag(f.velocity()) << " m/s, turning at " << mag(f.omega())
        << " rad/s"
        << (
               interactions_->active() && step_[fi].load.implicit
             ? ", under implicit contact springs" : ""
           )
        << "): asked for by ";
    if (why == subStepStatistics::cell)
    {
        FatalError
            << "the cell limit (entry 'maxCo' " << control_.maxCo()
            << ", cell length " << cellLength_[f.location().celli]
            << " m)";
    }
    else if (control_.control() == subStepControl::mode::paper)
    {
        FatalError
            << "Eq. 22 (entry 'shearStepFactor' "
            << control_.shearStepFactor() << ")";
    }
    else
    {
        FatalError
            << "the tolerance control (entries 'tolerance' "
            << control_.tolerance() << ", 'maxRotation' "
            << control_.maxRotation() << ")";
    }
    FatalError << exit(FatalError);
}


bool Foam::fiberCloud::prepare
(
    const label fi,
    UList<fluidSample>& s,
    scalar& h,
    label& why
)
{
    if (!wallContact(fi, s))
    {
        return false;
    }
    fiber& f = fibers_[fi];
    const scalar rate = subStepRate(fi, s, why);
    step_[fi].rate = rate;

    // The time to the next break: the end of the step (of the interval),
    // or the end of the fiber's eddy if that comes first (Eq. 23: an eddy
    // interaction ends when the eddy does).  The fluctuation is added to
    // the samples here
    scalar T = step_[fi].tLeft - tStopLeft_;
    bool eddyEnds = false;
    if (dispersion_->active())
    {
        const scalar tEddy = dispersion_->correct(f, s);
        if (tEddy < (1 + 1e-9)*T)
        {
            eddyEnds = true;
            if (tEddy > (1 - 1e-9)*T)
            {
                // Both end at the same instant up to round-off
                f.eddyTime() = T;
            }
            else
            {
                T = tEddy;
            }
        }
    }

    // Equal parts up to the break: no sliver of a sub-step is left where
    // the steps the rate asks for do not fill it
    const scalar parts = T*rate;
    if (parts > labelMax/2)
    {
        tooManySubSteps(fi, parts, T, why);
    }
    // Round-off tolerant: a count that is an integer up to round-off
    // (uniform shear) must not flip to the next one
    const label nParts = max(1, label(std::ceil(parts*(1 - 1e-9))));
    if (parts < 1 - 1e-6)
    {
        // The rate allows a step longer than the time to the break (up to
        // round-off: the last of equal parts has parts = 1): the break
        // binds, the eddy's end, the step's, or the rest of the step of a
        // fiber released in it
        why =
            eddyEnds ? subStepStatistics::eddy
          : step_[fi].nSub == 0 && step_[fi].tLeft < (1 - 1e-12)*dt_
          ? subStepStatistics::release
          : subStepStatistics::stepEnd;
    }
    h = T/nParts;

    constraint_.constrain(s);
    return true;
}


void Foam::fiberCloud::finish
(
    const label fi,
    const UList<fluidSample>& s,
    const scalar h,
    const label why
)
{
    fiber& f = fibers_[fi];
    const point x0(f.position());
    fiber::motion& m0 = motion0_;
    f.saveMotion(m0);

    // Gravity, less buoyancy if asked for (segments of one density)
    const vector g(gravityOn(f));
    if (f.flexible())
    {
        flexWork_.advance
        (
            f, s, hydro_, g, h, coupling_.valid() ? &forces_ : nullptr,
            interactions_->active() ? &step_[fi].load : nullptr
        );
    }
    else
    {
        integrator_->advance
        (
            f, s, hydro_, g, h, coupling_.valid() ? &forces_ : nullptr,
            interactions_->active() ? &step_[fi].load : nullptr
        );
    }
    constraint_.constrain(f);

    // The response to implicit contacts is no error of the sub-step: the
    // interaction's intervals resolve it (maxApproach)
    const bool inContact =
        interactions_->active() && step_[fi].load.implicit;
    if (!control_.update(f, s, h, inContact))
    {
        // Rejected: undone, to be taken again with a shorter step
        f.restoreMotion(m0);
        ++nRejected_;
        return;
    }
    if (interactions_->active())
    {
        step_[fi].load.record(f, h);
    }
    if (coupling_.valid())
    {
        addReaction(fi, s, h);
    }
    nSegmentSteps_ += f.nSegments();
    dispersion_->elapse(f, h);
    stepState& st = step_[fi];
    ++st.nSub;
    f.countSubStep(why);
    stepStats_.add(why, h, h*st.rate);
    st.tLeft -= h;
    if (st.tLeft - tStopLeft_ <= 1e-9*h)
    {
        st.tLeft = tStopLeft_;
        st.st = status::done;
    }

    // Move the centre's location along
    centreMoved(fi, tracker_.track(f.location(), f.position() - x0));
}


void Foam::fiberCloud::addReaction
(
    const label fi,
    const UList<fluidSample>& s,
    const scalar h
)
{
    // The part of a change of the fluid velocity at the step's start
    // that the fiber's translation has not followed yet (implicit Euler).
    // A fiber within one cell enters the implicit part with its drag's
    // true sensitivity K u; a fiber across cells with K, which also damps
    // the force couple it answers the strain with (fiberCoupling)
    const fiber& f = fibers_[fi];
    scalar sumK = 0;
    bool oneCell = true;
    forAll(s, i)
    {
        sumK += forces_.K[i];
        oneCell =
            oneCell && s[i].cell == s[0].cell && s[i].proc == s[0].proc;
    }
    step_[fi].unfollowed /= 1 + h*sumK/f.mass();
    const scalar r = oneCell ? step_[fi].unfollowed : 1;
    forAll(s, i)
    {
        coupling_->add(s[i], forces_.F[i], r*forces_.K[i], h);
    }
}


void Foam::fiberCloud::centreMoved
(
    const label fi,
    const fiberTracker::hit& c
)
{
    if (c.crossed)
    {
        fiber& f = fibers_[fi];
        f.transform(c.T);
        step_[fi].load.transform(c.T);
        if (c.where == fiberTracker::stop::none)
        {
            // The location went across face to matching face; on a mesh
            // whose periodic faces match only to its matchTolerance that
            // image and the transformed centre differ by the mismatch:
            // the fiber follows its location
            f.translate(tracker_.position(f.location()) - f.position());
        }
    }

    if
    (
        fibers_[fi].inMat()
     && c.where != fiberTracker::stop::none
     && c.where != fiberTracker::stop::processor
    )
    {
        // A mat fiber its belt carried out of the domain
        carriedOut(fi, mesh_.boundaryMesh().whichPatch(c.face));
        return;
    }

    switch (c.where)
    {
        case fiberTracker::stop::none:
        {
            if (c.slid && !c.crossed)
            {
                // Across a sliding interface the location may have ended
                // within the sides' mismatch of where the fiber is: back
                // to the fiber, as near as the mesh holds it
                fiber& f = fibers_[fi];
                trackedPoint& loc = f.location();
                tracker_.track(loc, f.position() - tracker_.position(loc));
            }
            break;
        }
        case fiberTracker::stop::processor:
        {
            step_[fi].st = status::moving;
            tracker_.processorAddress
            (
                c.face,
                step_[fi].toProc,
                step_[fi].toPatch,
                step_[fi].toFace
            );
            break;
        }
        case fiberTracker::stop::wall:
        case fiberTracker::stop::symmetry:
        {
            centreAtWall(fi, c, c.where == fiberTracker::stop::symmetry);
            break;
        }
        case fiberTracker::stop::outlet:
        {
            const label patchi = mesh_.boundaryMesh().whichPatch(c.face);
            if (rules_->isMat(patchi))
            {
                // Stopped by the wire the fluid passes
                centreAtWall(fi, c, false);
            }
            else
            {
                escape(fi, patchi);
            }
            break;
        }
    }
}


void Foam::fiberCloud::centreAtWall
(
    const label fi,
    const fiberTracker::hit& c,
    const bool mirror
)
{
    // Rebound off the face hit; on a curved wall or in a corner the way
    // back can meet another wall face: rebound off that one in turn
    fiber& f = fibers_[fi];
    fiberTracker::hit h(c);
    bool isMirror = mirror;
    for (label k = 0; k < 8; ++k)
    {
        const label patchi = mesh_.boundaryMesh().whichPatch(h.face);
        const wallRule rule =
            isMirror ? wallRule::rebound : rules_->ruleOf(patchi);
        if (rule == wallRule::deposit)
        {
            deposit(fi);
            return;
        }
        const vector& Sf = mesh_.faceAreas()[h.face];
        const vector n(Sf/mag(Sf));
        if (rule == wallRule::mat)
        {
            // Its location stopped where the centre went through the wire
            land(fi, patchi, n, tracker_.position(f.location()), h.face);
            return;
        }
        const point onWall(tracker_.position(f.location()));
        const scalar e = isMirror ? 1 : restitution_;
        stepStats_.addRebound();
        rebound(f, n, max(h.left & n, scalar(0)), e);
        h = tracker_.track(f.location(), f.position() - onWall, h.face);
        if
        (
            h.where != fiberTracker::stop::wall
         && h.where != fiberTracker::stop::symmetry
        )
        {
            centreMoved(fi, h);
            return;
        }
        if (h.crossed)
        {
            f.transform(h.T);
        }
        isMirror = (h.where == fiberTracker::stop::symmetry);
    }

    // Rebounds that do not bring it back: deposited
    deposit(fi);
}


void Foam::fiberCloud::runLocal(const label fi)
{
    fiber& f = fibers_[fi];
    const label n = f.nSegments();
    if (samples_.size() < n)
    {
        samples_.setSize(n);
        samples2_.setSize(n);
    }
    SubList<fluidSample> s(samples_, n);
    SubList<fluidSample> s2(samples2_, n);

    while (step_[fi].st == status::running)
    {
        if (!sampleSegments(fi, Zero, f.R(), s))
        {
            step_[fi].st = status::waiting;
            return;
        }
        scalar h;
        label why;
        if (!prepare(fi, s, h, why))
        {
            return;
        }
        // A flexible fiber: its own implicit Euler (flexibleChain), at the
        // current configuration, whatever the rigid fibers' integrator
        if (integrator_->predicts() && !f.flexible())
        {
            vector dx;
            tensor R;
            integrator_->predict(f, h, dx, R);
            if (!sampleSegments(fi, dx, R, s2))
            {
                step_[fi].st = status::waiting;
                return;
            }
            if (dispersion_->active())
            {
                dispersion_->correct(f, s2);
            }
            constraint_.constrain(s2);
            finish(fi, s2, h, why);
        }
        else
        {
            finish(fi, s, h, why);
        }
    }
}


Foam::vector Foam::fiberCloud::rebound
(
    fiber& f,
    const vector& n,
    const scalar d,
    const scalar e
) const
{
    // Back inside the wall plane, with a margin of a thousandth of the
    // penetration and a millionth of the diameter
    const vector shift(-((1 + 1e-3)*d + 1e-6*f.minDiameter())*n);
    f.translate(shift);

    f.clearHistory();
    const scalar vn = f.velocity() & n;
    if (vn > 0)
    {
        f.setVelocity(f.velocity() - (1 + e)*vn*n);
    }
    return shift;
}


void Foam::fiberCloud::deposit(const label fi)
{
    const fiber& f = fibers_[fi];
    if (rules_->any(wallRule::deposit))
    {
        events_.deposit(f);
    }
    step_[fi].st = status::gone;
    counters_.deposited(f.setIndex());
    events_.record
    (
        f, tEnd_ - step_[fi].tLeft, fiberEventLog::deposited, -1
    );
}


void Foam::fiberCloud::escape(const label fi, const label patchi)
{
    const fiber& f = fibers_[fi];
    step_[fi].st = status::gone;
    counters_.escaped(f.setIndex(), patchi);
    events_.record
    (
        f, tEnd_ - step_[fi].tLeft, fiberEventLog::escaped, patchi
    );
}

// ************************************************************************* //
