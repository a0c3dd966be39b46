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

#include "subStepStatistics.H"
#include "openfoamCompat.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "Ostream.H"
#include <cmath>
#include <string>

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::string Foam::subStepStatistics::name
(
    const label l,
    const string& ruleName
)
{
    switch (l)
    {
        case rule: return ruleName;
        case cell: return "cell limit";
        case eddy: return "eddy end (Eq. 23)";
        case release: return "release";
        case stepEnd: return "step end";
    }
    return "unknown";
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::subStepStatistics::subStepStatistics()
:
    n_(Zero),
    histogram_((maxDecade - minDecade)*binsPerDecade, Zero),
    hMin_(GREAT),
    hMinLimit_(stepEnd),
    nRebounds_(0),
    nOwn_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::subStepStatistics::add
(
    const label l,
    const scalar h,
    const scalar own
)
{
    n_[l] += 1;
    nOwn_ += own;
    const scalar x =
        h > 0 ? (std::log10(h) - minDecade)*binsPerDecade : scalar(-1);
    const label bin =
        min(max(label(std::floor(x)), label(0)), histogram_.size() - 1);
    histogram_[bin] += 1;
    if (h < hMin_)
    {
        hMin_ = h;
        hMinLimit_ = l;
    }
}


void Foam::subStepStatistics::operator+=(const subStepStatistics& s)
{
    forAll(n_, l)
    {
        n_[l] += s.n_[l];
    }
    forAll(histogram_, b)
    {
        histogram_[b] += s.histogram_[b];
    }
    if (s.n() > 0 && s.hMin_ < hMin_)
    {
        hMin_ = s.hMin_;
        hMinLimit_ = s.hMinLimit_;
    }
    nRebounds_ += s.nRebounds_;
    nOwn_ += s.nOwn_;
}


void Foam::subStepStatistics::reduce()
{
    if (!Pstream::parRun())
    {
        return;
    }
    scalarList n(nLimits);
    forAll(n_, l)
    {
        n[l] = n_[l];
    }
    fiberCompat::listCombineReduce(n, plusEqOp<scalar>());
    forAll(n_, l)
    {
        n_[l] = n[l];
    }
    fiberCompat::listCombineReduce(histogram_, plusEqOp<scalar>());
    Foam::reduce(nRebounds_, sumOp<scalar>());
    Foam::reduce(nOwn_, sumOp<scalar>());

    // The smallest with its limit: the processor with the smallest says
    const scalar hMin = returnReduce(hMin_, minOp<scalar>());
    label l = (hMin_ == hMin ? hMinLimit_ : label(nLimits));
    Foam::reduce(l, minOp<label>());
    hMin_ = hMin;
    hMinLimit_ = (l < nLimits ? l : label(stepEnd));
}


void Foam::subStepStatistics::clear()
{
    *this = subStepStatistics();
}


Foam::scalar Foam::subStepStatistics::n() const
{
    scalar s = 0;
    for (const scalar n : n_)
    {
        s += n;
    }
    return s;
}


Foam::scalar Foam::subStepStatistics::quantile(const scalar q) const
{
    const scalar total = n();
    if (!(total > 0))
    {
        return 0;
    }
    scalar below = 0;
    forAll(histogram_, b)
    {
        below += histogram_[b];
        if (below >= q*total)
        {
            return
                std::pow(10, minDecade + (b + 0.5)/scalar(binsPerDecade));
        }
    }
    return std::pow(10, scalar(maxDecade));
}


void Foam::subStepStatistics::report
(
    Ostream& os,
    const string& ruleName
) const
{
    const scalar total = n();
    // Counts as whole numbers, every digit (beyond the stream's precision)
    auto count = [](const scalar n)
    {
        return std::to_string(std::llround(n));
    };
    os  << count(total).c_str() << " sub-steps, bound by";
    for (label l = 0; l < nLimits; ++l)
    {
        os  << (l ? ", " : " ") << name(l, ruleName).c_str() << ' '
            << count(n_[l]).c_str() << " ("
            << (total > 0 ? 0.1*std::round(1000*n_[l]/total) : 0) << " %)";
    }
    os  << "; median " << median() << " s, smallest " << hMin()
        << " s (" << name(hMinLimit_, ruleName).c_str() << "); rebounds "
        << count(nRebounds_).c_str()
        << "; without breaks the own limits would take "
        << count(nOwn_).c_str();
}


// ************************************************************************* //
