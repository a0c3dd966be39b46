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
    contact: the search for pairs (segments, periodic images, the segments
    of other processors within reach, the grid).

\*---------------------------------------------------------------------------*/

#include "contact.H"
#include "fiberTracker.H"
#include "periodicImages.H"
#include "PstreamBuffers.H"

#include <unordered_map>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;
typedef fiberInteractions::contact::segment segment;

void writeSegment(Ostream& os, const segment& s)
{
    os  << s.fiber << token::SPACE << s.seg << token::SPACE << s.a
        << token::SPACE << s.b << token::SPACE << s.d << token::SPACE << s.x
        << token::SPACE << s.v << token::SPACE << s.w << token::SPACE << s.m;
}


void readSegment(Istream& is, segment& s)
{
    is >> s.fiber >> s.seg >> s.a >> s.b >> s.d >> s.x >> s.v >> s.w >> s.m;
    s.local = -1;
}


//- The segment moved by T (an image across periodic patches)
segment image(const segment& s, const vectorTensorTransform& T)
{
    segment i(s);
    i.a = T.transformPosition(s.a);
    i.b = T.transformPosition(s.b);
    i.x = T.transformPosition(s.x);
    if (T.hasR())
    {
        i.v = T.R() & s.v;
        i.w = T.R() & s.w;
    }
    i.local = -1;
    return i;
}


//- The bounding box of a segment's axis, grown by r
boundBox segmentBox(const segment& s, const scalar r)
{
    boundBox bb(min(s.a, s.b), max(s.a, s.b));
    bb.min() -= vector::uniform(r);
    bb.max() += vector::uniform(r);
    return bb;
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberInteractions::contact::findPeriodic()
{
    label nBase = 0;
    periodic_ = periodicImages::transforms(mesh_, nBase);
    if (periodic_.size())
    {
        Info<< "    Fiber contacts across " << nBase
            << " periodic transforms (" << periodic_.size()
            << " images with their compositions)" << endl;
    }
}


Foam::scalar Foam::fiberInteractions::contact::reach
(
    const UList<segment>& segs
) const
{
    scalar r = 0;
    for (const segment& s : segs)
    {
        r = max(r, mag(s.b - s.a) + s.d);
    }
    return returnReduce(r, maxOp<scalar>()) + range_;
}


void Foam::fiberInteractions::contact::localSegments
(
    const PtrList<fiber>& fibers,
    const UList<role>& roles,
    DynamicList<segment>& segs
) const
{
    forAll(fibers, fi)
    {
        if (roles[fi] == role::absent)
        {
            continue;
        }
        const fiber& f = fibers[fi];
        const tensor R(f.R());
        for (label i = 0; i < f.nSegments(); ++i)
        {
            const point c(f.position() + f.segmentOffset(R, i));
            const vector half
            (
                (0.5*f.segmentLength(i))*f.segmentDirection(R, i)
            );
            segs.append
            (
                segment
                {
                    f.id(), i, c - half, c + half, f.segmentDiameter(i),
                    f.position(), f.velocity(), f.omega(),
                    roles[fi] == role::fixed ? 0 : f.mass(), fi
                }
            );
        }
    }
}


void Foam::fiberInteractions::contact::addImages
(
    DynamicList<segment>& segs,
    const scalar r
) const
{
    if (periodic_.empty())
    {
        return;
    }
    boundBox domain(mesh_.bounds());
    reduce(domain.min(), minOp<point>());
    reduce(domain.max(), maxOp<point>());
    domain.min() -= vector::uniform(r);
    domain.max() += vector::uniform(r);

    const label n = segs.size();
    for (label i = 0; i < n; ++i)
    {
        for (const vectorTensorTransform& T : periodic_)
        {
            const segment s(image(segs[i], T));
            if (domain.overlaps(segmentBox(s, 0)))
            {
                segs.append(s);
            }
        }
    }
}


void Foam::fiberInteractions::contact::addGhosts
(
    DynamicList<segment>& segs,
    const scalar r
) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    List<boundBox> parts(Pstream::nProcs());
    parts[Pstream::myProcNo()] = mesh_.bounds();
    Pstream::gatherList(parts);
    Pstream::scatterList(parts);

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        DynamicList<label> send;
        forAll(segs, i)
        {
            if (parts[proci].overlaps(segmentBox(segs[i], r)))
            {
                send.append(i);
            }
        }
        UOPstream os(proci, pBufs);
        os << send.size();
        for (const label i : send)
        {
            os << token::SPACE;
            writeSegment(os, segs[i]);
        }
    }
    pBufs.finishedSends();
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (proci == Pstream::myProcNo())
        {
            continue;
        }
        UIPstream is(proci, pBufs);
        const label n = readLabel(is);
        for (label k = 0; k < n; ++k)
        {
            segment s;
            readSegment(is, s);
            segs.append(s);
        }
    }
}


void Foam::fiberInteractions::contact::candidates
(
    const UList<segment>& segs,
    const scalar r,
    DynamicList<FixedList<label, 2>>& cand
) const
{
    if (segs.empty() || !(r > 0))
    {
        return;
    }

    // Cells of size r over the centres' box; a cell by its integer
    // coordinates
    boundBox bb(boundBox::invertedBox);
    List<point> c(segs.size());
    forAll(segs, i)
    {
        c[i] = 0.5*(segs[i].a + segs[i].b);
        bb.add(c[i]);
    }
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
    std::unordered_map<int64_t, std::vector<label>> grid;
    forAll(segs, i)
    {
        grid[key(cell(c[i], 0), cell(c[i], 1), cell(c[i], 2))].push_back(i);
    }

    forAll(segs, q)
    {
        const segment& Q = segs[q];
        if (Q.local < 0)
        {
            continue;
        }
        const int64_t ci = cell(c[q], 0);
        const int64_t cj = cell(c[q], 1);
        const int64_t ck = cell(c[q], 2);
        for (int64_t k = ck - 1; k <= ck + 1; ++k)
        {
            for (int64_t j = cj - 1; j <= cj + 1; ++j)
            {
                for (int64_t i = ci - 1; i <= ci + 1; ++i)
                {
                    const auto it = grid.find(key(i, j, k));
                    if (it == grid.end())
                    {
                        continue;
                    }
                    for (const label p : it->second)
                    {
                        const segment& P = segs[p];
                        const scalar within =
                            0.5*(mag(Q.b - Q.a) + mag(P.b - P.a) + Q.d + P.d)
                          + range_;
                        if
                        (
                            P.fiber != Q.fiber
                         && magSqr(c[p] - c[q]) <= sqr(within)
                        )
                        {
                            cand.append(FixedList<label, 2>{q, p});
                        }
                    }
                }
            }
        }
    }
}


// ************************************************************************* //
