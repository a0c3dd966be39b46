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
    const fiberTracker::hit here
    {
        fiberTracker::stop::none, -1, Zero, false, vectorTensorTransform::I,
        false
    };
    fluidSample s;
    fluidSampler::request req;
    scalar drive = 0;
    scalar kLo = 0;
    if (sampler_.sample(f.location(), here, s, req))
    {
        drive = mag(s.U - w.U);
        for (label i = 0; hydro_.viscous() && i < f.nSegments(); ++i)
        {
            kLo += s.mu*min(f.kAx(i), f.kAp(i));
        }
    }
    const vector g
    (
        buoyancy_ ? (1 - hydro_.rho()/f.segmentDensity(0))*g_ : g_
    );
    if (kLo > 0)
    {
        drive += mag(g)*f.mass()/kLo;
    }
    return w.restFraction*drive;
}


void Foam::fiberCloud::joinAtRest()
{
    // A free fiber touching a fixed one (a mat's, or a fixed set's) comes
    // to rest there at a step end; it joins the mat at a later step end,
    // still touching, where it has been at rest for the wire's restTime:
    // its ends have moved, since, less than the rest speed relative to
    // the wire times the time.  Where they moved more, it comes to rest
    // anew there.  A mean over the time, not the speed of the moment: a
    // fiber rocking in place on a pile is at rest
    if (rules_->wires().empty() || !interactions_->active())
    {
        return;
    }
    forAll(fibers_, fi)
    {
        fiber& f = fibers_[fi];
        vector Uw(Zero);
        if
        (
            step_[fi].st == status::gone || f.inMat()
         || fixedSet_[f.setIndex()]
         || !interactions_->touchesFixed(f.id(), Uw)
        )
        {
            f.restSince() = -1;
            continue;
        }
        const label k = wireOfPartner(Uw);
        const wallRules::wire& w = rules_->wires()[k];
        const FixedList<point, 2> e(f.ends());
        const scalar T = tEnd_ - f.restSince();
        if (f.restSince() < 0 || !(T > 0))
        {
            f.restSince() = tEnd_;
            f.restEnds() = e;
            continue;
        }

        // The ends' largest displacement relative to the wire
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
            continue;
        }
        const scalar tRest =
            w.restTime > 0 ? w.restTime
          : 0.1*f.minDiameter()/max(vRest, VSMALL);
        if (T >= tRest*(1 - 1e-9))
        {
            step_[fi].tLeft = 0;
            toMat(fi, w.patch);
        }
    }
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
