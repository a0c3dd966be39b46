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

#include "fiberInjection.H"
#include "openfoamCompat.H"
#include "flexibleChain.H"
#include "periodicImages.H"
#include "Switch.H"
#include "keywordCheck.H"
#include "polyMesh.H"
#include "Random.H"
#include "counterRandom.H"
#include "boundBox.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Uniform on the sphere (in the free directions): normalised Gaussian
vector randomDirection(Random& rnd, const vector& freeDirections)
{
    vector p;
    do
    {
        p = cmptMultiply
        (
            freeDirections,
            vector
            (
                rnd.GaussNormal<scalar>(),
                rnd.GaussNormal<scalar>(),
                rnd.GaussNormal<scalar>()
            )
        );
    } while (mag(p) < 1e-6);
    return p/mag(p);
}


scalar orDefault(const dictionary& dict, const word& key, const scalar def)
{
    return keywordCheck::positive(dict, key, def);
}


//- A straight fiber of the size s in set setIndex
fiber* makeFiber
(
    const label id,
    const point& c,
    const vector& p,
    const fiberSizes::size& s,
    const scalar rho,
    const label setIndex
)
{
    fiber* f = new fiber(fiber::straight(id, c, p, s.n, s.l, s.d, rho));
    f->setIndex(setIndex);
    return f;
}


//- What the readers of one fiber set share
struct setContext
{
    const dictionary& dict;
    const word& name;
    const label index;
    const fiberSizes& sizes;
    const label seed;
    const vector& freeDirections;

    //- Random orientations in the plane normal to this (zero: in 3-D, or
    //  the free directions of a 2-D case)
    const vector planeNormal;

    DynamicList<fiber*>& made;
    DynamicList<fiberInjection::origin>& orig;

    //- Keep fiber k of the set
    void add(fiber* f, const label k) const
    {
        made.append(f);
        orig.append(fiberInjection::origin{name, k});
    }
};


//- The keywords of a set of type setType (FatalIOError for an unknown
//  type)
wordList knownKeys(const dictionary& setDict, const word& setType)
{
    wordList known
    ({
        "type", "nSegments", "segmentLength", "diameter", "density", "seed",
        "model", "curvature"
    });
    if (setDict.getOrDefault<word>("model", "rigid") == "flexible")
    {
        known.append
        (
            wordList({"youngsModulus", "poissonRatio", "shearModulus"})
        );
    }
    if (setType != "patch")
    {
        known.append("fixed");
    }
    if (setType == "list")
    {
        known.append("fibers");
    }
    else if (setType == "randomBox")
    {
        known.append
        (
            wordList({"nFibers", "box", "direction", "planeNormal"})
        );
    }
    else if (setType == "line")
    {
        known.append(wordList({"nFibers", "start", "end", "direction"}));
    }
    else if (setType == "mesh" || setType == "cellZone")
    {
        known.append(wordList({"nFibers", "direction", "planeNormal"}));
        if (setType == "cellZone")
        {
            known.append("cellZone");
        }
    }
    else if (setType == "patch")
    {
        known.append
        (
            wordList
            ({
                "patch", "start", "duration", "fibersPerSecond",
                "direction", "velocity", "placement", "phi"
            })
        );
    }
    else
    {
        FatalIOErrorInFunction(setDict)
            << "Unknown fiber set type '" << setType
            << "' in entry 'type'; valid types:"
            << " (list line randomBox mesh cellZone patch)"
            << exit(FatalIOError);
    }
    return known;
}


//- The entry nFibers, at least 1
label nFibersOf(const dictionary& setDict)
{
    const label nFibers = setDict.get<label>("nFibers");
    if (nFibers < 1)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'nFibers' must be at least 1, not " << nFibers
            << exit(FatalIOError);
    }
    return nFibers;
}


//- The entry direction if given (fixed), else (1 0 0)
vector directionOf(const dictionary& setDict, bool& fixed)
{
    fixed = setDict.found("direction");
    if (fixed)
    {
        keywordCheck::noEffect
        (
            setDict, "planeNormal",
            "with 'direction' (every fiber of the set takes that direction)"
        );
    }
    return
        fixed
      ? keywordCheck::unitVector(setDict, "direction")
      : vector(1, 0, 0);
}


//- A random orientation of a set: uniform on the sphere, in the free
//  directions of a 2-D case, or in the plane normal to planeNormal
vector drawDirection(Random& rnd, const setContext& set)
{
    if (magSqr(set.planeNormal) == 0)
    {
        return randomDirection(rnd, set.freeDirections);
    }
    vector p;
    do
    {
        p = vector
        (
            rnd.GaussNormal<scalar>(),
            rnd.GaussNormal<scalar>(),
            rnd.GaussNormal<scalar>()
        );
        p -= (p & set.planeNormal)*set.planeNormal;
    } while (mag(p) < 1e-6);
    return p/mag(p);
}


//- A uniform point in the box bb
point inBox(Random& rnd, const boundBox& bb)
{
    point c;
    for (direction cmpt = 0; cmpt < 3; ++cmpt)
    {
        c[cmpt] = bb.min()[cmpt]
          + rnd.sample01<scalar>()*(bb.max()[cmpt] - bb.min()[cmpt]);
    }
    return c;
}


//- Set type list: every fiber given
void listSet(const setContext& set)
{
    const List<dictionary> entries
    (
        set.dict.get<List<dictionary>>("fibers")
    );
    if (entries.empty())
    {
        FatalIOErrorInFunction(set.dict)
            << "Entry 'fibers' is an empty list" << exit(FatalIOError);
    }
    forAll(entries, k)
    {
        dictionary fd(entries[k]);
        fd.name() = set.dict.name() + "/fibers/" + Foam::name(k);
        keywordCheck::warnUnknown
        (
            fd,
            wordList
            ({
                "centre", "direction", "nSegments", "segmentLength",
                "diameter", "density", "velocity"
            }),
            "fiber " + Foam::name(k) + " of set '" + set.name + "'"
        );
        // The set's size, a value of the entry overriding it
        fiberSizes::size sz(set.sizes.draw(set.seed, k));
        sz.n = fd.getOrDefault<label>("nSegments", sz.n);
        sz.l = orDefault(fd, "segmentLength", sz.l);
        sz.d = orDefault(fd, "diameter", sz.d);
        const scalar rho = orDefault(fd, "density", set.sizes.density());
        fiberSizes::checkSize(fd, sz);
        fiber* f = makeFiber
        (
            set.made.size(),
            fd.get<point>("centre"),
            keywordCheck::unitVector(fd, "direction"),
            sz, rho, set.index
        );
        f->setVelocity(fd.getOrDefault<vector>("velocity", Zero));
        set.add(f, k);
    }
}


//- Set type randomBox: centres uniform in a box
void boxSet(const setContext& set)
{
    const label nFibers = nFibersOf(set.dict);
    const Pair<point> corners(set.dict.get<Pair<point>>("box"));
    const boundBox bb(corners.first(), corners.second());
    if (!bb.valid() || bb.volume() < 0)
    {
        FatalIOErrorInFunction(set.dict)
            << "Entry 'box' must be (min max) with min <= max, not "
            << corners << exit(FatalIOError);
    }
    bool fixedDir;
    const vector dir(directionOf(set.dict, fixedDir));

    Random rnd(set.seed);
    for (label k = 0; k < nFibers; ++k)
    {
        const point c(inBox(rnd, bb));
        const vector p
        (
            fixedDir ? dir : drawDirection(rnd, set)
        );
        set.add
        (
            makeFiber
            (
                set.made.size(), c, p, set.sizes.draw(set.seed, k),
                set.sizes.density(), set.index
            ),
            k
        );
    }
}


//- Set type line: centres evenly from start to end
void lineSet(const setContext& set)
{
    const label nFibers = nFibersOf(set.dict);
    const point a(set.dict.get<point>("start"));
    const point b(set.dict.get<point>("end"));
    const vector dir(keywordCheck::unitVector(set.dict, "direction"));
    for (label k = 0; k < nFibers; ++k)
    {
        const scalar w = nFibers > 1 ? scalar(k)/(nFibers - 1) : 0.5;
        set.add
        (
            makeFiber
            (
                set.made.size(), a + w*(b - a), dir,
                set.sizes.draw(set.seed, k), set.sizes.density(), set.index
            ),
            k
        );
    }
}


//- The cells of a region (set types mesh, cellZone) and its bounding box
void regionOf
(
    const polyMesh& mesh,
    const dictionary& setDict,
    const word& setType,
    boolList& inside,
    boundBox& bb
)
{
    inside.setSize(mesh.nCells());
    inside = true;
    bb = mesh.bounds();
    if (setType != "cellZone")
    {
        return;
    }
    const word zone(setDict.get<word>("cellZone"));
    const label zoneI = mesh.cellZones().findZoneID(zone);
    if (zoneI < 0)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'cellZone': no cell zone '" << zone
            << "' in the mesh; zones: " << mesh.cellZones().names()
            << exit(FatalIOError);
    }
    inside = false;
    bb = boundBox::invertedBox;
    for (const label celli : mesh.cellZones()[zoneI])
    {
        inside[celli] = true;
        for (const label pointi : mesh.cellPoints()[celli])
        {
            bb.add(mesh.points()[pointi]);
        }
    }
    reduce(bb.min(), minOp<point>());
    reduce(bb.max(), maxOp<point>());
    if (bb.empty())
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'cellZone': cell zone '" << zone << "' is empty"
            << exit(FatalIOError);
    }
}


//- Candidates of a region set, one per slot (the size of the fiber of
//  that slot): the fibers, their sizes, and m flags each: the centre in
//  the region, then the centre and both ends of every segment in the mesh
//  (combined over the processors; m from the most segments of the batch)
void regionCandidates
(
    const polyMesh& mesh,
    const UList<vectorTensorTransform>& images,
    const setContext& set,
    const boolList& inside,
    const boundBox& bb,
    const labelUList& slots,
    const label idBase,
    Random& rnd,
    PtrList<fiber>& cand,
    List<fiberSizes::size>& sz,
    labelList& ok,
    label& m
)
{
    const scalar kappa = set.dict.getOrDefault<scalar>("curvature", 0);
    bool fixedDir;
    const vector dir(directionOf(set.dict, fixedDir));
    const label nb = slots.size();
    cand.setSize(nb);
    sz.setSize(nb);
    m = 1;
    forAll(sz, j)
    {
        sz[j] = set.sizes.draw(set.seed, slots[j]);
        m = max(m, 1 + 3*sz[j].n);
    }
    ok.setSize(nb*m);
    ok = 0;
    List<point> pts;
    forAll(cand, j)
    {
        point c(inBox(rnd, bb));
        // In a 2-D case on the mid-plane of the constrained directions
        for (direction cmpt = 0; cmpt < 3; ++cmpt)
        {
            if (set.freeDirections[cmpt] < 0.5)
            {
                c[cmpt] = 0.5*(bb.min()[cmpt] + bb.max()[cmpt]);
            }
        }
        const vector p
        (
            fixedDir ? dir : drawDirection(rnd, set)
        );
        cand.set
        (
            j,
            makeFiber(0, c, p, sz[j], set.sizes.density(), set.index)
        );
        const label celli = periodicImages::findCell(mesh, c);
        ok[j*m] = (celli >= 0 && inside[celli]);

        // The segments as the fiber will have them: bent for a curvature
        // (the fiber of slot k gets the id idBase + k, and its bend plane
        // from it)
        fiber f(cand[j]);
        if (kappa > 0)
        {
            f.setId(idBase + slots[j]);
            f.setIndex(set.index);
            fiberInjection::bend(f, kappa, set.freeDirections);
        }
        const tensor R(f.R());
        f.segmentCentres(pts);
        forAll(pts, i)
        {
            const vector half
            (
                (0.5*f.segmentLength(i))*f.segmentDirection(R, i)
            );
            const point ends[3] = {pts[i], pts[i] - half, pts[i] + half};
            for (label q = 0; q < 3; ++q)
            {
                ok[j*m + 1 + 3*i + q] =
                    periodicImages::inside(mesh, images, ends[q]);
            }
        }
    }
    fiberCompat::listCombineReduce(ok, maxEqOp<label>());
}


//- Fibers random in a region of the mesh (set types mesh and cellZone):
//  centres uniform in volume, drawn in the region's bounding box and kept
//  where the region holds them, so a cell is hit in proportion to its
//  volume and uniformly inside it; a candidate with a segment (centre or
//  end) outside the mesh is drawn again (counted); a point beyond a
//  periodic patch is in the mesh where its image is.  Every processor draws
//  the same candidates (one random stream, seed) and the tests are
//  combined, so the fibers are the same for any decomposition.  Fiber k
//  keeps its size (stream k): a candidate that does not fit is placed
//  again with the same size in a later batch, so that the sizes follow
//  the distribution
void inRegion
(
    const polyMesh& mesh,
    const setContext& set,
    const word& setType
)
{
    const label nFibers = nFibersOf(set.dict);
    boolList inside;
    boundBox bb;
    regionOf(mesh, set.dict, setType, inside, bb);

    // A segment end beyond a periodic patch lies in the mesh as its image
    label nBase = 0;
    const List<vectorTensorTransform> images
    (
        periodicImages::transforms(mesh, nBase)
    );

    Random rnd(set.seed);
    const label idBase = set.made.size();
    const label batch = 256;
    const label maxCandidates = 1000*nFibers + 100000;
    label nCandidates = 0, nRedrawn = 0, nOutside = 0, nPlaced = 0;
    label nextSlot = 0;
    PtrList<fiber> placed(nFibers);
    DynamicList<label> retry;
    while (nPlaced < nFibers)
    {
        if (nCandidates >= maxCandidates)
        {
            FatalIOErrorInFunction(set.dict)
                << "Fiber set '" << set.name << "': " << nPlaced << " of "
                << nFibers << " fibers placed after " << nCandidates
                << " candidates (" << nRedrawn << " with a segment outside"
                << " the mesh): the region cannot hold fibers of length "
                << set.sizes.maxFiberLength() << " m" << exit(FatalIOError);
        }

        // The fibers of this batch: those to place again, then new ones
        DynamicList<label> slots(retry);
        retry.clear();
        while (slots.size() < batch && nextSlot < nFibers)
        {
            slots.append(nextSlot++);
        }
        PtrList<fiber> cand;
        List<fiberSizes::size> sz;
        labelList ok;
        label m;
        regionCandidates
        (
            mesh, images, set, inside, bb, slots, idBase, rnd, cand, sz, ok,
            m
        );
        forAll(cand, j)
        {
            ++nCandidates;
            bool all = ok[j*m];
            for (label i = 1; all && i < 1 + 3*sz[j].n; ++i)
            {
                all = ok[j*m + i];
            }
            if (!all)
            {
                nRedrawn += ok[j*m] ? 1 : 0;
                nOutside += ok[j*m] ? 0 : 1;
                retry.append(slots[j]);
                continue;
            }
            placed.set(slots[j], cand.set(j, nullptr));
            ++nPlaced;
        }
    }
    forAll(placed, k)
    {
        fiber* f = placed.set(k, nullptr).ptr();
        f->setId(set.made.size());
        set.add(f, k);
    }
    Info<< "    Fiber set '" << set.name << "' (" << setType << "): "
        << nFibers << " fibers from " << nCandidates << " candidates in"
        << " the region's bounding box, drawn again: " << nOutside
        << " with the centre outside the region, " << nRedrawn
        << " with a segment outside the mesh" << endl;
}

//- One fiber set of the injection dictionary: its fibers (made, orig),
//  or its feed (fed)
void readSet
(
    const dictionary& setDict,
    const word& setName,
    const label setIndex,
    const vector& freeDirections,
    const polyMesh* mesh,
    const bool feedsOnly,
    DynamicList<fiber*>& made,
    DynamicList<fiberInjection::origin>& orig,
    DynamicList<fiberPatchInjection*>& fed
)
{
    const word setType(setDict.get<word>("type"));
    keywordCheck::warnUnknown
    (
        setDict,
        knownKeys(setDict, setType),
        "fiber set '" + setName + "' (type " + setType + ")"
    );

    if (setType != "patch" && feedsOnly)
    {
        return;
    }
    if (!mesh && setType != "list" && setType != "randomBox"
     && setType != "line")
    {
        FatalIOErrorInFunction(setDict)
            << "Set type '" << setType << "' needs the mesh"
            << exit(FatalIOError);
    }
    if (setType == "patch")
    {
        fed.append
        (
            new fiberPatchInjection
            (
                *mesh, setDict, setName, setIndex, freeDirections
            )
        );
        return;
    }

    const fiberSizes sizes(setDict);
    const setContext set
    {
        setDict, setName, setIndex, sizes, keywordCheck::seed(setDict),
        freeDirections,
        setDict.found("planeNormal")
      ? keywordCheck::unitVector(setDict, "planeNormal")
      : vector::zero,
        made, orig
    };
    if (setType == "list")
    {
        listSet(set);
    }
    else if (setType == "randomBox")
    {
        boxSet(set);
    }
    else if (setType == "line")
    {
        lineSet(set);
    }
    else
    {
        inRegion(*mesh, set, setType);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::fiberInjection::read
(
    const dictionary& dict,
    PtrList<fiber>& fibers,
    List<origin>& origins,
    wordList& setNames,
    PtrList<fiberPatchInjection>& feeds,
    const vector& freeDirections,
    const polyMesh* mesh,
    const bool feedsOnly
)
{
    DynamicList<origin> orig;
    DynamicList<fiber*> made;
    DynamicList<word> names;
    DynamicList<fiberPatchInjection*> fed;

    if (dict.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Dictionary 'injection' has no fiber sets"
            << exit(FatalIOError);
    }

    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << e.keyword() << "' of 'injection' must be a"
                << " dictionary (a fiber set)"
                << exit(FatalIOError);
        }
        names.append(e.keyword());
        readSet
        (
            e.dict(), e.keyword(), names.size() - 1, freeDirections, mesh,
            feedsOnly, made, orig, fed
        );
    }

    fibers.setSize(made.size());
    forAll(made, i)
    {
        fibers.set(i, made[i]);
    }
    origins.transfer(orig);
    setNames.transfer(names);
    feeds.setSize(fed.size());
    forAll(fed, i)
    {
        feeds.set(i, fed[i]);
    }
}


Foam::boolList Foam::fiberInjection::fixedSets(const dictionary& dict)
{
    DynamicList<bool> fixed;
    for (const entry& e : dict)
    {
        if (e.isDict())
        {
            const dictionary& d = e.dict();
            fixed.append
            (
                d.get<word>("type") != "patch"
             && d.getOrDefault<Switch>("fixed", false)
            );
        }
    }
    return boolList(std::move(fixed));
}


void Foam::fiberInjection::bend
(
    fiber& f,
    const scalar kappa,
    const vector& freeDirections
)
{
    if (kappa <= 0)
    {
        return;
    }
    scalar L = 0;
    for (label i = 0; i < f.nSegments(); ++i)
    {
        L += f.segmentLength(i);
    }
    if (kappa*L > constant::mathematical::twoPi*(1 + 1e-12))
    {
        // A list entry's own size, longer than its set's
        FatalErrorInFunction
            << "Fiber " << f.id() << " of " << L << " m with the curvature "
            << kappa << " of its set: more than a full turn (2 pi), the arc"
            << " would overlap itself" << exit(FatalError);
    }
    const vector p(f.orientation());
    vector n;
    if (cmptMin(freeDirections) < 0.5)
    {
        // In the plane of the case
        const vector e(vector(1, 1, 1) - freeDirections);
        n = e ^ p;
    }
    else
    {
        // A plane through the chord at a random angle (from the id)
        // (about the axis least aligned with the chord)
        const vector a
        (
            mag(p.x()) <= min(mag(p.y()), mag(p.z())) ? vector(1, 0, 0)
          : mag(p.y()) <= mag(p.z()) ? vector(0, 1, 0) : vector(0, 0, 1)
        );
        const vector b1((p ^ a)/mag(p ^ a));
        const vector b2(p ^ b1);
        const scalar phi =
            constant::mathematical::twoPi
           *counterRandom::uniform(7919, f.id(), 0);
        n = std::cos(phi)*b1 + std::sin(phi)*b2;
    }
    fiber bent
    (
        fiber::arc
        (
            f.id(), f.position(), p, n, f.nSegments(), f.segmentLength(0),
            f.segmentDiameter(0), f.segmentDensity(0), kappa
        )
    );
    bent.setIndex(f.setIndex());
    bent.setVelocity(f.velocity());
    bent.setOmega(f.omega());
    bent.location() = f.location();
    f = bent;
}


Foam::scalarList Foam::fiberInjection::curvatures(const dictionary& dict)
{
    DynamicList<scalar> kappa;
    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& d = e.dict();
        const scalar k = d.getOrDefault<scalar>("curvature", 0);
        if (!(k >= 0))
        {
            FatalIOErrorInFunction(d)
                << "curvature " << k << " of fiber set " << e.keyword()
                << " must be >= 0" << exit(FatalIOError);
        }
        if (k > 0)
        {
            // An arc of more than a full turn overlaps itself
            const scalar L = fiberSizes(d).maxFiberLength();
            if (k*L > constant::mathematical::twoPi*(1 + 1e-12))
            {
                FatalIOErrorInFunction(d)
                    << "curvature " << k << " of fiber set " << e.keyword()
                    << " bends its longest fibers (" << L << " m) by "
                    << k*L << " rad, more than a full turn (2 pi): the arc"
                    << " would overlap itself; curvature must be <= "
                    << constant::mathematical::twoPi/L
                    << exit(FatalIOError);
            }
        }
        kappa.append(k);
    }
    return scalarList(std::move(kappa));
}


void Foam::fiberInjection::flexibleSets
(
    const dictionary& dict,
    scalarList& E,
    scalarList& G
)
{
    DynamicList<scalar> Es, Gs;
    for (const entry& e : dict)
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& d = e.dict();
        const word model(d.getOrDefault<word>("model", "rigid"));
        scalar Ei = 0, Gi = 0;
        if (model == "flexible")
        {
            flexibleChain::moduli(d, Ei, Gi);
        }
        else if (model != "rigid")
        {
            FatalIOErrorInFunction(d)
                << "Unknown model " << model << " of fiber set "
                << e.keyword() << ": rigid or flexible"
                << exit(FatalIOError);
        }
        Es.append(Ei);
        Gs.append(Gi);
    }
    E.transfer(Es);
    G.transfer(Gs);
}


// ************************************************************************* //
