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
#include "openfoamCompat.H"
#include "keywordCheck.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "patchWave.H"
#include "Switch.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <ctime>
#include <utility>
#include <vector>

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
    if (!fiberCompat::isSwitch(w))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'inertialDrag' must be auto, on or off, not '" << w
            << "'" << exit(FatalIOError);
    }
    return Switch(w) ? "on" : "off";
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


// Two-way coupling if 'coupled' (else null)
fiberCoupling* couplingFrom
(
    const fvMesh& mesh,
    const dictionary& dict,
    const scalar rhoFluid
)
{
    if (!dict.getOrDefault<Switch>("coupled", false))
    {
        return nullptr;
    }
    return new fiberCoupling
    (
        mesh,
        dict.dictName(),
        rhoFluid,
        dict.getOrDefault<word>("U", "U")
    );
}


// The hydrodynamic laws from the drag entries
fiberHydrodynamics hydrodynamicsFrom
(
    const dictionary& dict,
    const scalar rhoFluid
)
{
    if (inertialMode(dict) != "auto")
    {
        keywordCheck::noEffect
        (
            dict, "inertialDragBound",
            "with inertialDrag " + inertialMode(dict) + " (it bounds the"
            " drag that inertialDrag auto leaves out)"
        );
    }
    return fiberHydrodynamics
    (
        rhoFluid,
        inertialMode(dict) != "off",
        keywordCheck::positive(dict, "dragCoefficient", 1),
        inertialMode(dict) == "auto"
      ? keywordCheck::positive(dict, "inertialDragBound", 1e-3)
      : 0,
        dict.getOrDefault<Switch>("viscousDrag", true)
    );
}

} // End anonymous namespace


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
    mats_(),
    near_(),
    nearMotion_(0),
    nearMargin_(0),
    nearFrom_(),
    nBeyondMargin_(0),
    view_(),
    jeffery_(dict.getOrDefault<bool>("jefferyCorrection", false)),
    coupling_(couplingFrom(mesh, dict, rhoFluid)),
    buoyancy_(dict.getOrDefault<Switch>("buoyancy", false)),
    hydro_(hydrodynamicsFrom(dict, rhoFluid)),
    integrator_(fiberIntegrator::New(dict)),
    dispersion_(fiberDispersion::New(dict)),
    rules_(),
    restitution_(dict.getOrDefault<scalar>("restitution", 1)),
    g_(g),
    control_(dict),
    tracker_(mesh),
    neighbours_(mesh),
    sampler_(mesh, tracker_, neighbours_, checkedScheme(dict)),
    constraint_(mesh),
    wallClearance_(),
    wallClearanceIndex_(-1),
    counters_(tracker_.outletPatches(), mesh.boundaryMesh().size()),
    interactions_(fiberInteraction::New(dict, mesh, rhoFluid)),
    fixedSet_(),
    setE_(),
    setG_(),
    setKappa_(),
    flexWork_(),
    motion0_(),
    images_(),
    tEnd_(0),
    dt_(0),
    tStopLeft_(0),
    tCommon_(0),
    inIntervals_(false),
    restarted_(restart != nullptr),
    nSubMax_(0),
    nRemote_(0),
    nForwarded_(0),
    nFurther_(0),
    nTransferred_(0),
    nOnward_(0),
    nOutside_(0),
    nInertial_(0),
    nInertialSkipped_(0),
    nSegmentSteps_(0),
    nIntervals_(0),
    nWindows_(0),
    nEngaged_(0),
    nInWindows_(0),
    cpuInteractions_(0),
    nRejected_(0),
    nSentStep_(0),
    nOnwardStep_(0)
{
    readWallRule(dict);
    interactions_->setResponder
    (
        [this]
        (
            const labelUList& fis, const scalar h, List<scalarList>& M,
            List<scalarList>& v
        )
        {
            fiberResponses(fis, h, M, v);
        }
    );
    label nPeriodic = 0;
    images_ = periodicImages::transforms(mesh_, nPeriodic);
    if (constraint_.active())
    {
        g_ = constraint_.constrain(g);
        Info<< "    2-D case: fibers held in the plane (free directions "
            << constraint_.freeDirections() << "), gravity " << g_ << endl;
    }
    control_.report(Info);
    calcCellLength();

    const dictionary& injectionDict =
        keywordCheck::subDict
        (
            dict, "injection", "{ setName { type mesh; nFibers 100; ... } }"
        );

    PtrList<fiber> all;
    List<fiberInjection::origin> origins;
    wordList setNames;
    fiberInjection::read
    (
        injectionDict,
        all,
        origins,
        setNames,
        feeds_,
        constraint_.freeDirections(),
        &mesh_,
        restart != nullptr
    );
    counters_.setSets(setNames);
    fixedSet_ = fiberInjection::fixedSets(injectionDict);
    fiberInjection::flexibleSets(injectionDict, setE_, setG_);
    setKappa_ = fiberInjection::curvatures(injectionDict);

    if (restart)
    {
        restartFrom(*restart);
        return;
    }
    injectAtStart(dict, injectionDict, all, origins);
}


namespace Foam
{
    //- The flow of a fiber the interactions do not move (a mat's)
    static const fiberInteraction::flow noFlow
    {
        Zero, Zero, 0, GREAT, GREAT, 0, GREAT, false, true
    };
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::fiberCloud::lightestBody() const
{
    scalar m = GREAT;
    for (const fiber& f : fibers_)
    {
        m = min(m, f.mass());
        for (label i = 0; f.flexible() && i < f.nSegments(); ++i)
        {
            m = min(m, f.segmentMass(i));
        }
    }
    for (const fiberPatchInjection& feed : feeds_)
    {
        m = min(m, feed.sizes().lightestMass(setE_[feed.setIndex()] > 0));
    }
    return returnReduce(m, minOp<scalar>());
}


void Foam::fiberCloud::checkInteractionCost
(
    const dictionary& dict,
    const scalar dt
) const
{
    if (interactions_->active())
    {
        interactions_->checkCost
        (
            dict.subDict("interactions"), lightestBody(), dt
        );
    }
}


void Foam::fiberCloud::readWallRule(const dictionary& dict)
{
    rules_.reset
    (
        new wallRules
        (
            dict, mesh_.boundaryMesh(), tracker_.wallPatches(),
            tracker_.outletPatches()
        )
    );
    if (!rules_->any(wallRule::rebound))
    {
        keywordCheck::noEffect
        (
            dict, "restitution",
            "where no wall rebounds fibers (wallInteraction)"
        );
    }

    if (restitution_ < 0 || restitution_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'restitution' must lie in [0, 1], not " << restitution_
            << exit(FatalIOError);
    }
    rules_->report(mesh_.boundaryMesh());
    if (rules_->any(wallRule::rebound))
    {
        Info<< "    Restitution at the walls " << restitution_ << endl;
    }
}


void Foam::fiberCloud::restartFrom(Istream& is)
{
    // A file cut short (a run killed while writing it) fails deep in the
    // stream's readers: caught here and said in its terms
    const bool throwing = FatalError.throwExceptions(true);
    const bool throwingIO = FatalIOError.throwExceptions(true);
    string why;
    try
    {
        readRestart(is);
    }
    catch (const Foam::error& e)
    {
        why = e.message();
    }
    FatalError.throwExceptions(throwing);
    FatalIOError.throwExceptions(throwingIO);
    if (why.size())
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name()
            << " is incomplete or damaged (" << why.c_str() << ")."
            << nl << "    The fiber state of this time cannot be read:"
            << " the run that wrote it may have stopped while writing."
            << " Start from an earlier write time (startFrom startTime;"
            << " startTime <an earlier time>), or remove the file to"
            << " inject the fibers anew" << exit(FatalIOError);
    }
}


void Foam::fiberCloud::injectAtStart
(
    const dictionary& dict,
    const dictionary& injectionDict,
    PtrList<fiber>& all,
    const List<fiberInjection::origin>& origins
)
{
    labelList setIndex(all.size());
    forAll(all, fi)
    {
        setIndex[fi] = all[fi].setIndex();
    }
    counters_.injectedAtStart(setIndex);
    forAll(all, fi)
    {
        bend(all[fi]);
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
    for (fiber& f : all)
    {
        makeFlexible(f);
    }

    distribute(injectionDict, all, origins);

    Info<< "    Injected " << counters_.nInjected() << " fibers" << endl;
}


void Foam::fiberCloud::bend(fiber& f) const
{
    fiberInjection::bend
    (
        f, setKappa_[f.setIndex()], constraint_.freeDirections()
    );
}


void Foam::fiberCloud::makeFlexible(fiber& f) const
{
    const scalar E = setE_[f.setIndex()];
    if (E > 0)
    {
        flexibleChain::checkConnected(f);
        f.makeFlexible(E, setG_[f.setIndex()]);
    }
}


void Foam::fiberCloud::calcWallClearance() const
{
    wallClearanceIndex_ = mesh_.time().timeIndex();
    wallClearance_.setSize(mesh_.nCells(), GREAT);
    labelHashSet ids;
    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        if
        (
            isA<wallPolyPatch>(pp) || isA<symmetryPolyPatch>(pp)
         || isA<symmetryPlanePolyPatch>(pp)
        )
        {
            ids.insert(patchi);
        }
    }
    if (ids.empty())
    {
        return;
    }
    const patchWave wave(mesh_, ids, true);
    const scalarField& y = wave.distance();
    const pointField& pts = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const labelListList& cellPts = mesh_.cellPoints();
    forAll(wallClearance_, celli)
    {
        scalar r = 0;
        for (const label pointi : cellPts[celli])
        {
            r = max(r, mag(pts[pointi] - C[celli]));
        }
        wallClearance_[celli] = y[celli] - r;
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


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCloud::evolve(const scalar t0, const scalar dt)
{
    sortByCell();
    beginStep(t0, dt);
    if (mesh_.moving())
    {
        followMesh();
    }

    // The windows and intervals of the interaction model: at a window's
    // start the model says which fibers could meet a partner in it
    // (engaged); the others run through the window on their own first.
    // At the end of each interval of the window every engaged fiber of
    // every processor is at the same time and they act on each other
    // ('none': one window, one interval, no call)
    const bool active = interactions_->active();
    scalar tLeft = dt;
    while (true)
    {
        scalar tWindow = 0;
        bool anyEngaged = true;
        if (active)
        {
            tWindow = openWindow(dt, tLeft, anyEngaged);
        }
        intervals(dt, tLeft, tWindow, active && anyEngaged);
        if (!(tWindow > 0))
        {
            break;
        }
        tLeft = tWindow;
    }

    endStep(dt);
}


Foam::scalar Foam::fiberCloud::openWindow
(
    const scalar dt,
    const scalar tLeft,
    bool& anyEngaged
)
{
    // The window from where tLeft of the step is left, and the fibers
    // that run through it without stops; the time left at its end
    tCommon_ = tLeft;
    const std::clock_t c0 = std::clock();
    List<fiberInteraction::flow> fl(flows());
    if (!(tLeft < dt))
    {
        // The step's first window: the mat fibers it may meet
        selectNear(fl);
        fl.resize(fibers_.size() + near_.size(), noFlow);
    }
    List<bool> engaged(fl.size(), true);
    const scalar H =
        interactions_->nextWindow(view(), roles(true), fl, dt, tLeft, engaged);
    cpuInteractions_ += scalar(std::clock() - c0)/CLOCKS_PER_SEC;
    const scalar tWindow = H < tLeft ? tLeft - H : 0;
    label nEngaged = 0;
    label nFree = 0;
    forAll(step_, fi)
    {
        stepState& st = step_[fi];
        st.engaged = engaged[fi];
        const fiber& f = fibers_[fi];
        if (st.st == status::gone || fixedSet_[f.setIndex()] || f.inMat())
        {
            continue;
        }
        ++nFree;
        if (st.engaged)
        {
            ++nEngaged;
        }
        else
        {
            st.load = fiberIntegrator::load();
        }
        st.st =
            !st.engaged && st.tLeft > tWindow ? status::running : status::done;
    }
    reduce(nEngaged, sumOp<label>());
    reduce(nFree, sumOp<label>());
    anyEngaged = nEngaged > 0;
    nEngaged_ += nEngaged;
    nInWindows_ += nFree;
    ++nWindows_;
    inIntervals_ = false;
    advance(tWindow);
    return tWindow;
}


void Foam::fiberCloud::intervals
(
    const scalar dt,
    const scalar tLeft,
    const scalar tWindow,
    const bool engaged
)
{
    // The intervals of the window from tLeft to tWindow left
    const bool active = interactions_->active();
    inIntervals_ = active;
    scalar tl = tLeft;
    while (true)
    {
        tCommon_ = tl;
        scalar h = tl - tWindow;
        if (engaged)
        {
            const std::clock_t c0 = std::clock();
            h = interactions_->nextInterval(view(), roles(), dt, h);
            cpuInteractions_ += scalar(std::clock() - c0)/CLOCKS_PER_SEC;
        }
        tStopLeft_ = h < tl - tWindow ? tl - h : tWindow;

        // The engaged fibers that reach into the interval run in it; one
        // a feed releases after its end (less time left) waits
        for (stepState& st : step_)
        {
            if
            (
                (st.st == status::done || st.st == status::running)
             && (st.engaged || !active)
            )
            {
                st.st = st.tLeft > tStopLeft_ ? status::running : status::done;
            }
        }
        if (active)
        {
            interact(tEnd_ - tl, tl - tStopLeft_);
        }
        advance(tStopLeft_);
        if (rules_->anyMoving())
        {
            // The belts' mats to the interval's end (those a belt took to
            // another processor sent on)
            carry(tEnd_ - tl, tEnd_ - tStopLeft_);
            advance(tStopLeft_);
        }
        if (active)
        {
            tCommon_ = tStopLeft_;
            settle();
            captureOnContact();
        }
        if (!(tStopLeft_ > tWindow))
        {
            break;
        }
        tl = tStopLeft_;
    }
    inIntervals_ = false;
}


void Foam::fiberCloud::beginStep(const scalar t0, const scalar dt)
{
    tEnd_ = t0 + dt;
    dt_ = dt;
    sampler_.resetCounters();
    stepStats_.clear();

    if (events_.initialDue())
    {
        for (const fiber& f : fibers_)
        {
            events_.record(f, t0, fiberEventLog::injected, -1);
        }
    }

    // The feeds' fibers due in this step, with the time each has left
    const label nOld = fibers_.size();
    DynamicList<scalar> tLeftNew;
    if (feeds_.size() && dt > 0)
    {
        release(t0, tEnd_, tLeftNew);
    }

    // Every fiber's state in the step; a release at the step's end up to
    // round-off takes no sub-step, a fixed fiber none
    const label nF = fibers_.size();
    const label nPrev = min(nOld, step_.size());
    step_.setSize(nF);
    for (label fi = 0; fi < nF; ++fi)
    {
        // Whether it took part in the intervals of the last window (a
        // fiber released in this step: as if it had)
        const bool engaged = fi < nPrev ? step_[fi].engaged : true;
        scalar tLeft = dt;
        if (fi >= nOld)
        {
            tLeft = tLeftNew[fi - nOld] > 1e-9*dt ? tLeftNew[fi - nOld] : 0;
        }
        if (fixedSet_[fibers_[fi].setIndex()] || fibers_[fi].inMat())
        {
            tLeft = 0;
        }
        step_[fi] =
            stepState
            {
                tLeft > 0 ? status::running : status::done,
                tLeft, 0, 1, -1, -1, -1, fiberIntegrator::load(), engaged,
                0
            };
    }
    near_.clear();
    counters_.beginStep();
    nSentStep_ = 0;
    nOnwardStep_ = 0;

    hydro_.resetCounters();
}


Foam::List<Foam::fiberInteraction::flow> Foam::fiberCloud::flows() const
{
    // At each fiber's centre (where its location is, on this processor):
    // the fluid's mean velocity and its gradient, the fluctuation the
    // random walk may add (the present eddy's or a new one's); the times
    // in which the drag brings the fiber to the fluid's velocity, from the
    // viscous resistance across (the larger) and along the segments
    // (tauHi) and with the inertial drag at the largest slip added
    // (tauLo); gravity less buoyancy
    // The gap to the walls and symmetry planes, where a fiber rebounds:
    // its centre's cell's clearance less half its length and diameter
    if
    (
        wallClearance_.size() != mesh_.nCells()
     || (mesh_.moving() && wallClearanceIndex_ != mesh_.time().timeIndex())
    )
    {
        calcWallClearance();
    }
    List<fiberInteraction::flow> fl(fibers_.size() + near_.size(), noFlow);
    forAll(fibers_, fi)
    {
        fiberInteraction::flow& fw = fl[fi];
        fw.engaged = step_[fi].engaged;
        const fiber& f = fibers_[fi];
        if (f.inMat())
        {
            // On a belt: moving at its velocity
            fw.U = f.velocity();
        }
        fluidSample s;
        if
        (
            step_[fi].st == status::gone || f.inMat() || !sampleCentre(f, s)
        )
        {
            continue;
        }
        fw.U = s.U;
        fw.G = s.G;
        scalar dMax = 0;
        for (label i = 0; i < f.nSegments(); ++i)
        {
            dMax = max(dMax, f.segmentDiameter(i));
        }
        fw.wall =
            wallClearance_[f.location().celli] - 0.5*(f.length() + dMax);
        fw.slack = dispersion_->fluctuationBound(f, s);
        const scalar slip =
            mag(f.velocity() - s.U) + 0.5*mag(f.omega())*f.length()
          + fw.slack;
        scalar kLo = 0;
        scalar kHi = 0;
        for (label i = 0; i < f.nSegments(); ++i)
        {
            if (hydro_.viscous())
            {
                kLo += s.mu*min(f.kAx(i), f.kAp(i));
                kHi += s.mu*max(f.kAx(i), f.kAp(i));
            }
            if (hydro_.inertial())
            {
                kHi +=
                    0.5*hydro_.rho()*hydro_.CD()*f.segmentDiameter(i)
                   *f.segmentLength(i)*slip;
            }
        }
        fw.tauLo = kHi > 0 ? f.mass()/kHi : GREAT;
        fw.tauHi = kLo > 0 ? f.mass()/kLo : GREAT;
        fw.g = mag(gravityOn(f));
        if (step_[fi].tLeft < tCommon_ - 1e-9*dt_)
        {
            // Released later in the window: it rests where the feed puts
            // it until then, while its neighbours move on, so that it
            // moves against the flow at up to its own speed (and its path
            // is no straight line from the window's start)
            fw.slack += max(mag(fw.U), mag(f.velocity()));
            fw.tauLo = 0;
            fw.later = true;
        }
    }
    return fl;
}


Foam::List<Foam::fiberInteraction::role> Foam::fiberCloud::roles
(
    const bool window
) const
{
    typedef fiberInteraction::role role;
    List<role> r(fibers_.size() + near_.size(), role::fixed);
    forAll(fibers_, fi)
    {
        // A fiber a feed releases later in the step is not there yet (at
        // a window's start: it will be, where the feed puts it); in a
        // window's intervals a fiber not engaged is not there either
        r[fi] =
            step_[fi].st == status::gone ? role::absent
          : fixedSet_[fibers_[fi].setIndex()] || fibers_[fi].inMat()
          ? role::fixed
          : window ? role::free
          : step_[fi].tLeft < tCommon_ - 1e-9*dt_ ? role::absent
          : inIntervals_ && !step_[fi].engaged ? role::absent
          : role::free;
    }
    return r;
}


const Foam::UPtrList<Foam::fiber>& Foam::fiberCloud::view()
{
    const label nF = fibers_.size();
    view_.resize(nF + near_.size());
    forAll(fibers_, fi)
    {
        view_.set(fi, &fibers_[fi]);
    }
    forAll(near_, k)
    {
        view_.set(nF + k, &mats_[near_[k]]);
    }
    return view_;
}


void Foam::fiberCloud::interact(const scalar t, const scalar h)
{
    // The loads of the fibers present, new, in a buffer kept between
    // intervals; an absent fiber's load is left as it is (a fiber not
    // engaged in the window: none since the window's start)
    const List<fiberInteraction::role> r(roles());
    List<fiberIntegrator::load>& loads = loadBuf_;
    loads.resize(r.size());
    forAll(r, fi)
    {
        if (r[fi] != fiberInteraction::role::absent)
        {
            loads[fi] = fiberIntegrator::load();
        }
    }
    const std::clock_t c0 = std::clock();
    interactions_->interact(view(), r, t, h, loads);
    cpuInteractions_ += scalar(std::clock() - c0)/CLOCKS_PER_SEC;
    ++nIntervals_;
    forAll(fibers_, fi)
    {
        if (r[fi] != fiberInteraction::role::absent)
        {
            loads[fi].holdAxial(fibers_[fi]);
            step_[fi].load = std::move(loads[fi]);
        }
    }
}


void Foam::fiberCloud::settle()
{
    const List<fiberInteraction::role> r(roles());
    List<fiberIntegrator::load>& loads = loadBuf_;
    loads.resize(r.size());
    forAll(r, fi)
    {
        if (r[fi] != fiberInteraction::role::absent)
        {
            loads[fi] =
                fi < fibers_.size()
              ? std::move(step_[fi].load) : fiberIntegrator::load();
        }
    }
    const std::clock_t c0 = std::clock();
    interactions_->settle(view(), r, loads);
    cpuInteractions_ += scalar(std::clock() - c0)/CLOCKS_PER_SEC;
    forAll(fibers_, fi)
    {
        if (r[fi] != fiberInteraction::role::absent)
        {
            step_[fi].load = std::move(loads[fi]);
        }
    }
}


void Foam::fiberCloud::followMesh()
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


void Foam::fiberCloud::advance(const scalar tStopLeft)
{
    tStopLeft_ = tStopLeft;
    while (true)
    {
        forAll(fibers_, fi)
        {
            if (step_[fi].st == status::running)
            {
                runLocal(fi);
            }
        }
        if (!Pstream::parRun())
        {
            break;
        }
        bool pending = false;
        for (const stepState& st : step_)
        {
            pending =
                pending || st.st == status::waiting
             || st.st == status::moving;
        }
        if (!returnReduce(pending, orOp<bool>()))
        {
            break;
        }
        round();
        transfer();
    }
}


void Foam::fiberCloud::endStep(const scalar dt)
{
    checkMargin();
    joinAtRest();
    label nSubMax = 0;
    for (const stepState& st : step_)
    {
        nSubMax = max(nSubMax, st.nSub);
    }
    nSubMax_ = returnReduce(nSubMax, maxOp<label>());
    nRemote_ = returnReduce(sampler_.nRemote(), sumOp<label>());
    nForwarded_ = returnReduce(sampler_.nForwarded(), sumOp<label>());
    nFurther_ = returnReduce(sampler_.nFurther(), sumOp<label>());
    nOutside_ = returnReduce(sampler_.nOutside(), sumOp<label>());
    nInertial_ = returnReduce(hydro_.nInertial(), sumOp<label>());
    nInertialSkipped_ = returnReduce(hydro_.nSkipped(), sumOp<label>());
    counters_.endStep();
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


void Foam::fiberCloud::compact()
{
    // The fibers that joined a mat at rest move to mats_, at once
    PtrList<fiber> joining(fibers_.size());
    label nJoining = 0;
    label n = 0;
    forAll(fibers_, fi)
    {
        if (step_[fi].st != status::gone && restsInMat(fibers_[fi]))
        {
            joining.set(nJoining++, fibers_.set(fi, nullptr).ptr());
        }
        else if (step_[fi].st != status::gone)
        {
            if (n != fi)
            {
                fibers_.set(n, fibers_.set(fi, nullptr));
                step_[n] = step_[fi];
            }
            ++n;
        }
    }
    fibers_.setSize(n);
    step_.setSize(n);
    joining.setSize(nJoining);
    mats_.add(joining);
}


void Foam::fiberCloud::sortByCell()
{
    // Before the first step there are no step states yet
    const label n = fibers_.size();
    if (step_.size() && step_.size() != n)
    {
        return;
    }

    // The fibers in the order of their cells (then ids): the segments the
    // contact model gathers from them, and the mesh data their steps read,
    // then lie in memory roughly as in space, so the pairs of neighbours
    // and the cells of a region share the caches.  The keys are read once
    // (each fiber is a pointer away); fibers already in order stay
    std::vector<std::pair<label, label>> key(n);
    forAll(fibers_, fi)
    {
        key[fi] = {fibers_[fi].location().celli, fibers_[fi].id()};
    }
    if (std::is_sorted(key.begin(), key.end()))
    {
        return;
    }
    List<label> order(n);
    forAll(order, i)
    {
        order[i] = i;
    }
    std::sort
    (
        order.begin(), order.end(),
        [&](const label i, const label j) { return key[i] < key[j]; }
    );
    List<label> oldToNew(n);
    forAll(order, i)
    {
        oldToNew[order[i]] = i;
    }
    fibers_.reorder(oldToNew);
    if (step_.size())
    {
        const List<stepState> st(step_);
        forAll(order, i)
        {
            step_[i] = st[order[i]];
        }
    }
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


// ************************************************************************* //
