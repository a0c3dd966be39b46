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
    staticMesh_(tetCache != 0)
{
    if (!tetCache)
    {
        Info<< "fiberTracker: tetrahedron cache off"
            << " (OptimisationSwitches fiberTrackerTetCache 0)" << endl;
    }

    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        patchKind& k = kind_[patchi];
        if (isA<processorPolyPatch>(pp))
        {
            k = patchKind::processor;
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

    // The tet base points are built collectively: on every processor now,
    // not on the first that happens to track
    (void)mesh_.tetBasePtIs();

    // A cyclicAMI crossing is resolved on the processor the point is on:
    // both sides of every AMI pair must be there (as OpenFOAM's Cloud
    // requires)
    forAll(pbm, patchi)
    {
        if (kind_[patchi] != patchKind::cyclicAMI)
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::fiberTracker::fillCache(const trackedPoint& tp) const
{
    if (!staticMesh_ || mesh_.changing())
    {
        staticMesh_ = false;
        return false;
    }
    if (!tp.located())
    {
        return false;
    }
    trackedPoint::tetGeometry& c = tp.cache;
    if
    (
        c.celli != tp.celli || c.tetFacei != tp.tetFacei
     || c.tetPti != tp.tetPti
    )
    {
        // The tetrahedron of particle's stationary walk: the cell centre
        // and the triangle of the tet decomposition, and its reverse
        // transform: the volume-scaled face normals opposite each vertex
        c.tri = tp.tet().faceTriIs(mesh_);
        const pointField& pts = mesh_.points();
        c.A = barycentricTensor
        (
            mesh_.cellCentres()[tp.celli],
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
    }
    return true;
}


bool Foam::fiberTracker::cross
(
    trackedPoint& tp,
    const label facei,
    vector& d,
    vectorTensorTransform& T
) const
{
    const polyPatch& pp =
        mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(facei)];

    if (isA<cyclicAMIPolyPatch>(pp))
    {
        const cyclicAMIPolyPatch& cpp = refCast<const cyclicAMIPolyPatch>(pp);
        const cyclicAMIPolyPatch& rcv = cpp.neighbPatch();

        point pos(position(tp));
        const label rf = cpp.pointFace(facei - cpp.start(), d, pos);
        if (rf < 0)
        {
            return false;
        }
        const vectorTensorTransform Tf(receiving(rcv, rf));
        if (Tf.hasR())
        {
            d = Tf.R() & d;
        }
        // From the receiving cell's centre to the mapped point, then on
        atCellCentre(mesh_.faceOwner()[rcv.start() + rf], tp);
        d += pos - position(tp);
        T = after(Tf, T);
        return true;
    }

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
    return true;
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


Foam::fiberTracker::hit Foam::fiberTracker::track
(
    trackedPoint& tp,
    const vector& d,
    const label startFace
) const
{
    hit h{stop::none, -1, Zero, false, vectorTensorTransform::I};

    // particle counts its constructions in a label
    if (particle::particleCount_ > labelMax/2)
    {
        particle::particleCount_ = 0;
    }

    // Within the tetrahedron (no face of it reached): the new coordinates
    // as particle::trackToStationaryTri computes them, from the cache
    const trackedPoint::tetGeometry& c = tp.cache;
    if
    (
        startFace < 0 && cached(tp) && std::isnormal(c.detA) && c.detA > 0
    )
    {
        const barycentric Tx(d & c.T);
        const scalar muH = 1/c.detA;
        bool inside = true;
        for (label i = 0; i < 4; ++i)
        {
            if (std::isnormal(Tx[i]) && Tx[i] < 0)
            {
                const scalar mu = -tp.coordinates[i]/Tx[i];
                if (0 <= mu && mu < muH)
                {
                    inside = false;
                }
            }
        }
        if (inside)
        {
            barycentric y(tp.coordinates + muH*Tx);
            for (label i = 0; i < 4; ++i)
            {
                y.replace(i, max(0, y[i]));
            }
            y /= cmptSum(y);
            tp.coordinates = y;
            return h;
        }
    }

    vector disp(d);
    label onFace = startFace;
    for (label n = 0; n <= maxCrossings; ++n)
    {
        particle p(mesh_, tp.coordinates, tp.celli, tp.tetFacei, tp.tetPti);
        p.stepFraction() = 1;
        p.face() = onFace;
        const scalar f = p.track(disp, 0);

        tp.coordinates = p.coordinates();
        tp.celli = p.cell();
        tp.tetFacei = p.tetFace();
        tp.tetPti = p.tetPt();

        if (!p.onBoundaryFace() || f <= 0)
        {
            return h;
        }

        const label facei = p.face();
        disp *= f;
        const patchKind k = kind_[mesh_.boundaryMesh().whichPatch(facei)];
        switch (k)
        {
            case patchKind::cyclic:
            case patchKind::cyclicAMI:
            {
                if (!cross(tp, facei, disp, h.T))
                {
                    h.where = stop::outlet;
                    h.face = facei;
                    h.left = disp;
                    return h;
                }
                h.crossed = true;
                onFace = (k == patchKind::cyclic ? tp.tetFacei : -1);
                break;
            }
            case patchKind::inside:
            {
                return h;
            }
            default:
            {
                h.where =
                    k == patchKind::wall ? stop::wall
                  : k == patchKind::symmetry ? stop::symmetry
                  : k == patchKind::processor ? stop::processor
                  : stop::outlet;
                h.face = facei;
                h.left = disp;
                return h;
            }
        }
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
            return hit{stop::outlet, -1, Zero, false, vectorTensorTransform::I};
        }
    }
    atCellCentre(seed, tp);
    return track(tp, p - position(tp));
}


// ************************************************************************* //
