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

#include "fiberPatchInjection.H"
#include "openfoamCompat.H"
#include "surfaceFields.H"
#include "counterRandom.H"
#include "keywordCheck.H"
#include "Pstream.H"
#include "SubField.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberPatchInjection::localTriangles
(
    const polyMesh& mesh,
    DynamicList<FixedList<point, 3>>& tri,
    DynamicList<vector>& nrm,
    DynamicList<scalar>& share,
    DynamicList<label>& face
) const
{
    // Triangles about the face centres, with the face normal
    const polyPatch& pp = mesh.boundaryMesh()[patchi_];
    const pointField& pts = mesh.points();
    forAll(pp, i)
    {
        const Foam::face& f = pp[i];
        const point& c = pp.faceCentres()[i];
        const scalar magA = mag(pp.faceAreas()[i]);
        const vector n(pp.faceAreas()[i]/magA);
        forAll(f, k)
        {
            const FixedList<point, 3> t({c, pts[f[k]], pts[f.nextLabel(k)]});
            tri.append(t);
            nrm.append(n);
            share.append(0.5*mag((t[1] - t[0]) ^ (t[2] - t[0]))/magA);
            face.append(i);
        }
    }
}


void Foam::fiberPatchInjection::gatherTriangles
(
    const polyMesh& mesh,
    List<FixedList<point, 3>>& tri,
    vectorList& nrm,
    List<point>& centroid,
    scalarList& share,
    labelList& gFace
) const
{
    const polyPatch& pp = mesh.boundaryMesh()[patchi_];
    DynamicList<FixedList<point, 3>> myTri;
    DynamicList<vector> myN;
    DynamicList<scalar> myShare;
    DynamicList<label> myFace;
    localTriangles(mesh, myTri, myN, myShare, myFace);

    List<List<FixedList<point, 3>>> allTri(Pstream::nProcs());
    List<vectorList> allN(Pstream::nProcs());
    List<scalarList> allShare(Pstream::nProcs());
    List<labelList> allFace(Pstream::nProcs());
    labelList nFaces(Pstream::nProcs(), Zero);
    allTri[Pstream::myProcNo()] = myTri;
    allN[Pstream::myProcNo()] = myN;
    allShare[Pstream::myProcNo()] = myShare;
    allFace[Pstream::myProcNo()] = myFace;
    nFaces[Pstream::myProcNo()] = pp.size();
    fiberCompat::allGatherList(allTri);
    fiberCompat::allGatherList(allN);
    fiberCompat::allGatherList(allShare);
    fiberCompat::allGatherList(allFace);
    fiberCompat::allGatherList(nFaces);

    label n = 0;
    for (const List<FixedList<point, 3>>& t : allTri)
    {
        n += t.size();
    }
    tri.setSize(n);
    nrm.setSize(n);
    centroid.setSize(n);
    share.setSize(n);
    gFace.setSize(n);
    n = 0;
    label offset = 0;
    forAll(allTri, proci)
    {
        forAll(allTri[proci], i)
        {
            const FixedList<point, 3>& t = allTri[proci][i];
            tri[n] = t;
            nrm[n] = allN[proci][i];
            centroid[n] = (t[0] + t[1] + t[2])/3;
            share[n] = allShare[proci][i];
            gFace[n] = offset + allFace[proci][i];
            ++n;
        }
        offset += nFaces[proci];
    }
}


void Foam::fiberPatchInjection::gatherPatch(const polyMesh& mesh)
{
    List<FixedList<point, 3>> tri;
    vectorList nrm;
    List<point> centroid;
    scalarList share;
    labelList gFace;
    gatherTriangles(mesh, tri, nrm, centroid, share, gFace);
    const label n = tri.size();

    // A decomposition-independent order: by centroid, x then y then z, as
    // the patch was first gathered (a moving patch keeps it)
    if (order_.size() != n)
    {
        order_ = identity(n);
        std::sort
        (
            order_.begin(),
            order_.end(),
            [&centroid](const label a, const label b)
            {
                const point& pa = centroid[a];
                const point& pb = centroid[b];
                if (pa.x() != pb.x()) return pa.x() < pb.x();
                if (pa.y() != pb.y()) return pa.y() < pb.y();
                return pa.z() < pb.z();
            }
        );
    }
    const labelList& order = order_;

    tri_.setSize(n);
    normal_.setSize(n);
    cdf_.setSize(n);
    areaShare_.setSize(n);
    gatheredFace_.setSize(n);
    scalar sum = 0;
    forAll(order, i)
    {
        const FixedList<point, 3>& t = tri[order[i]];
        tri_[i] = t;
        normal_[i] = nrm[order[i]];
        areaShare_[i] = share[order[i]];
        gatheredFace_[i] = gFace[order[i]];
        sum += 0.5*mag((t[1] - t[0]) ^ (t[2] - t[0]));
        cdf_[i] = sum;
    }
}


void Foam::fiberPatchInjection::weighByFlux(const polyMesh& mesh)
{
    const surfaceScalarField* phiPtr =
        mesh.findObject<surfaceScalarField>(phiName_);
    if (!phiPtr)
    {
        FatalErrorInFunction
            << "Fiber set '" << name_ << "' (placement flux): no flux field '"
            << phiName_ << "' in the case (entry 'phi')" << exit(FatalError);
    }

    // The patch's face fluxes of all processors, in processor order
    List<scalarList> allPhi(Pstream::nProcs());
    allPhi[Pstream::myProcNo()] = phiPtr->boundaryField()[patchi_];
    fiberCompat::allGatherList(allPhi);
    DynamicList<scalar> phi;
    for (const scalarList& p : allPhi)
    {
        phi.append(p);
    }

    // Inflow only (phi < 0 points into the domain), each triangle its
    // share of its face's
    scalar sum = 0;
    forAll(cdf_, i)
    {
        sum += max(-phi[gatheredFace_[i]], scalar(0))*areaShare_[i];
        cdf_[i] = sum;
    }
    if (!(sum > 0))
    {
        FatalErrorInFunction
            << "Fiber set '" << name_ << "' (placement flux): no flow enters"
            << " the domain through patch '"
            << mesh.boundaryMesh()[patchi_].name() << "' at time "
            << mesh.time().timeName() << ": the fibers due cannot be placed"
            << " by flux (placement area places them anyway)"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberPatchInjection::fiberPatchInjection
(
    const polyMesh& mesh,
    const dictionary& setDict,
    const word& setName,
    const label setIndex,
    const vector& freeDirections
)
:
    name_(setName),
    setIndex_(setIndex),
    patchi_(-1),
    start_(setDict.get<scalar>("start")),
    duration_(keywordCheck::positive(setDict, "duration")),
    rate_(keywordCheck::positive(setDict, "fibersPerSecond")),
    seed_(keywordCheck::seed(setDict)),
    fixedDir_(setDict.found("direction")),
    dir_(1, 0, 0),
    fixedU_(setDict.found("velocity")),
    U0_(setDict.getOrDefault<vector>("velocity", Zero)),
    free_(freeDirections),
    sizes_(setDict),
    byFlux_(false),
    phiName_(setDict.getOrDefault<word>("phi", "phi")),
    nReleased_(0),
    nRedrawn_(0)
{
    checkEntries(mesh, setDict);
    const word& patchName = mesh.boundaryMesh()[patchi_].name();

    const word placement(setDict.getOrDefault<word>("placement", "area"));
    if (placement != "area" && placement != "flux")
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'placement': '" << placement << "' is neither area"
            << " nor flux" << exit(FatalIOError);
    }
    byFlux_ = (placement == "flux");
    if (!byFlux_ && setDict.found("phi"))
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'phi' has no effect with placement area; remove it or"
            << " set placement flux" << exit(FatalIOError);
    }

    gatherPatch(mesh);
    if (cdf_.empty() || !(cdf_.last() > 0))
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'patch': patch '" << patchName << "' has no faces"
            << exit(FatalIOError);
    }

    Info<< "    Fiber set '" << name_ << "' (patch): " << rate_
        << " fibers/s through '" << patchName << "' (" << tri_.size()
        << " triangles, area " << cdf_.last() << " m2) from " << start_
        << " s for " << duration_ << " s";
    if (sizes_.distributed())
    {
        Info<< ", sizes drawn per fiber";
    }
    if (byFlux_)
    {
        Info<< ", placed by the inflow through its faces (" << phiName_
            << ")";
    }
    Info<< endl;
}


void Foam::fiberPatchInjection::checkEntries
(
    const polyMesh& mesh,
    const dictionary& setDict
)
{
    const word patchName(setDict.get<word>("patch"));
    patchi_ = mesh.boundaryMesh().findPatchID(patchName);
    if (patchi_ < 0)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'patch': no patch '" << patchName << "' in the mesh;"
            << " patches: " << mesh.boundaryMesh().names()
            << exit(FatalIOError);
    }
    const polyPatch& pp = mesh.boundaryMesh()[patchi_];
    if (polyPatch::constraintType(pp.type()))
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'patch': patch '" << patchName << "' is of type "
            << pp.type() << "; fibers are fed through a physical patch"
            << " (an inlet, a wall), not a coupled, empty, wedge or"
            << " symmetry patch" << exit(FatalIOError);
    }
    if (start_ < 0)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'start' must be at least 0, not " << start_
            << exit(FatalIOError);
    }
    if (rate_*duration_ > labelMax/2)
    {
        FatalIOErrorInFunction(setDict)
            << "Entries 'fibersPerSecond' and 'duration' ask for "
            << rate_*duration_ << " fibers, more than this build's labels"
            << " can count (" << labelMax/2 << ")" << exit(FatalIOError);
    }
    if (fixedDir_)
    {
        dir_ = keywordCheck::unitVector(setDict, "direction");
        if (mag(dir_ - cmptMultiply(free_, dir_)) > 1e-9)
        {
            FatalIOErrorInFunction(setDict)
                << "Entry 'direction' " << dir_ << " is not in the"
                << " solution plane of this 2-D case (free directions "
                << free_ << ")" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberPatchInjection::prepare(const polyMesh& mesh)
{
    // A moving patch: place where it is now
    if (mesh.moving())
    {
        gatherPatch(mesh);
    }
    if (byFlux_)
    {
        weighByFlux(mesh);
    }
}


Foam::label Foam::fiberPatchInjection::nDue(const scalar t) const
{
    const scalar span = min(t, start_ + duration_) - start_;
    if (span <= 0)
    {
        return 0;
    }
    return label(std::floor(rate_*span + 1e-9));
}


Foam::scalar Foam::fiberPatchInjection::releaseTime(const label k) const
{
    return start_ + (k + 1)/rate_;
}


Foam::fiber Foam::fiberPatchInjection::candidate
(
    const label id,
    const label kFiber,
    const label attempt
) const
{
    // The size: of fiber kFiber; the place and orientation: attempt
    // 'attempt' of fiber kFiber, from a stream of its own (another seed),
    // so that neither depends on how fibers are grouped into steps
    const fiberSizes::size s(sizes_.draw(seed_, kFiber));
    const label seed = seed_ ^ 0x2545F491;
    const label j0 = 32*attempt;

    // A triangle by area, a point uniform in it
    const scalar u = counterRandom::uniform(seed, kFiber, j0)*cdf_.last();
    const label t = min
    (
        label(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()),
        cdf_.size() - 1
    );
    scalar a = counterRandom::uniform(seed, kFiber, j0 + 1);
    scalar b = counterRandom::uniform(seed, kFiber, j0 + 2);
    if (a + b > 1)
    {
        a = 1 - a;
        b = 1 - b;
    }
    const FixedList<point, 3>& T = tri_[t];
    const point onPatch(T[0] + a*(T[1] - T[0]) + b*(T[2] - T[0]));

    // Orientation: given, or uniform in the free directions (normal
    // deviates from draws 8 attempt + 1, 2, ...: j0 + 4 onwards)
    vector p(dir_);
    if (!fixedDir_)
    {
        for (label draw = 8*attempt + 1; ; ++draw)
        {
            p = cmptMultiply
            (
                free_,
                counterRandom::gaussian(seed, kFiber, draw)
            );
            if (mag(p) > 1e-6)
            {
                break;
            }
        }
        p /= mag(p);
    }

    // Just inside: half the extent along the normal and a margin
    const scalar L = s.n*s.l;
    const vector& n = normal_[t];
    const point c(onPatch - (0.5*L*mag(p & n) + 1e-3*L)*n);

    fiber f(fiber::straight(id, c, p, s.n, s.l, s.d, sizes_.density()));
    f.setIndex(setIndex_);
    return f;
}


void Foam::fiberPatchInjection::writeRestart(Ostream& os) const
{
    os  << nReleased_ << token::SPACE << nRedrawn_;
}


void Foam::fiberPatchInjection::readRestart(Istream& is)
{
    is >> nReleased_ >> nRedrawn_;
}


// ************************************************************************* //
