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
        }
        else
        {
            keep[fi] = false;
            ++nEscaped;
        }
    }

    nEscaped_ += returnReduce(nEscaped, sumOp<label>());

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
        dict.getOrDefault<bool>("inertialDrag", true),
        positiveOrDefault(dict, "dragCoefficient", 1)
    ),
    integrator_(fiberIntegrator::New(dict)),
    g_(g),
    shearStepFactor_(positiveOrDefault(dict, "shearStepFactor", 0.1)),
    sampler_(mesh, checkedScheme(dict)),
    nInjected_(0),
    nEscaped_(0),
    nSubMax_(0),
    dtSubMin_(0),
    nRemote_(0),
    nTransferred_(0),
    nOutside_(0)
{
    const dictionary& injectionDict = dict.subDict("injection");

    PtrList<fiber> all;
    List<fiberInjection::origin> origins;
    fiberInjection::read(injectionDict, all, origins);
    nInjected_ = all.size();

    distribute(injectionDict, all, origins);

    Info<< "    Injected " << nInjected_ << " fibers" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCloud::evolve(const scalar dt)
{
    const label nF = fibers_.size();
    labelList nSub(nF, 1);

    // Flattened segment lists
    labelList offset(nF + 1, 0);
    forAll(fibers_, fi)
    {
        offset[fi + 1] = offset[fi] + fibers_[fi].nSegments();
    }

    List<point> pts(offset.last());
    labelList cells(offset.last());
    List<fluidSample> samples;
    List<point> segPts;

    label nRounds = 1;
    nSubMax_ = 1;
    sampler_.resetCounters();
    dtSubMin_ = dt;

    for (label round = 0; round < nRounds; ++round)
    {
        // Gather the segments of the fibers that step in this round
        label nPts = 0;
        labelList start(nF, -1);
        forAll(fibers_, fi)
        {
            if (round >= nSub[fi])
            {
                continue;
            }
            fiber& f = fibers_[fi];
            f.segmentCentres(segPts);
            labelList& segCells = f.segmentCells();
            start[fi] = nPts;
            forAll(segPts, i)
            {
                pts[nPts] = segPts[i];
                cells[nPts] = segCells[i] >= 0 ? segCells[i] : f.cell();
                ++nPts;
            }
        }

        sampler_.sample
        (
            SubList<point>(pts, nPts),
            cells,
            samples
        );

        if (round == 0)
        {
            // Eq. 22 sub-steps per fiber
            label nMax = 0;
            forAll(fibers_, fi)
            {
                const fiber& f = fibers_[fi];
                scalar gammaDot = 0;
                for (label i = 0; i < f.nSegments(); ++i)
                {
                    gammaDot =
                        max(gammaDot, samples[start[fi] + i].shearRate());
                }
                const scalar rc = f.length()/f.minDiameter();
                const scalar steps = dt*rc*gammaDot/shearStepFactor_;
                if (steps > labelMax/2)
                {
                    FatalErrorInFunction
                        << "Fiber " << f.id() << " needs " << steps
                        << " sub-steps over dt = " << dt
                        << " (shear rate " << gammaDot << ")"
                        << exit(FatalError);
                }
                // Round-off tolerant: a step count that is an integer up to
                // round-off (uniform shear) must not flip to the next one
                nSub[fi] = max(1, label(std::ceil(steps*(1 - 1e-9))));
                nMax = max(nMax, nSub[fi]);
            }
            nRounds = returnReduce(nMax, maxOp<label>());
            nSubMax_ = max(nRounds, 1);
            scalar dtMin = dt;
            forAll(nSub, fi)
            {
                dtMin = min(dtMin, dt/nSub[fi]);
            }
            dtSubMin_ = returnReduce(dtMin, minOp<scalar>());
        }

        forAll(fibers_, fi)
        {
            if (start[fi] < 0)
            {
                continue;
            }
            fiber& f = fibers_[fi];
            const label n = f.nSegments();
            labelList& segCells = f.segmentCells();
            for (label i = 0; i < n; ++i)
            {
                segCells[i] = cells[start[fi] + i];
            }
            integrator_->advance
            (
                f,
                SubList<fluidSample>(samples, n, start[fi]),
                hydro_,
                g_,
                dt/nSub[fi]
            );
        }
    }

    nRemote_ = returnReduce(sampler_.nRemote(), sumOp<label>());
    nOutside_ = returnReduce(sampler_.nOutside(), sumOp<label>());

    relocate();
}


Foam::fiberCloud::statistics Foam::fiberCloud::stats() const
{
    statistics s;
    s.nInjected = nInjected_;
    s.nEscaped = nEscaped_;
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
    // Per processor: ids and four vectors (x, p, v, omega) per fiber
    List<labelList> ids(Pstream::nProcs());
    List<vectorList> vals(Pstream::nProcs());
    labelList& myIds = ids[Pstream::myProcNo()];
    vectorList& myVals = vals[Pstream::myProcNo()];
    myIds.setSize(fibers_.size());
    myVals.setSize(4*fibers_.size());
    forAll(fibers_, fi)
    {
        const fiber& f = fibers_[fi];
        myIds[fi] = f.id();
        myVals[4*fi] = f.position();
        myVals[4*fi + 1] = f.orientation();
        myVals[4*fi + 2] = f.velocity();
        myVals[4*fi + 3] = f.omega();
    }

    Pstream::gatherList(ids);
    Pstream::gatherList(vals);

    List<state> result;
    if (Pstream::master())
    {
        DynamicList<state> all;
        DynamicList<label> allIds;
        forAll(ids, proci)
        {
            forAll(ids[proci], k)
            {
                const vectorList& v = vals[proci];
                all.append
                (
                    state{ids[proci][k], v[4*k], v[4*k+1], v[4*k+2], v[4*k+3]}
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


// ************************************************************************* //
