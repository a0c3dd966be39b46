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

#include "implicitEuler.H"
#include "addToRunTimeSelectionTable.H"


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fiberIntegrators
{
    defineTypeNameAndDebug(implicitEuler, 0);
    addToRunTimeSelectionTable(fiberIntegrator, implicitEuler, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberIntegrators::implicitEuler::implicitEuler(const dictionary&)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberIntegrators::implicitEuler::advance
(
    fiber& f,
    const UList<fluidSample>& samples,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const scalar dt,
    segmentForces* out,
    const load* ext
) const
{
    // Eq. 14-15: c = 1/dt, history m V_n/dt and I w_n/dt, gyroscopic
    // term with w_n (symmetric, see fiberIntegrator.H), everything in the
    // configuration of level n
    const tensor R(f.R());
    vector V, w;
    solve
    (
        f, samples, hydro, g, R, 1/dt,
        f.mass()*f.velocity()/dt,
        (f.inertia(R) & f.omega())/dt,
        f.omega(),
        V, w, out, ext, Zero, Zero, dt
    );

    // Eq. 16-17, rigid
    f.move(V, w, dt);
}


// ************************************************************************* //
