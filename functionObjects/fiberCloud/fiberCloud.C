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
#include "PstreamBuffers.H"
#include "processorPolyPatch.H"
#include "ListOps.H"
#include "wallPolyPatch.H"
#include "Switch.H"

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

scalar positiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar def
)
{
    const scalar v = dict.getOrDefault<scalar>(key, def);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be positive, not " << v
            << exit(FatalIOError);
    }
    return v;
}


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

void Foam::fiberCloud::distribute
(
    const dictionary& injectionDict,
    PtrList<fiber>& all,
    const List<fiberInjection::origin>& origins
)
{
    const label nProcs = Pstream::nProcs();
    const label myProc = Pstream::myProcNo();

    // Owner: the lowest processor whose mesh holds the centre
    labelList owner(all.size(), nProcs);
    labelList centreCell(all.size(), -1);

    // Segments found somewhere: flattened, per fiber offset
    labelList offset(all.size() + 1, 0);
    forAll(all, fi)
    {
        offset[fi + 1] = offset[fi] + all[fi].nSegments();
    }
    labelList segFound(offset.last(), 0);

    List<point> pts;
    forAll(all, fi)
    {
        const label c = mesh_.findCell(all[fi].position());
        if (c >= 0)
        {
            owner[fi] = myProc;
            centreCell[fi] = c;
        }
        all[fi].segmentCentres(pts);
        forAll(pts, i)
        {
            if (mesh_.findCell(pts[i]) >= 0)
            {
                segFound[offset[fi] + i] = 1;
            }
        }
    }

    Pstream::listCombineGather(owner, minEqOp<label>());
    Pstream::listCombineScatter(owner);
    Pstream::listCombineGather(segFound, maxEqOp<label>());
    Pstream::listCombineScatter(segFound);

    forAll(all, fi)
    {
        const fiberInjection::origin& o = origins[fi];
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
            fPtr->cell() = centreCell[fi];
            fPtr->segmentCells() = centreCell[fi];
            fibers_.set(nMine++, fPtr);
        }
    }
}


void Foam::fiberCloud::relocate()
{
    const label nProcs = Pstream::nProcs();
    List<DynamicList<label>> sendFibers(nProcs);
    List<DynamicList<label>> sendFaces(nProcs);
    boolList keep(fibers_.size(), true);
    label nEscaped = 0;
    label nDeposited = 0;

    forAll(fibers_, fi)
    {
        fiber& f = fibers_[fi];
        label hitFace = -1;
        label celli = f.cell();
        if (sampler_.walk(f.position(), celli, hitFace))
        {
            f.cell() = celli;
            continue;
        }

        label proci, patchFace;
        if (sampler_.processorFace(hitFace, proci, patchFace))
        {
            sendFibers[proci].append(fi);
            sendFaces[proci].append(patchFace);
            keep[fi] = false;
            continue;
        }

        const label found = mesh_.findCell(f.position());
        if (found >= 0)
        {
            f.cell() = found;
            continue;
        }

        const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
        if
        (
            hitFace >= 0
         && isA<wallPolyPatch>(pbm[pbm.whichPatch(hitFace)])
        )
        {
            const vector& Sf = mesh_.faceAreas()[hitFace];
            const vector n(Sf/mag(Sf));
            const scalar d =
                (f.position() - mesh_.faceCentres()[hitFace]) & n;
            if (wallRule_ == wallRule::rebound)
            {
                rebound(f, n, max(d, scalar(0)));
                f.cell() = celli;
                label hit2 = -1;
                if (sampler_.walk(f.position(), celli, hit2))
                {
                    f.cell() = celli;
                    continue;
                }
            }
            // deposit rule, or a rebound that did not bring it back
            deposit(f);
            keep[fi] = false;
            ++nDeposited;
        }
        else
        {
            keep[fi] = false;
            ++nEscaped;
        }
    }

    nEscaped_ += returnReduce(nEscaped, sumOp<label>());
    nDeposited_ += returnReduce(nDeposited, sumOp<label>());

    label nSend = 0;
    forAll(sendFibers, proci)
    {
        nSend += sendFibers[proci].size();
    }
    nTransferred_ = returnReduce(nSend, sumOp<label>());

    PstreamBuffers buf(Pstream::commsTypes::nonBlocking);
    if (Pstream::parRun())
    {
        forAll(sendFibers, proci)
        {
            if (sendFibers[proci].size())
            {
                UOPstream os(proci, buf);
                os << sendFibers[proci].size();
                forAll(sendFibers[proci], k)
                {
                    os  << sendFaces[proci][k] << token::SPACE
                        << fibers_[sendFibers[proci][k]];
                }
            }
        }
    }
    labelList recvSizes;
    if (Pstream::parRun())
    {
        buf.finishedSends(recvSizes);
    }

    // Compact the kept fibers
    PtrList<fiber> kept(fibers_.size());
    label n = 0;
    forAll(fibers_, fi)
    {
        if (keep[fi])
        {
            kept.set(n++, fibers_.set(fi, nullptr));
        }
    }

    if (Pstream::parRun())
    {
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (!recvSizes[proci])
            {
                continue;
            }
            UIPstream is(proci, buf);
            const label nRecv = readLabel(is);
            kept.setSize(n + nRecv);
            for (label k = 0; k < nRecv; ++k)
            {
                const label patchFace = readLabel(is);
                fiber* fPtr = new fiber(is);

                // Continue the walk from the matching face
                const label procPatchi = sampler_.processorPatch(proci);
                label celli =
                    mesh_.boundaryMesh()[procPatchi].faceCells()[patchFace];
                label hitFace = -1;
                if (!sampler_.walk(fPtr->position(), celli, hitFace))
                {
                    const label found = mesh_.findCell(fPtr->position());
                    if (found >= 0)
                    {
                        celli = found;
                    }
                }
                fPtr->cell() = celli;
                fPtr->segmentCells() = celli;
                kept.set(n++, fPtr);
            }
        }
    }

    kept.setSize(n);
    fibers_.transfer(kept);
}


void Foam::fiberCloud::rebound
(
    fiber& f,
    const vector& n,
    const scalar d
) const
{
    // Back inside the wall plane, with a margin of a thousandth of the
    // penetration and a millionth of the diameter
    f.translate(-((1 + 1e-3)*d + 1e-6*f.minDiameter())*n);

    f.clearHistory();
    const scalar vn = f.velocity() & n;
    if (vn > 0)
    {
        f.setVelocity(f.velocity() - (1 + restitution_)*vn*n);
    }
}


void Foam::fiberCloud::deposit(const fiber& f)
{
    deposits_.append(stateOf(f));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberCloud::fiberCloud
(
    const fvMesh& mesh,
    const dictionary& dict,
    const scalar rhoFluid,
    const vector& g
)
:
    mesh_(mesh),
    fibers_(),
    hydro_
    (
        rhoFluid,
        inertialMode(dict) != "off",
        positiveOrDefault(dict, "dragCoefficient", 1),
        inertialMode(dict) == "auto"
      ? positiveOrDefault(dict, "inertialDragBound", 1e-3)
      : 0,
        dict.getOrDefault<Switch>("viscousDrag", true)
    ),
    integrator_(fiberIntegrator::New(dict)),
    dispersion_(fiberDispersion::New(dict)),
    wallRule_(wallRule::rebound),
    restitution_(dict.getOrDefault<scalar>("restitution", 1)),
    g_(g),
    shearStepFactor_(positiveOrDefault(dict, "shearStepFactor", 0.1)),
    sampler_(mesh, checkedScheme(dict)),
    nInjected_(0),
    nEscaped_(0),
    nDeposited_(0),
    deposits_(),
    nSubMax_(0),
    dtSubMin_(0),
    nRemote_(0),
    nTransferred_(0),
    nOutside_(0),
    nInertial_(0),
    nInertialSkipped_(0),
    nSegmentSteps_(0)
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

    const dictionary& injectionDict = dict.subDict("injection");

    PtrList<fiber> all;
    List<fiberInjection::origin> origins;
    fiberInjection::read(injectionDict, all, origins);
    nInjected_ = all.size();

    if (dict.getOrDefault<bool>("jefferyCorrection", false))
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
            << " strain coupling scaled by " << all[0].alpha()
            << " (fiber 0)" << endl;
    }

    distribute(injectionDict, all, origins);

    Info<< "    Injected " << nInjected_ << " fibers" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCloud::evolve(const scalar dt)
{
    const label nF = fibers_.size();

    // Flattened segment lists
    labelList offset(nF + 1, 0);
    forAll(fibers_, fi)
    {
        offset[fi + 1] = offset[fi] + fibers_[fi].nSegments();
    }
    List<point> pts(offset.last());
    labelList cells(offset.last());
    labelList cells2(offset.last());
    List<fluidSample> samples;
    List<fluidSample> samples2;
    scalarList dtStep(nF, Zero);
    List<point> segPts;
    labelList start(nF, -1);

    // Time left per fiber in this step; done below tTol
    scalarList tLeft(nF, dt);
    const scalar tTol = 1e-9*dt;
    boolList gone(nF, false);
    label nDeposited = 0;

    sampler_.resetCounters();
    hydro_.resetCounters();
    label nRounds = 0;
    dtSubMin_ = dt;

    while (true)
    {
        // The segments of the fibers that still have time to go
        label nPts = 0;
        bool any = false;
        forAll(fibers_, fi)
        {
            start[fi] = -1;
            if (gone[fi] || tLeft[fi] <= tTol)
            {
                continue;
            }
            any = true;
            fiber& f = fibers_[fi];
            f.segmentCentres(segPts);
            const labelList& segCells = f.segmentCells();
            start[fi] = nPts;
            forAll(segPts, i)
            {
                pts[nPts] = segPts[i];
                cells[nPts] = segCells[i] >= 0 ? segCells[i] : f.cell();
                ++nPts;
            }
        }

        if (!returnReduce(any, orOp<bool>()))
        {
            break;
        }
        ++nRounds;

        sampler_.sample(SubList<point>(pts, nPts), cells, samples);

        // Per fiber: wall contact, step length (Eq. 22, 23)
        forAll(fibers_, fi)
        {
            dtStep[fi] = 0;
            if (start[fi] < 0)
            {
                continue;
            }
            fiber& f = fibers_[fi];
            const label n = f.nSegments();
            SubList<fluidSample> s(samples, n, start[fi]);
            labelList& segCells = f.segmentCells();
            for (label i = 0; i < n; ++i)
            {
                segCells[i] = cells[start[fi] + i];
            }

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
                if (wallRule_ == wallRule::deposit)
                {
                    deposit(f);
                    gone[fi] = true;
                    ++nDeposited;
                    continue;
                }
                // Back inside, then the step goes on with these samples
                // (a fiber pressed onto a wall slides along it)
                rebound(f, s[iWall].nWall, s[iWall].dWall);
            }

            // Eq. 22: equal parts of the time left
            scalar gammaDot = 0;
            forAll(s, i)
            {
                gammaDot = max(gammaDot, s[i].shearRate());
            }
            const scalar rc = f.length()/f.minDiameter();
            const scalar parts = tLeft[fi]*rc*gammaDot/shearStepFactor_;
            if (parts > labelMax/2)
            {
                FatalErrorInFunction
                    << "Fiber " << f.id() << " needs " << parts
                    << " sub-steps over " << tLeft[fi] << " s (shear rate "
                    << gammaDot << ")" << exit(FatalError);
            }
            // Round-off tolerant: a count that is an integer up to
            // round-off (uniform shear) must not flip to the next one
            const label nParts = max(1, label(std::ceil(parts*(1 - 1e-9))));
            dtStep[fi] = tLeft[fi]/nParts;

            // Eq. 23: not beyond the end of the fiber's eddy
            if (dispersion_->active())
            {
                dtStep[fi] = min(dtStep[fi], dispersion_->correct(f, s));
            }
        }

        // Schemes that evaluate the forces in a predicted configuration:
        // sample there (collective)
        List<fluidSample>* stepSamples = &samples;
        if (integrator_->predicts())
        {
            label nPts2 = 0;
            forAll(fibers_, fi)
            {
                if (dtStep[fi] <= 0)
                {
                    start[fi] = -1;
                    continue;
                }
                integrator_->predictedCentres
                (
                    fibers_[fi], dtStep[fi], segPts
                );
                const label s0 = start[fi];
                start[fi] = nPts2;
                forAll(segPts, i)
                {
                    pts[nPts2] = segPts[i];
                    cells2[nPts2] = cells[s0 + i];
                    ++nPts2;
                }
            }
            sampler_.sample(SubList<point>(pts, nPts2), cells2, samples2);
            if (dispersion_->active())
            {
                forAll(fibers_, fi)
                {
                    if (start[fi] >= 0)
                    {
                        SubList<fluidSample> s2
                        (
                            samples2, fibers_[fi].nSegments(), start[fi]
                        );
                        dispersion_->correct(fibers_[fi], s2);
                    }
                }
            }
            stepSamples = &samples2;
        }

        // Advance
        forAll(fibers_, fi)
        {
            if (dtStep[fi] <= 0 || start[fi] < 0)
            {
                continue;
            }
            fiber& f = fibers_[fi];
            const SubList<fluidSample> s
            (
                *stepSamples, f.nSegments(), start[fi]
            );
            integrator_->advance(f, s, hydro_, g_, dtStep[fi]);
            nSegmentSteps_ += f.nSegments();
            dispersion_->elapse(f, dtStep[fi]);

            tLeft[fi] -= dtStep[fi];
            if (tLeft[fi] <= tTol)
            {
                tLeft[fi] = 0;
            }
            dtSubMin_ = min(dtSubMin_, dtStep[fi]);
        }
    }

    nSubMax_ = nRounds;
    dtSubMin_ = returnReduce(dtSubMin_, minOp<scalar>());
    nRemote_ = returnReduce(sampler_.nRemote(), sumOp<label>());
    nOutside_ = returnReduce(sampler_.nOutside(), sumOp<label>());
    nInertial_ = returnReduce(hydro_.nInertial(), sumOp<label>());
    nInertialSkipped_ = returnReduce(hydro_.nSkipped(), sumOp<label>());
    nDeposited_ += returnReduce(nDeposited, sumOp<label>());

    // Remove the deposited fibers
    if (gone.found(true))
    {
        PtrList<fiber> kept(nF);
        label n = 0;
        forAll(fibers_, fi)
        {
            if (!gone[fi])
            {
                kept.set(n++, fibers_.set(fi, nullptr));
            }
        }
        kept.setSize(n);
        fibers_.transfer(kept);
    }

    relocate();
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


Foam::List<Foam::fiberCloud::state> Foam::fiberCloud::gatherDeposits()
{
    List<state> all(gatherSorted(deposits_));
    deposits_.clear();
    return all;
}


// ************************************************************************* //
