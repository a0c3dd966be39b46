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

#include "fiberIntegrator.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fiberIntegrator, 0);
    defineRunTimeSelectionTable(fiberIntegrator, dictionary);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

typedef Eigen::Matrix<double, 6, 6> Matrix6;
typedef Eigen::Matrix<double, 6, 1> Vector6;

inline void addBlock
(
    Matrix6& M,
    const label r,
    const label c,
    const tensor& t
)
{
    for (label i = 0; i < 3; ++i)
    {
        for (label j = 0; j < 3; ++j)
        {
            M(r + i, c + j) += t(i, j);
        }
    }
}

inline void addBlock(Vector6& b, const label r, const vector& v)
{
    for (label i = 0; i < 3; ++i)
    {
        b(r + i) += v[i];
    }
}

//- Segment i's terms of the 6x6 system; with out, the parts of its force
//  at the solution
void addSegment
(
    Matrix6& M,
    Vector6& rhs,
    const fiber& f,
    const label i,
    const tensor& R,
    const fluidSample& s,
    const fiberHydrodynamics& hydro,
    const vector& V0,
    const vector& w0,
    const vector& g,
    fiberHydrodynamics::segmentLaw& k,
    fiberIntegrator::segmentForces* out,
    List<vector>& Fs0,
    List<tensor>& FV0,
    List<tensor>& Fw0
)
{
    const vector Omega(s.Omega());
    const vector r(f.segmentOffset(R, i));

    hydro.law(f, i, R, s, V0 + (w0 ^ r), w0, k);

    // F_i = -Kuu V + (Kuu S - Kuw) w + Fs, with v_i = V - S w
    const vector Fs((k.Kuu & s.U) + (k.Kuw & Omega) + k.f0);
    const vector Ts((k.Kwu & s.U) + (k.Kww & Omega) + k.t0);

    if (out)
    {
        Fs0[i] = Fs;
        FV0[i] = -k.Kuu;
        Fw0[i] = (k.Kuu & fiberHydrodynamics::crossMatrix(r)) - k.Kuw;
        out->K[i] = tr(k.Kuu)/3;
    }

    if (magSqr(r) == 0)
    {
        // A segment at the centre of mass (S = 0): the lever-arm
        // terms vanish
        addBlock(M, 0, 0, k.Kuu);
        addBlock(M, 0, 3, k.Kuw);
        addBlock(rhs, 0, Fs);
        addBlock(M, 3, 0, k.Kwu);
        addBlock(M, 3, 3, k.Kww);
        addBlock(rhs, 3, Ts);
        return;
    }

    const tensor S(fiberHydrodynamics::crossMatrix(r));
    const tensor FV(-k.Kuu);
    const tensor Fw((k.Kuu & S) - k.Kuw);
    const tensor TV(-k.Kwu);
    const tensor Tw((k.Kwu & S) - k.Kww);

    // Linear momentum
    addBlock(M, 0, 0, -FV);
    addBlock(M, 0, 3, -Fw);
    addBlock(rhs, 0, Fs);

    // Angular momentum about the centre of mass: T_i + r x F_i
    addBlock(M, 3, 0, -(TV + (S & FV)));
    addBlock(M, 3, 3, -(Tw + (S & Fw)));
    addBlock(rhs, 3, Ts + (S & Fs) + (r ^ (f.segmentMass(i)*g)));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberIntegrator::predictedCentres
(
    const fiber& f,
    const scalar h,
    List<point>& pts
) const
{
    vector dx;
    tensor R;
    predict(f, h, dx, R);
    pts.setSize(f.nSegments());
    forAll(pts, i)
    {
        pts[i] = f.position() + dx + f.segmentOffset(R, i);
    }
}


void Foam::fiberIntegrator::solve
(
    const fiber& f,
    const UList<fluidSample>& samples,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const tensor& R,
    const scalar c,
    const vector& bV,
    const vector& bW,
    const vector& wHat,
    vector& V,
    vector& w,
    segmentForces* out,
    const load* ext
)
{
    const vector V0(f.velocity());
    const vector w0(f.omega());
    const scalar m = f.mass();
    const tensor I(f.inertia(R));

    Matrix6 M(Matrix6::Zero());
    Vector6 rhs(Vector6::Zero());

    // Inertia and gyroscopic term w x (I wHat), linear in w
    addBlock(M, 0, 0, (c*m)*tensor::I);
    addBlock(M, 3, 3, c*I - fiberHydrodynamics::crossMatrix(I & wHat));
    addBlock(rhs, 0, bV + m*g);
    addBlock(rhs, 3, bW);
    if (ext)
    {
        addBlock(rhs, 0, ext->F);
        addBlock(rhs, 3, ext->M - (f.position() ^ ext->F));
    }

    fiberHydrodynamics::segmentLaw k;

    // Per segment for the forces at the solution (out only)
    List<vector> Fs0;
    List<tensor> FV0, Fw0;
    if (out)
    {
        Fs0.setSize(samples.size());
        FV0.setSize(samples.size());
        Fw0.setSize(samples.size());
        out->K.setSize(samples.size());
    }

    forAll(samples, i)
    {
        addSegment
        (
            M, rhs, f, i, R, samples[i], hydro, V0, w0, g, k, out,
            Fs0, FV0, Fw0
        );
    }

    const Vector6 x(M.partialPivLu().solve(rhs));

    V = vector(x(0), x(1), x(2));
    w = vector(x(3), x(4), x(5));

    if (out)
    {
        out->F.setSize(samples.size());
        forAll(samples, i)
        {
            out->F[i] = Fs0[i] + (FV0[i] & V) + (Fw0[i] & w);
        }
    }
}


// ************************************************************************* //
