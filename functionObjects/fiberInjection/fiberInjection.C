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
#include "keywordCheck.H"
#include "polyMesh.H"
#include "Random.H"
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


//- Fibers random in a region of the mesh (set types mesh and cellZone):
//  centres uniform in volume, drawn in the region's bounding box and kept
//  where the region holds them, so a cell is hit in proportion to its
//  volume and uniformly inside it; a candidate with a segment (centre or
//  end) outside the mesh is drawn again (counted).  Every processor draws
//  the same candidates (one random stream, seed) and the tests are
//  combined, so the fibers are the same for any decomposition.
void inRegion
(
    const polyMesh& mesh,
    const dictionary& setDict,
    const word& setName,
    const word& setType,
    const label setIndex,
    const fiberSizes& sizes,
    const vector& freeDirections,
    DynamicList<fiber*>& made,
    DynamicList<fiberInjection::origin>& orig
)
{
    const label nFibers = setDict.get<label>("nFibers");
    if (nFibers < 1)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'nFibers' must be at least 1, not " << nFibers
            << exit(FatalIOError);
    }
    const label seed = keywordCheck::seed(setDict);
    const bool fixedDir = setDict.found("direction");
    const vector dir
    (
        fixedDir
      ? keywordCheck::unitVector(setDict, "direction")
      : vector(1, 0, 0)
    );

    // The region's cells and bounding box
    boolList inside(mesh.nCells(), true);
    boundBox bb(mesh.bounds());
    if (setType == "cellZone")
    {
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

    // Candidates in batches; all segment centres must be in the mesh.
    // Fiber k keeps its size (stream k): a candidate that does not fit is
    // placed again with the same size in a later batch, so that the sizes
    // follow the distribution
    Random rnd(seed);
    const label batch = 256;
    const label maxCandidates = 1000*nFibers + 100000;
    label nCandidates = 0, nRedrawn = 0, nPlaced = 0, nextSlot = 0;
    PtrList<fiber> placed(nFibers);
    DynamicList<label> retry;
    List<point> pts;
    while (nPlaced < nFibers)
    {
        if (nCandidates >= maxCandidates)
        {
            FatalIOErrorInFunction(setDict)
                << "Fiber set '" << setName << "': " << nPlaced << " of "
                << nFibers << " fibers placed after " << nCandidates
                << " candidates (" << nRedrawn << " with a segment outside"
                << " the mesh): the region cannot hold fibers of length "
                << sizes.maxFiberLength() << " m" << exit(FatalIOError);
        }

        // The fibers of this batch: those to place again, then new ones
        DynamicList<label> slots(retry);
        retry.clear();
        while (slots.size() < batch && nextSlot < nFibers)
        {
            slots.append(nextSlot++);
        }
        const label nb = slots.size();

        // Per candidate: the centre in the region, then the centre and
        // both ends of every segment in the mesh (up to the most segments
        // a fiber of the batch has)
        PtrList<fiber> cand(nb);
        List<fiberSizes::size> sz(nb);
        label m = 1;
        forAll(sz, j)
        {
            sz[j] = sizes.draw(seed, slots[j]);
            m = max(m, 1 + 3*sz[j].n);
        }
        labelList ok(nb*m, 0);
        forAll(cand, j)
        {
            point c;
            for (direction cmpt = 0; cmpt < 3; ++cmpt)
            {
                c[cmpt] = bb.min()[cmpt]
                  + rnd.sample01<scalar>()*(bb.max()[cmpt] - bb.min()[cmpt]);
            }
            // In a 2-D case on the mid-plane of the constrained directions
            for (direction cmpt = 0; cmpt < 3; ++cmpt)
            {
                if (freeDirections[cmpt] < 0.5)
                {
                    c[cmpt] = 0.5*(bb.min()[cmpt] + bb.max()[cmpt]);
                }
            }
            const vector p
            (
                fixedDir ? dir : randomDirection(rnd, freeDirections)
            );
            cand.set
            (
                j,
                makeFiber(0, c, p, sz[j], sizes.density(), setIndex)
            );
            const label celli = mesh.findCell(c);
            ok[j*m] = (celli >= 0 && inside[celli]);
            const fiber& f = cand[j];
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
                    ok[j*m + 1 + 3*i + q] = (mesh.findCell(ends[q]) >= 0);
                }
            }
        }
        Pstream::listCombineGather(ok, maxEqOp<label>());
        Pstream::listCombineScatter(ok);
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
                if (ok[j*m])
                {
                    ++nRedrawn;
                }
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
        f->setId(made.size());
        made.append(f);
        orig.append(fiberInjection::origin{setName, k});
    }
    Info<< "    Fiber set '" << setName << "' (" << setType << "): "
        << nFibers << " fibers from " << nCandidates << " candidates, "
        << nRedrawn << " drawn again (a segment outside the mesh)" << endl;
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

        const dictionary& setDict = e.dict();
        const word setName(e.keyword());
        const word setType(setDict.get<word>("type"));
        const label setIndex = names.size();
        names.append(setName);

        wordList known
        ({
            "type", "nSegments", "segmentLength", "diameter", "density",
            "seed"
        });
        if (setType == "list")
        {
            known.append("fibers");
        }
        else if (setType == "randomBox")
        {
            known.append(wordList({"nFibers", "box", "direction"}));
        }
        else if (setType == "line")
        {
            known.append(wordList({"nFibers", "start", "end", "direction"}));
        }
        else if (setType == "mesh" || setType == "cellZone")
        {
            known.append(wordList({"nFibers", "direction"}));
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
        keywordCheck::warnUnknown
        (
            setDict,
            known,
            "fiber set '" + setName + "' (type " + setType + ")"
        );

        if (setType == "patch")
        {
            if (!mesh)
            {
                FatalIOErrorInFunction(setDict)
                    << "Set type 'patch' needs the mesh"
                    << exit(FatalIOError);
            }
            fed.append
            (
                new fiberPatchInjection
                (
                    *mesh, setDict, setName, setIndex, freeDirections
                )
            );
            continue;
        }

        if (feedsOnly)
        {
            continue;
        }

        const fiberSizes sizes(setDict);
        const label seed = keywordCheck::seed(setDict);

        if (setType == "list")
        {
            const List<dictionary> entries
            (
                setDict.get<List<dictionary>>("fibers")
            );
            if (entries.empty())
            {
                FatalIOErrorInFunction(setDict)
                    << "Entry 'fibers' is an empty list"
                    << exit(FatalIOError);
            }
            forAll(entries, k)
            {
                dictionary fd(entries[k]);
                fd.name() = setDict.name() + "/fibers/" + Foam::name(k);
                keywordCheck::warnUnknown
                (
                    fd,
                    wordList
                    ({
                        "centre", "direction", "nSegments", "segmentLength",
                        "diameter", "density"
                    }),
                    "fiber " + Foam::name(k) + " of set '" + setName + "'"
                );
                // The set's size, a value of the entry overriding it
                fiberSizes::size sz(sizes.draw(seed, k));
                sz.n = fd.getOrDefault<label>("nSegments", sz.n);
                sz.l = orDefault(fd, "segmentLength", sz.l);
                sz.d = orDefault(fd, "diameter", sz.d);
                const scalar rho = orDefault(fd, "density", sizes.density());
                fiberSizes::checkSize(fd, sz);
                made.append
                (
                    makeFiber
                    (
                        made.size(),
                        fd.get<point>("centre"),
                        keywordCheck::unitVector(fd, "direction"),
                        sz, rho, setIndex
                    )
                );
                orig.append(origin{setName, k});
            }
        }
        else if (setType == "randomBox")
        {
            const label nFibers = setDict.get<label>("nFibers");
            if (nFibers < 1)
            {
                FatalIOErrorInFunction(setDict)
                    << "Entry 'nFibers' must be at least 1, not " << nFibers
                    << exit(FatalIOError);
            }
            const Pair<point> corners(setDict.get<Pair<point>>("box"));
            const boundBox bb(corners.first(), corners.second());
            if (!bb.valid() || bb.volume() < 0)
            {
                FatalIOErrorInFunction(setDict)
                    << "Entry 'box' must be (min max) with min <= max, not "
                    << corners << exit(FatalIOError);
            }
            const bool fixedDir = setDict.found("direction");
            const vector dir
            (
                fixedDir
      ? keywordCheck::unitVector(setDict, "direction")
      : vector(1, 0, 0)
            );

            Random rnd(seed);
            for (label k = 0; k < nFibers; ++k)
            {
                point c;
                for (direction cmpt = 0; cmpt < 3; ++cmpt)
                {
                    c[cmpt] = bb.min()[cmpt]
                      + rnd.sample01<scalar>()*(bb.max()[cmpt]
                      - bb.min()[cmpt]);
                }
                const vector p
                (
                    fixedDir ? dir : randomDirection(rnd, freeDirections)
                );
                made.append
                (
                    makeFiber
                    (
                        made.size(), c, p, sizes.draw(seed, k),
                        sizes.density(), setIndex
                    )
                );
                orig.append(origin{setName, k});
            }
        }
        else if (setType == "line")
        {
            const label nFibers = setDict.get<label>("nFibers");
            if (nFibers < 1)
            {
                FatalIOErrorInFunction(setDict)
                    << "Entry 'nFibers' must be at least 1, not " << nFibers
                    << exit(FatalIOError);
            }
            const point a(setDict.get<point>("start"));
            const point b(setDict.get<point>("end"));
            const vector dir(keywordCheck::unitVector(setDict, "direction"));
            for (label k = 0; k < nFibers; ++k)
            {
                const scalar w = nFibers > 1 ? scalar(k)/(nFibers - 1) : 0.5;
                made.append
                (
                    makeFiber
                    (
                        made.size(), a + w*(b - a), dir, sizes.draw(seed, k),
                        sizes.density(), setIndex
                    )
                );
                orig.append(origin{setName, k});
            }
        }
        else
        {
            if (!mesh)
            {
                FatalIOErrorInFunction(setDict)
                    << "Set type '" << setType << "' needs the mesh"
                    << exit(FatalIOError);
            }
            inRegion
            (
                *mesh, setDict, setName, setType, setIndex, sizes,
                freeDirections, made, orig
            );
        }
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


// ************************************************************************* //
