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

#include "segmentDistance.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

inline scalar clamp01(const scalar x)
{
    return x < 0 ? 0 : (x > 1 ? 1 : x);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::segmentDistance::toPoint
(
    const point& p,
    const point& q,
    const point& x
)
{
    const vector d(q - p);
    const scalar dd = d & d;
    if (!(dd > 0))
    {
        return 0;
    }
    return clamp01(((x - p) & d)/dd);
}


Foam::segmentDistance::result Foam::segmentDistance::closest
(
    const point& p1,
    const point& q1,
    const point& p2,
    const point& q2
)
{
    const vector d1(q1 - p1);
    const vector d2(q2 - p2);
    const vector r(p1 - p2);
    const scalar a = d1 & d1;
    const scalar e = d2 & d2;
    const scalar f = d2 & r;

    scalar s = 0, t = 0;
    if (!(a > 0) && !(e > 0))
    {
        // Two points
    }
    else if (!(a > 0))
    {
        t = clamp01(f/e);
    }
    else if (!(e > 0))
    {
        s = clamp01(-(d1 & r)/a);
    }
    else
    {
        const scalar b = d1 & d2;
        const scalar c = d1 & r;
        const scalar denom = a*e - b*b;

        if (denom > 1e-14*a*e)
        {
            s = clamp01((b*f - c*e)/denom);
            t = (b*s + f)/e;
        }
        else
        {
            // Parallel: the middle of the overlap of the projections of
            // segment 2's ends on segment 1, else the nearest ends
            const scalar sA = -c/a;
            const scalar sB = (b - c)/a;
            const scalar lo = max(min(sA, sB), scalar(0));
            const scalar hi = min(max(sA, sB), scalar(1));
            s = lo <= hi ? 0.5*(lo + hi) : (min(sA, sB) > 1 ? 1 : 0);
            t = (b*s + f)/e;
        }

        // The other parameter outside [0, 1]: clamp it, then this one at
        // the clamped value
        if (t < 0)
        {
            t = 0;
            s = clamp01(-c/a);
        }
        else if (t > 1)
        {
            t = 1;
            s = clamp01((b - c)/a);
        }
    }

    const point pa(p1 + s*d1);
    const point pb(p2 + t*d2);
    return result{s, t, pa, pb, magSqr(pa - pb)};
}


// ************************************************************************* //
