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

#include "GosmanIoannides.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"
#include "keywordCheck.H"

#include "counterRandom.H"

#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberDispersions
{
    defineTypeNameAndDebug(GosmanIoannides, 0);
    addToRunTimeSelectionTable(fiberDispersion, GosmanIoannides, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberDispersions::GosmanIoannides::GosmanIoannides
(
    const dictionary& coeffs
)
:
    Cmu_(coeffs.getOrDefault<scalar>("Cmu", 0.09)),
    CmuExponent_(coeffs.getOrDefault<scalar>("CmuExponent", 0.63)),
    seed_(keywordCheck::seed(coeffs)),
    CmuN_(0)
{
    keywordCheck::warnUnknown
    (
        coeffs,
        wordList({"Cmu", "CmuExponent", "seed"}),
        "GosmanIoannidesCoeffs"
    );
    if (!(Cmu_ > 0))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'Cmu' must be positive, not " << Cmu_
            << exit(FatalIOError);
    }
    CmuN_ = std::pow(Cmu_, CmuExponent_);

    Info<< "    Gosman-Ioannides: l_e = " << CmuN_ << " k^1.5/epsilon"
        << " (Cmu " << Cmu_ << "^" << CmuExponent_ << "), seed " << seed_
        << endl;
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fiberDispersions::GosmanIoannides::eddyLifetime
(
    const scalar le,
    const scalar magUprime
)
{
    return magUprime > 0 ? le/magUprime : GREAT;
}


Foam::scalar Foam::fiberDispersions::GosmanIoannides::transitTime
(
    const scalar le,
    const scalar tau,
    const scalar magSlip
)
{
    if (le < tau*magSlip)
    {
        return -tau*std::log1p(-le/(tau*magSlip));
    }
    return GREAT;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::fiberDispersions::GosmanIoannides::eddyLength
(
    const scalar k,
    const scalar epsilon
) const
{
    if (k > 0 && epsilon > 0)
    {
        return CmuN_*std::pow(k, 1.5)/epsilon;
    }
    return 0;
}


Foam::scalar Foam::fiberDispersions::GosmanIoannides::correct
(
    fiber& f,
    UList<fluidSample>& s
) const
{
    const tensor R(f.R());
    const bool newEddy = (f.eddyTime() <= 0);

    if (newEddy)
    {
        f.psi() = counterRandom::gaussian(seed_, f.id(), f.nDraws());
        ++f.nDraws();
        f.jumped() = true;
    }

    scalar tInteraction = GREAT;
    forAll(s, i)
    {
        const vector uPrime(f.psi()*std::sqrt(2*s[i].k/3));
        s[i].U += uPrime;

        if (newEddy)
        {
            const scalar le = eddyLength(s[i].k, s[i].epsilon);
            if (le <= 0)
            {
                continue;
            }
            // tau_i = m_i/(3 pi eta l Y^A) = m_i/(eta 6 pi a Y^A)
            const scalar tau = f.segmentMass(i)/(s[i].mu*f.kAp(i));
            const vector vSeg(f.segmentVelocity(R, i));
            tInteraction = min
            (
                tInteraction,
                min
                (
                    eddyLifetime(le, mag(uPrime)),
                    transitTime(le, tau, mag(s[i].U - vSeg))
                )
            );
        }
    }

    if (newEddy)
    {
        // No turbulence at any segment: draw again at the next sub-step
        f.eddyTime() = (tInteraction < GREAT ? tInteraction : 0);
    }

    return f.eddyTime() > 0 ? f.eddyTime() : GREAT;
}


// ************************************************************************* //
