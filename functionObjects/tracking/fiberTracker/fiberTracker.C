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

#include "fiberTracker.H"
#include "particle.H"
#include "cyclicPolyPatch.H"
#include "cyclicAMIPolyPatch.H"
#include "cyclicACMIPolyPatch.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "globalMeshData.H"
#include "registerSwitch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

int Foam::fiberTracker::tetCache
(
    Foam::debug::optimisationSwitch("fiberTrackerTetCache", 1)
);

registerOptSwitch
(
    "fiberTrackerTetCache",
    int,
    Foam::fiberTracker::tetCache
);

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberTracker::fiberTracker(const polyMesh& mesh)
:
    mesh_(mesh),
    kind_(mesh.boundaryMesh().size(), patchKind::outlet),
    acmiOf_(mesh.boundaryMesh().size(), -1),
    useCache_(tetCache != 0),
    stamp_(0),
    stampIndex_(-1),
    stampMoving_(false),
    movingCentre_(),
    movingCentreStamp_()
{
    if (!tetCache)
    {
        Info<< "fiberTracker: tetrahedron cache off"
            << " (OptimisationSwitches fiberTrackerTetCache 0)" << endl;
    }
    classifyPatches();

    // The tet base points are built collectively: on every processor now,
    // not on the first that happens to track
    (void)mesh_.tetBasePtIs();

    checkAMIDecomposition();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberTracker::classifyPatches()
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        patchKind& k = kind_[patchi];
        if (isA<processorPolyPatch>(pp))
        {
            k = patchKind::processor;
        }
        else if (isA<cyclicACMIPolyPatch>(pp))
        {
            k = patchKind::cyclicACMI;
        }
        else if (isA<cyclicAMIPolyPatch>(pp))
        {
            k = patchKind::cyclicAMI;
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            k = patchKind::cyclic;
        }
        else if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            k = patchKind::inside;
        }
        else if
        (
            isA<symmetryPolyPatch>(pp) || isA<symmetryPlanePolyPatch>(pp)
        )
        {
            k = patchKind::symmetry;
        }
        else if (isA<wallPolyPatch>(pp))
        {
            k = patchKind::wall;
        }
    }

    // The non-overlap patches of the ACMI patches
    forAll(pbm, patchi)
    {
        if (kind_[patchi] == patchKind::cyclicACMI)
        {
            acmiOf_
            [
                refCast<const cyclicACMIPolyPatch>(pbm[patchi])
               .nonOverlapPatchID()
            ] = patchi;
        }
    }
}


void Foam::fiberTracker::checkAMIDecomposition() const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    // A cyclicAMI crossing is resolved on the processor the point is on:
    // both sides of every AMI pair must be there (as OpenFOAM's Cloud
    // requires)
    forAll(pbm, patchi)
    {
        if
        (
            kind_[patchi] != patchKind::cyclicAMI
         && kind_[patchi] != patchKind::cyclicACMI
        )
        {
            continue;
        }
        const cyclicAMIPolyPatch& cpp =
            refCast<const cyclicAMIPolyPatch>(pbm[patchi]);
        if (cpp.owner() && cpp.AMI().singlePatchProc() == -1)
        {
            FatalErrorInFunction
                << "The cyclicAMI patches " << cpp.name() << " and "
                << cpp.neighbPatchName() << " are split over processors;"
                << " fibers can cross an AMI pair only where both sides lie"
                << " on one processor." << nl
                << "    Keep them together in system/decomposeParDict,"
                << " e.g. constraints { ami { type singleProcessorFaceSets;"
                << " singleProcessorFaceSets ((<faceSet of both patches>"
                << " -1)); } }, or run in serial" << exit(FatalError);
        }
    }
}


const Foam::point& Foam::fiberTracker::tetCentre(const label celli) const
{
    const label s = stamp();
    if (!stampMoving_)
    {
        // particle's stationary geometry
        return mesh_.cellCentres()[celli];
    }
    if (movingCentre_.size() != mesh_.nCells())
    {
        movingCentre_.setSize(mesh_.nCells());
        movingCentreStamp_.setSize(mesh_.nCells());
        movingCentreStamp_ = -1;
    }
    if (movingCentreStamp_[celli] != s)
    {
        movingCentre_[celli] =
            mesh_.cells()[celli].centre(mesh_.points(), mesh_.faces());
        movingCentreStamp_[celli] = s;
    }
    return movingCentre_[celli];
}


bool Foam::fiberTracker::fillCache(const trackedPoint& tp) const
{
    if (!useCache_ || !tp.located())
    {
        return false;
    }
    trackedPoint::tetGeometry& c = tp.cache;
    const label s = stamp();
    if
    (
        c.celli != tp.celli || c.tetFacei != tp.tetFacei
     || c.tetPti != tp.tetPti || c.stamp != s
    )
    {
        // The tetrahedron of particle's walk: the cell centre and the
        // triangle of the tet decomposition, and its reverse transform:
        // the volume-scaled face normals opposite each vertex.  On a mesh
        // that moved, that of the present points, as particle's moving
        // geometry takes it at the end of the motion (step fraction 1,
        // where the fibers move)
        c.tri = tp.tet().faceTriIs(mesh_);
        const pointField& pts = mesh_.points();
        c.A = barycentricTensor
        (
            tetCentre(tp.celli),
            pts[c.tri[0]],
            pts[c.tri[1]],
            pts[c.tri[2]]
        );
        const vector ab(c.A.b() - c.A.a());
        const vector ac(c.A.c() - c.A.a());
        const vector ad(c.A.d() - c.A.a());
        const vector bc(c.A.c() - c.A.b());
        const vector bd(c.A.d() - c.A.b());
        c.detA = ab & (ac ^ ad);
        c.T = barycentricTensor(bd ^ bc, ac ^ ad, ad ^ ab, ab ^ ac);
        c.celli = tp.celli;
        c.tetFacei = tp.tetFacei;
        c.tetPti = tp.tetPti;
        c.stamp = s;
    }
    return true;
}


void Foam::fiberTracker::cross
(
    trackedPoint& tp,
    const label facei,
    vector& d,
    vectorTensorTransform& T
) const
{
    const polyPatch& pp =
        mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(facei)];
    const cyclicPolyPatch& cpp = refCast<const cyclicPolyPatch>(pp);
    const cyclicPolyPatch& rcv = cpp.neighbPatch();
    const label local = facei - cpp.start();
    const label newFace = rcv.start() + local;

    // Same point of the matching face: the triangle seen from the other
    // side has its two points in the reverse order
    tp.celli = mesh_.faceOwner()[newFace];
    tp.tetFacei = newFace;
    tp.tetPti = mesh_.faces()[newFace].size() - 1 - tp.tetPti;
    std::swap(tp.coordinates.c(), tp.coordinates.d());

    const vectorTensorTransform Tf(receiving(rcv, local));
    if (Tf.hasR())
    {
        d = Tf.R() & d;
    }
    T = after(Tf, T);
}


bool Foam::fiberTracker::crossAMI
(
    trackedPoint& tp,
    const label facei,
    vector& d,
    vectorTensorTransform& T,
    label& onFace
) const
{
    const cyclicAMIPolyPatch& cpp =
        refCast<const cyclicAMIPolyPatch>
        (
            mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(facei)]
        );
    const cyclicAMIPolyPatch& rcv = cpp.neighbPatch();

    point pos(position(tp));
    const label rf = cpp.pointFace(facei - cpp.start(), d, pos);
    if (rf < 0)
    {
        return false;
    }
    T = receiving(rcv, rf);
    if (T.hasR())
    {
        d = T.R() & d;
    }

    // The mapped point, reached from the receiving cell's centre; it lies
    // on the receiving face, so the walk may stop on that face (or on a
    // neighbouring face of the interface) by round-off: it landed there
    atCellCentre(mesh_.faceOwner()[rcv.start() + rf], tp);
    onFace = -1;
    walk(tp, pos - position(tp), onFace);
    return true;
}


bool Foam::fiberTracker::acmiCouples
(
    const trackedPoint& tp,
    const label facei,
    const vector& d
) const
{
    const cyclicACMIPolyPatch& cpp =
        refCast<const cyclicACMIPolyPatch>
        (
            mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(facei)]
        );
    const label local = facei - cpp.start();
    const scalar mask = cpp.mask()[local];
    if (mask >= 1 - cpp.tolerance())
    {
        return true;
    }
    if (mask <= cpp.tolerance())
    {
        return false;
    }
    // Partly overlapped: the AMI takes a near miss of the other side's
    // faces for a hit (pointFace), which would carry a point of the
    // blocked part across; it couples only where its line meets a face of
    // the other side
    point pos(position(tp));
    const label rf = cpp.pointFace(local, d, pos);
    if (rf < 0)
    {
        return false;
    }
    const cyclicAMIPolyPatch& nbr = cpp.neighbPatch();
    return
        nbr[rf].ray(pos, d, nbr.points(), intersection::FULL_RAY).hit();
}


void Foam::fiberTracker::stepOff(trackedPoint& tp, const scalar frac)
{
    // The tetrahedron's first vertex is the cell centre
    tp.coordinates =
        (1 - frac)*tp.coordinates + frac*barycentric(1, 0, 0, 0);
}


Foam::scalar Foam::fiberTracker::walk
(
    trackedPoint& tp,
    const vector& d,
    label& onFace
) const
{
    particle p(mesh_, tp.coordinates, tp.celli, tp.tetFacei, tp.tetPti);
    p.stepFraction() = 1;
    p.face() = onFace;
    const scalar f = p.track(d, 0);

    tp.coordinates = p.coordinates();
    tp.celli = p.cell();
    tp.tetFacei = p.tetFace();
    tp.tetPti = p.tetPt();
    onFace = p.onBoundaryFace() ? p.face() : -1;
    return f;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vectorTensorTransform Foam::fiberTracker::receiving
(
    const coupledPolyPatch& pp,
    const label patchFace
)
{
    point o(Zero);
    pp.transformPosition(o, patchFace);
    tensor Rt(Zero);
    for (direction j = 0; j < vector::nComponents; ++j)
    {
        point e(Zero);
        e[j] = 1;
        pp.transformPosition(e, patchFace);
        Rt.row(j, e - o);
    }
    const tensor R(Rt.T());
    if (mag(R - tensor::I) < 1e-12)
    {
        return vectorTensorTransform(o);
    }
    return vectorTensorTransform(o, R, true);
}


Foam::vectorTensorTransform Foam::fiberTracker::after
(
    const vectorTensorTransform& a,
    const vectorTensorTransform& b
)
{
    if (!a.hasR())
    {
        return vectorTensorTransform(a.t() + b.t(), b.R(), b.hasR());
    }
    return vectorTensorTransform
    (
        a.t() + (a.R() & b.t()),
        a.R() & b.R(),
        true
    );
}


void Foam::fiberTracker::processorAddress
(
    const label facei,
    label& proc,
    label& patch,
    label& patchFace
) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label patchi = pbm.whichPatch(facei);
    const processorPolyPatch& pp =
        refCast<const processorPolyPatch>(pbm[patchi]);
    proc = pp.neighbProcNo();
    patch = mesh_.globalData().processorPatchNeighbours()[patchi];
    patchFace = facei - pp.start();
}


const Foam::processorPolyPatch& Foam::fiberTracker::processorPatch
(
    const label patch
) const
{
    return refCast<const processorPolyPatch>
    (
        mesh_.boundaryMesh()[mesh_.globalData().processorPatches()[patch]]
    );
}


Foam::labelList Foam::fiberTracker::outletPatches() const
{
    DynamicList<label> out;
    forAll(kind_, patchi)
    {
        if (kind_[patchi] == patchKind::outlet)
        {
            out.append(patchi);
        }
    }
    return labelList(std::move(out));
}


Foam::labelList Foam::fiberTracker::wallPatches() const
{
    DynamicList<label> w;
    forAll(kind_, patchi)
    {
        if (kind_[patchi] == patchKind::wall)
        {
            w.append(patchi);
        }
    }
    return labelList(std::move(w));
}


Foam::point Foam::fiberTracker::position(const trackedPoint& tp) const
{
    if (cached(tp))
    {
        return tp.cache.A & tp.coordinates;
    }
    particle p(mesh_, tp.coordinates, tp.celli, tp.tetFacei, tp.tetPti);
    p.stepFraction() = 1;
    return p.position();
}


Foam::scalar Foam::fiberTracker::mismatch(const trackedPoint& tp) const
{
    scalar m = 0;
    if (!tp.located())
    {
        return m;
    }
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    for (const label facei : mesh_.cells()[tp.celli])
    {
        if (mesh_.isInternalFace(facei))
        {
            continue;
        }
        label patchi = pbm.whichPatch(facei);
        if (acmiOf_[patchi] >= 0)
        {
            patchi = acmiOf_[patchi];
        }
        if
        (
            kind_[patchi] == patchKind::cyclicAMI
         || kind_[patchi] == patchKind::cyclicACMI
        )
        {
            // The face's own size (an ACMI face's area is scaled by its
            // mask): from its points
            const scalar a =
                mag(mesh_.faces()[facei].areaNormal(mesh_.points()));
            m = max(m, 0.1*sqrt(a));
        }
    }
    return m;
}


Foam::triFace Foam::fiberTracker::triangle(const trackedPoint& tp) const
{
    if (cached(tp))
    {
        return tp.cache.tri;
    }
    return tp.tet().faceTriIs(mesh_);
}


void Foam::fiberTracker::atCellCentre
(
    const label celli,
    trackedPoint& tp
) const
{
    // Just off the centre, in the first tetrahedron of the first face
    tp.coordinates = barycentric(1 - 3*SMALL, SMALL, SMALL, SMALL);
    tp.celli = celli;
    tp.tetFacei = mesh_.cells()[celli][0];
    tp.tetPti = 1;
}


bool Foam::fiberTracker::withinTet
(
    trackedPoint& tp,
    const vector& d
) const
{
    // Within the tetrahedron (no face of it reached): the new coordinates
    // as particle::trackToStationaryTri computes them, from the cache
    const trackedPoint::tetGeometry& c = tp.cache;
    if (!(cached(tp) && std::isnormal(c.detA) && c.detA > 0))
    {
        return false;
    }
    const barycentric Tx(d & c.T);
    const scalar muH = 1/c.detA;
    for (label i = 0; i < 4; ++i)
    {
        if (std::isnormal(Tx[i]) && Tx[i] < 0)
        {
            const scalar mu = -tp.coordinates[i]/Tx[i];
            if (0 <= mu && mu < muH)
            {
                return false;
            }
        }
    }
    barycentric y(tp.coordinates + muH*Tx);
    for (label i = 0; i < 4; ++i)
    {
        y.replace(i, max(0, y[i]));
    }
    y /= cmptSum(y);
    tp.coordinates = y;
    return true;
}


Foam::fiberTracker::patchKind Foam::fiberTracker::faceKind
(
    trackedPoint& tp,
    label& facei,
    const vector& disp
) const
{
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    label patchi = pbm.whichPatch(facei);

    // A face of a non-overlap patch coincides with the ACMI face of the
    // same index (the same points: the tetrahedron holds)
    if (acmiOf_[patchi] >= 0)
    {
        const label acmi = acmiOf_[patchi];
        facei += pbm[acmi].start() - pbm[patchi].start();
        patchi = acmi;
        tp.tetFacei = facei;
    }
    if (kind_[patchi] != patchKind::cyclicACMI)
    {
        return kind_[patchi];
    }
    if (acmiCouples(tp, facei, disp))
    {
        return patchKind::cyclicAMI;
    }

    // The blocked part: the non-overlap patch
    const label no =
        refCast<const cyclicACMIPolyPatch>(pbm[patchi]).nonOverlapPatchID();
    facei += pbm[no].start() - pbm[patchi].start();
    tp.tetFacei = facei;
    return kind_[no];
}


bool Foam::fiberTracker::alongInterface
(
    trackedPoint& tp,
    const label facei,
    walkState& ws
) const
{
    // Landed on the interface and at once back at it: moving along it, or
    // back across.  The two sides' faces differ in direction by their
    // mismatch; a displacement outward of both by less than that moves
    // along the interface: on along this side's face (the end is
    // corrected after)
    const vector nR(normalised(mesh_.faceAreas()[facei]));
    const scalar out = ws.disp & nR;
    if (out > (2*mag(ws.nSent + nR) + 1e-9)*mag(ws.disp))
    {
        return false;
    }
    if (out > 0)
    {
        ws.disp -= out*nR;
    }
    stepOff(tp, 1e-9);
    ws.onFace = -1;
    ws.landed = -1;
    return true;
}


bool Foam::fiberTracker::overAMI
(
    trackedPoint& tp,
    const label facei,
    walkState& ws,
    hit& h
) const
{
    const point here(position(tp));
    ws.nSent = normalised(mesh_.faceAreas()[facei]);
    const vector left(ws.disp);
    vectorTensorTransform Tf;
    if (!crossAMI(tp, facei, ws.disp, Tf, ws.onFace))
    {
        // No face on the other side: mirrored
        h.where = stop::symmetry;
        h.face = facei;
        h.left = left;
        return false;
    }
    ws.landed = ws.onFace;
    if (Tf.hasR())
    {
        ws.nSent = Tf.R() & ws.nSent;
    }
    if (!Tf.hasR() && magSqr(Tf.t()) == 0)
    {
        ws.slid = true;
        h.slid = true;
        ws.intended = here + left;
    }
    else
    {
        h.T = after(Tf, h.T);
        h.crossed = true;
        ws.slid = false;
    }
    return true;
}


void Foam::fiberTracker::ended(trackedPoint& tp, const walkState& ws) const
{
    // After sliding crossings: on from the mapped point to the end
    // intended, stopping at the interface (or any boundary face)
    if (ws.slid)
    {
        label of = ws.onFace;
        walk(tp, ws.intended - position(tp), of);
    }
}


Foam::fiberTracker::hit Foam::fiberTracker::track
(
    trackedPoint& tp,
    const vector& d,
    const label startFace
) const
{
    hit h{stop::none, -1, Zero, false, vectorTensorTransform::I, false};

    // particle counts its constructions in a label
    if (particle::particleCount_ > labelMax/2)
    {
        particle::particleCount_ = 0;
    }
    if (startFace < 0 && withinTet(tp, d))
    {
        return h;
    }

    walkState ws{d, startFace, false, Zero, -1, Zero};

    for (label n = 0; n <= maxCrossings; ++n)
    {
        const scalar f = walk(tp, ws.disp, ws.onFace);
        if (ws.onFace < 0 || f <= 0)
        {
            ended(tp, ws);
            return h;
        }
        label facei = ws.onFace;
        ws.disp *= f;
        const patchKind k = faceKind(tp, facei, ws.disp);
        ws.onFace = facei;

        if (k == patchKind::cyclic)
        {
            cross(tp, facei, ws.disp, h.T);
            h.crossed = true;
            ws.slid = false;
            ws.landed = -1;
            ws.onFace = tp.tetFacei;
            continue;
        }
        if (k == patchKind::cyclicAMI)
        {
            if
            (
                (facei == ws.landed && f > 1 - 1e-9
              && alongInterface(tp, facei, ws))
             || overAMI(tp, facei, ws, h)
            )
            {
                continue;
            }
            return h;
        }
        if (k == patchKind::inside)
        {
            ended(tp, ws);
            return h;
        }
        h.where =
            k == patchKind::wall ? stop::wall
          : k == patchKind::symmetry ? stop::symmetry
          : k == patchKind::processor ? stop::processor
          : stop::outlet;
        h.face = facei;
        h.left = ws.disp;
        return h;
    }

    FatalErrorInFunction
        << "A displacement " << d << " crossed periodic patches more than "
        << maxCrossings << " times" << exit(FatalError);
    return h;
}


Foam::fiberTracker::hit Foam::fiberTracker::locate
(
    const point& p,
    trackedPoint& tp,
    label seed
) const
{
    if (seed < 0)
    {
        seed = mesh_.findCell(p);
        if (seed < 0)
        {
            tp = trackedPoint();
            return hit
            {
                stop::outlet, -1, Zero, false, vectorTensorTransform::I, false
            };
        }
    }
    atCellCentre(seed, tp);
    return track(tp, p - position(tp));
}


// ************************************************************************* //
