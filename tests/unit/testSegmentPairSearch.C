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
    Unit tests of the contact model's broad phase (segmentPairSearch)
    against a brute-force count over every pair of segments, with their
    exact surface distance (segmentDistance).  Part of Test-fiberModel.
    - every pair whose surfaces are within range + skin is a candidate,
      in the orders the contact model relies on: (local, other), and both
      orders where both are local; none twice; none of a rigid fiber with
      itself; every pair within range is in inReach, and inReach is part
      of the candidates;
    - the dense grid (segments crowded in a box) and the sorted keys (a
      few segments spread far apart) alike, with segments of other
      processors (local -1) and flexible fibers' own segments (selfPair);
    - one fiber in five fixed (mass 0): two fixed segments never pair.

\*---------------------------------------------------------------------------*/

#include "segmentPairSearch.H"
#include "segmentDistance.H"

#include <random>
#include <set>
#include <sstream>
#include <utility>

using namespace Foam;
using fiberInteractions::contactSegment;
using fiberInteractions::segmentPairSearch;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);

namespace
{

//- nFibers fibers of 1 to 5 segments, in a box of side box: rigid
//  straight, or (every fourth) flexible chains turning by up to 90
//  degrees at each joint; a third of the fibers another processor's
std::vector<contactSegment> randomSegments
(
    const label nFibers,
    const scalar box,
    std::mt19937& gen
)
{
    std::uniform_real_distribution<scalar> u01(0, 1);
    auto dir = [&]()
    {
        vector v;
        do
        {
            v = vector(2*u01(gen) - 1, 2*u01(gen) - 1, 2*u01(gen) - 1);
        } while (magSqr(v) > 1 || magSqr(v) < 1e-6);
        return v/mag(v);
    };
    std::vector<contactSegment> segs;
    for (label f = 0; f < nFibers; ++f)
    {
        const label nSeg = 1 + label(5*u01(gen));
        const bool flexible = (f % 4 == 0);
        const bool local = (f % 3 != 0);
        const scalar l = 0.1 + 0.9*u01(gen);
        const scalar d = 0.01 + 0.05*u01(gen);
        point a(box*u01(gen), box*u01(gen), box*u01(gen));
        vector t(dir());
        scalar s0 = 0;
        for (label i = 0; i < nSeg; ++i)
        {
            contactSegment s{};
            s.v = s.w = s.sX = s.sTheta = s.sV = s.sW = Zero;
            s.dX = s.dTheta = s.u = Zero;
            s.fiber = f;
            s.seg = i;
            s.nSeg = nSeg;
            s.a = a;
            s.b = a + l*t;
            s.d = d;
            s.zPrev = t;
            s.s0 = s0;
            s.flexible = flexible;
            s.x = a;
            s.local = local ? f : -1;
            s.proc = local ? 0 : 1;
            s.m = f % 5 == 0 ? 0 : 1;
            s.turn = -1;
            segs.push_back(s);
            a = s.b;
            s0 += l;
            if (flexible)
            {
                t = t + dir();
                t /= mag(t);
            }
        }
    }
    return segs;
}


//- Search and brute force on segs; true where they agree
bool agree
(
    const std::vector<contactSegment>& all,
    const scalar range,
    const scalar skin,
    std::ostringstream& det
)
{
    typedef segmentPairSearch::indexPair indexPair;
    const UList<contactSegment> segs
    (
        const_cast<contactSegment*>(all.data()), label(all.size())
    );
    scalar r = 0;
    for (const contactSegment& s : all)
    {
        r = max(r, mag(s.b - s.a) + s.d);
    }
    r += range + skin;

    segmentPairSearch search;
    DynamicList<indexPair> cand;
    DynamicList<indexPair> inReach;
    scalar lambda = 0;
    search.pairs(segs, r, range, skin, cand, &inReach, &lambda);

    std::set<std::pair<label, label>> got;
    label twice = 0;
    label wrong = 0;
    for (const indexPair& ij : cand)
    {
        const contactSegment& Q = segs[ij[0]];
        const contactSegment& P = segs[ij[1]];
        twice += !got.insert({ij[0], ij[1]}).second;
        wrong +=
            Q.local < 0
         || (Q.fiber == P.fiber && !fiberInteractions::selfPair(Q, P))
         || (!(Q.m > 0) && !(P.m > 0));
    }
    std::set<std::pair<label, label>> near;
    for (const indexPair& ij : inReach)
    {
        near.insert({ij[0], ij[1]});
        wrong += !got.count({ij[0], ij[1]});
    }

    // Every pair, with its exact surface distance
    label expected = 0;
    label missed = 0;
    label missedNear = 0;
    forAll(segs, i)
    {
        for (label j = i + 1; j < segs.size(); ++j)
        {
            const contactSegment& A = segs[i];
            const contactSegment& B = segs[j];
            if
            (
                (A.local < 0 && B.local < 0)
             || (!(A.m > 0) && !(B.m > 0))
            )
            {
                continue;
            }
            if (A.fiber == B.fiber && !fiberInteractions::selfPair(A, B))
            {
                continue;
            }
            const segmentDistance::result res =
                segmentDistance::closest(A.a, A.b, B.a, B.b);
            const scalar gap =
                std::sqrt(res.distSqr) - 0.5*(A.d + B.d);
            if (gap > range + skin)
            {
                continue;
            }
            for (const auto& o : {std::make_pair(i, j), {j, i}})
            {
                if (segs[o.first].local < 0)
                {
                    continue;
                }
                ++expected;
                missed += !got.count(o);
                missedNear += gap <= range && !near.count(o);
            }
        }
    }
    det << expected << " pairs within range + skin, " << cand.size()
        << " candidates, missed " << missed << ", within range missed "
        << missedNear << ", twice " << twice << ", wrong " << wrong;
    return expected > 0 && missed == 0 && missedNear == 0 && twice == 0
        && wrong == 0;
}

} // End anonymous namespace


void testSegmentPairSearch()
{
    std::mt19937 gen(17);

    // Crowded: the dense grid.  Spread: the sorted keys
    for (const std::pair<const char*, scalar>& c :
        {std::make_pair("dense", 6.0), std::make_pair("sparse", 50.0)})
    {
        const std::vector<contactSegment> segs =
            randomSegments(c.second < 10 ? 1000 : 3000, c.second, gen);
        for (const scalar skin : {0.0, 0.05})
        {
            std::ostringstream nm;
            std::ostringstream det;
            nm << "pairSearch." << c.first << ".skin" << skin;
            const bool ok = agree(segs, 0.02, skin, det);
            check(nm.str() + ".bruteForce", ok, det.str());
        }
    }
}


// ************************************************************************* //
