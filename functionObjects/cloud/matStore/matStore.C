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

#include "matStore.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::matStore::matStore()
:
    fibers_(),
    side_(0),
    all_(),
    maxHalf_(Zero),
    grid_(),
    perSet_(),
    byId_(),
    mark_(),
    query_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::matStore::cube Foam::matStore::cubeOf(const point& p) const
{
    return
        cube
        {{
            long(std::floor(p.x()/side_)), long(std::floor(p.y()/side_)),
            long(std::floor(p.z()/side_))
        }};
}


void Foam::matStore::insert(const entry& en)
{
    grid_[cubeOf(en.box.centre())].push_back(en);
}


void Foam::matStore::regrid(const scalar s)
{
    std::vector<entry> all;
    for (const auto& cubeEntries : grid_)
    {
        const std::vector<entry>& es = cubeEntries.second;
        all.insert(all.end(), es.begin(), es.end());
    }
    side_ = s;
    grid_.clear();
    for (const entry& en : all)
    {
        insert(en);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::boundBox> Foam::matStore::segmentBoxes(const fiber& f)
{
    const tensor R(f.R());
    List<boundBox> bb(f.nSegments());
    forAll(bb, i)
    {
        const point c(f.position() + f.segmentOffset(R, i));
        const vector half(0.5*f.segmentLength(i)*f.segmentDirection(R, i));
        const vector r(vector::uniform(0.5*f.segmentDiameter(i)));
        bb[i] =
            boundBox(min(c - half, c + half) - r, max(c - half, c + half) + r);
    }
    return bb;
}


void Foam::matStore::add(PtrList<fiber>& fs)
{
    // One resize of the list for all of them
    label i = fibers_.size();
    fibers_.resize(i + fs.size());
    forAll(fs, j)
    {
        fibers_.set(i, fs.set(j, nullptr).ptr());
        mark_.append(0);
        const label k = fibers_[i].setIndex();
        if (k >= perSet_.size())
        {
            perSet_.setSize(k + 1, 0);
        }
        ++perSet_[k];
        byId_[fibers_[i].id()] = i;

        // Cubes about as large as the largest box (a query visits the
        // cubes of its box widened by the largest half-span): regridded
        // when a larger box comes, by a quarter more (few regrids)
        for (const boundBox& b : segmentBoxes(fibers_[i]))
        {
            all_.add(b);
            maxHalf_ = max(maxHalf_, 0.5*b.span());
            const scalar extent = cmptMax(b.span());
            if (extent > side_)
            {
                regrid(1.25*extent);
            }
            insert(entry{b, i});
        }
        ++i;
    }
}


Foam::labelList Foam::matStore::near(const UList<boundBox>& boxes) const
{
    DynamicList<label> found;
    if (fibers_.empty())
    {
        return labelList();
    }
    ++query_;
    for (const boundBox& q : boxes)
    {
        if (!q.overlaps(all_))
        {
            continue;
        }
        const cube lo(cubeOf(max(q.min() - maxHalf_, all_.min())));
        const cube hi(cubeOf(min(q.max() + maxHalf_, all_.max())));
        for (long x = lo[0]; x <= hi[0]; ++x)
        {
            for (long y = lo[1]; y <= hi[1]; ++y)
            {
                for (long z = lo[2]; z <= hi[2]; ++z)
                {
                    const auto it = grid_.find(cube{{x, y, z}});
                    if (it == grid_.end())
                    {
                        continue;
                    }
                    for (const entry& en : it->second)
                    {
                        const label i = en.fiber;
                        if (mark_[i] != query_ && en.box.overlaps(q))
                        {
                            mark_[i] = query_;
                            found.append(i);
                        }
                    }
                }
            }
        }
    }
    std::sort(found.begin(), found.end());
    return labelList(std::move(found));
}


// ************************************************************************* //
