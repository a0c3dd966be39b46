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

#include "matSheet.H"
#include "segmentDistance.H"
#include "counterRandom.H"
#include "mathematicalConstants.H"
#include "Map.H"
#include "scalarField.H"
#include "DynamicList.H"
#include "HashSet.H"
#include <algorithm>
#include <cmath>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

typedef FixedList<scalar, 3> massPoint;
typedef FixedList<scalar, 4> line2D;

//- Mass m spread over points along [a, b] (2-D) at most h apart
void spread
(
    const scalar ua, const scalar va, const scalar ub, const scalar vb,
    const scalar m, const scalar h, DynamicList<massPoint>& pts
)
{
    const scalar len = std::hypot(ub - ua, vb - va);
    const label k = max(label(1), label(std::ceil(len/h)));
    for (label j = 0; j < k; ++j)
    {
        const scalar s = (j + 0.5)/k;
        pts.append(massPoint{ua + s*(ub - ua), va + s*(vb - va), m/k});
    }
}


//- The 2-D lines cross (proper or touching)
bool linesCross(const line2D& a, const line2D& b)
{
    auto orient = [](scalar ax, scalar ay, scalar bx, scalar by,
        scalar cx, scalar cy)
    {
        return (bx - ax)*(cy - ay) - (by - ay)*(cx - ax);
    };
    const scalar d1 = orient(a[0], a[1], a[2], a[3], b[0], b[1]);
    const scalar d2 = orient(a[0], a[1], a[2], a[3], b[2], b[3]);
    const scalar d3 = orient(b[0], b[1], b[2], b[3], a[0], a[1]);
    const scalar d4 = orient(b[0], b[1], b[2], b[3], a[2], a[3]);
    return d1*d2 <= 0 && d3*d4 <= 0;
}


//- Grid cells of side c over a bounding box: the cells an item's box
//  [lo, hi] covers
void cellsOf
(
    const scalar lu, const scalar lv, const scalar hu, const scalar hv,
    const scalar u0, const scalar v0, const scalar c,
    DynamicList<FixedList<label, 2>>& out
)
{
    out.clear();
    const label i0 = label(std::floor((lu - u0)/c));
    const label i1 = label(std::floor((hu - u0)/c));
    const label j0 = label(std::floor((lv - v0)/c));
    const label j1 = label(std::floor((hv - v0)/c));
    for (label i = i0; i <= i1; ++i)
    {
        for (label j = j0; j <= j1; ++j)
        {
            out.append(FixedList<label, 2>{i, j});
        }
    }
}

typedef HashTable<DynamicList<label>, FixedList<label, 2>,
    FixedList<label, 2>::Hash<>> lineGrid;


//- The lines binned by the cells of side c (from the lowest corner of
//  all, u0 v0) their boxes cover
lineGrid binLines
(
    const UList<line2D>& lines,
    const scalar c,
    scalar& u0,
    scalar& v0
)
{
    u0 = GREAT;
    v0 = GREAT;
    for (const line2D& l : lines)
    {
        u0 = min(u0, min(l[0], l[2]));
        v0 = min(v0, min(l[1], l[3]));
    }
    lineGrid grid;
    DynamicList<FixedList<label, 2>> cells;
    forAll(lines, k)
    {
        const line2D& l = lines[k];
        cellsOf
        (
            min(l[0], l[2]), min(l[1], l[3]), max(l[0], l[2]),
            max(l[1], l[3]), u0, v0, c, cells
        );
        for (const FixedList<label, 2>& ck : cells)
        {
            grid(ck).append(k);
        }
    }
    return grid;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::matSheet::matSheet(const frame& fr, const scalarList& records)
:
    fr_(fr),
    segs_(records.size()/recordSize),
    lambda_(),
    mass_(),
    p_(),
    lMean_(0),
    dMean_(0)
{
    Map<label> fiberIndex;
    DynamicList<scalar> lambda;
    DynamicList<scalar> mass;
    DynamicList<vector> p;
    forAll(segs_, k)
    {
        const scalar* r = &records[recordSize*k];
        segment& s = segs_[k];
        s.fiber = label(r[0]);
        s.c = point(r[1], r[2], r[3]);
        s.z = vector(r[4], r[5], r[6]);
        s.l = r[7];
        s.d = r[8];
        s.m = r[9];
        s.p = vector(r[10], r[11], r[12]);
        if (!fiberIndex.found(s.fiber))
        {
            fiberIndex.insert(s.fiber, lambda.size());
            lambda.append(0);
            mass.append(0);
            p.append(s.p);
        }
        const label fi = fiberIndex[s.fiber];
        lambda[fi] += s.l*std::sqrt(1 - min(sqr(s.z & fr_.n), 1.0));
        mass[fi] += s.m;
        dMean_ += s.d;
    }
    lambda_.transfer(lambda);
    mass_.transfer(mass);
    p_.transfer(p);
    lMean_ = lambda_.size() ? sum(lambda_)/lambda_.size() : 0;
    dMean_ = segs_.size() ? dMean_/segs_.size() : 0;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::FixedList<Foam::scalar, 3>> Foam::matSheet::points
(
    const scalar h
) const
{
    DynamicList<massPoint> pts(4*segs_.size());
    for (const segment& s : segs_)
    {
        const vector a(s.c - 0.5*s.l*s.z - fr_.o);
        const vector b(s.c + 0.5*s.l*s.z - fr_.o);
        spread
        (
            a & fr_.e1, a & fr_.e2, b & fr_.e1, b & fr_.e2, s.m, h, pts
        );
    }
    return List<massPoint>(std::move(pts));
}


Foam::List<Foam::FixedList<Foam::scalar, 3>> Foam::matSheet::randomPoints
(
    const scalar h,
    const label seed,
    const label r,
    List<FixedList<scalar, 4>>& lines
) const
{
    const scalar pi = constant::mathematical::pi;
    DynamicList<massPoint> pts(4*segs_.size());
    lines.setSize(lambda_.size());
    forAll(lambda_, fi)
    {
        const scalar u =
            fr_.u0 + (fr_.u1 - fr_.u0)*counterRandom::uniform(seed, r, 3*fi);
        const scalar v =
            fr_.v0
          + (fr_.v1 - fr_.v0)*counterRandom::uniform(seed, r, 3*fi + 1);
        const scalar th = pi*counterRandom::uniform(seed, r, 3*fi + 2);
        const scalar du = 0.5*lambda_[fi]*std::cos(th);
        const scalar dv = 0.5*lambda_[fi]*std::sin(th);
        lines[fi] = line2D{u - du, v - dv, u + du, v + dv};
        spread(u - du, v - dv, u + du, v + dv, mass_[fi], h, pts);
    }
    return List<massPoint>(std::move(pts));
}


Foam::scalarList Foam::matSheet::zoneMass
(
    const List<FixedList<scalar, 3>>& pts,
    const scalar a,
    label& nU,
    label& nV
) const
{
    nU = label(std::floor((fr_.u1 - fr_.u0)/a*(1 + 1e-12)));
    nV = label(std::floor((fr_.v1 - fr_.v0)/a*(1 + 1e-12)));
    scalarList m(max(nU*nV, label(0)), Zero);
    for (const massPoint& q : pts)
    {
        const label i = label(std::floor((q[0] - fr_.u0)/a));
        const label j = label(std::floor((q[1] - fr_.v0)/a));
        if (i >= 0 && i < nU && j >= 0 && j < nV)
        {
            m[i*nV + j] += q[2];
        }
    }
    return m;
}


Foam::scalar Foam::matSheet::cvOf(const scalarList& m)
{
    const label n = m.size();
    if (n < 2)
    {
        return 0;
    }
    const scalar mean = sum(m)/n;
    scalar var = 0;
    for (const scalar x : m)
    {
        var += sqr(x - mean);
    }
    var /= n - 1;
    return mean > 0 ? std::sqrt(var)/mean : 0;
}


Foam::scalar Foam::matSheet::crossings
(
    const List<FixedList<scalar, 4>>& lines,
    const labelUList& fiberOf,
    const label nFibers,
    const scalar cell
)
{
    // Lines binned by the cells their boxes cover; each pair of lines of
    // two fibers tested once (in the cell of the lower corner of the
    // overlap of their boxes), each fiber pair counted once
    if (nFibers == 0 || lines.empty())
    {
        return 0;
    }
    scalar u0, v0;
    const lineGrid grid(binLines(lines, cell, u0, v0));

    // The pairs of fibers crossing, as keys lower * nFibers + higher (a
    // sort, not a hash set: millions of them in a large mat)
    auto cellOf = [&](const scalar u, const scalar v)
    {
        return FixedList<label, 2>
        {
            label(std::floor((u - u0)/cell)), label(std::floor((v - v0)/cell))
        };
    };
    std::vector<int64_t> keys;
    forAllConstIters(grid, it)
    {
        const DynamicList<label>& in = it.val();
        for (label x = 0; x < in.size(); ++x)
        {
            const line2D& la = lines[in[x]];
            for (label y = x + 1; y < in.size(); ++y)
            {
                const line2D& lb = lines[in[y]];
                const label fa = fiberOf[in[x]];
                const label fb = fiberOf[in[y]];
                if
                (
                    fa == fb
                 || cellOf
                    (
                        max(min(la[0], la[2]), min(lb[0], lb[2])),
                        max(min(la[1], la[3]), min(lb[1], lb[3]))
                    ) != it.key()
                 || !linesCross(la, lb)
                )
                {
                    continue;
                }
                keys.push_back(int64_t(min(fa, fb))*nFibers + max(fa, fb));
            }
        }
    }
    labelList nLines(nFibers, 0);
    bool several = false;
    for (const label f : fiberOf)
    {
        several = several || ++nLines[f] > 1;
    }
    if (several)
    {
        // Fibers of several lines may cross more than once
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    }
    return 2.0*keys.size()/nFibers;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::matSheet::totalMass() const
{
    return sum(mass_);
}


Foam::scalarList Foam::matSheet::zoneSizes() const
{
    DynamicList<scalar> a;
    const scalar side = min(fr_.u1 - fr_.u0, fr_.v1 - fr_.v0);
    for (label k = 0; k < 10 && lMean_ > 0; ++k)
    {
        const scalar ak = 0.1*lMean_*std::pow(100.0, k/9.0);
        if (ak > 0.5*side*(1 + 1e-12))
        {
            break;
        }
        a.append(ak);
    }
    return scalarList(std::move(a));
}


Foam::List<Foam::matSheet::zone> Foam::matSheet::formation
(
    const label nRandom,
    const label seed,
    scalar& randomCrossings
) const
{
    const scalarList a(zoneSizes());
    List<zone> z(a.size());
    randomCrossings = 0;
    if (a.empty())
    {
        return z;
    }
    const scalar h = 0.25*a[0];
    const List<massPoint> pts(points(h));
    forAll(a, k)
    {
        label nU, nV;
        const scalarList m(zoneMass(pts, a[k], nU, nV));
        z[k] = zone{a[k], nU*nV, sum(m)/max(m.size(), 1)/sqr(a[k]),
            cvOf(m), 0, 0};
    }

    // The random sheets: each zone size's CV, mean and spread
    scalarList s1(a.size(), Zero);
    scalarList s2(a.size(), Zero);
    labelList fiberOf(identity(lambda_.size()));
    for (label r = 0; r < nRandom; ++r)
    {
        List<line2D> lines;
        const List<massPoint> rp(randomPoints(h, seed, r, lines));
        forAll(a, k)
        {
            label nU, nV;
            const scalar cv = cvOf(zoneMass(rp, a[k], nU, nV));
            s1[k] += cv;
            s2[k] += sqr(cv);
        }
        randomCrossings +=
            crossings(lines, fiberOf, lambda_.size(), max(lMean_, SMALL));
    }
    forAll(a, k)
    {
        const scalar mean = s1[k]/max(nRandom, 1);
        z[k].cvRandom = mean;
        z[k].sdRandom =
            nRandom > 1
          ? std::sqrt(max(s2[k] - nRandom*sqr(mean), 0)/(nRandom - 1))
          : 0;
    }
    randomCrossings /= max(nRandom, 1);
    return z;
}


Foam::List<Foam::FixedList<Foam::scalar, 3>> Foam::matSheet::grammageMap
(
    const scalar a
) const
{
    label nU, nV;
    const scalarList m(zoneMass(points(0.25*a), a, nU, nV));
    List<massPoint> map(m.size());
    for (label i = 0; i < nU; ++i)
    {
        for (label j = 0; j < nV; ++j)
        {
            map[i*nV + j] =
                massPoint
                {
                    fr_.u0 + (i + 0.5)*a, fr_.v0 + (j + 0.5)*a,
                    m[i*nV + j]/sqr(a)
                };
        }
    }
    return map;
}


Foam::labelList Foam::matSheet::angleClasses() const
{
    const scalar pi = constant::mathematical::pi;
    labelList n(nAngles, Zero);
    for (const vector& p : p_)
    {
        const scalar pu = p & fr_.e1;
        const scalar pv = p & fr_.e2;
        if (sqr(pu) + sqr(pv) == 0)
        {
            continue;
        }
        scalar th = std::atan2(pv, pu);
        th = th < 0 ? th + pi : th;
        ++n[min(label(th/pi*nAngles), nAngles - 1)];
    }
    return n;
}


Foam::FixedList<Foam::scalar, 3> Foam::matSheet::orientationTensor() const
{
    FixedList<scalar, 3> t(Zero);
    label n = 0;
    for (const vector& p : p_)
    {
        const scalar pu = p & fr_.e1;
        const scalar pv = p & fr_.e2;
        const scalar q = sqr(pu) + sqr(pv);
        if (q > 0)
        {
            t[0] += sqr(pu)/q;
            t[1] += pu*pv/q;
            t[2] += sqr(pv)/q;
            ++n;
        }
    }
    for (scalar& x : t)
    {
        x /= max(n, 1);
    }
    return t;
}


Foam::scalar Foam::matSheet::outOfPlane() const
{
    scalar s = 0;
    for (const vector& p : p_)
    {
        s += std::asin(min(mag(p & fr_.n)/max(mag(p), VSMALL), 1.0));
    }
    return p_.size() ? s/p_.size() : 0;
}


Foam::scalarList Foam::matSheet::solidFraction
(
    const scalar dz,
    scalar& thickness
) const
{
    const scalar pi = constant::mathematical::pi;
    DynamicList<scalar> phi;
    List<std::pair<scalar, scalar>> hv(segs_.size());
    scalar vTotal = 0;
    forAll(segs_, k)
    {
        const segment& s = segs_[k];
        const scalar h = max((s.c - fr_.o) & fr_.n, scalar(0));
        const scalar v = 0.25*pi*sqr(s.d)*s.l;
        hv[k] = std::make_pair(h, v);
        vTotal += v;
        const label j = label(std::floor(h/dz));
        if (j >= phi.size())
        {
            phi.resize(j + 1, 0);
        }
        phi[j] += v/(area()*dz);
    }
    std::sort(hv.begin(), hv.end());
    thickness = 0;
    scalar cum = 0;
    for (const auto& x : hv)
    {
        cum += x.second;
        if (cum >= 0.95*vTotal)
        {
            thickness = x.first + 0.5*dMean_;
            break;
        }
    }
    return scalarList(std::move(phi));
}


Foam::scalar Foam::matSheet::contactsPerFiber() const
{
    // Segments binned by the cells of side the longest segment plus the
    // largest diameter that their centres lie in; pairs in the same or
    // neighbouring cells tested
    if (segs_.empty())
    {
        return 0;
    }
    scalar c = 0;
    for (const segment& s : segs_)
    {
        c = max(c, s.l + 2*s.d);
    }
    HashTable<DynamicList<label>, FixedList<label, 3>,
        FixedList<label, 3>::Hash<>> grid;
    List<FixedList<label, 3>> at(segs_.size());
    forAll(segs_, k)
    {
        const vector x(segs_[k].c - fr_.o);
        at[k] =
            FixedList<label, 3>
            {
                label(std::floor((x & fr_.e1)/c)),
                label(std::floor((x & fr_.e2)/c)),
                label(std::floor((x & fr_.n)/c))
            };
        grid(at[k]).append(k);
    }
    HashSet<FixedList<label, 2>, FixedList<label, 2>::Hash<>> pairs;
    forAll(segs_, k)
    {
        const segment& A = segs_[k];
        for (label di = -1; di <= 1; ++di)
        for (label dj = -1; dj <= 1; ++dj)
        for (label dk = -1; dk <= 1; ++dk)
        {
            const auto it = grid.cfind
            (
                FixedList<label, 3>{at[k][0] + di, at[k][1] + dj,
                    at[k][2] + dk}
            );
            if (!it.found())
            {
                continue;
            }
            for (const label j : *it)
            {
                const segment& B = segs_[j];
                if (j <= k || B.fiber == A.fiber)
                {
                    continue;
                }
                const segmentDistance::result r =
                    segmentDistance::closest
                    (
                        A.c - 0.5*A.l*A.z, A.c + 0.5*A.l*A.z,
                        B.c - 0.5*B.l*B.z, B.c + 0.5*B.l*B.z
                    );
                const scalar reach = 0.5*(A.d + B.d)*1.01;
                if (r.distSqr <= sqr(reach))
                {
                    pairs.insert
                    (
                        FixedList<label, 2>
                        {
                            min(A.fiber, B.fiber), max(A.fiber, B.fiber)
                        }
                    );
                }
            }
        }
    }
    return nFibers() ? 2.0*pairs.size()/nFibers() : 0;
}


Foam::scalar Foam::matSheet::crossingsPerFiber() const
{
    Map<label> index;
    forAll(segs_, k)
    {
        if (!index.found(segs_[k].fiber))
        {
            index.insert(segs_[k].fiber, index.size());
        }
    }
    List<line2D> lines(segs_.size());
    labelList fiberOf(segs_.size());
    forAll(segs_, k)
    {
        const segment& s = segs_[k];
        const vector a(s.c - 0.5*s.l*s.z - fr_.o);
        const vector b(s.c + 0.5*s.l*s.z - fr_.o);
        lines[k] = line2D{a & fr_.e1, a & fr_.e2, b & fr_.e1, b & fr_.e2};
        fiberOf[k] = index[s.fiber];
    }
    return crossings(lines, fiberOf, nFibers(), max(lMean_, SMALL));
}


Foam::scalar Foam::matSheet::kallmesCorte() const
{
    return
        area() > 0
      ? 2/constant::mathematical::pi*sqr(lMean_)*nFibers()/area()
      : 0;
}


// ************************************************************************* //
