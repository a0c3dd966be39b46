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
#include "spheroidResistance.H"
#include "Random.H"
#include "boundBox.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

scalar positive(const dictionary& dict, const word& key)
{
    return keywordCheck::positive(dict, key);
}


vector unitVector(const dictionary& dict, const word& key)
{
    const vector p = dict.get<vector>(key);
    if (!(mag(p) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be a non-zero vector, not " << p
            << exit(FatalIOError);
    }
    return p/mag(p);
}


scalar orDefault(const dictionary& dict, const word& key, const scalar def)
{
    return keywordCheck::positive(dict, key, def);
}


struct segmentProps
{
    label n;
    scalar l, d, rho;

    segmentProps(const dictionary& dict)
    :
        n(dict.get<label>("nSegments")),
        l(positive(dict, "segmentLength")),
        d(positive(dict, "diameter")),
        rho(positive(dict, "density"))
    {
        fiberInjection::checkSegment(dict, n, l, d, rho);
    }

    // Overrides of a list entry
    segmentProps(const dictionary& dict, const segmentProps& def)
    :
        n(dict.getOrDefault<label>("nSegments", def.n)),
        l(orDefault(dict, "segmentLength", def.l)),
        d(orDefault(dict, "diameter", def.d)),
        rho(orDefault(dict, "density", def.rho))
    {
        fiberInjection::checkSegment(dict, n, l, d, rho);
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::fiberInjection::checkSegment
(
    const dictionary& dict,
    const label nSegments,
    const scalar l,
    const scalar d,
    const scalar
)
{
    if (nSegments < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nSegments' must be at least 1, not " << nSegments
            << exit(FatalIOError);
    }

    const scalar rc = l/d;
    if (rc < spheroidResistance::rcMin)
    {
        FatalIOErrorInFunction(dict)
            << "Segment aspect ratio segmentLength/diameter = " << rc
            << " is below " << spheroidResistance::rcMin << "." << nl
            << "    Cox's equivalent aspect ratio (Eq. 8) is a slender-body"
            << " fit: it exceeds l/d below 4.65 and" << nl
            << "    is not monotonic below 1.65, so the segment drag would"
            << " be meaningless." << nl
            << "    Use fewer, longer segments (reduce 'nSegments' and raise"
            << " 'segmentLength') so that" << nl
            << "    segmentLength >= " << spheroidResistance::rcMin
            << "*diameter = " << spheroidResistance::rcMin*d
            << exit(FatalIOError);
    }
}


void Foam::fiberInjection::read
(
    const dictionary& dict,
    PtrList<fiber>& fibers,
    List<origin>& origins,
    const vector& freeDirections
)
{
    DynamicList<origin> orig;
    DynamicList<fiber*> made;

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
        const segmentProps def(setDict);

        wordList known
        ({
            "type", "nSegments", "segmentLength", "diameter", "density"
        });
        if (setType == "list")
        {
            known.append("fibers");
        }
        else if (setType == "randomBox")
        {
            known.append(wordList({"nFibers", "box", "seed", "direction"}));
        }
        else if (setType == "line")
        {
            known.append(wordList({"nFibers", "start", "end", "direction"}));
        }
        keywordCheck::warnUnknown
        (
            setDict,
            known,
            "fiber set '" + setName + "' (type " + setType + ")"
        );

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
                const segmentProps sp(fd, def);
                made.append
                (
                    new fiber
                    (
                        fiber::straight
                        (
                            made.size(),
                            fd.get<point>("centre"),
                            unitVector(fd, "direction"),
                            sp.n, sp.l, sp.d, sp.rho
                        )
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
            const label seed = setDict.getOrDefault<label>("seed", 1);
            const bool fixedDir = setDict.found("direction");
            const vector dir
            (
                fixedDir ? unitVector(setDict, "direction") : vector(1, 0, 0)
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
                vector p(dir);
                if (!fixedDir)
                {
                    // Uniform on the sphere: normalised Gaussian vector
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
                    p /= mag(p);
                }
                made.append
                (
                    new fiber
                    (
                        fiber::straight
                        (
                            made.size(), c, p, def.n, def.l, def.d, def.rho
                        )
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
            const vector dir(unitVector(setDict, "direction"));
            for (label k = 0; k < nFibers; ++k)
            {
                const scalar w = nFibers > 1 ? scalar(k)/(nFibers - 1) : 0.5;
                made.append
                (
                    new fiber
                    (
                        fiber::straight
                        (
                            made.size(), a + w*(b - a), dir,
                            def.n, def.l, def.d, def.rho
                        )
                    )
                );
                orig.append(origin{setName, k});
            }
        }
        else
        {
            FatalIOErrorInFunction(setDict)
                << "Unknown fiber set type '" << setType
                << "' in entry 'type'; valid types: (list line randomBox)"
                << exit(FatalIOError);
        }
    }

    fibers.setSize(made.size());
    forAll(made, i)
    {
        fibers.set(i, made[i]);
    }
    origins.transfer(orig);
}


// ************************************************************************* //
