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

#include "fiberCellFields.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

template<class Type>
void copyToBoundary
(
    Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>& f
)
{
    for (auto& pf : f.boundaryFieldRef())
    {
        if (!pf.coupled())
        {
            pf == pf.patchInternalField();
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberCellFields::fiberCellFields
(
    const fvMesh& mesh,
    const word& objectName
)
:
    mesh_(mesh),
    prefix_(objectName == "fibers" ? word::null : word(objectName + ":")),
    count_(mesh.nCells(), Zero),
    volume_(mesh.nCells(), Zero),
    pp_(mesh.nCells(), Zero),
    velocity_(mesh.nCells(), Zero),
    window_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCellFields::add
(
    const PtrList<fiber>& fibers,
    const scalar dt
)
{
    window_ += dt;
    for (const fiber& f : fibers)
    {
        const label c = f.location().celli;
        if (c < 0)
        {
            continue;
        }
        scalar v = 0;
        for (label i = 0; i < f.nSegments(); ++i)
        {
            v += 0.25*constant::mathematical::pi
                *sqr(f.segmentDiameter(i))*f.segmentLength(i);
        }
        const vector p(f.orientation());
        count_[c] += dt;
        volume_[c] += v*dt;
        pp_[c] += dt*sqr(p);
        velocity_[c] += dt*f.velocity();
    }
}


void Foam::fiberCellFields::write()
{
    if (!(window_ > 0))
    {
        return;
    }
    const scalarField& V = mesh_.V();
    const IOobject::writeOption w = IOobject::NO_WRITE;
    auto io = [&](const word& q)
    {
        return IOobject
        (
            fieldName(q), mesh_.time().timeName(), mesh_,
            IOobject::NO_READ, w, false
        );
    };

    volScalarField n
    (
        io("fiberNumberDensity"), mesh_, dimensionedScalar(dimless/dimVolume)
    );
    volScalarField alpha
    (
        io("fiberVolumeFraction"), mesh_, dimensionedScalar(dimless)
    );
    volSymmTensorField A
    (
        io("fiberOrientation"), mesh_, dimensionedSymmTensor(dimless)
    );
    volVectorField U
    (
        io("fiberVelocity"), mesh_, dimensionedVector(dimVelocity)
    );

    forAll(V, c)
    {
        n[c] = count_[c]/(V[c]*window_);
        alpha[c] = volume_[c]/(V[c]*window_);
        if (count_[c] > 0)
        {
            A[c] = pp_[c]/count_[c];
            U[c] = velocity_[c]/count_[c];
        }
    }
    // Boundary values: the adjacent cell's (no communication: the write
    // must not wait on the fibers' own exchanges; coupled patches are
    // not written to reconstructed fields)
    copyToBoundary(n);
    copyToBoundary(alpha);
    copyToBoundary(A);
    copyToBoundary(U);
    n.write();
    alpha.write();
    A.write();
    U.write();

    count_ = Zero;
    volume_ = Zero;
    pp_ = Zero;
    velocity_ = Zero;
    window_ = 0;
}


// ************************************************************************* //
