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

#include "fluidSampler.H"
#include "processorPolyPatch.H"
#include "globalMeshData.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The interpolation of scheme for psi: fluidSampler's cellPoint (the
//  same numbers, its values in view) for cellPoint, else the run-time
//  selected one
template<class Type>
autoPtr<interpolation<Type>> interpolator
(
    const word& scheme,
    const GeometricField<Type, fvPatchField, volMesh>& psi,
    const coupledPointValues& coupled
)
{
    if (scheme == interpolationCellPoint<Type>::typeName)
    {
        return autoPtr<interpolation<Type>>
        (
            new fluidSampler::cellPoint<Type>(psi, coupled)
        );
    }
    return interpolation<Type>::New(scheme, psi);
}


template<class Type>
const fluidSampler::cellPoint<Type>* cellPointOf
(
    const autoPtr<interpolation<Type>>& ip
)
{
    return ip.valid() ? isA<fluidSampler::cellPoint<Type>>(ip()) : nullptr;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidSampler::fluidSampler
(
    const fvMesh& mesh,
    const fiberTracker& tracker,
    neighbourExchange& neighbours,
    const word& scheme
)
:
    mesh_(mesh),
    tracker_(tracker),
    neighbours_(neighbours),
    scheme_(scheme),
    coupled_(mesh),
    UInterp_(),
    gradUInterp_(),
    kInterp_(),
    epsilonInterp_(),
    UCellPoint_(nullptr),
    gradUCellPoint_(nullptr),
    kCellPoint_(nullptr),
    epsilonCellPoint_(nullptr),
    mu_(),
    nRemote_(0),
    nOutside_(0),
    nForwarded_(0),
    nFurther_(0)
{
    // Processor patch addressing is built collectively
    (void)mesh_.globalData();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fluidSampler::interpolate
(
    const trackedPoint& tp,
    fluidSample& s
) const
{
    const tetIndices tet(tp.tet());
    const barycentric& w = tp.coordinates;
    s.mu = mu_[tp.celli];
    s.cell = tp.celli;
    s.proc = Pstream::myProcNo();
    s.R = tensor::I;

    if (UCellPoint_)
    {
        const triFace tri(tracker_.triangle(tp));
        s.U = UCellPoint_->value(w, tp.celli, tri);
        // fvc::grad(U) holds du_j/dx_i; G_ij = du_i/dx_j
        s.G = gradUCellPoint_->value(w, tp.celli, tri).T();
        if (kCellPoint_)
        {
            s.k = kCellPoint_->value(w, tp.celli, tri);
            s.epsilon = epsilonCellPoint_->value(w, tp.celli, tri);
        }
    }
    else
    {
        s.U = UInterp_->interpolate(w, tet);
        s.G = gradUInterp_->interpolate(w, tet).T();
        if (kInterp_.valid())
        {
            s.k = kInterp_->interpolate(w, tet);
            s.epsilon = epsilonInterp_->interpolate(w, tet);
        }
    }
    s.k = max(s.k, scalar(0));
    s.epsilon = max(s.epsilon, scalar(0));
    s.inside = true;
    s.nWall = Zero;
    s.dWall = 0;
    s.mirror = false;
    s.patch = -1;
    s.outlet = false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fluidSampler::update
(
    const volVectorField& U,
    const volTensorField& gradU,
    const scalarField& muCells,
    const volScalarField* kPtr,
    const volScalarField* epsilonPtr
)
{
    UInterp_ = interpolator(scheme_, U, coupled_);
    gradUInterp_ = interpolator(scheme_, gradU, coupled_);
    mu_ = muCells;
    if (kPtr && epsilonPtr)
    {
        kInterp_ = interpolator(scheme_, *kPtr, coupled_);
        epsilonInterp_ = interpolator(scheme_, *epsilonPtr, coupled_);
    }
    else
    {
        kInterp_.clear();
        epsilonInterp_.clear();
    }

    UCellPoint_ = cellPointOf(UInterp_);
    gradUCellPoint_ = cellPointOf(gradUInterp_);
    kCellPoint_ = cellPointOf(kInterp_);
    epsilonCellPoint_ = cellPointOf(epsilonInterp_);
    const bool allCellPoint =
        UCellPoint_ && gradUCellPoint_
     && (!kInterp_.valid() || (kCellPoint_ && epsilonCellPoint_));
    if (!allCellPoint)
    {
        UCellPoint_ = nullptr;
    }
}


bool Foam::fluidSampler::sample
(
    const trackedPoint& tp,
    const fiberTracker::hit& h,
    fluidSample& s,
    request& req
) const
{
    typedef fiberTracker::stop stop;

    if (h.where == stop::processor)
    {
        tracker_.processorAddress(h.face, req.proc, req.patch, req.face);
        req.p = tracker_.position(tp);
        req.d = h.left;
        return false;
    }

    interpolate(tp, s);

    if
    (
        h.where == stop::wall || h.where == stop::symmetry
     || h.where == stop::outlet
    )
    {
        const vector& Sf = mesh_.faceAreas()[h.face];
        s.inside = false;
        s.nWall = Sf/mag(Sf);
        s.dWall = max(h.left & s.nWall, scalar(0));
        s.mirror = (h.where == stop::symmetry);
        s.patch = mesh_.boundaryMesh().whichPatch(h.face);
        s.outlet = (h.where == stop::outlet);
        if (s.outlet)
        {
            ++nOutside_;
        }
    }

    toStartFrame(h, s);
    return true;
}


void Foam::fluidSampler::toAskerFrame
(
    const vectorTensorTransform& T,
    fluidSample& s
)
{
    const fiberTracker::hit back
    {
        fiberTracker::stop::none, -1, Zero, true, T, false
    };
    toStartFrame(back, s);
}


void Foam::fluidSampler::toStartFrame
(
    const fiberTracker::hit& h,
    fluidSample& s
)
{
    if (h.crossed && h.T.hasR())
    {
        const tensor& R = h.T.R();
        s.U = R.T() & s.U;
        s.G = R.T() & s.G & R;
        s.nWall = R.T() & s.nWall;
        s.R = s.R & R;
    }
}


bool Foam::fluidSampler::answer
(
    Istream& is,
    fluidSample& s,
    request& onward,
    fiberTracker::hit& h,
    vectorTensorTransform& T
) const
{
    label patch, face;
    point p;
    vector d;
    is >> patch >> face >> p >> d;
    const processorPolyPatch& pp = tracker_.processorPatch(patch);
    T = fiberTracker::receiving(pp, face);

    // The point on the face, reached from the cell behind it (it may stop
    // on the face by round-off), then on along the line
    trackedPoint tp;
    tracker_.locate(T.transformPosition(p), tp, pp.faceCells()[face]);
    h = tracker_.track(tp, T.hasR() ? (T.R() & d) : d);
    const bool further = (h.where == fiberTracker::stop::processor);
    if (further)
    {
        // On into a further processor's part (a third one, or back into
        // the asker's where the boundary is not a plane): a request to
        // that processor, as sample() makes it; meanwhile the data at the
        // boundary, used only if the request cannot go on
        sample(tp, h, s, onward);
        interpolate(tp, s);
        s.inside = false;
        toStartFrame(h, s);
    }
    else
    {
        request dummy;
        sample(tp, h, s, dummy);
    }
    toAskerFrame(T, s);
    return !further;
}


void Foam::fluidSampler::exchange
(
    const UList<request>& reqs,
    UList<fluidSample>& answers
) const
{
    exchange(reqs, answers, 0);
}


void Foam::fluidSampler::exchange
(
    const UList<request>& reqs,
    UList<fluidSample>& answers,
    const label depth
) const
{
    const label nProcs = Pstream::nProcs();

    // Requests per neighbour, in the order of reqs
    List<DynamicList<label>> index(nProcs);
    forAll(reqs, k)
    {
        index[reqs[k].proc].append(k);
    }

    forAll(index, proci)
    {
        if (index[proci].size())
        {
            autoPtr<UOPstream> osPtr(neighbours_.sendStream(proci));
            UOPstream& os = osPtr();
            os << index[proci].size();
            for (const label k : index[proci])
            {
                os  << reqs[k].patch << token::SPACE << reqs[k].face
                    << token::SPACE << reqs[k].p << token::SPACE
                    << reqs[k].d;
            }
        }
    }
    neighbours_.exchange();

    // Answer: locate the point from the cell behind the patch face, in
    // this processor's frame (processorCyclic: transformed), and go on
    // along the line.  Every request is read before any goes on: the
    // buffers serve that exchange too.
    List<List<fluidSample>> result(nProcs);
    boolList asked(nProcs, false);
    DynamicList<request> onward;
    DynamicList<labelPair> onwardFor;
    DynamicList<fiberTracker::hit> onwardHit;
    DynamicList<vectorTensorTransform> onwardT;
    for (const label proci : neighbours_.neighbours())
    {
        if (!neighbours_.received(proci))
        {
            continue;
        }
        autoPtr<UIPstream> isPtr(neighbours_.recvStream(proci));
        UIPstream& is = isPtr();
        const label n = readLabel(is);
        asked[proci] = true;
        result[proci].setSize(n);
        for (label k = 0; k < n; ++k)
        {
            request r;
            fiberTracker::hit h;
            vectorTensorTransform T;
            if (!answer(is, result[proci][k], r, h, T))
            {
                onward.append(r);
                onwardFor.append(labelPair(proci, k));
                onwardHit.append(h);
                onwardT.append(T);
            }
        }
        if (depth == 0)
        {
            nRemote_ += n;
        }
    }

    // Lines that went on into a further processor's part are sampled
    // there (every processor takes part while any has such a line).  The
    // answer comes in the frame the line reached here; it is brought back
    // into the asker's.
    if (returnReduce(onward.size() > 0, orOp<bool>()))
    {
        if (depth < maxDepth_)
        {
            List<fluidSample> further(onward.size());
            exchange(onward, further, depth + 1);
            forAll(onward, j)
            {
                fluidSample& s =
                    result[onwardFor[j].first()][onwardFor[j].second()];
                s = further[j];
                toStartFrame(onwardHit[j], s);
                toAskerFrame(onwardT[j], s);
            }
            nForwarded_ += onward.size();
        }
        else
        {
            // Kept: the data at the boundary (counted)
            nFurther_ += onward.size();
        }
    }

    for (const label proci : neighbours_.neighbours())
    {
        if (asked[proci])
        {
            neighbours_.sendStream(proci)() << result[proci];
        }
    }
    neighbours_.exchange();

    forAll(index, proci)
    {
        if (index[proci].empty())
        {
            continue;
        }
        autoPtr<UIPstream> isPtr(neighbours_.recvStream(proci));
        const List<fluidSample> got(isPtr());
        forAll(got, k)
        {
            answers[index[proci][k]] = got[k];
        }
    }
}


// ************************************************************************* //
