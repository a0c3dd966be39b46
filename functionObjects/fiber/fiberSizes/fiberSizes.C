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

#include "fiberSizes.H"
#include "Pair.H"
#include "counterRandom.H"
#include "keywordCheck.H"
#include "spheroidResistance.H"
#include "mathematicalConstants.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::FixedList<Foam::word, 3> Foam::fiberSizes::keys
({
    "nSegments", "segmentLength", "diameter"
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiberSizes::readEntry(const dictionary& dict, const label i)
{
    const word& key = keys[i];
    const dictionary* dPtr = dict.findDict(key);
    if (!dPtr)
    {
        value_[i] =
            i == 0
          ? scalar(dict.get<label>(key))
          : keywordCheck::positive(dict, key);
        return;
    }

    // A distribution: its range checked here, where the entry can be
    // named (the model's own checks abort without naming it)
    const dictionary& d = *dPtr;
    const word type(d.get<word>("type"));
    const dictionary coeffs(d.subOrEmptyDict(type & "Distribution"));
    if (coeffs.found("minValue") && coeffs.found("maxValue"))
    {
        const scalar lo = coeffs.get<scalar>("minValue");
        const scalar hi = coeffs.get<scalar>("maxValue");
        if (!(lo > 0) || !(hi >= lo))
        {
            FatalIOErrorInFunction(d)
                << "Entry '" << key << "': the " << type << " distribution"
                << " needs 0 < minValue <= maxValue, not minValue " << lo
                << ", maxValue " << hi << exit(FatalIOError);
        }
    }
    // Shape parameters that must be positive (the models take any value:
    // a negative variance gave a normal that is not one)
    static const List<Pair<word>> positive
    ({
        {"normal", "variance"},
        {"RosinRammler", "d"}, {"RosinRammler", "n"},
        {"massRosinRammler", "d"}, {"massRosinRammler", "n"},
        {"exponential", "lambda"}
    });
    for (const Pair<word>& p : positive)
    {
        if (p.first() == type && coeffs.found(p.second()))
        {
            const scalar v = coeffs.get<scalar>(p.second());
            if (!(v > 0))
            {
                FatalIOErrorInFunction(d)
                    << "Entry '" << key << "': the " << type
                    << " distribution needs a positive '" << p.second()
                    << "', not " << v << exit(FatalIOError);
            }
        }
    }
    dist_[i] = distributionModel::New(d, rnd_);
}


Foam::scalar Foam::fiberSizes::minValue(const label i) const
{
    return dist_[i].valid() ? dist_[i]->minValue() : value_[i];
}


Foam::scalar Foam::fiberSizes::maxValue(const label i) const
{
    return dist_[i].valid() ? dist_[i]->maxValue() : value_[i];
}


void Foam::fiberSizes::check(const dictionary& dict) const
{
    for (label i = 1; i < 3; ++i)
    {
        if (dist_[i].valid() && !(minValue(i) > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << keys[i] << "': its distribution can give "
                << minValue(i) << "; every value must be positive"
                << exit(FatalIOError);
        }
    }

    if (dist_[0].valid())
    {
        const label nMin = std::lround(minValue(0));
        if (nMin < 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'nSegments': its distribution can give "
                << minValue(0) << ", rounded to " << nMin
                << " segments; the rounded values must be at least 1"
                << exit(FatalIOError);
        }
    }

    if (!distributed())
    {
        checkSize(dict, size{label(value_[0]), value_[1], value_[2]});
        return;
    }

    // The smallest aspect ratio any fiber can have
    const scalar rc = minValue(1)/maxValue(2);
    if (rc < spheroidResistance::rcMin)
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'segmentLength' and 'diameter' can give a segment of"
            << " aspect ratio" << nl << "    min(segmentLength)/"
            << "max(diameter) = " << minValue(1) << "/" << maxValue(2)
            << " = " << rc << ", below " << spheroidResistance::rcMin
            << " (Cox's Eq. 8 is meaningless there)." << nl
            << "    Narrow the distributions so that every segment has"
            << " segmentLength >= " << spheroidResistance::rcMin
            << "*diameter" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberSizes::fiberSizes(const dictionary& dict)
:
    rnd_(1),
    value_(Zero),
    dist_(),
    rho_(keywordCheck::positive(dict, "density"))
{
    for (label i = 0; i < 3; ++i)
    {
        readEntry(dict, i);
    }
    check(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fiberSizes::distributed() const
{
    return dist_[0].valid() || dist_[1].valid() || dist_[2].valid();
}


Foam::fiberSizes::size Foam::fiberSizes::draw
(
    const label seed,
    const label stream
) const
{
    FixedList<scalar, 3> x(value_);
    for (label i = 0; i < 3; ++i)
    {
        if (dist_[i].valid())
        {
            rnd_.reset(counterRandom::seed31(seed, stream, 100 + i));
            x[i] = dist_[i]->sample();
        }
    }
    return size{label(std::lround(x[0])), x[1], x[2]};
}


Foam::scalar Foam::fiberSizes::maxFiberLength() const
{
    return std::lround(maxValue(0))*maxValue(1);
}


Foam::scalar Foam::fiberSizes::lightestMass(const bool segment) const
{
    const label n =
        segment ? 1 : max(label(1), label(std::lround(minValue(0))));
    return
        rho_*constant::mathematical::pi/4*sqr(minValue(2))*minValue(1)*n;
}


void Foam::fiberSizes::checkSize(const dictionary& dict, const size& s)
{
    if (s.n < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nSegments' must be at least 1, not " << s.n
            << exit(FatalIOError);
    }

    const scalar rc = s.l/s.d;
    if (rc < spheroidResistance::rcMin)
    {
        FatalIOErrorInFunction(dict)
            << "Segment aspect ratio segmentLength/diameter = " << rc
            << " is below " << spheroidResistance::rcMin << "." << nl
            << "    Cox's equivalent aspect ratio (Eq. 8) is a slender-body"
            << " fit: it exceeds l/d below 4.65 and" << nl
            << "    is not monotonic below 1.65, so the segment drag would"
            << " be meaningless." << nl
            << "    Use fewer, longer segments (reduce 'nSegments' and raise"
            << " 'segmentLength') so that" << nl
            << "    segmentLength >= " << spheroidResistance::rcMin
            << "*diameter = " << spheroidResistance::rcMin*s.d
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
