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
    minEddyRatio_(coeffs.getOrDefault<scalar>("minEddyRatio", 0.1)),
    seed_(keywordCheck::seed(coeffs)),
    CmuN_(0),
    driftTable_()
{
    keywordCheck::warnUnknown
    (
        coeffs,
        wordList({"Cmu", "CmuExponent", "minEddyRatio", "seed"}),
        "GosmanIoannidesCoeffs"
    );
    if (!(Cmu_ > 0))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'Cmu' must be positive, not " << Cmu_
            << exit(FatalIOError);
    }
    if (minEddyRatio_ < 0)
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry 'minEddyRatio' must be >= 0 (0: every eddy as it"
            << " is drawn), not " << minEddyRatio_ << exit(FatalIOError);
    }
    CmuN_ = std::pow(Cmu_, CmuExponent_);

    Info<< "    Gosman-Ioannides: l_e = " << CmuN_ << " k^1.5/epsilon"
        << " (Cmu " << Cmu_ << "^" << CmuExponent_ << "), eddies shorter"
        << " than " << minEddyRatio_ << " relaxation times merged, seed "
        << seed_ << endl;
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


Foam::scalar Foam::fiberDispersions::GosmanIoannides::driftRatio
(
    const scalar w,
    const scalar eps
)
{
    // In units of sigma and t_L = l_e/sigma: psi = r (cosine c to w), an
    // eddy lasts T = min(1/r, tr(c)), tr the transit (Eq. 20) at the
    // speed |psi + w| with tau = t_L/eps; tr falls with c, so T is the
    // lifetime below one c and the transit above (found by bisection)
    auto transit = [w, eps](const scalar r, const scalar c)
    {
        const scalar slip = std::sqrt(max(r*r + 2*r*c*w + w*w, 0));
        if (eps <= 0)
        {
            return slip > 0 ? 1/slip : GREAT;
        }
        return eps < slip ? -std::log1p(-eps/slip)/eps : GREAT;
    };
    const label nr = 150, nc = 32;
    const scalar rMax = 9;
    scalar A = 0, B = 0;
    for (label i = 0; i < nr; ++i)
    {
        const scalar r = (i + 0.5)*rMax/nr;
        const scalar pr =
            std::sqrt(2/constant::mathematical::pi)*r*r*std::exp(-r*r/2)
           *rMax/nr/2;
        scalar cLo = -1, cHi = 1;
        if (transit(r, 1) >= 1/r)
        {
            cLo = 1;
        }
        else if (transit(r, -1) <= 1/r)
        {
            cHi = -1;
        }
        for (label k = 0; k < 40 && cLo < cHi; ++k)
        {
            const scalar c = (cLo + cHi)/2;
            (transit(r, c) < 1/r ? cHi : cLo) = c;
        }
        const scalar cKink = (cLo + cHi)/2;
        for (label piece = 0; piece < 2; ++piece)
        {
            const scalar a = piece ? cKink : -1;
            const scalar b = piece ? 1 : cKink;
            for (label j = 0; j < nc && b > a; ++j)
            {
                const scalar c = a + (j + 0.5)*(b - a)/nc;
                const scalar T = min(1/r, transit(r, c));
                A += pr*(b - a)/nc*r*c*T;
                B += pr*(b - a)/nc*T;
            }
        }
    }
    return A/B;
}


Foam::scalar Foam::fiberDispersions::GosmanIoannides::drift
(
    const scalar w,
    const scalar eps
) const
{
    // Bilinear in the table on [0, wTable_] x [0, epsMax]; beyond
    // wTable_ |psi + w| > |psi| almost surely and the ratio is -1/w
    if (w >= wTable_)
    {
        return -1/w;
    }
    // eps = t_L/tau of a merged eddy is below wTable_ minEddyRatio (t_L
    // below w times the eddy's time, which is below minEddyRatio tau)
    const scalar epsMax = wTable_*minEddyRatio_;
    if (driftTable_.empty())
    {
        // Built at the first merged eddy (about 0.3 s); eps on a grid
        // refined towards 0, where the ratio changes fastest
        driftTable_.setSize(21, scalarList(101));
        forAll(driftTable_, j)
        {
            const scalar eps =
                epsMax*sqr(scalar(j)/(driftTable_.size() - 1));
            scalarList& t = driftTable_[j];
            forAll(t, i)
            {
                t[i] = driftRatio(i*wTable_/(t.size() - 1), eps);
            }
        }
    }
    const label nw = driftTable_[0].size() - 1;
    const label ne = driftTable_.size() - 1;
    const scalar x = w/wTable_*nw;
    const scalar y = std::sqrt(min(max(eps/epsMax, 0), 1))*ne;
    const label i = min(label(x), nw - 1);
    const label j = min(label(y), ne - 1);
    const scalarList& t0 = driftTable_[j];
    const scalar a = t0[i] + (x - i)*(t0[i + 1] - t0[i]);
    const scalarList& t1 = driftTable_[j + 1];
    const scalar b = t1[i] + (x - i)*(t1[i + 1] - t1[i]);
    return a + (y - j)*(b - a);
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


Foam::scalar Foam::fiberDispersions::GosmanIoannides::merge
(
    const fiber& f,
    const UList<fluidSample>& s,
    const tensor& R,
    vector& mu
) const
{
    mu = Zero;
    if (!(minEddyRatio_ > 0))
    {
        return 1;
    }
    // From what is known before the draw, over the segments with
    // turbulence: the shortest relaxation time (Eq. 20), the eddy length
    // and sigma, the mean slip W
    scalar tau = GREAT, le = GREAT, sigma = 0;
    vector W(Zero);
    label n = 0;
    forAll(s, i)
    {
        const scalar lei = eddyLength(s[i].k, s[i].epsilon);
        if (lei > 0)
        {
            tau = min(tau, f.segmentMass(i)/(s[i].mu*f.kAp(i)));
            le = min(le, lei);
            sigma += std::sqrt(2*s[i].k/3);
            W += s[i].U - f.segmentVelocity(R, i);
            ++n;
        }
    }
    if (n == 0)
    {
        return 1;
    }
    sigma /= n;
    W /= n;
    // The eddies' time scale: their lifetime l_e/sigma, or the time the
    // fiber takes to cross one, l_e/|W|, if shorter
    const scalar tEddy = le/max(sigma, mag(W));
    if (!(tEddy < minEddyRatio_*tau))
    {
        return 1;
    }
    const scalar w = mag(W)/sigma;
    if (w > 0)
    {
        mu = drift(w, le/sigma/tau)*W/mag(W);
    }
    return minEddyRatio_*tau/tEddy;
}


Foam::scalar Foam::fiberDispersions::GosmanIoannides::correct
(
    fiber& f,
    UList<fluidSample>& s
) const
{
    const tensor R(f.R());

    if (f.eddyTime() <= 0)
    {
        // A new eddy: its interaction time (Eq. 19-20, 23) from the
        // fluctuation it brings to every segment
        const vector psi(counterRandom::gaussian(seed_, f.id(), f.nDraws()));
        ++f.nDraws();
        f.jumped() = true;

        scalar tInteraction = GREAT;
        forAll(s, i)
        {
            const scalar le = eddyLength(s[i].k, s[i].epsilon);
            if (le <= 0)
            {
                continue;
            }
            const vector uPrime(psi*std::sqrt(2*s[i].k/3));
            // tau_i = m_i/(3 pi eta l Y^A) = m_i/(eta 6 pi a Y^A)
            const scalar tau = f.segmentMass(i)/(s[i].mu*f.kAp(i));
            const vector vSeg(f.segmentVelocity(R, i));
            tInteraction = min
            (
                tInteraction,
                min
                (
                    eddyLifetime(le, mag(uPrime)),
                    transitTime(le, tau, mag(s[i].U + uPrime - vSeg))
                )
            );
        }

        if (tInteraction < GREAT)
        {
            // Eddies far shorter than the fiber can respond to: this one
            // stands for n in a row, lasting n times as long, with the
            // mean fluctuation of such a run and its own deviation from
            // that mean over sqrt(n) (same mean and variance per time)
            vector mu;
            const scalar n = merge(f, s, R, mu);
            f.psi() = n > 1 ? mu + (psi - mu)/std::sqrt(n) : psi;
            f.eddyTime() = n*tInteraction;
        }
        else
        {
            // No turbulence at any segment: draw again at the next
            // sub-step
            f.psi() = psi;
            f.eddyTime() = 0;
        }
    }

    forAll(s, i)
    {
        s[i].U += f.psi()*std::sqrt(2*s[i].k/3);
    }

    return f.eddyTime() > 0 ? f.eddyTime() : GREAT;
}


// ************************************************************************* //
