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
    fiberCloud: the mats on the wires (wallRules): a fiber that lands on a
    wire, and one that comes to rest on the mat, joins it.

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"
#include "openfoamCompat.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberCloud::land
(
    const label fi,
    const label patchi,
    const vector& n,
    const point& p0,
    const label face
)
{
    // Back along the wire's normal n until the fiber's lowest surface
    // point lies on the wire's plane through p0 (each segment's ends
    // and radius; a millionth of a diameter clear), its location moved
    // along (from the wire face it stopped on, if it did)
    fiber& f = fibers_[fi];
    const tensor R(f.R());
    scalar depth = -GREAT;
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const point c(f.position() + f.segmentOffset(R, i));
        const scalar zn = min(mag(f.segmentDirection(R, i) & n), 1.0);
        const scalar a =
            0.5*f.segmentLength(i)*zn
          + 0.5*f.segmentDiameter(i)*std::sqrt(1 - sqr(zn));
        depth = max(depth, ((c - p0) & n) + a);
    }
    const point from(tracker_.position(f.location()));
    f.translate(-(depth + 1e-6*f.minDiameter())*n);
    toMat(fi, patchi);
    const fiberTracker::hit h =
        tracker_.track(f.location(), f.position() - from, face);
    if (h.crossed)
    {
        f.transform(h.T);
    }
    if (h.where == fiberTracker::stop::processor)
    {
        centreMoved(fi, h);
    }
    f.clearSegmentLocations();
}


void Foam::fiberCloud::toMat(const label fi, const label patchi)
{
    fiber& f = fibers_[fi];
    stepState& st = step_[fi];
    const scalar t = tEnd_ - st.tLeft;
    const wallRules::wire& w = rules_->wires()[rules_->wireOf(patchi)];
    f.joinMat(patchi, t, w.U);
    st.load = fiberIntegrator::load();
    st.st = status::done;
    st.tLeft = 0;
    events_.record(f, t, fiberEventLog::mat, patchi);
}


void Foam::fiberCloud::captureOnContact()
{
    // At an interval's end: the free fibers that touched a fixed fiber in
    // it join the wire of that fiber's velocity where they are, if that
    // wire takes fibers on contact
    if (!rules_->anyCapture())
    {
        return;
    }
    forAll(fibers_, fi)
    {
        const fiber& f = fibers_[fi];
        vector Uw(Zero);
        if
        (
            step_[fi].st == status::gone || f.inMat()
         || fixedSet_[f.setIndex()]
         || !interactions_->touchesFixed(f.id(), Uw)
        )
        {
            continue;
        }
        const wallRules::wire& w = rules_->wires()[wireOfPartner(Uw)];
        if (w.capture)
        {
            toMat(fi, w.patch);
        }
    }
}


Foam::scalar Foam::fiberCloud::restSpeed
(
    const label fi,
    const label k
) const
{
    const wallRules::wire& w = rules_->wires()[k];
    if (w.restSpeed > 0)
    {
        return w.restSpeed;
    }

    // restFraction of what the flow and gravity would give the fiber:
    // the fluid's speed relative to the wire at its centre, and its
    // terminal speed under gravity less buoyancy along its weakest
    // viscous resistance
    const fiber& f = fibers_[fi];
    fluidSample s;
    scalar drive = 0;
    scalar kLo = 0;
    if (sampleCentre(f, s))
    {
        drive = mag(s.U - w.U);
        for (label i = 0; hydro_.viscous() && i < f.nSegments(); ++i)
        {
            kLo += s.mu*min(f.kAx(i), f.kAp(i));
        }
    }
    if (kLo > 0)
    {
        drive += mag(gravityOn(f))*f.mass()/kLo;
    }
    return w.restFraction*drive;
}


bool Foam::fiberCloud::sampleCentre(const fiber& f, fluidSample& s) const
{
    const fiberTracker::hit here
    {
        fiberTracker::stop::none, -1, Zero, false, vectorTensorTransform::I,
        false
    };
    fluidSampler::request req;
    return
        f.location().located()
     && sampler_.sample(f.location(), here, s, req);
}


Foam::vector Foam::fiberCloud::gravityOn(const fiber& f) const
{
    return buoyancy_ ? (1 - hydro_.rho()/f.segmentDensity(0))*g_ : g_;
}


bool Foam::fiberCloud::atRest(const label fi, const label k)
{
    // Its rest: since the first step end it was found in contact, where
    // its ends have moved, relative to the wire, less than the rest speed
    // times the time; over the wire's restTime it is ready to join
    fiber& f = fibers_[fi];
    const wallRules::wire& w = rules_->wires()[k];
    const FixedList<point, 2> e(f.ends());
    const scalar T = tEnd_ - f.restSince();
    if (f.restSince() < 0 || !(T > 0))
    {
        f.restSince() = tEnd_;
        f.restEnds() = e;
        return false;
    }
    scalar moved = 0;
    forAll(e, j)
    {
        moved = max(moved, mag(e[j] - f.restEnds()[j] - w.U*T));
    }
    const scalar vRest = restSpeed(fi, k);
    if (moved > vRest*T)
    {
        f.restSince() = tEnd_;
        f.restEnds() = e;
        return false;
    }
    const scalar tRest =
        w.restTime > 0 ? w.restTime
      : 0.1*f.minDiameter()/max(vRest, VSMALL);
    return T >= tRest*(1 - 1e-9);
}


void Foam::fiberCloud::joinAtRest()
{
    // The fibers in contact come to rest (atRest); of those ready, the
    // ones that touch a fixed fiber join the mat, and so do the ready
    // ones that touch a joining one, through the pairs of the last
    // interval (a pile at rest on the mat joins at one step end).  Every
    // processor has every ready fiber and pair, and finds the same ones
    if (rules_->wires().empty() || !interactions_->active())
    {
        return;
    }
    List<labelList> pairsOf(Pstream::nProcs());
    {
        const List<FixedList<label, 2>> p(interactions_->touchingPairs());
        labelList& mine = pairsOf[Pstream::myProcNo()];
        mine.setSize(2*p.size());
        forAll(p, k)
        {
            mine[2*k] = p[k][0];
            mine[2*k + 1] = p[k][1];
        }
    }
    fiberCompat::allGatherList(pairsOf);
    labelHashSet inPair;
    for (const labelList& p : pairsOf)
    {
        for (const label id : p)
        {
            inPair.insert(id);
        }
    }

    // This processor's fibers ready to join, and those that touch a
    // fixed fiber (with the wire of that fiber's velocity)
    List<labelList> readyOf(Pstream::nProcs());
    DynamicList<label> ready;
    Map<label> local;
    forAll(fibers_, fi)
    {
        fiber& f = fibers_[fi];
        vector Uw(Zero);
        const bool onFixed =
            step_[fi].st != status::gone && !f.inMat()
         && !fixedSet_[f.setIndex()]
         && interactions_->touchesFixed(f.id(), Uw);
        if
        (
            step_[fi].st == status::gone || f.inMat()
         || fixedSet_[f.setIndex()] || (!onFixed && !inPair.found(f.id()))
        )
        {
            f.restSince() = -1;
            continue;
        }
        const label k = onFixed ? wireOfPartner(Uw) : 0;
        if (atRest(fi, k))
        {
            // id, and its wire if it touches a fixed fiber (-1: not)
            ready.append(f.id());
            ready.append(onFixed ? k : -1);
            local.insert(f.id(), fi);
        }
    }
    readyOf[Pstream::myProcNo()] = std::move(ready);
    fiberCompat::allGatherList(readyOf);
    joinPiles(pairsOf, readyOf, local);
}


void Foam::fiberCloud::joinPiles
(
    const List<labelList>& pairsOf,
    const List<labelList>& readyOf,
    const Map<label>& local
)
{
    // Breadth first from the ready fibers on a fixed one through the
    // pairs of ready fibers; each joins its parent's wire
    Map<label> wireOf;
    DynamicList<label> front;
    Map<DynamicList<label>> next;
    labelHashSet isReady;
    for (const labelList& r : readyOf)
    {
        for (label k = 0; k < r.size(); k += 2)
        {
            isReady.insert(r[k]);
            if (r[k + 1] >= 0)
            {
                wireOf.insert(r[k], r[k + 1]);
                front.append(r[k]);
            }
        }
    }
    for (const labelList& p : pairsOf)
    {
        for (label k = 0; k < p.size(); k += 2)
        {
            if (isReady.found(p[k]) && isReady.found(p[k + 1]))
            {
                next(p[k]).append(p[k + 1]);
                next(p[k + 1]).append(p[k]);
            }
        }
    }
    for (label q = 0; q < front.size(); ++q)
    {
        const auto it = next.cfind(front[q]);
        if (!it.found())
        {
            continue;
        }
        for (const label id : *it)
        {
            if (wireOf.insert(id, wireOf[front[q]]))
            {
                front.append(id);
            }
        }
    }
    forAllConstIters(wireOf, it)
    {
        const auto fi = local.cfind(it.key());
        if (fi.found())
        {
            step_[*fi].tLeft = 0;
            toMat(*fi, rules_->wires()[it.val()].patch);
        }
    }
}


void Foam::fiberCloud::carry(const scalar ta, const scalar tb)
{
    forAll(fibers_, fi)
    {
        // From ta, or from its landing if later (in the interval, or in
        // the window a fiber ran through on its own before it)
        fiber& f = fibers_[fi];
        if (!f.inMat() || step_[fi].st == status::gone)
        {
            continue;
        }
        const vector& U =
            rules_->wires()[rules_->wireOf(f.matPatch())].U;
        const scalar h = tb - max(ta, f.landTime());
        if (magSqr(U) > 0 && h > 0)
        {
            f.translate(h*U);
            f.clearSegmentLocations();
            centreMoved(fi, tracker_.track(f.location(), h*U));
        }
    }
}


void Foam::fiberCloud::carriedOut(const label fi, const label patchi)
{
    const fiber& f = fibers_[fi];
    step_[fi].st = status::gone;
    counters_.carried(f.setIndex());
    events_.record(f, tEnd_ - tStopLeft_, fiberEventLog::carried, patchi);
}


bool Foam::fiberCloud::restsInMat(const fiber& f) const
{
    return
        f.inMat()
     && magSqr(rules_->wires()[rules_->wireOf(f.matPatch())].U) == 0;
}


Foam::scalar Foam::fiberCloud::speedBound
(
    const fiber& f,
    const fiberInteraction::flow& w
) const
{
    // Its own speed and its ends' turning (a flexible fiber's: each
    // segment's), or the fluid's with the slack and its gradient across
    // the fiber and the terminal speed of gravity less buoyancy (or what
    // gravity adds over the step, if less), whichever is larger: the drag
    // relaxes the velocity from the one towards the other
    const scalar L = f.length();
    scalar v = mag(f.velocity()) + 0.5*mag(f.omega())*L;
    if (f.flexible())
    {
        const tensor R(f.R());
        for (label i = 0; i < f.nSegments(); ++i)
        {
            v =
                max
                (
                    v,
                    mag(f.segmentVelocity(R, i))
                  + 0.5*mag(f.segmentOmega(i))*f.segmentLength(i)
                );
        }
    }
    return
        max(v, mag(w.U) + w.slack + 0.5*mag(w.G)*L + w.g*min(w.tauHi, dt_));
}


void Foam::fiberCloud::selectNear(const UList<fiberInteraction::flow>& fl)
{
    near_.clear();
    nearFrom_.clear();
    if (returnReduce(mats_.size(), sumOp<label>()) == 0)
    {
        return;
    }

    // How far a free fiber may move in the step: twice the step times the
    // largest speed bound of every processor's fibers (a belt's speed
    // too); the margin adds the range and the largest diameter
    scalar V = 0;
    scalar d = 0;
    DynamicList<point> boxes;
    forAll(fibers_, fi)
    {
        const fiber& f = fibers_[fi];
        if (step_[fi].st == status::gone)
        {
            continue;
        }
        if (f.inMat() || fixedSet_[f.setIndex()])
        {
            V = max(V, mag(f.velocity()));
            continue;
        }
        V = max(V, speedBound(f, fl[fi]));
        for (label i = 0; i < f.nSegments(); ++i)
        {
            d = max(d, f.segmentDiameter(i));
        }
        for (const boundBox& bb : matStore::segmentBoxes(f))
        {
            boxes.append(bb.min());
            boxes.append(bb.max());
        }
        nearFrom_.insert(f.id(), f.ends());
    }
    reduce(V, maxOp<scalar>());
    reduce(d, maxOp<scalar>());
    nearMotion_ = 2*V*dt_;
    nearMargin_ = nearMotion_ + interactions_->range() + d;

    near_ = mats_.near(nearQueries(boxes));
}


Foam::List<Foam::boundBox> Foam::fiberCloud::nearQueries
(
    const UList<point>& boxes
) const
{
    // Every processor's segments' boxes, widened, and their periodic images
    List<pointField> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = pointField(boxes);
    fiberCompat::allGatherList(all);

    // Only those that meet this processor's mat: most are far from it
    const vector m(vector::uniform(nearMargin_));
    const boundBox& matBox = mats_.bounds();
    DynamicList<boundBox> q;
    auto keep = [&](const boundBox& bb)
    {
        if (bb.overlaps(matBox))
        {
            q.append(bb);
        }
    };
    for (const pointField& b : all)
    {
        for (label k = 0; k < b.size(); k += 2)
        {
            const boundBox bb(b[k] - m, b[k + 1] + m);
            keep(bb);
            for (const vectorTensorTransform& T : images_)
            {
                if (!T.hasR())
                {
                    keep(boundBox(bb.min() + T.t(), bb.max() + T.t()));
                    continue;
                }
                boundBox image;
                const pointField corners(bb.points());
                for (const point& p : corners)
                {
                    image.add(T.transformPosition(p));
                }
                keep(image);
            }
        }
    }
    return List<boundBox>(std::move(q));
}


void Foam::fiberCloud::checkMargin()
{
    // The ends of each free fiber against where they were at the step's
    // start (or an image of there: it may have crossed a periodic patch)
    forAll(fibers_, fi)
    {
        const fiber& f = fibers_[fi];
        const auto it = nearFrom_.cfind(f.id());
        if (step_[fi].st == status::gone || !it.found())
        {
            continue;
        }
        const FixedList<point, 2> e(f.ends());
        scalar moved = GREAT;
        for (label t = -1; t < images_.size(); ++t)
        {
            scalar m = 0;
            forAll(e, j)
            {
                const point p0
                (
                    t < 0 ? (*it)[j] : images_[t].transformPosition((*it)[j])
                );
                m = max(m, mag(e[j] - p0));
            }
            moved = min(moved, m);
        }
        if (moved > nearMotion_)
        {
            if (nBeyondMargin_++ < 5)
            {
                WarningInFunction
                    << "Fiber " << f.id() << " moved " << moved << " m in the"
                    << " step, more than the margin " << nearMotion_
                    << " m of the mat fibers searched for its contacts"
                    << endl;
            }
        }
    }
    nearFrom_.clear();
}


Foam::label Foam::fiberCloud::wireOfPartner(const vector& U) const
{
    // The wire whose velocity the partner has (the first), else the first
    const List<wallRules::wire>& wires = rules_->wires();
    forAll(wires, j)
    {
        if (mag(wires[j].U - U) <= 1e-9*(mag(U) + SMALL))
        {
            return j;
        }
    }
    return 0;
}


// ************************************************************************* //
