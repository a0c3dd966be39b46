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
    fiberCloud: what the function object reports: orientation statistics,
    states and segments gathered on the master, the counts per set, the
    fibers with the most sub-steps.

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"
#include "fiberVtkWriter.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fiberCloud::statistics Foam::fiberCloud::stats() const
{
    statistics s;
    s.nInjected = counters_.nInjected();
    s.nEscaped = counters_.nEscaped();
    s.nDeposited = counters_.nDeposited();
    s.nActive = 0;
    s.nMat = 0;
    s.nCarried = counters_.nCarried();
    s.absP = Zero;
    s.pp = Zero;

    // The active fibers' orientation (a mat's: its wire's measures)
    forAll(fibers_, fi)
    {
        if (fibers_[fi].inMat())
        {
            ++s.nMat;
            continue;
        }
        ++s.nActive;
        const vector p(fibers_[fi].orientation());
        s.absP += cmptMag(p);
        s.pp += sqr(p);
    }

    s.nMat += mats_.size();
    reduce(s.nActive, sumOp<label>());
    reduce(s.nMat, sumOp<label>());
    s.nMat += s.nCarried;
    reduce(s.absP, sumOp<vector>());
    reduce(s.pp, sumOp<symmTensor>());

    if (s.nActive > 0)
    {
        s.absP /= s.nActive;
        s.pp /= s.nActive;
    }
    return s;
}


Foam::List<Foam::fiberCloud::state> Foam::fiberCloud::gatherStates() const
{
    List<state> local(fibers_.size() + mats_.size());
    label k = 0;
    for (const PtrList<fiber>* fs : {&fibers_, &mats_.fibers()})
    {
        for (const fiber& f : *fs)
        {
            local[k++] = fiberEventLog::stateOf(f);
        }
    }
    return fiberEventLog::gatherSorted(local);
}


Foam::List<Foam::FixedList<Foam::label, 5>>
Foam::fiberCloud::setCounts() const
{
    labelList active(counters_.setNames().size(), 0);
    labelList mat(active.size(), 0);
    for (const fiber& f : fibers_)
    {
        ++(f.inMat() ? mat : active)[f.setIndex()];
    }
    forAll(mats_.perSet(), k)
    {
        mat[k] += mats_.perSet()[k];
    }
    reduce(active, sumOp<labelList>());
    reduce(mat, sumOp<labelList>());
    return counters_.setCounts(active, mat);
}


namespace Foam
{
    //- Merge packed records of costly fibers by id (the one with the most
    //  sub-steps of each) and keep the n with the most, most first
    static scalarList keepCostliest
    (
        const UList<scalar>& recs,
        const label m,
        const label n
    )
    {
        auto nSub = [&](const label r)
        {
            scalar t = 0;
            for (label l = 0; l < subStepStatistics::nLimits; ++l)
            {
                t += recs[m*r + 1 + l];
            }
            return t;
        };
        const label nRec = recs.size()/m;
        DynamicList<label> keep;
        for (label r = 0; r < nRec; ++r)
        {
            bool better = true;
            for (label q = 0; q < nRec; ++q)
            {
                // A record of the same fiber with more sub-steps (or the
                // same and earlier in the list) wins
                if
                (
                    q != r && recs[m*q] == recs[m*r]
                 && (nSub(q) > nSub(r) || (nSub(q) == nSub(r) && q < r))
                )
                {
                    better = false;
                    break;
                }
            }
            if (better)
            {
                keep.append(r);
            }
        }
        std::stable_sort
        (
            keep.begin(),
            keep.end(),
            [&](const label a, const label b) { return nSub(a) > nSub(b); }
        );
        keep.setSize(min(keep.size(), n));
        scalarList out(m*keep.size());
        forAll(keep, k)
        {
            for (label j = 0; j < m; ++j)
            {
                out[m*k + j] = recs[m*keep[k] + j];
            }
        }
        return out;
    }
}


void Foam::fiberCloud::recordCostly()
{
    const label m = costlySize;

    // The nCostly fibers here with the most sub-steps (one pass)
    FixedList<label, nCostly> top(-1);
    FixedList<scalar, nCostly> topN(-1);
    forAll(fibers_, fi)
    {
        scalar n = 0;
        for (const scalar k : fibers_[fi].nSubSteps())
        {
            n += k;
        }
        label at = nCostly;
        while (at > 0 && n > topN[at - 1])
        {
            --at;
        }
        if (at < nCostly)
        {
            for (label k = nCostly - 1; k > at; --k)
            {
                top[k] = top[k - 1];
                topN[k] = topN[k - 1];
            }
            top[at] = fi;
            topN[at] = n;
        }
    }

    // With those kept from before (fibers gone since, or passed on)
    DynamicList<scalar> recs(costly_);
    for (const label fi : top)
    {
        if (fi < 0)
        {
            continue;
        }
        const fiber& f = fibers_[fi];
        recs.append(f.id());
        for (const scalar k : f.nSubSteps())
        {
            recs.append(k);
        }
        for (direction c = 0; c < 3; ++c)
        {
            recs.append(f.position()[c]);
        }
        recs.append(f.location().celli);
        recs.append(tEnd_);
    }
    costly_ = keepCostliest(recs, m, nCostly);
}


Foam::scalarList Foam::fiberCloud::costliest() const
{
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = costly_;
    Pstream::gatherList(all);
    DynamicList<scalar> recs;
    for (const scalarList& r : all)
    {
        recs.append(r);
    }
    return keepCostliest(recs, costlySize, nCostly);
}


Foam::scalarList Foam::fiberCloud::gatherMatSegments() const
{
    DynamicList<scalar> rec;
    for (const fiber& f : mats_.fibers())
    {
        matRecords(f, rec);
    }
    for (const fiber& f : fibers_)
    {
        if (f.inMat())
        {
            matRecords(f, rec);
        }
    }
    return gatherConcatenated(rec);
}


void Foam::fiberCloud::matRecords
(
    const fiber& f,
    DynamicList<scalar>& rec
)
{
    const tensor R(f.R());
    const vector p(f.orientation());
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const vector c(f.position() + f.segmentOffset(R, i));
        const vector z(f.segmentDirection(R, i));
        for
        (
            const scalar x
          : {
                scalar(f.matPatch()), scalar(f.id()), c.x(), c.y(), c.z(),
                z.x(), z.y(), z.z(), f.segmentLength(i),
                f.segmentDiameter(i), f.segmentMass(i), p.x(), p.y(), p.z()
            }
        )
        {
            rec.append(x);
        }
    }
}


Foam::scalarList Foam::fiberCloud::gatherConcatenated
(
    DynamicList<scalar>& rec
)
{
    // Every processor's records on the master, one after the other
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = std::move(rec);
    Pstream::gatherList(all);
    if (!Pstream::master())
    {
        return scalarList();
    }
    label nAll = 0;
    for (const scalarList& r : all)
    {
        nAll += r.size();
    }
    scalarList out(nAll);
    nAll = 0;
    for (const scalarList& r : all)
    {
        SubList<scalar>(out, r.size(), nAll) = r;
        nAll += r.size();
    }
    return out;
}


Foam::scalarList Foam::fiberCloud::gatherSegments() const
{
    const label m = fiberVtkWriter::recordSize;
    DynamicList<scalar> rec;
    for (const PtrList<fiber>* fs : {&fibers_, &mats_.fibers()})
    {
        for (const fiber& f : *fs)
        {
            rec.reserve(rec.size() + m*f.nSegments());
            vtkRecords(f, rec);
        }
    }
    return gatherConcatenated(rec);
}


void Foam::fiberCloud::vtkRecords
(
    const fiber& f,
    DynamicList<scalar>& rec
)
{
    const tensor R(f.R());
    const vector p(f.orientation());
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const vector r(f.segmentOffset(R, i));
        const vector half
        (
            (0.5*f.segmentLength(i))*f.segmentDirection(R, i)
        );
        const vector v(f.segmentVelocity(R, i));
        rec.append(f.id());
        for
        (
            const vector& w
          : {
                vector(f.position() + r - half),
                vector(f.position() + r + half),
                v, f.velocity(), f.segmentOmega(i), p
            }
        )
        {
            for (direction c = 0; c < 3; ++c)
            {
                rec.append(w[c]);
            }
        }
        rec.append(f.segmentDiameter(i));
        rec.append(f.matPatch());
        rec.append(f.inMat() ? f.landTime() : -1);
    }
}

// ************************************************************************* //
