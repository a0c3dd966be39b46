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

#include "fiberEventLog.H"
#include "Pstream.H"
#include "ListOps.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberEventLog::fiberEventLog()
:
    logEvents_(false),
    logInitial_(false),
    events_(),
    deposits_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fiberEventLog::state Foam::fiberEventLog::stateOf(const fiber& f)
{
    return state
    {
        f.id(), f.position(), f.orientation(), f.velocity(), f.omega(),
        f.chordRatio()
    };
}


Foam::List<Foam::fiberEventLog::state> Foam::fiberEventLog::gatherSorted
(
    const UList<state>& local
)
{
    // Per processor: ids and five vectors (x, p, v, omega, (chord 0 0))
    // per fiber
    List<labelList> ids(Pstream::nProcs());
    List<vectorList> vals(Pstream::nProcs());
    labelList& myIds = ids[Pstream::myProcNo()];
    vectorList& myVals = vals[Pstream::myProcNo()];
    myIds.setSize(local.size());
    myVals.setSize(5*local.size());
    forAll(local, i)
    {
        myIds[i] = local[i].id;
        myVals[5*i] = local[i].x;
        myVals[5*i + 1] = local[i].p;
        myVals[5*i + 2] = local[i].v;
        myVals[5*i + 3] = local[i].omega;
        myVals[5*i + 4] = vector(local[i].chord, 0, 0);
    }

    Pstream::gatherList(ids);
    Pstream::gatherList(vals);

    List<state> result;
    if (Pstream::master())
    {
        DynamicList<state> all;
        DynamicList<label> allIds;
        forAll(ids, proci)
        {
            const vectorList& v = vals[proci];
            forAll(ids[proci], k)
            {
                all.append
                (
                    state
                    {
                        ids[proci][k], v[5*k], v[5*k+1], v[5*k+2], v[5*k+3],
                        v[5*k+4].x()
                    }
                );
                allIds.append(ids[proci][k]);
            }
        }
        const labelList order(sortedOrder(allIds));
        result.setSize(order.size());
        forAll(order, k)
        {
            result[k] = all[order[k]];
        }
    }
    return result;
}


void Foam::fiberEventLog::record
(
    const fiber& f,
    const scalar t,
    const eventKind kind,
    const label patchi
)
{
    if (!logEvents_)
    {
        return;
    }
    const vector p(f.orientation());
    for
    (
        const scalar v
      : {
            t, scalar(f.id()), scalar(f.setIndex()), scalar(kind),
            scalar(patchi), scalar(f.nSegments()), f.length(),
            f.segmentDiameter(0), f.position().x(), f.position().y(),
            f.position().z(), p.x(), p.y(), p.z()
        }
    )
    {
        events_.append(v);
    }
}


Foam::scalarList Foam::fiberEventLog::gatherEvents()
{
    List<scalarList> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = events_;
    events_.clear();
    Pstream::gatherList(all);
    if (!Pstream::master())
    {
        return scalarList();
    }

    // By time, then id
    DynamicList<scalar> flat;
    for (const scalarList& r : all)
    {
        flat.append(r);
    }
    const label m = eventSize;
    const label n = flat.size()/m;
    labelList order(identity(n));
    std::sort
    (
        order.begin(),
        order.end(),
        [&flat, m](const label a, const label b)
        {
            if (flat[m*a] != flat[m*b]) return flat[m*a] < flat[m*b];
            return flat[m*a + 1] < flat[m*b + 1];
        }
    );
    scalarList out(flat.size());
    forAll(order, k)
    {
        for (label i = 0; i < m; ++i)
        {
            out[m*k + i] = flat[m*order[k] + i];
        }
    }
    return out;
}


Foam::List<Foam::fiberEventLog::state> Foam::fiberEventLog::gatherDeposits()
{
    List<state> all(gatherSorted(deposits_));
    deposits_.clear();
    return all;
}


// ************************************************************************* //
