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

#include "fiberCoupling.H"
#include "PstreamBuffers.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberCoupling::fiberCoupling
(
    const fvMesh& mesh,
    const word& name,
    const scalar rho,
    const word& UName
)
:
    mesh_(mesh),
    rho_(rho),
    impulse_(mesh.nCells(), Zero),
    coeff_(mesh.nCells(), Zero),
    remote_(Pstream::nProcs()),
    fiberImpulse_(Zero),
    force_
    (
        IOobject
        (
            forceName(name),
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimAcceleration, Zero)
    ),
    dragRate_
    (
        IOobject
        (
            dragRateName(name),
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(inv(dimTime), Zero)
    ),
    fluidForce_(Zero),
    fiberForce_(Zero),
    UName_(UName),
    linearised_
    (
        IOobject
        (
            linearisedName(name),
            word::null,
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    ),
    returned_(Zero)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCoupling::finish(const scalar dt)
{
    // Deposits in other processors' cells
    if (Pstream::parRun())
    {
        exchangeRemote();
    }

    const scalarField& V = mesh_.V();
    vectorField& S = force_.field();
    scalarField& beta = dragRate_.field();
    fluidForce_ = Zero;
    returned_ = Zero;

    // The implicit part of the flow step just taken, beta (U* - U), gave
    // the fluid what the fibers' drag would have become had they not
    // followed the change; they did follow, and their impulses hold the
    // change of their drag again.  Return it in the next source, so that
    // the fluid gets, over the steps, what the fibers gave up
    vectorField back;
    const volVectorField* UPtr = mesh_.findObject<volVectorField>(UName_);
    if (UPtr && linearised_.instance() == mesh_.time().timeName())
    {
        back = beta*(UPtr->primitiveField() - linearised_.field());
    }

    if (dt > 0)
    {
        forAll(S, celli)
        {
            S[celli] = impulse_[celli]/(rho_*V[celli]*dt);
            beta[celli] = coeff_[celli]/(rho_*V[celli]*dt);
            fluidForce_ += impulse_[celli]/dt;
        }
        fiberForce_ = fiberImpulse_/dt;
    }
    else
    {
        fiberForce_ = Zero;
    }
    if (back.size())
    {
        S += back;
        forAll(back, celli)
        {
            returned_ += rho_*V[celli]*back[celli];
        }
        linearised_.instance() = word::null;
    }
    reduce(fluidForce_, sumOp<vector>());
    reduce(fiberForce_, sumOp<vector>());
    reduce(returned_, sumOp<vector>());

    impulse_ = Zero;
    coeff_ = Zero;
    fiberImpulse_ = Zero;
}


void Foam::fiberCoupling::exchangeRemote()
{
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(remote_, proci)
    {
        if (remote_[proci].size())
        {
            UOPstream os(proci, pBufs);
            os << remote_[proci].size();
            for (const remote& r : remote_[proci])
            {
                os << r.cell << r.impulse << r.coeff;
            }
            remote_[proci].clear();
        }
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);
    for (label proci = 0; proci < Pstream::nProcs(); ++proci)
    {
        if (recvSizes[proci])
        {
            UIPstream is(proci, pBufs);
            const label n = readLabel(is);
            for (label k = 0; k < n; ++k)
            {
                label celli;
                vector J;
                scalar c;
                is >> celli >> J >> c;
                impulse_[celli] += J;
                coeff_[celli] += c;
            }
        }
    }
}


// ************************************************************************* //
