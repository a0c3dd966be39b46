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

#include "eigenBlocks.H"

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
    eigenBlocks::addTensor(M, r, c, t);
}

inline void addBlock(Vector6& b, const label r, const vector& v)
{
    eigenBlocks::addVector(b, r, v);
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

//- The interactions' load: explicit force and torque, and the implicit
//  springs on the displacement at the sub-step's end, dX + dxKnown + V/c,
//  and dashpots on the velocities
void addLoad
(
    Matrix6& M,
    Vector6& rhs,
    const fiber& f,
    const tensor& R,
    const scalar c,
    const fiberIntegrator::load& l,
    const vector& dxKnown,
    const vector& dthetaKnown,
    const scalar h
)
{
    // The torques about the axis of least inertia held (load::holdAxial)
    const vector e(R & l.axisBody);
    addBlock(rhs, 0, l.F);
    addBlock(rhs, 3, l.heldTorque(e, l.M - (f.position() ^ l.F)));
    if (!l.implicit)
    {
        return;
    }
    // The springs' torque rows and rotation columns alike, so that they
    // stay a spring's (symmetric)
    const tensor A(l.heldRows(e));
    const tensor At(A.T());
    const vector dX(l.dX + dxKnown);
    const vector dT(At & (l.dTheta + dthetaKnown));
    const scalar tau = l.tau + h;
    addBlock(M, 0, 0, l.Kxx/c + l.Cxx);
    addBlock(M, 0, 3, (l.Kxt/c + l.Cxt) & At);
    addBlock(M, 3, 0, A & (l.Ktx/c + l.Ctx));
    addBlock(M, 3, 3, A & (l.Ktt/c + l.Ctt) & At);
    addBlock(rhs, 0, tau*l.P - (l.Kxx & dX) - (l.Kxt & dT));
    addBlock(rhs, 3, A & (tau*l.Q - (l.Ktx & dX) - (l.Ktt & dT)));
}


//- The 6x6 system of a step (fiberIntegrator::solve) and its right-hand
//  side; with out, each segment's force at the solution's parts
void assemble
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
    fiberIntegrator::segmentForces* out,
    const fiberIntegrator::load* ext,
    const vector& dxKnown,
    const vector& dthetaKnown,
    const scalar h,
    Matrix6& M,
    Vector6& rhs,
    List<vector>& Fs0,
    List<tensor>& FV0,
    List<tensor>& Fw0
)
{
    const vector V0(f.velocity());
    const vector w0(f.omega());
    const scalar m = f.mass();
    const tensor I(f.inertia(R));

    // Inertia and gyroscopic term (w x I wHat + wHat x I w)/2, linear in w
    addBlock(M, 0, 0, (c*m)*tensor::I);
    addBlock
    (
        M, 3, 3,
        c*I
      + 0.5
       *(
            (fiberHydrodynamics::crossMatrix(wHat) & I)
          - fiberHydrodynamics::crossMatrix(I & wHat)
        )
    );
    addBlock(rhs, 0, bV + m*g);
    addBlock(rhs, 3, bW);
    if (ext)
    {
        addLoad(M, rhs, f, R, c, *ext, dxKnown, dthetaKnown, h);
    }
    fiberHydrodynamics::segmentLaw k;
    forAll(samples, i)
    {
        addSegment
        (
            M, rhs, f, i, R, samples[i], hydro, V0, w0, g, k, out,
            Fs0, FV0, Fw0
        );
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberIntegrator::load::load()
:
    F(Zero),
    M(Zero),
    implicit(false),
    Kxx(Zero),
    Kxt(Zero),
    Ktx(Zero),
    Ktt(Zero),
    Cxx(Zero),
    Cxt(Zero),
    Ctx(Zero),
    Ctt(Zero),
    P(Zero),
    Q(Zero),
    dX(Zero),
    dTheta(Zero),
    tau(0),
    sX(Zero),
    sTheta(Zero),
    sTau(0),
    sV(Zero),
    sW(Zero),
    H(0),
    held(false),
    axis0(Zero),
    axisBody(Zero),
    Maxis(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberIntegrator::load::holdAxial(const fiber& f)
{
    // No load (most fibers of a dilute case): nothing to hold, and no
    // eigenvalue problem per fiber and interval
    if (!implicit && seg.empty() && magSqr(F) == 0 && magSqr(M) == 0)
    {
        return;
    }

    // A rigid fiber: the body's axis of least inertia (a straight fiber's
    // axis), from the inertia in the body frame
    const tensor R(f.R());
    const symmTensor I0(f.inertia(tensor::I));
    Eigen::Matrix3d J;
    J << I0.xx(), I0.xy(), I0.xz(),
         I0.xy(), I0.yy(), I0.yz(),
         I0.xz(), I0.yz(), I0.zz();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(J);
    const Eigen::Vector3d e(eig.eigenvectors().col(0));
    held = true;
    axisBody = vector(e(0), e(1), e(2));
    axis0 = R & axisBody;
    Maxis = axis0 & (M - (f.position() ^ F));

    // A flexible fiber's segments: each its own axis
    forAll(seg, i)
    {
        load& s = seg[i];
        const point c(f.position() + f.segmentOffset(R, label(i)));
        s.held = true;
        s.axis0 = f.segmentDirection(R, label(i));
        s.Maxis = s.axis0 & (s.M - (c ^ s.F));
    }
}


Foam::vector Foam::fiberIntegrator::load::heldTorque
(
    const vector& e,
    const vector& Te
) const
{
    return held ? Te + e*(Maxis - (e & Te)) : Te;
}


Foam::tensor Foam::fiberIntegrator::load::heldRows(const vector& e) const
{
    return held ? tensor::I + e*(axis0 - e) : tensor::I;
}


void Foam::fiberIntegrator::load::addImplicit
(
    const tensor& K,
    const tensor& C,
    const vector& r,
    const vector& vp
)
{
    // The point moves by dX + dTheta x r = dX - S dTheta, S = [r]x; its
    // force acts at r: torque S F
    const tensor S(fiberHydrodynamics::crossMatrix(r));
    implicit = true;
    Kxx += K;
    Kxt -= K & S;
    Ktx += S & K;
    Ktt -= S & K & S;
    Cxx += C;
    Cxt -= C & S;
    Ctx += S & C;
    Ctt -= S & C & S;
    P += K & vp;
    Q += S & (K & vp);
}


void Foam::fiberIntegrator::load::transform(const vectorTensorTransform& T)
{
    // M = sum c x F: with c' = R c + t, F' = R F, M' = R M + t x F'; the
    // implicit terms are about the centre
    if (T.hasR())
    {
        const tensor& R = T.R();
        F = R & F;
        M = R & M;
        for (tensor* t : {&Kxx, &Kxt, &Ktx, &Ktt, &Cxx, &Cxt, &Ctx, &Ctt})
        {
            *t = R & *t & R.T();
        }
        for
        (
            vector* v
          : {&P, &Q, &dX, &dTheta, &sX, &sTheta, &sV, &sW, &axis0}
        )
        {
            *v = R & *v;
        }
    }
    M += T.t() ^ F;
    for (load& s : seg)
    {
        s.transform(T);
    }
    if (T.hasR())
    {
        const tensor& R = T.R();
        for (link& k : links)
        {
            k.rA = R & k.rA;
            k.rB = R & k.rB;
            k.K = R & k.K & R.T();
            k.C = R & k.C & R.T();
        }
    }
}


Foam::fiberIntegrator::load& Foam::fiberIntegrator::load::segment
(
    const fiber& f,
    const label i
)
{
    if (seg.empty())
    {
        seg.resize(f.nSegments());
    }
    return seg[i];
}


void Foam::fiberIntegrator::load::addForce
(
    const fiber& f,
    const label i,
    const vector& F,
    const point& c
)
{
    this->F += F;
    M += c ^ F;
    if (f.flexible())
    {
        load& s = segment(f, i);
        s.F += F;
        s.M += c ^ F;
    }
}


void Foam::fiberIntegrator::load::addSpring
(
    const fiber& f,
    const label i,
    const tensor& K,
    const tensor& C,
    const vector& r,
    const vector& vp
)
{
    if (f.flexible())
    {
        implicit = true;
        segment(f, i).addImplicit(K, C, r, vp);
    }
    else
    {
        addImplicit(K, C, r, vp);
    }
}


void Foam::fiberIntegrator::load::addLink
(
    const fiber& f,
    const label i,
    const label j,
    const vector& rA,
    const vector& rB,
    const tensor& K,
    const tensor& C
)
{
    // Both segments keep the record of their motion
    implicit = true;
    segment(f, i);
    links.push_back(link{i, j, rA, rB, K, C});
}


void Foam::fiberIntegrator::load::recordMotion
(
    const vector& dx,
    const vector& dtheta,
    const vector& v,
    const vector& w,
    const scalar h
)
{
    dX += dx;
    dTheta += dtheta;
    tau += h;
    sX += h*dX;
    sTheta += h*dTheta;
    sTau += h*tau;
    sV += h*v;
    sW += h*w;
    H += h;
}


void Foam::fiberIntegrator::load::record(const fiber& f, const scalar h)
{
    recordMotion(f.dxPrev(), f.dthetaPrev(), f.velocity(), f.omega(), h);
    if (seg.size())
    {
        // A flexible fiber's segments: the implicit step moved each by h
        // times its new velocities (the joints' closing aside)
        const tensor R(f.R());
        forAll(seg, i)
        {
            const vector v(f.segmentVelocity(R, label(i)));
            const vector& w = f.segmentOmega(label(i));
            seg[i].recordMotion(h*v, h*w, v, w, h);
        }
    }
}


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
    const load* ext,
    const vector& dxKnown,
    const vector& dthetaKnown,
    const scalar h
)
{
    Matrix6 M(Matrix6::Zero());
    Vector6 rhs(Vector6::Zero());

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
    assemble
    (
        f, samples, hydro, g, R, c, bV, bW, wHat, out, ext, dxKnown,
        dthetaKnown, h, M, rhs, Fs0, FV0, Fw0
    );

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


void Foam::fiberIntegrator::response
(
    const fiber& f,
    const UList<fluidSample>& samples,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const scalar h,
    scalarList& mobility,
    scalarList& vFree
)
{
    // The implicit Euler step of h in the present configuration (as
    // implicitEuler::advance): the system M x = rhs + G for a load G held
    // over the step, so x = M^-1 rhs + M^-1 G
    const tensor R(f.R());
    Matrix6 M(Matrix6::Zero());
    Vector6 rhs(Vector6::Zero());
    List<vector> Fs0;
    List<tensor> FV0, Fw0;
    assemble
    (
        f, samples, hydro, g, R, 1/h, f.mass()*f.velocity()/h,
        (f.inertia(R) & f.omega())/h, f.omega(), nullptr, nullptr, Zero,
        Zero, h, M, rhs, Fs0, FV0, Fw0
    );
    const Matrix6 Mi(M.inverse());
    const Vector6 x(Mi*rhs);
    mobility.setSize(36);
    vFree.setSize(6);
    for (label i = 0; i < 6; ++i)
    {
        vFree[i] = x(i);
        for (label j = 0; j < 6; ++j)
        {
            mobility[6*i + j] = Mi(i, j);
        }
    }
}


// * * * * * * * * * * * * * * * Global Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const fiberIntegrator::load& l
)
{
    os  << l.F << token::SPACE << l.M << token::SPACE << l.implicit;
    if (l.implicit)
    {
        for
        (
            const tensor& t
          : {l.Kxx, l.Kxt, l.Ktx, l.Ktt, l.Cxx, l.Cxt, l.Ctx, l.Ctt}
        )
        {
            os << token::SPACE << t;
        }
        os  << token::SPACE << l.P << token::SPACE << l.Q;
    }
    os  << token::SPACE << l.dX << token::SPACE << l.dTheta
        << token::SPACE << l.tau << token::SPACE << l.sX
        << token::SPACE << l.sTheta << token::SPACE << l.sTau
        << token::SPACE << l.sV << token::SPACE << l.sW
        << token::SPACE << l.H << token::SPACE << l.held
        << token::SPACE << l.axis0 << token::SPACE << l.axisBody
        << token::SPACE << l.Maxis << token::SPACE << label(l.seg.size());
    for (const fiberIntegrator::load& s : l.seg)
    {
        os << token::SPACE << s;
    }
    os << token::SPACE << label(l.links.size());
    for (const fiberIntegrator::link& k : l.links)
    {
        os  << token::SPACE << k.i << token::SPACE << k.j
            << token::SPACE << k.rA << token::SPACE << k.rB
            << token::SPACE << k.K << token::SPACE << k.C;
    }
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, fiberIntegrator::load& l)
{
    l = fiberIntegrator::load();
    is >> l.F >> l.M >> l.implicit;
    if (l.implicit)
    {
        is  >> l.Kxx >> l.Kxt >> l.Ktx >> l.Ktt >> l.Cxx >> l.Cxt >> l.Ctx
            >> l.Ctt >> l.P >> l.Q;
    }
    is  >> l.dX >> l.dTheta >> l.tau >> l.sX >> l.sTheta >> l.sTau >> l.sV
        >> l.sW >> l.H >> l.held >> l.axis0 >> l.axisBody >> l.Maxis;
    l.seg.resize(readLabel(is));
    for (fiberIntegrator::load& s : l.seg)
    {
        is >> s;
    }
    l.links.resize(readLabel(is));
    for (fiberIntegrator::link& k : l.links)
    {
        is >> k.i >> k.j >> k.rA >> k.rB >> k.K >> k.C;
    }
    return is;
}


// ************************************************************************* //
