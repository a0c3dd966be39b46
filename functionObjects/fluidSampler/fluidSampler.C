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
#include "processorCyclicPolyPatch.H"
#include "PstreamBuffers.H"
#include "wallPolyPatch.H"
#include "interpolationCellPoint.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fluidSampler::fluidSampler(const fvMesh& mesh, const word& scheme)
:
    mesh_(mesh),
    scheme_(scheme),
    procPatch_(),
    UInterp_(),
    gradUInterp_(),
    kInterp_(),
    epsilonInterp_(),
    mu_(),
    cellPoint_(false),
    nRemote_(0),
    nOutside_(0)
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        if
        (
            isA<processorPolyPatch>(pp)
         && !isA<processorCyclicPolyPatch>(pp)
        )
        {
            procPatch_.insert
            (
                refCast<const processorPolyPatch>(pp).neighbProcNo(),
                patchi
            );
        }
    }
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::fluidSample Foam::fluidSampler::sampleLocal
(
    const point& p,
    const label celli,
    const bool inside,
    const label hitFace
) const
{
    fluidSample s;
    s.mu = mu_[celli];

    if (cellPoint_)
    {
        const cellPointWeight cpw(mesh_, p, celli);
        s.U = static_cast<const interpolationCellPoint<vector>&>
            (UInterp_()).interpolate(cpw);
        s.G = static_cast<const interpolationCellPoint<tensor>&>
            (gradUInterp_()).interpolate(cpw).T();
        if (kInterp_.valid())
        {
            s.k = static_cast<const interpolationCellPoint<scalar>&>
                (kInterp_()).interpolate(cpw);
            s.epsilon = static_cast<const interpolationCellPoint<scalar>&>
                (epsilonInterp_()).interpolate(cpw);
        }
    }
    else
    {
        s.U = UInterp_->interpolate(p, celli);
        // fvc::grad(U) holds du_j/dx_i; G_ij = du_i/dx_j
        s.G = gradUInterp_->interpolate(p, celli).T();
        if (kInterp_.valid())
        {
            s.k = kInterp_->interpolate(p, celli);
            s.epsilon = epsilonInterp_->interpolate(p, celli);
        }
    }
    s.k = max(s.k, scalar(0));
    s.epsilon = max(s.epsilon, scalar(0));
    s.inside = inside;
    if (!inside)
    {
        ++nOutside_;
        if
        (
            hitFace >= 0
         && isA<wallPolyPatch>
            (
                mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(hitFace)]
            )
        )
        {
            const vector& Sf = mesh_.faceAreas()[hitFace];
            s.nWall = Sf/mag(Sf);
            s.dWall =
                max((p - mesh_.faceCentres()[hitFace]) & s.nWall, scalar(0));
        }
    }
    return s;
}


void Foam::fluidSampler::exchange
(
    const labelList& remoteProc,
    const labelList& remoteFace,
    const UList<point>& pts,
    const labelList& remoteIndex,
    List<fluidSample>& out
) const
{
    // Requests: per destination the points and patch faces
    List<DynamicList<point>> sendPts(Pstream::nProcs());
    List<DynamicList<label>> sendFaces(Pstream::nProcs());
    List<DynamicList<label>> sendIndex(Pstream::nProcs());

    forAll(remoteIndex, k)
    {
        const label proci = remoteProc[k];
        sendPts[proci].append(pts[remoteIndex[k]]);
        sendFaces[proci].append(remoteFace[k]);
        sendIndex[proci].append(remoteIndex[k]);
    }

    PstreamBuffers req(Pstream::commsTypes::nonBlocking);
    forAll(sendPts, proci)
    {
        if (sendPts[proci].size())
        {
            UOPstream os(proci, req);
            os << pointField(sendPts[proci]) << labelList(sendFaces[proci]);
        }
    }
    labelList recvSizes;
    req.finishedSends(recvSizes);

    // Answer the neighbours' requests
    PstreamBuffers ans(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (!recvSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, req);
        const pointField rp(is);
        const labelList rf(is);

        List<fluidSample> result(rp.size());
        const label patchi = procPatch_[proci];
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];

        forAll(rp, k)
        {
            label celli = pp.faceCells()[rf[k]];
            label hit = -1;
            if (walk(rp[k], celli, hit))
            {
                result[k] = sampleLocal(rp[k], celli, true);
                continue;
            }
            const label found = mesh_.findCell(rp[k]);
            if (found >= 0)
            {
                result[k] = sampleLocal(rp[k], found, true);
            }
            else
            {
                result[k] = sampleLocal(rp[k], celli, false, hit);
            }
        }

        UOPstream os(proci, ans);
        os << result;
    }
    ans.finishedSends();

    forAll(sendIndex, proci)
    {
        if (sendIndex[proci].empty())
        {
            continue;
        }
        UIPstream is(proci, ans);
        const List<fluidSample> result(is);
        forAll(result, k)
        {
            out[sendIndex[proci][k]] = result[k];
        }
    }
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
    UInterp_ = interpolation<vector>::New(scheme_, U);
    gradUInterp_ = interpolation<tensor>::New(scheme_, gradU);
    mu_ = muCells;
    if (kPtr && epsilonPtr)
    {
        kInterp_ = interpolation<scalar>::New(scheme_, *kPtr);
        epsilonInterp_ = interpolation<scalar>::New(scheme_, *epsilonPtr);
    }
    else
    {
        kInterp_.clear();
        epsilonInterp_.clear();
    }

    cellPoint_ =
        isA<interpolationCellPoint<vector>>(UInterp_())
     && isA<interpolationCellPoint<tensor>>(gradUInterp_())
     && (!kInterp_.valid() || isA<interpolationCellPoint<scalar>>(kInterp_()))
     && (
            !epsilonInterp_.valid()
         || isA<interpolationCellPoint<scalar>>(epsilonInterp_())
        );
}


bool Foam::fluidSampler::walk
(
    const point& p,
    label& celli,
    label& hitFace
) const
{
    const cellList& cells = mesh_.cells();
    const vectorField& Cf = mesh_.faceCentres();
    const vectorField& Sf = mesh_.faceAreas();
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();

    hitFace = -1;
    label c = celli;
    const label maxSteps = 100 + mesh_.nCells();

    for (label step = 0; step < maxSteps; ++step)
    {
        scalar dMax = 0;
        label fMax = -1;
        for (const label facei : cells[c])
        {
            scalar d = ((p - Cf[facei]) & Sf[facei])/mag(Sf[facei]);
            if (own[facei] != c)
            {
                d = -d;
            }
            if (d > dMax)
            {
                dMax = d;
                fMax = facei;
            }
        }

        if (fMax < 0)
        {
            celli = c;
            return true;
        }

        if (!mesh_.isInternalFace(fMax))
        {
            celli = c;
            hitFace = fMax;
            return false;
        }

        c = (own[fMax] == c ? nei[fMax] : own[fMax]);
    }

    celli = c;
    return false;
}


bool Foam::fluidSampler::processorFace
(
    const label hitFace,
    label& neighbProc,
    label& patchFace
) const
{
    if (hitFace < 0)
    {
        return false;
    }
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label patchi = pbm.whichPatch(hitFace);
    const polyPatch& pp = pbm[patchi];
    if (!isA<processorPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp))
    {
        return false;
    }
    neighbProc = refCast<const processorPolyPatch>(pp).neighbProcNo();
    patchFace = hitFace - pp.start();
    return true;
}


void Foam::fluidSampler::sample
(
    const UList<point>& pts,
    labelList& cells,
    List<fluidSample>& out
) const
{
    out.setSize(pts.size());

    DynamicList<label> remoteProc;
    DynamicList<label> remoteFace;
    DynamicList<label> remoteIndex;

    forAll(pts, i)
    {
        const point& p = pts[i];
        label celli = cells[i];
        label hitFace = -1;

        if (celli >= 0 && walk(p, celli, hitFace))
        {
            cells[i] = celli;
            out[i] = sampleLocal(p, celli, true);
            continue;
        }

        label proci, facei;
        if (processorFace(hitFace, proci, facei))
        {
            remoteProc.append(proci);
            remoteFace.append(facei);
            remoteIndex.append(i);
            // keep the last local cell as the seed of the next walk
            cells[i] = celli;
            continue;
        }

        // Left through a physical boundary, walk failed or no seed
        const label found = mesh_.findCell(p);
        if (found >= 0)
        {
            cells[i] = found;
            out[i] = sampleLocal(p, found, true);
        }
        else if (celli >= 0)
        {
            cells[i] = celli;
            out[i] = sampleLocal(p, celli, false, hitFace);
        }
        else
        {
            out[i] = fluidSample();
        }
    }

    if (Pstream::parRun())
    {
        nRemote_ += remoteIndex.size();
        exchange(remoteProc, remoteFace, pts, remoteIndex, out);
    }
}


// ************************************************************************* //
