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

#include "fiberCloud.H"
#include "keywordCheck.H"
#include "fiberVtkWriter.H"
#include "processorPolyPatch.H"
#include "ListOps.H"
#include "Switch.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::fiberCloud::wallRule>
Foam::fiberCloud::wallRuleNames
({
    { wallRule::rebound, "rebound" },
    { wallRule::deposit, "deposit" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// inertialDrag: auto (default), on or off (also true/false, yes/no)
word inertialMode(const dictionary& dict)
{
    const word w(dict.getOrDefault<word>("inertialDrag", "auto"));
    if (w == "auto")
    {
        return w;
    }
    const Switch sw(w, true);
    if (!sw.valid())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'inertialDrag' must be auto, on or off, not '" << w
            << "'" << exit(FatalIOError);
    }
    return sw ? "on" : "off";
}


word checkedScheme(const dictionary& dict)
{
    const word scheme
    (
        dict.getOrDefault<word>("interpolationScheme", "cellPoint")
    );
    if
    (
        !interpolation<vector>::dictionaryConstructorTablePtr_
      ->found(scheme)
    )
    {
        FatalIOErrorInLookup
        (
            dict,
            "interpolationScheme",
            scheme,
            *interpolation<vector>::dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }
    return scheme;
}


// All states of all processors on the master, sorted by fiber id
List<fiberCloud::state> gatherSorted(const UList<fiberCloud::state>& local)
{
    // Per processor: ids and four vectors (x, p, v, omega) per fiber
    List<labelList> ids(Pstream::nProcs());
    List<vectorList> vals(Pstream::nProcs());
    labelList& myIds = ids[Pstream::myProcNo()];
    vectorList& myVals = vals[Pstream::myProcNo()];
    myIds.setSize(local.size());
    myVals.setSize(4*local.size());
    forAll(local, i)
    {
        myIds[i] = local[i].id;
        myVals[4*i] = local[i].x;
        myVals[4*i + 1] = local[i].p;
        myVals[4*i + 2] = local[i].v;
        myVals[4*i + 3] = local[i].omega;
    }

    Pstream::gatherList(ids);
    Pstream::gatherList(vals);

    List<fiberCloud::state> result;
    if (Pstream::master())
    {
        DynamicList<fiberCloud::state> all;
        DynamicList<label> allIds;
        forAll(ids, proci)
        {
            const vectorList& v = vals[proci];
            forAll(ids[proci], k)
            {
                all.append
                (
                    fiberCloud::state
                    {
                        ids[proci][k], v[4*k], v[4*k+1], v[4*k+2], v[4*k+3]
                    }
                );
                allIds.append(ids[proci][k]);
            }
        }
        const labelList order(sortedOrder(allIds));
        result.setSize(order.size());
        forAll(order, k)
        {
            result[k] = all[order[k]];
        }
    }
    return result;
}


fiberCloud::state stateOf(const fiber& f)
{
    return fiberCloud::state
    {
        f.id(), f.position(), f.orientation(), f.velocity(), f.omega()
    };
}

} // End anonymous namespace


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
    Pstream::listCombineGather(segFound, maxEqOp<label>());
    Pstream::listCombineScatter(segFound);

    List<point> pts;
    forAll(all, fi)
    {
        all[fi].segmentCentres(pts);
        forAll(pts, i)
        {
            if (!segFound[offset[fi] + i] && mesh_.findCell(pts[i]) >= 0)
            {
                segFound[offset[fi] + i] = 1;
            }
        }
    }

    Pstream::listCombineGather(owner, minEqOp<label>());
    Pstream::listCombineScatter(owner);
    Pstream::listCombineGather(segFound, maxEqOp<label>());
    Pstream::listCombineScatter(segFound);
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


void Foam::fiberCloud::calcCellLength()
{
    const scalarField& V = mesh_.V();
    cellLength_.setSize(V.size());
    if (constraint_.active())
    {
        // 2-D: the side of a square of the cell's area in the plane
        const vector span(mesh_.bounds().span());
        const vector& fr = constraint_.freeDirections();
        scalar depth = 1;
        label nFree = 0;
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            if (fr[i] > 0)
            {
                ++nFree;
            }
            else
            {
                depth *= span[i];
            }
        }
        forAll(V, celli)
        {
            cellLength_[celli] =
                std::pow(V[celli]/depth, 1.0/max(nFree, label(1)));
        }
    }
    else
    {
        forAll(V, celli)
        {
            cellLength_[celli] = std::cbrt(V[celli]);
        }
    }
}


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


bool Foam::fiberCloud::prepare
(
    const label fi,
    UList<fluidSample>& s,
    scalar& h,
    label& why
)
{
    fiber& f = fibers_[fi];

    // Wall contact: the deepest segment beyond a wall
    label iWall = -1;
    forAll(s, i)
    {
        if
        (
            s[i].beyondWall()
         && (iWall < 0 || s[i].dWall > s[iWall].dWall)
        )
        {
            iWall = i;
        }
    }
    if (iWall >= 0)
    {
        if (wallRule_ == wallRule::deposit && !s[iWall].mirror)
        {
            deposit(fi);
            return false;
        }
        // Back inside, then the step goes on with these samples, taken
        // on the wall face (a fiber pressed onto a wall slides along it);
        // the centre's location moves along
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
        const status before = status_[fi];
        centreMoved(fi, tracker_.track(f.location(), shift));
        if (status_[fi] != before)
        {
            return false;
        }
    }

    // The rate the step control asks for on the mean flow (Eq. 22 or the
    // error estimate, and the cell limit)
    scalar rate =
        control_.rate(f, s, cellLength_[f.location().celli], &why);

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

    // The time to the next break: the end of the step, or the end of the
    // fiber's eddy if that comes first (Eq. 23: an eddy interaction ends
    // when the eddy does).  The fluctuation is added to the samples here
    scalar T = tLeft_[fi];
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
        FatalErrorInFunction
            << "Fiber " << f.id() << " needs " << parts
            << " sub-steps over " << T << " s, at " << f.position()
            << " in cell " << f.location().celli << ": asked for by ";
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
          : nSub_[fi] == 0 && tLeft_[fi] < (1 - 1e-12)*dt_
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
    const fiber::motion m0(f.saveMotion());

    // Gravity, less buoyancy if asked for (segments of one density)
    const vector g
    (
        buoyancy_ ? (1 - hydro_.rho()/f.segmentDensity(0))*g_ : g_
    );
    integrator_->advance
    (
        f, s, hydro_, g, h, coupling_.valid() ? &forces_ : nullptr
    );
    constraint_.constrain(f);
    if (!control_.update(f, s, h))
    {
        // Rejected: undone, to be taken again with a shorter step
        f.restoreMotion(m0);
        ++nRejected_;
        return;
    }
    if (coupling_.valid())
    {
        // The part of a change of the fluid velocity at the step's start
        // that the fiber's translation has not followed yet (implicit
        // Euler).  A fiber within one cell enters the implicit part with
        // its drag's true sensitivity K u; a fiber across cells with K,
        // which also damps the force couple it answers the strain with
        // (fiberCoupling)
        scalar sumK = 0;
        bool oneCell = true;
        forAll(s, i)
        {
            sumK += forces_.K[i];
            oneCell =
                oneCell && s[i].cell == s[0].cell && s[i].proc == s[0].proc;
        }
        unfollowed_[fi] /= 1 + h*sumK/f.mass();
        const scalar r = oneCell ? unfollowed_[fi] : 1;
        forAll(s, i)
        {
            coupling_->add(s[i], forces_.F[i], r*forces_.K[i], h);
        }
    }
    nSegmentSteps_ += f.nSegments();
    dispersion_->elapse(f, h);
    ++nSub_[fi];
    f.countSubStep(why);
    stepStats_.add(why, h);
    tLeft_[fi] -= h;
    if (tLeft_[fi] <= 1e-9*h)
    {
        tLeft_[fi] = 0;
        status_[fi] = status::done;
    }

    // Move the centre's location along
    centreMoved(fi, tracker_.track(f.location(), f.position() - x0));
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
        if (c.where == fiberTracker::stop::none)
        {
            // The location went across face to matching face; on a mesh
            // whose periodic faces match only to its matchTolerance that
            // image and the transformed centre differ by the mismatch:
            // the fiber follows its location
            f.translate(tracker_.position(f.location()) - f.position());
        }
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
            status_[fi] = status::moving;
            tracker_.processorAddress
            (
                c.face,
                toProc_[fi],
                toPatch_[fi],
                toFace_[fi]
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
            status_[fi] = status::gone;
            ++nEscapedStep_;
            const label patchi = mesh_.boundaryMesh().whichPatch(c.face);
            ++nEscapedSetStep_[fibers_[fi].setIndex()];
            ++nEscapedOutletStep_[outletIndex_[patchi]];
            recordEvent
            (
                fibers_[fi], tEnd_ - tLeft_[fi], eventKind::escaped, patchi
            );
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
        if (wallRule_ == wallRule::deposit && !isMirror)
        {
            deposit(fi);
            return;
        }
        const vector& Sf = mesh_.faceAreas()[h.face];
        const vector n(Sf/mag(Sf));
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

    while (status_[fi] == status::running)
    {
        if (!sampleSegments(fi, Zero, f.R(), s))
        {
            status_[fi] = status::waiting;
            return;
        }
        scalar h;
        label why;
        if (!prepare(fi, s, h, why))
        {
            return;
        }
        if (integrator_->predicts())
        {
            vector dx;
            tensor R;
            integrator_->predict(f, h, dx, R);
            if (!sampleSegments(fi, dx, R, s2))
            {
                status_[fi] = status::waiting;
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
        if (status_[fi] != status::waiting)
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
    labelList waiting(status_.size());
    label nWaiting = 0;
    labelList offset(status_.size() + 1, 0);
    forAll(status_, fi)
    {
        offset[fi + 1] = offset[fi];
        if (status_[fi] == status::waiting)
        {
            waiting[nWaiting++] = fi;
            offset[fi + 1] += fibers_[fi].nSegments();
        }
    }
    waiting.setSize(nWaiting);

    List<fluidSample> s(offset.last());
    List<fluidSample> s2(offset.last());
    scalarList h(status_.size(), Zero);
    labelList why(status_.size(), Zero);

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
        if (status_[fi] != status::waiting)
        {
            continue;
        }
        status_[fi] = status::running;
        fiber& f = fibers_[fi];
        if (integrator_->predicts())
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
    forAll(status_, fi)
    {
        if (status_[fi] == status::moving)
        {
            send[toProc_[fi]].append(fi);
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
            os  << toPatch_[fi] << token::SPACE << toFace_[fi]
                << token::SPACE << tLeft_[fi] << token::SPACE << nSub_[fi]
                << token::SPACE << unfollowed_[fi]
                << token::SPACE << fibers_[fi];
            status_[fi] = status::gone;
            ++nSentStep_;
        }
    }
    neighbours_.exchange();

    for (const label proci : neighbours_.neighbours())
    {
        if (!neighbours_.received(proci))
        {
            continue;
        }
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
            autoPtr<fiber> fPtr(new fiber(is));

            const processorPolyPatch& pp = tracker_.processorPatch(patch);
            // processorCyclic: into this side's frame
            const vectorTensorTransform T(fiberTracker::receiving(pp, face));
            fPtr->transform(T);

            const label fi = fibers_.size();
            fibers_.append(fPtr.ptr());
            status_.append(tLeft > 0 ? status::running : status::done);
            tLeft_.append(tLeft);
            nSub_.append(nSub);
            unfollowed_.append(unfollowed);
            toProc_.append(-1);
            toPatch_.append(-1);
            toFace_.append(-1);

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
                // A centre on the processor face itself (round-off): it
                // stays here rather than going back and forth
                c.where = fiberTracker::stop::none;
            }
            centreMoved(fi, c);
            if (status_[fi] == status::moving)
            {
                // On into a third processor's part
                ++nOnwardStep_;
            }
        }
    }
}


void Foam::fiberCloud::compact()
{
    label n = 0;
    forAll(fibers_, fi)
    {
        if (status_[fi] != status::gone)
        {
            if (n != fi)
            {
                fibers_.set(n, fibers_.set(fi, nullptr));
                status_[n] = status_[fi];
                tLeft_[n] = tLeft_[fi];
                nSub_[n] = nSub_[fi];
                unfollowed_[n] = unfollowed_[fi];
                toProc_[n] = toProc_[fi];
                toPatch_[n] = toPatch_[fi];
                toFace_[n] = toFace_[fi];
            }
            ++n;
        }
    }
    fibers_.setSize(n);
    status_.setSize(n);
    tLeft_.setSize(n);
    nSub_.setSize(n);
    unfollowed_.setSize(n);
    toProc_.setSize(n);
    toPatch_.setSize(n);
    toFace_.setSize(n);
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
    if (wallRule_ == wallRule::deposit)
    {
        deposits_.append(stateOf(fibers_[fi]));
    }
    status_[fi] = status::gone;
    ++nDepositedStep_;
    ++nDepositedSetStep_[fibers_[fi].setIndex()];
    recordEvent(fibers_[fi], tEnd_ - tLeft_[fi], eventKind::deposited, -1);
}


void Foam::fiberCloud::recordEvent
(
    const fiber& f,
    const scalar t,
    const eventKind kind,
    const label patchi
)
{
    if (!logEvents_)
    {
        return;
    }
    const vector p(f.orientation());
    for
    (
        const scalar v
      : {
            t, scalar(f.id()), scalar(f.setIndex()), scalar(kind),
            scalar(patchi), scalar(f.nSegments()), f.length(),
            f.segmentDiameter(0), f.position().x(), f.position().y(),
            f.position().z(), p.x(), p.y(), p.z()
        }
    )
    {
        events_.append(v);
    }
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

        // Fiber k0 + j keeps its size; its place is drawn again until the
        // whole fiber lies in the mesh (so the sizes released follow the
        // distribution).  Every processor draws the same candidates and
        // the location is combined.
        PtrList<fiber> placed(nNew);
        labelList owner(nNew, Pstream::nProcs());
        List<trackedPoint> centre(nNew);
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

        // In release order: the next ids, the release times
        forAll(placed, slot)
        {
            const scalar tRel = max(feed.releaseTime(k0 + slot), t0);
            const label id = nInjected_++;
            ++nInjectedSet_[feed.setIndex()];
            if (owner[slot] != myProc)
            {
                continue;
            }
            fiber* fPtr = placed.set(slot, nullptr).ptr();
            fPtr->setId(id);
            fiber& f = *fPtr;
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
            recordEvent(f, tRel, eventKind::injected, feed.patch());
            fibers_.append(fPtr);
            tLeft.append(max(t1 - tRel, scalar(0)));
        }
        feed.released(nNew, nRedrawn);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberCloud::fiberCloud
(
    const fvMesh& mesh,
    const dictionary& dict,
    const scalar rhoFluid,
    const vector& g,
    Istream* restart
)
:
    mesh_(mesh),
    fibers_(),
    feeds_(),
    jeffery_(dict.getOrDefault<bool>("jefferyCorrection", false)),
    coupling_
    (
        dict.getOrDefault<Switch>("coupled", false)
      ? new fiberCoupling
        (
            mesh,
            dict.dictName(),
            rhoFluid,
            dict.getOrDefault<word>("U", "U")
        )
      : nullptr
    ),
    buoyancy_(dict.getOrDefault<Switch>("buoyancy", false)),
    hydro_
    (
        rhoFluid,
        inertialMode(dict) != "off",
        keywordCheck::positive(dict, "dragCoefficient", 1),
        inertialMode(dict) == "auto"
      ? keywordCheck::positive(dict, "inertialDragBound", 1e-3)
      : 0,
        dict.getOrDefault<Switch>("viscousDrag", true)
    ),
    integrator_(fiberIntegrator::New(dict)),
    dispersion_(fiberDispersion::New(dict)),
    wallRule_(wallRule::rebound),
    restitution_(dict.getOrDefault<scalar>("restitution", 1)),
    g_(g),
    control_(dict),
    tracker_(mesh),
    neighbours_(mesh),
    sampler_(mesh, tracker_, neighbours_, checkedScheme(dict)),
    constraint_(mesh),
    cellLength_(),
    nInjected_(0),
    nEscaped_(0),
    nDeposited_(0),
    outlets_(tracker_.outletPatches()),
    outletIndex_(mesh.boundaryMesh().size(), -1),
    nEscapedOutlet_(outlets_.size(), 0),
    nEscapedOutletStep_(outlets_.size(), 0),
    deposits_(),
    logEvents_(false),
    events_(),
    logInitial_(false),
    tEnd_(0),
    dt_(0),
    restarted_(restart != nullptr),
    nSubMax_(0),
    nRemote_(0),
    nTransferred_(0),
    nOnward_(0),
    nOutside_(0),
    nInertial_(0),
    nInertialSkipped_(0),
    nSegmentSteps_(0),
    nRejected_(0),
    nEscapedStep_(0),
    nDepositedStep_(0),
    nSentStep_(0),
    nOnwardStep_(0)
{
    const word rule(dict.getOrDefault<word>("wallInteraction", "rebound"));
    if (!wallRuleNames.found(rule))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wallInteraction': unknown rule '" << rule
            << "'; valid rules: " << wallRuleNames.sortedToc()
            << exit(FatalIOError);
    }
    wallRule_ = wallRuleNames[rule];

    if (restitution_ < 0 || restitution_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'restitution' must lie in [0, 1], not " << restitution_
            << exit(FatalIOError);
    }
    Info<< "    Wall interaction " << wallRuleNames[wallRule_];
    if (wallRule_ == wallRule::rebound)
    {
        Info<< ", restitution " << restitution_;
    }
    Info<< endl;

    if (constraint_.active())
    {
        g_ = constraint_.constrain(g);
        Info<< "    2-D case: fibers held in the plane (free directions "
            << constraint_.freeDirections() << "), gravity " << g_ << endl;
    }
    control_.report(Info);
    forAll(outlets_, i)
    {
        outletIndex_[outlets_[i]] = i;
    }
    calcCellLength();

    const dictionary& injectionDict = dict.subDict("injection");

    PtrList<fiber> all;
    List<fiberInjection::origin> origins;
    fiberInjection::read
    (
        injectionDict,
        all,
        origins,
        setNames_,
        feeds_,
        constraint_.freeDirections(),
        &mesh_,
        restart != nullptr
    );
    nEscapedSet_.setSize(setNames_.size(), 0);
    nDepositedSet_.setSize(setNames_.size(), 0);
    nEscapedSetStep_.setSize(setNames_.size(), 0);
    nDepositedSetStep_.setSize(setNames_.size(), 0);

    if (restart)
    {
        // A file cut short (a run killed while writing it) fails deep in
        // the stream's readers: caught here and said in its terms
        const bool throwing = FatalError.throwExceptions(true);
        const bool throwingIO = FatalIOError.throwExceptions(true);
        string why;
        try
        {
            readRestart(*restart);
        }
        catch (const Foam::error& e)
        {
            why = e.message();
        }
        FatalError.throwExceptions(throwing);
        FatalIOError.throwExceptions(throwingIO);
        if (why.size())
        {
            FatalIOErrorInFunction(*restart)
                << "The fiber restart file " << restart->name()
                << " is incomplete or damaged (" << why.c_str() << ")."
                << nl << "    The fiber state of this time cannot be read:"
                << " the run that wrote it may have stopped while writing."
                << " Start from an earlier write time (startFrom startTime;"
                << " startTime <an earlier time>), or remove the file to"
                << " inject the fibers anew" << exit(FatalIOError);
        }
        return;
    }

    nInjected_ = all.size();
    nInjectedSet_.setSize(setNames_.size(), 0);
    for (const fiber& f : all)
    {
        ++nInjectedSet_[f.setIndex()];
    }

    if (jeffery_)
    {
        forAll(all, fi)
        {
            if (!all[fi].jefferyCorrection())
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'jefferyCorrection' applies to straight"
                    << " fibers only; fiber " << all[fi].id() << " is not"
                    << exit(FatalIOError);
            }
        }
        Info<< "    Jeffery correction: segment tumbling resistance and"
            << " strain coupling scaled";
        if (all.size())
        {
            Info<< " by " << all[0].alpha() << " (fiber 0)";
        }
        Info<< endl;
    }

    distribute(injectionDict, all, origins);

    Info<< "    Injected " << nInjected_ << " fibers" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void writeLocation(Ostream& os, const trackedPoint& tp)
{
    os  << tp.celli << token::SPACE << tp.tetFacei << token::SPACE
        << tp.tetPti;
    for (direction k = 0; k < 4; ++k)
    {
        os << token::SPACE << tp.coordinates[k];
    }
}


void readLocation(Istream& is, trackedPoint& tp)
{
    is >> tp.celli >> tp.tetFacei >> tp.tetPti;
    for (direction k = 0; k < 4; ++k)
    {
        is >> tp.coordinates[k];
    }
}

} // End anonymous namespace


void Foam::fiberCloud::writeRestart(Ostream& os) const
{
    os  << "nProcs " << Pstream::nProcs() << " proc " << Pstream::myProcNo()
        << " cells " << mesh_.nCells() << nl
        << "nInjected " << nInjected_ << " nEscaped " << nEscaped_
        << " nDeposited " << nDeposited_ << nl
        << "nEscapedOutlet " << nEscapedOutlet_ << nl
        << "sets " << setNames_ << token::SPACE << nInjectedSet_
        << token::SPACE << nEscapedSet_ << token::SPACE << nDepositedSet_
        << nl
        << "feeds " << feeds_.size();
    for (const fiberPatchInjection& feed : feeds_)
    {
        os << token::SPACE;
        feed.writeRestart(os);
    }
    os  << nl << "coupled " << label(coupling_.valid());
    if (coupling_.valid())
    {
        os  << nl << coupling_->force().field() << nl
            << coupling_->dragRate().field();
    }
    os  << nl
        << "nFibers " << fibers_.size() << nl;
    for (const fiber& f : fibers_)
    {
        os << f << nl;
        writeLocation(os, f.location());
        for (const trackedPoint& tp : f.segmentLocations())
        {
            os << token::SPACE;
            writeLocation(os, tp);
        }
        os << nl;
    }
    os.check(FUNCTION_NAME);
}


void Foam::fiberCloud::readRestart(Istream& is)
{
    // Written by this decomposition of this mesh?
    word key;
    label nProcs, proc, nCells;
    is >> key >> nProcs >> key >> proc >> key >> nCells;
    if
    (
        nProcs != Pstream::nProcs() || proc != Pstream::myProcNo()
     || nCells != mesh_.nCells()
    )
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " was written by"
            << " processor " << proc << " of " << nProcs << " on a mesh of "
            << nCells << " cells; this is processor " << Pstream::myProcNo()
            << " of " << Pstream::nProcs() << " with " << mesh_.nCells()
            << " cells. Restart with the decomposition the file was written"
            << " with (docs: restart)" << exit(FatalIOError);
    }
    is  >> key >> nInjected_ >> key >> nEscaped_ >> key >> nDeposited_;
    labelList outlets;
    is  >> key >> outlets;
    if (outlets.size() != nEscapedOutlet_.size())
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " counts "
            << outlets.size() << " outlet patches, the mesh has "
            << nEscapedOutlet_.size() << exit(FatalIOError);
    }
    nEscapedOutlet_ = outlets;
    const wordList names(setNames_);
    is  >> key >> setNames_ >> nInjectedSet_ >> nEscapedSet_
        >> nDepositedSet_;
    label nFeeds;
    is  >> key >> nFeeds;
    if (setNames_ != names || nFeeds != feeds_.size())
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " has the fiber"
            << " sets " << setNames_ << " (" << nFeeds << " fed through"
            << " patches); the dictionary has " << names << " ("
            << feeds_.size() << "). Restart with the sets of the run that"
            << " wrote it" << exit(FatalIOError);
    }
    for (fiberPatchInjection& feed : feeds_)
    {
        feed.readRestart(is);
    }

    // The coupling's averages of the last step (written by a coupled run)
    label wasCoupled;
    is  >> key >> wasCoupled;
    if (wasCoupled)
    {
        const vectorField S(is);
        const scalarField beta(is);
        if (coupling_.valid())
        {
            coupling_->restore(S, beta);
        }
    }
    else if (coupling_.valid())
    {
        Info<< "    Restart: the file was written without coupling; the"
            << " fibers act on the fluid from the first step on" << endl;
    }
    label n;
    is >> key >> n;
    fibers_.setSize(n);
    for (label fi = 0; fi < n; ++fi)
    {
        fiber* fPtr = new fiber(is);
        readLocation(is, fPtr->location());
        for (trackedPoint& tp : fPtr->segmentLocations())
        {
            readLocation(is, tp);
        }
        fibers_.set(fi, fPtr);
    }
    is.check(FUNCTION_NAME);
    checkLocations();

    Info<< "    Restart: " << returnReduce(n, sumOp<label>())
        << " fibers read (injected " << nInjected_ << ", escaped "
        << nEscaped_ << ", deposited " << nDeposited_
        << "); the injection is not repeated" << endl;
}


void Foam::fiberCloud::evolve(const scalar t0, const scalar dt)
{
    tEnd_ = t0 + dt;
    dt_ = dt;
    sampler_.resetCounters();
    stepStats_.clear();

    if (logInitial_)
    {
        for (const fiber& f : fibers_)
        {
            recordEvent(f, t0, eventKind::injected, -1);
        }
        logInitial_ = false;
    }

    // The feeds' fibers due in this step, with the time each has left
    const label nOld = fibers_.size();
    DynamicList<scalar> tLeftNew;
    if (feeds_.size() && dt > 0)
    {
        release(t0, tEnd_, tLeftNew);
    }

    const label nF = fibers_.size();
    status_.setSize(nF);
    status_ = (dt > 0 ? status::running : status::done);
    tLeft_.setSize(nF);
    tLeft_ = dt;
    forAll(tLeftNew, j)
    {
        // A release at the step's end up to round-off takes no sub-step
        tLeft_[nOld + j] = tLeftNew[j] > 1e-9*dt ? tLeftNew[j] : 0;
        if (!(tLeft_[nOld + j] > 0))
        {
            status_[nOld + j] = status::done;
        }
    }
    nSub_.setSize(nF);
    nSub_ = 0;
    unfollowed_.setSize(nF);
    unfollowed_ = 1;
    toProc_.setSize(nF);
    toProc_ = -1;
    toPatch_.setSize(nF);
    toPatch_ = -1;
    toFace_.setSize(nF);
    toFace_ = -1;
    nEscapedStep_ = 0;
    nEscapedOutletStep_ = 0;
    nDepositedStep_ = 0;
    nEscapedSetStep_ = 0;
    nDepositedSetStep_ = 0;
    nSentStep_ = 0;
    nOnwardStep_ = 0;

    hydro_.resetCounters();

    // A moving mesh carries the stored locations with it: bring each back
    // to its fiber's centre
    if (mesh_.moving())
    {
        forAll(fibers_, fi)
        {
            fiber& f = fibers_[fi];
            trackedPoint& loc = f.location();
            centreMoved
            (
                fi,
                tracker_.track(loc, f.position() - tracker_.position(loc))
            );
        }
    }

    while (true)
    {
        forAll(fibers_, fi)
        {
            if (status_[fi] == status::running)
            {
                runLocal(fi);
            }
        }
        if (!Pstream::parRun())
        {
            break;
        }
        bool pending = false;
        for (const status st : status_)
        {
            pending = pending || st == status::waiting || st == status::moving;
        }
        if (!returnReduce(pending, orOp<bool>()))
        {
            break;
        }
        round();
        transfer();
    }

    label nSubMax = 0;
    for (const label n : nSub_)
    {
        nSubMax = max(nSubMax, n);
    }
    nSubMax_ = returnReduce(nSubMax, maxOp<label>());
    nRemote_ = returnReduce(sampler_.nRemote(), sumOp<label>());
    nOutside_ = returnReduce(sampler_.nOutside(), sumOp<label>());
    nInertial_ = returnReduce(hydro_.nInertial(), sumOp<label>());
    nInertialSkipped_ = returnReduce(hydro_.nSkipped(), sumOp<label>());
    nEscaped_ += returnReduce(nEscapedStep_, sumOp<label>());
    reduce(nEscapedOutletStep_, sumOp<labelList>());
    forAll(nEscapedOutlet_, i)
    {
        nEscapedOutlet_[i] += nEscapedOutletStep_[i];
    }
    nDeposited_ += returnReduce(nDepositedStep_, sumOp<label>());
    reduce(nEscapedSetStep_, sumOp<labelList>());
    reduce(nDepositedSetStep_, sumOp<labelList>());
    forAll(setNames_, k)
    {
        nEscapedSet_[k] += nEscapedSetStep_[k];
        nDepositedSet_[k] += nDepositedSetStep_[k];
    }
    nTransferred_ = returnReduce(nSentStep_, sumOp<label>());
    nOnward_ = returnReduce(nOnwardStep_, sumOp<label>());
    stepStats_.reduce();
    runStats_ += stepStats_;
    recordCostly();

    if (coupling_.valid())
    {
        coupling_->finish(dt);
    }

    compact();
    checkLocations();
}


void Foam::fiberCloud::checkLocations() const
{
    forAll(fibers_, fi)
    {
        const fiber& f = fibers_[fi];
        const scalar off =
            mag(tracker_.position(f.location()) - f.position());
        if
        (
            off > 1e-6*f.length()
         && off > tracker_.mismatch(f.location())
        )
        {
            FatalErrorInFunction
                << "Fiber " << f.id() << ": its mesh location is "
                << off << " m off its centre " << f.position()
                << " (fiber length " << f.length() << "): the tracking"
                << " lost the fiber. Please report this case."
                << exit(FatalError);
        }
    }
}


Foam::fiberCloud::statistics Foam::fiberCloud::stats() const
{
    statistics s;
    s.nInjected = nInjected_;
    s.nEscaped = nEscaped_;
    s.nDeposited = nDeposited_;
    s.nActive = fibers_.size();
    s.absP = Zero;
    s.pp = Zero;

    forAll(fibers_, fi)
    {
        const vector p(fibers_[fi].orientation());
        s.absP += cmptMag(p);
        s.pp += sqr(p);
    }

    reduce(s.nActive, sumOp<label>());
    reduce(s.absP, sumOp<vector>());
    reduce(s.pp, sumOp<symmTensor>());

    if (s.nActive > 0)
    {
        s.absP /= s.nActive;
        s.pp /= s.nActive;
    }
    return s;
}


Foam::List<Foam::fiberCloud::state> Foam::fiberCloud::gatherStates() const
{
    List<state> local(fibers_.size());
    forAll(fibers_, fi)
    {
        local[fi] = stateOf(fibers_[fi]);
    }
    return gatherSorted(local);
}


Foam::List<Foam::FixedList<Foam::label, 4>>
Foam::fiberCloud::setCounts() const
{
    labelList active(setNames_.size(), 0);
    for (const fiber& f : fibers_)
    {
        ++active[f.setIndex()];
    }
    reduce(active, sumOp<labelList>());
    List<FixedList<label, 4>> c(setNames_.size());
    forAll(c, k)
    {
        c[k][0] = nInjectedSet_[k];
        c[k][1] = active[k];
        c[k][2] = nEscapedSet_[k];
        c[k][3] = nDepositedSet_[k];
    }
    return c;
}


namespace Foam
{
    //- Merge packed records of costly fibers by id (the one with the most
    //  sub-steps of each) and keep the n with the most, most first
    static scalarList keepCostliest
    (
        const UList<scalar>& recs,
        const label m,
        const label n
    )
    {
        auto nSub = [&](const label r)
        {
            scalar t = 0;
            for (label l = 0; l < subStepStatistics::nLimits; ++l)
            {
                t += recs[m*r + 1 + l];
            }
            return t;
        };
        const label nRec = recs.size()/m;
        DynamicList<label> keep;
        for (label r = 0; r < nRec; ++r)
        {
            bool better = true;
            for (label q = 0; q < nRec; ++q)
            {
                // A record of the same fiber with more sub-steps (or the
                // same and earlier in the list) wins
                if
                (
                    q != r && recs[m*q] == recs[m*r]
                 && (nSub(q) > nSub(r) || (nSub(q) == nSub(r) && q < r))
                )
                {
                    better = false;
                    break;
                }
            }
            if (better)
            {
                keep.append(r);
            }
        }
        std::stable_sort
        (
            keep.begin(),
            keep.end(),
            [&](const label a, const label b) { return nSub(a) > nSub(b); }
        );
        keep.setSize(min(keep.size(), n));
        scalarList out(m*keep.size());
        forAll(keep, k)
        {
            for (label j = 0; j < m; ++j)
            {
                out[m*k + j] = recs[m*keep[k] + j];
            }
        }
        return out;
    }
}


void Foam::fiberCloud::recordCostly()
{
    const label m = costlySize;

    // The nCostly fibers here with the most sub-steps (one pass)
    FixedList<label, nCostly> top(-1);
    FixedList<scalar, nCostly> topN(-1);
    forAll(fibers_, fi)
    {
        scalar n = 0;
        for (const scalar k : fibers_[fi].nSubSteps())
        {
            n += k;
        }
        label at = nCostly;
        while (at > 0 && n > topN[at - 1])
        {
            --at;
        }
        if (at < nCostly)
        {
            for (label k = nCostly - 1; k > at; --k)
            {
                top[k] = top[k - 1];
                topN[k] = topN[k - 1];
            }
            top[at] = fi;
            topN[at] = n;
        }
    }

    // With those kept from before (fibers gone since, or passed on)
    DynamicList<scalar> recs(costly_);
    for (const label fi : top)
    {
        if (fi < 0)
        {
            continue;
        }
        const fiber& f = fibers_[fi];
        recs.append(f.id());
        for (const scalar k : f.nSubSteps())
        {
            recs.append(k);
        }
        for (direction c = 0; c < 3; ++c)
        {
            recs.append(f.position()[c]);
        }
        recs.append(f.location().celli);
        recs.append(tEnd_);
    }
    costly_ = keepCostliest(recs, m, nCostly);
}


Foam::scalarList Foam::fiberCloud::costliest() const
{
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = costly_;
    Pstream::gatherList(all);
    DynamicList<scalar> recs;
    for (const scalarList& r : all)
    {
        recs.append(r);
    }
    return keepCostliest(recs, costlySize, nCostly);
}


Foam::scalarList Foam::fiberCloud::gatherSegments() const
{
    const label m = fiberVtkWriter::recordSize;
    label n = 0;
    for (const fiber& f : fibers_)
    {
        n += f.nSegments();
    }
    List<scalarList> all(Pstream::nProcs());
    scalarList& rec = all[Pstream::myProcNo()];
    rec.setSize(m*n);
    label k = 0;
    for (const fiber& f : fibers_)
    {
        const tensor R(f.R());
        const vector p(f.orientation());
        for (label i = 0; i < f.nSegments(); ++i)
        {
            const vector r(f.segmentOffset(R, i));
            const vector half
            (
                (0.5*f.segmentLength(i))*f.segmentDirection(R, i)
            );
            const vector v(f.velocity() + (f.omega() ^ r));
            rec[k++] = f.id();
            for
            (
                const vector& w
              : {
                    vector(f.position() + r - half),
                    vector(f.position() + r + half),
                    v, f.velocity(), f.omega(), p
                }
            )
            {
                for (direction c = 0; c < 3; ++c)
                {
                    rec[k++] = w[c];
                }
            }
            rec[k++] = f.segmentDiameter(i);
        }
    }
    Pstream::gatherList(all);
    if (!Pstream::master())
    {
        return scalarList();
    }
    label nAll = 0;
    for (const scalarList& r : all)
    {
        nAll += r.size();
    }
    scalarList out(nAll);
    nAll = 0;
    for (const scalarList& r : all)
    {
        SubList<scalar>(out, r.size(), nAll) = r;
        nAll += r.size();
    }
    return out;
}


Foam::scalarList Foam::fiberCloud::gatherEvents()
{
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = events_;
    events_.clear();
    Pstream::gatherList(all);
    if (!Pstream::master())
    {
        return scalarList();
    }

    // By time, then id
    DynamicList<scalar> flat;
    for (const scalarList& r : all)
    {
        flat.append(r);
    }
    const label m = eventSize;
    const label n = flat.size()/m;
    labelList order(identity(n));
    std::sort
    (
        order.begin(),
        order.end(),
        [&flat, m](const label a, const label b)
        {
            if (flat[m*a] != flat[m*b]) return flat[m*a] < flat[m*b];
            return flat[m*a + 1] < flat[m*b + 1];
        }
    );
    scalarList out(flat.size());
    forAll(order, k)
    {
        for (label i = 0; i < m; ++i)
        {
            out[m*k + i] = flat[m*order[k] + i];
        }
    }
    return out;
}


Foam::List<Foam::fiberCloud::state> Foam::fiberCloud::gatherDeposits()
{
    List<state> all(gatherSorted(deposits_));
    deposits_.clear();
    return all;
}


// ************************************************************************* //
