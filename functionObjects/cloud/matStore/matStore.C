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
    box_(),
    side_(0),
    all_(),
    grid_(),
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


void Foam::matStore::insert(const label i)
{
    grid_[cubeOf(box_[i].centre())].push_back(i);
}


void Foam::matStore::regrid(const scalar s)
{
    side_ = s;
    grid_.clear();
    forAll(box_, i)
    {
        insert(i);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::matStore::boxOf(const fiber& f)
{
    const tensor R(f.R());
    boundBox bb;
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const point c(f.position() + f.segmentOffset(R, i));
        const vector half(0.5*f.segmentLength(i)*f.segmentDirection(R, i));
        const vector r(vector::uniform(0.5*f.segmentDiameter(i)));
        bb.add(min(c - half, c + half) - r);
        bb.add(max(c - half, c + half) + r);
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
        box_.append(boxOf(fibers_[i]));
        all_.add(box_[i]);
        mark_.append(0);
        const scalar extent = cmptMax(box_[i].span());
        if (extent > side_)
        {
            // Cubes at least as large as every box: a box then reaches at
            // most half a cube beyond its centre's cube
            regrid(2*extent);
        }
        else
        {
            insert(i);
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
    const vector half(vector::uniform(0.5*side_));
    for (const boundBox& q : boxes)
    {
        if (!q.overlaps(all_))
        {
            continue;
        }
        const cube lo(cubeOf(max(q.min() - half, all_.min())));
        const cube hi(cubeOf(min(q.max() + half, all_.max())));
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
                    for (const label i : it->second)
                    {
                        if (mark_[i] != query_ && box_[i].overlaps(q))
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
