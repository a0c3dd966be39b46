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

#include "subStepControl.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::subStepControl::mode>
Foam::subStepControl::modeNames
({
    { mode::paper, "paper" },
    { mode::tolerance, "tolerance" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::subStepControl::subStepControl(const dictionary& dict)
:
    mode_(mode::tolerance),
    shearStepFactor_(keywordCheck::positive(dict, "shearStepFactor", 0.1)),
    tolerance_(keywordCheck::positive(dict, "tolerance", 0.1)),
    maxRotation_(keywordCheck::positive(dict, "maxRotation", 0.1)),
    maxCo_(keywordCheck::positive(dict, "maxCo", 1))
{
    // Limits so fine that no run could finish: refused before the first
    // step (each asks for 1e4 times the sub-steps of the value the paper
    // or the default uses, or more)
    struct lowest { const char* key; scalar value; scalar min;
        const char* per; };
    const lowest limits[] =
    {
        {"shearStepFactor", shearStepFactor_, 1e-5,
            "per shear time of a fiber (the paper: 0.1)"},
        {"tolerance", tolerance_, 1e-5,
            "per unit of path or turn error (the default: 0.1)"},
        {"maxRotation", maxRotation_, 1e-5,
            "per radian the fluid's strain turns a fiber (the default: 0.1)"},
        {"maxCo", maxCo_, 1e-4, "per cell a fiber crosses (the default: 1)"}
    };
    for (const lowest& l : limits)
    {
        if (l.value < l.min && dict.found(l.key))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << l.key << "' " << l.value << " asks for "
                << 1/l.value << " sub-steps or more " << l.per
                << "; the smallest accepted is " << l.min
                << exit(FatalIOError);
        }
    }

    const word m(dict.getOrDefault<word>("subStepControl", "tolerance"));
    if (!modeNames.found(m))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'subStepControl': unknown control '" << m
            << "'; valid controls: " << modeNames.sortedToc()
            << exit(FatalIOError);
    }
    mode_ = modeNames[m];

    // An entry of the other control is a mistake worth one message
    const wordList unused
    (
        mode_ == mode::paper
      ? wordList({"tolerance", "maxRotation"})
      : wordList({"shearStepFactor"})
    );
    for (const word& key : unused)
    {
        if (dict.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << key << "' has no effect with subStepControl "
                << m << "; remove it or set subStepControl "
                << (mode_ == mode::paper ? "tolerance" : "paper")
                << exit(FatalIOError);
        }
    }

}


Foam::subStepControl::subStepControl
(
    const mode m,
    const scalar shearStepFactor,
    const scalar tolerance,
    const scalar maxRotation,
    const scalar maxCo
)
:
    mode_(m),
    shearStepFactor_(shearStepFactor),
    tolerance_(tolerance),
    maxRotation_(maxRotation),
    maxCo_(maxCo)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::subStepControl::tipSpeed
(
    const fiber& f,
    const tensor& R,
    const vector& w
)
{
    // In the body frame: |w x (R x0)| = |(R^T w) x x0|
    const vector wb(w & R);
    scalar u2 = 0;
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const vector& r = f.bodyOffset(i);
        const vector a((0.5*f.segmentLength(i))*f.bodyDirection(i));
        u2 = max(u2, max(magSqr(wb ^ (r + a)), magSqr(wb ^ (r - a))));
    }
    return ::sqrt(u2);
}


void Foam::subStepControl::scales
(
    const fiber& f,
    const UList<fluidSample>& s,
    scalar& gammaDot,
    scalar& speed,
    scalar& dudt
)
{
    const tensor R(f.R());
    gammaDot = 0;
    speed = mag(f.velocity());
    dudt = 0;
    forAll(s, i)
    {
        const vector vi(f.segmentVelocity(R, i));
        gammaDot = max(gammaDot, s[i].shearRate());
        speed = max(speed, max(mag(s[i].U), mag(vi)));
        dudt = max(dudt, mag(s[i].G & vi));
    }
}


Foam::scalar Foam::subStepControl::rate
(
    const fiber& f,
    const UList<fluidSample>& s,
    const scalar cellLength,
    label* bound,
    const bool cellsOnly
) const
{
    scalar r = 0;
    scalar cells = 0;
    if (mode_ == mode::paper)
    {
        // Eq. 22 and the cell limit: the shear rate and the speeds only
        scalar gammaDot = 0;
        scalar speed = mag(f.velocity()) + 0.5*mag(f.omega())*f.length();
        forAll(s, i)
        {
            gammaDot = max(gammaDot, s[i].shearRate());
            speed = max(speed, mag(s[i].U));
        }
        const scalar rc = f.length()/f.minDiameter();
        r = rc*gammaDot/shearStepFactor_;
        cells = speed/(maxCo_*cellLength);
    }
    else
    {
        scalar gammaDot, speed, dudt;
        scales(f, s, gammaDot, speed, dudt);
        r = toleranceRate(f, gammaDot, speed, dudt);
        cells = speed/(maxCo_*cellLength);
    }
    if (cellsOnly)
    {
        r = 0;
    }
    if (bound)
    {
        *bound =
            cells > r ? subStepStatistics::cell : subStepStatistics::rule;
    }
    return max(r, cells);
}


Foam::scalar Foam::subStepControl::toleranceRate
(
    const fiber& f,
    const scalar gammaDot,
    const scalar speed,
    const scalar dudt
) const
{
    // The rotation and the lag of the sampled fluid (see Description)
    const scalar turn = 2*tipSpeed(f, f.R(), f.omega())/f.length();
    scalar r = max(gammaDot, turn)/maxRotation_;
    if (dudt > 0)
    {
        r = max(r, dudt/(2*tolerance_*speed));
    }
    if (f.hNext() > 0)
    {
        return max(r, 1/f.hNext());
    }

    // First step, no estimate yet: a turning error of the tips within the
    // tolerance if the turning rate changes on the shear time,
    // e_turn ~ h^2 s^2 L/4 <= tol h d s
    const scalar rc = f.length()/f.minDiameter();
    return max(r, rc*max(gammaDot, turn)/(4*tolerance_));
}


Foam::scalar Foam::subStepControl::error
(
    const fiber& f,
    const UList<fluidSample>& s,
    const scalar h
)
{
    scalar gammaDot, speed, dudt;
    scales(f, s, gammaDot, speed, dudt);
    const vector& Vn = f.vPrev();
    const vector& wn = f.omegaPrev();
    speed = max(speed, mag(Vn));
    const tensor R(f.R());
    const scalar halfL = 0.5*f.length();
    scalar spin =
        max(gammaDot, max(tipSpeed(f, R, wn), tipSpeed(f, R, f.omega()))/halfL);

    // Path: error of the centre and of the sampling against the distance
    // travelled; turning: error of the tips in diameters per shear time.
    // A fiber starting from rest has no speed or turning rate yet: the
    // scales are at least a tenth of those it gains over its own length
    // under the present accelerations, sqrt(a L) and sqrt(alpha)
    const scalar dV = mag(f.velocity() - Vn);
    const scalar dTip = tipSpeed(f, R, f.omega() - wn);
    speed = max(speed, 0.1*::sqrt(dV/h*f.length()));
    spin = max(spin, 0.1*::sqrt(dTip/(h*halfL)));
    const scalar ePath = 0.5*h*(dV + h*dudt);
    const scalar eTurn = 0.5*h*dTip;
    scalar e = 0;
    if (ePath > 0)
    {
        e = ePath/(h*speed);
    }
    if (eTurn > 0)
    {
        e = max(e, eTurn/(h*spin*f.minDiameter()));
    }
    return e;
}


bool Foam::subStepControl::update
(
    fiber& f,
    const UList<fluidSample>& s,
    const scalar h,
    const bool inContact
) const
{
    if (mode_ != mode::tolerance)
    {
        return true;
    }
    if (inContact)
    {
        // No error estimate under the springs (the intervals resolve the
        // contact): the proposal grows with the step, and a step a break
        // cut short (an eddy's end near a wall: 1e-15 s) does not shrink
        // it; it did, and the next step then needed 6e10 sub-steps
        // (channel395, random walk, implicit contacts)
        f.jumped() = false;
        f.hNext() = max(f.hNext(), h*maxGrowth);
        return true;
    }
    if (f.jumped())
    {
        // A jump of the forcing is no error of the step, and a step that
        // was rejected once is accepted: keep the proposal
        f.jumped() = false;
        return true;
    }
    // The error per unit step is O(h)
    const scalar e = error(f, s, h)/tolerance_;
    const scalar factor =
        e*maxGrowth <= safety
      ? maxGrowth
      : max(maxShrink, safety/e);
    f.hNext() = h*factor;
    if (e > 1)
    {
        f.jumped() = true;
        return false;
    }
    return true;
}


void Foam::subStepControl::report(Ostream& os) const
{
    os  << "    Sub-steps: ";
    if (mode_ == mode::paper)
    {
        os  << "paper (Eq. 22) with shearStepFactor " << shearStepFactor_;
    }
    else
    {
        os  << "tolerance " << tolerance_ << " (error per unit step),"
            << " at most maxRotation " << maxRotation_ << " rad";
    }
    os  << ", at most maxCo " << maxCo_ << " cell lengths" << endl;
}


// ************************************************************************* //
