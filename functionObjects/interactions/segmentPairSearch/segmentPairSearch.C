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

#include "segmentPairSearch.H"

#include <algorithm>
#include <cmath>
#include <utility>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::segmentPairSearch::build
(
    const UList<contactSegment>& segs,
    const boundBox& bb,
    const scalar r,
    const FixedList<int64_t, 3>& n
)
{
    const size_t ns = segs.size();
    cellOf_.resize(ns);
    start_.assign(n[0]*n[1]*n[2] + 1, 0);
    byCell_.resize(ns);
    cc_.resize(ns);
    ce_.resize(ns);
    ch_.resize(ns);
    cv_.resize(ns);
    cf_.resize(ns);
    cl_.resize(ns);
    for (size_t i = 0; i < ns; ++i)
    {
        int64_t k = 0;
        for (direction dim = 3; dim-- > 0; )
        {
            k = k*n[dim]
              + int64_t(std::floor((c_[i][dim] - bb.min()[dim])/r)) + 1;
        }
        cellOf_[i] = label(k);
        ++start_[cellOf_[i] + 1];
    }
    for (size_t k = 1; k < start_.size(); ++k)
    {
        start_[k] += start_[k - 1];
    }
    fill_.assign(start_.begin(), start_.end() - 1);
    ck_.resize(ns);
    for (size_t i = 0; i < ns; ++i)
    {
        ck_[fill_[cellOf_[i]]] = cellOf_[i];
        byCell_[fill_[cellOf_[i]]++] = label(i);
    }
    for (size_t e = 0; e < ns; ++e)
    {
        const label p = byCell_[e];
        cc_[e] = c_[p];
        ce_[e] = ext_[p];
        ch_[e] = halfExtent(segs[p]);
        cv_[e] = centreVelocity(segs[p]);
        cf_[e] = segs[p].fiber;
        cl_[e] =
            char
            (
                (segs[p].local >= 0) | (segs[p].flexible << 1)
              | (!(segs[p].m > 0) << 2)
            );
    }
}


inline void Foam::fiberInteractions::segmentPairSearch::densePair
(
    const UList<contactSegment>& segs,
    const denseEntry& A,
    const int64_t e,
    denseScan& s
) const
{
    // The centres' distance first: it rejects most of the entries met,
    // from the two arrays read in cell order
    const vector dc(cc_[e] - A.c);
    const scalar d2 = magSqr(dc);
    const scalar within = A.e + ce_[e];
    if (d2 > sqr(within + s.extra))
    {
        return;
    }
    // Neither local, or both fixed (a mat's, a fixed set's: they never
    // act on each other): no pair
    const bool lp = cl_[e] & 1;
    if ((!A.local && !lp) || (A.fixed && (cl_[e] & 4)))
    {
        return;
    }
    const label p = byCell_[e];
    if
    (
        cf_[e] == A.fiber
     && (!A.flexible || !selfPair(segs[A.q], segs[p]))
    )
    {
        return;
    }
    if (d2 >= s.rFar2)
    {
        const scalar v2 = magSqr(cv_[e] - A.v);
        if (v2 > s.lambda2*d2)
        {
            s.lambda2 = v2/d2;
        }
    }
    if (!boxesMeet(dc, A.h, ch_[e], s.extra))
    {
        return;
    }
    const bool near =
        s.inReach
     && d2 <= sqr(within + s.range)
     && boxesMeet(dc, A.h, ch_[e], s.range);
    if (A.local)
    {
        s.cand.append(indexPair{A.q, p});
        if (near)
        {
            s.inReach->append(indexPair{A.q, p});
        }
    }
    if (lp)
    {
        s.cand.append(indexPair{p, A.q});
        if (near)
        {
            s.inReach->append(indexPair{p, A.q});
        }
    }
}


void Foam::fiberInteractions::segmentPairSearch::dense
(
    const UList<contactSegment>& segs,
    const FixedList<int64_t, 3>& n,
    const scalar r,
    const scalar range,
    const scalar skin,
    DynamicList<indexPair>& cand,
    DynamicList<indexPair>* inReach,
    scalar* lambda
) const
{
    // A pair passes where its centres are within the sum of the half
    // lengths and diameters, reach and skin, and its boxes meet (the box
    // test holds every pair whose surfaces are within the cohesion range
    // and skin, or the range and a tenth of a diameter: within reach).
    // lambda: the largest relative speed of the centres per distance of
    // the pairs whose centres pass and are at least the reach apart
    denseScan scan
    {
        lambda ? sqr(max(r - skin, 0)) : GREAT, range + skin, range, 0,
        cand, inReach
    };

    // In cell order, every entry against those after it in its own cell
    // and against the 13 neighbouring cells ahead of it (a half stencil:
    // each pair is met once, and consecutive entries share their
    // neighbours in the cache); a pair with a local segment is kept, as
    // (local, other), and both orders where both are local
    const int64_t sy = n[0];
    const int64_t sz = n[0]*n[1];
    FixedList<std::pair<int64_t, int64_t>, 6> rows;
    const label ns = segs.size();
    for (label a = 0; a < ns; ++a)
    {
        const label q = byCell_[a];
        const int64_t k = ck_[a];
        const denseEntry A
        {
            q, cf_[a], bool(cl_[a] & 1), bool(cl_[a] & 2), bool(cl_[a] & 4),
            cc_[a], ce_[a], ch_[a], cv_[a]
        };

        // The rest of its own cell, the next cell of its row, the next
        // row's three cells and the nine of the next layer
        rows[0] = {a + 1, start_[k + 1]};
        rows[1] = {start_[k + 1], start_[k + 2]};
        rows[2] = {start_[k + sy - 1], start_[k + sy + 2]};
        rows[3] = {start_[k + sz - sy - 1], start_[k + sz - sy + 2]};
        rows[4] = {start_[k + sz - 1], start_[k + sz + 2]};
        rows[5] = {start_[k + sz + sy - 1], start_[k + sz + sy + 2]};
        for (const std::pair<int64_t, int64_t>& row : rows)
        {
            for (int64_t e = row.first; e < row.second; ++e)
            {
                densePair(segs, A, e, scan);
            }
        }
    }
    if (lambda)
    {
        *lambda = max(*lambda, sqrt(scan.lambda2));
    }
}


inline void Foam::fiberInteractions::segmentPairSearch::sparsePair
(
    const UList<contactSegment>& segs,
    const label q,
    const label p,
    const scalar r,
    const scalar range,
    const scalar skin,
    DynamicList<indexPair>& cand,
    scalar* lambda
) const
{
    // q is free (local or another processor's); a pair is met from both
    // sides where both are free, from q's only where p is fixed.  Kept:
    // (local, other), and both orders where both are local
    const contactSegment& Q = segs[q];
    const contactSegment& P = segs[p];
    const bool fixedP = !(P.m > 0);
    const bool localP = P.local >= 0;
    if (Q.local < 0 && !(fixedP && localP))
    {
        // Met from p's side, or neither is local
        return;
    }
    const scalar within = ext_[q] + ext_[p] + range + skin;
    const vector dc(c_[p] - c_[q]);
    const scalar d2 = magSqr(dc);
    if ((P.fiber == Q.fiber && !selfPair(Q, P)) || d2 > sqr(within))
    {
        return;
    }
    // Each pair once for lambda
    if
    (
        lambda
     && (!localP || q < p || fixedP)
     && d2 >= sqr(max(r - skin, 0))
    )
    {
        *lambda =
            max(*lambda, mag(centreVelocity(P) - centreVelocity(Q))/sqrt(d2));
    }
    if (boxesMeet(dc, halfExtent(Q), halfExtent(P), range + skin))
    {
        if (Q.local >= 0)
        {
            cand.append(indexPair{q, p});
        }
        if (fixedP && localP)
        {
            cand.append(indexPair{p, q});
        }
    }
}


void Foam::fiberInteractions::segmentPairSearch::sparse
(
    const UList<contactSegment>& segs,
    const boundBox& bb,
    const scalar r,
    const scalar range,
    const scalar skin,
    DynamicList<indexPair>& cand,
    scalar* lambda
) const
{
    // Cells of size r by their integer coordinates
    auto cell = [&](const point& p, const label dim)
    {
        return int64_t(std::floor((p[dim] - bb.min()[dim])/r));
    };
    const int64_t nx = cell(bb.max(), 0) + 3;
    const int64_t ny = cell(bb.max(), 1) + 3;
    // Neighbours reach one cell below the first: shifted by one
    auto key = [&](const int64_t i, const int64_t j, const int64_t k)
    {
        return ((k + 1)*ny + (j + 1))*nx + (i + 1);
    };
    // The segments sorted by their cells' keys (one array: a hash table of
    // lists cost an allocation per cell at every interval); the three
    // cells of a row of neighbours have consecutive keys, one search.
    // Half of each segment's length and diameter (ext)
    std::vector<std::pair<int64_t, label>> byKey(segs.size());
    forAll(segs, i)
    {
        byKey[i] = {key(cell(c_[i], 0), cell(c_[i], 1), cell(c_[i], 2)), i};
    }
    std::sort(byKey.begin(), byKey.end());

    forAll(segs, q)
    {
        // Free segments only: a fixed one's pairs are met from the other
        // side (two fixed never pair), a mat's segments cost their sort
        const contactSegment& Q = segs[q];
        if (!(Q.m > 0))
        {
            continue;
        }
        const int64_t ci = cell(c_[q], 0);
        const int64_t cj = cell(c_[q], 1);
        const int64_t ck = cell(c_[q], 2);
        for (int64_t k = ck - 1; k <= ck + 1; ++k)
        {
            for (int64_t j = cj - 1; j <= cj + 1; ++j)
            {
                const int64_t kLast = key(ci + 1, j, k);
                for
                (
                    auto it =
                        std::lower_bound
                        (
                            byKey.begin(), byKey.end(),
                            std::pair<int64_t, label>(key(ci - 1, j, k), -1)
                        );
                    it != byKey.end() && it->first <= kLast;
                    ++it
                )
                {
                    sparsePair
                    (
                        segs, q, it->second, r, range, skin, cand, lambda
                    );
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::fiberInteractions::segmentPairSearch::pairs
(
    const UList<contactSegment>& segs,
    const scalar r,
    const scalar range,
    const scalar skin,
    DynamicList<indexPair>& cand,
    DynamicList<indexPair>* inReach,
    scalar* lambda
)
{
    if (segs.empty() || !(r > 0))
    {
        return;
    }

    // Cells of size r over the centres' box, with a layer of empty cells
    // around it, so that every neighbour of an occupied cell exists
    boundBox bb(boundBox::invertedBox);
    c_.resize(segs.size());
    ext_.resize(segs.size());
    forAll(segs, i)
    {
        c_[i] = 0.5*(segs[i].a + segs[i].b);
        bb.add(c_[i]);
        ext_[i] = 0.5*(mag(segs[i].b - segs[i].a) + segs[i].d);
    }
    FixedList<int64_t, 3> n;
    for (direction dim = 0; dim < 3; ++dim)
    {
        n[dim] = int64_t(std::floor(bb.span()[dim]/r)) + 3;
    }
    if (n[0]*n[1]*n[2] > 8*int64_t(segs.size()) + 4096)
    {
        // Sparse: a few segments spread far apart
        sparse(segs, bb, r, range, skin, cand, lambda);
        if (inReach)
        {
            withinReach(segs, range, cand, *inReach);
        }
        return;
    }
    build(segs, bb, r, n);
    dense(segs, n, r, range, skin, cand, inReach, lambda);
}


void Foam::fiberInteractions::segmentPairSearch::withinReach
(
    const UList<contactSegment>& segs,
    const scalar range,
    const UList<indexPair>& cand,
    DynamicList<indexPair>& inReach
)
{
    for (const indexPair& ij : cand)
    {
        const contactSegment& Q = segs[ij[0]];
        const contactSegment& P = segs[ij[1]];
        const scalar within =
            0.5*(mag(Q.b - Q.a) + mag(P.b - P.a) + Q.d + P.d) + range;
        const vector dc(0.5*(P.a + P.b - Q.a - Q.b));
        if
        (
            magSqr(dc) <= sqr(within)
         && boxesMeet(dc, halfExtent(Q), halfExtent(P), range)
        )
        {
            inReach.append(ij);
        }
    }
}


// ************************************************************************* //
