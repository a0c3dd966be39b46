/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fiberTracking: rigid fibers for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fiberTracking, distributed under GPL-3.0-or-later.

Description
    Unit tests of the mats' store (matStore) against brute force: the
    fibers a query finds are exactly those with a segment's box meeting a
    query box (checked box by box over all segments), ascending and
    without repeats, for fibers added in batches of growing size (the
    grid made anew when a larger fiber comes), small, large and far query
    boxes; a straight fiber's segments' boxes are their axes' ends widened
    by the radius; the counts per set and the look-up by id equal a walk
    over all fibers.  Part of Test-fiberModel.

\*---------------------------------------------------------------------------*/

#include "matStore.H"

#include <random>
#include <sstream>

using namespace Foam;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);

namespace
{

//- n straight fibers of 1 to 4 segments of length l, at random in a box
//  of side 5 mm (ids from id0), at random orientations, in sets 0 to 4
PtrList<fiber> randomFibers
(
    const label n,
    const label id0,
    const scalar l,
    std::mt19937& gen
)
{
    std::uniform_real_distribution<scalar> u01(0, 1);
    std::normal_distribution<scalar> g01(0, 1);
    PtrList<fiber> fs(n);
    forAll(fs, k)
    {
        vector p(g01(gen), g01(gen), g01(gen));
        p /= mag(p);
        const point c(5e-3*u01(gen), 5e-3*u01(gen), 5e-3*u01(gen));
        const label nSeg = 1 + label(4*u01(gen)) % 4;
        fs.set
        (
            k,
            new fiber(fiber::straight(id0 + k, c, p, nSeg, l, 2e-5, 1000))
        );
        fs[k].setIndex(label(5*u01(gen)) % 5);
    }
    return fs;
}

} // End namespace


void testMatStore()
{
    std::mt19937 gen(11);
    std::uniform_real_distribution<scalar> u01(0, 1);

    // A straight fiber's segments' boxes: their axes' ends and radius
    {
        const vector p(0.6, 0, 0.8);
        const fiber f(fiber::straight(0, point(1, 2, 3), p, 3, 1e-3, 2e-4, 1));
        const List<boundBox> bb(matStore::segmentBoxes(f));
        scalar err = bb.size() == 3 ? 0 : GREAT;
        for (label i = 0; i < min(bb.size(), label(3)); ++i)
        {
            const point a(point(1, 2, 3) + (i - 1.5)*1e-3*p);
            const point b(a + 1e-3*p);
            err +=
                mag(bb[i].min() - (min(a, b) - vector::uniform(1e-4)))
              + mag(bb[i].max() - (max(a, b) + vector::uniform(1e-4)));
        }
        std::ostringstream d;
        d << "error of the corners " << err << " m";
        check("matStore.segmentBoxesStraight", err < 1e-15, d.str());
    }

    // Batches of 0.1, 0.3 and 1 mm segments: the grid is made anew twice
    matStore mats;
    PtrList<fiber> all;
    label id = 0;
    for (const scalar l : {1e-4, 3e-4, 1e-3})
    {
        PtrList<fiber> batch(randomFibers(700, id, l, gen));
        id += batch.size();
        forAll(batch, k)
        {
            all.append(new fiber(batch[k]));
        }
        mats.add(batch);
    }

    label nQueries = 0;
    label nFound = 0;
    label nWrong = 0;
    bool ordered = true;
    for (label q = 0; q < 60; ++q)
    {
        // 1 to 20 boxes of sides from 1 um to 3 mm, some beyond the mat
        List<boundBox> boxes(1 + label(20*u01(gen)) % 20);
        for (boundBox& b : boxes)
        {
            const point c
            (
                7e-3*u01(gen) - 1e-3, 7e-3*u01(gen) - 1e-3,
                7e-3*u01(gen) - 1e-3
            );
            const scalar s = std::pow(10, -6 + 3.5*u01(gen));
            b = boundBox(c - vector::uniform(s), c + vector::uniform(s));
        }
        const labelList found(mats.near(boxes));
        labelList want;
        forAll(all, i)
        {
            bool meets = false;
            for (const boundBox& bi : matStore::segmentBoxes(all[i]))
            {
                for (const boundBox& b : boxes)
                {
                    meets = meets || bi.overlaps(b);
                }
            }
            if (meets)
            {
                want.append(i);
            }
        }
        for (label k = 1; k < found.size(); ++k)
        {
            ordered = ordered && found[k - 1] < found[k];
        }
        nWrong += found == want ? 0 : 1;
        nFound += found.size();
        ++nQueries;
    }
    std::ostringstream d;
    d << nQueries << " queries over " << mats.size() << " fibers, "
      << nFound << " found, " << nWrong << " differ from brute force"
      << (ordered ? "" : ", not ascending");
    check
    (
        "matStore.nearEqualsBruteForce",
        nWrong == 0 && ordered && mats.size() == 2100 && nFound > 100,
        d.str()
    );

    // The counts per set and the look-up by id against a walk over all
    {
        labelList want(5, 0);
        label nBad = 0;
        forAll(all, i)
        {
            ++want[all[i].setIndex()];
            const label at = mats.find(all[i].id());
            nBad += at < 0 || mats.fibers()[at].id() != all[i].id();
        }
        nBad += mats.find(id) != -1;
        labelList got(mats.perSet());
        got.setSize(5, 0);
        std::ostringstream d;
        d << "per set";
        forAll(got, k)
        {
            d << " " << got[k] << " (walk " << want[k] << ")";
        }
        d << ", " << nBad << " ids not found where they are";
        check("matStore.countsAndIds", got == want && nBad == 0, d.str());
    }

    // A query that covers everything finds everything once
    const labelList every
    (
        mats.near
        (
            List<boundBox>
            (
                2, boundBox(vector::uniform(-1), vector::uniform(1))
            )
        )
    );
    check
    (
        "matStore.nearAll",
        every.size() == mats.size(),
        std::to_string(every.size()) + " of " + std::to_string(mats.size())
    );
}


// ************************************************************************* //
