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

#include "fiberConstraint.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberConstraint::fiberConstraint(const polyMesh& mesh)
:
    free_(1, 1, 1),
    freeAxes_(1, 1, 1),
    centre_(mesh.bounds().centre()),
    active_(false)
{
    const Vector<label>& D = mesh.geometricD();
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        if (D[i] < 0)
        {
            free_[i] = 0;
            active_ = true;
        }
    }
    // Rotation about axis i moves points along the other two directions
    for (direction i = 0; i < vector::nComponents; ++i)
    {
        freeAxes_[i] = free_[(i + 1) % 3]*free_[(i + 2) % 3];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberConstraint::constrain(fiber& f) const
{
    if (!active_)
    {
        return;
    }
    const point& x = f.position();
    f.translate(cmptMultiply(vector(1, 1, 1) - free_, centre_ - x));
    f.setVelocity(constrain(f.velocity()));
    f.setOmega(cmptMultiply(freeAxes_, f.omega()));
    if (f.flexible())
    {
        for (vector& v : f.segmentVelocities())
        {
            v = constrain(v);
        }
        for (vector& w : f.segmentOmegas())
        {
            w = cmptMultiply(freeAxes_, w);
        }
    }
}


void Foam::fiberConstraint::constrain(UList<fluidSample>& s) const
{
    if (!active_)
    {
        return;
    }
    const tensor P
    (
        free_.x(), 0, 0,
        0, free_.y(), 0,
        0, 0, free_.z()
    );
    for (fluidSample& si : s)
    {
        si.U = constrain(si.U);
        si.G = P & si.G & P;
    }
}


bool Foam::fiberConstraint::inPlane(const fiber& f) const
{
    if (!active_)
    {
        return true;
    }
    const tensor R(f.R());
    for (label i = 0; i < f.nSegments(); ++i)
    {
        const vector z(f.segmentDirection(R, i));
        const vector off(f.segmentOffset(R, i));
        if
        (
            mag(z - constrain(z)) > 1e-6
         || mag(off - constrain(off)) > 1e-6*f.length()
        )
        {
            return false;
        }
    }
    return true;
}


// ************************************************************************* //
