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

#include "flexibleChain.H"
#include "fiberHydrodynamics.H"
#include "mathematicalConstants.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

typedef Eigen::Matrix<double, 9, 9> Matrix9;
typedef Eigen::Matrix<double, 9, 1> Vector9;

// Block offsets of the unknowns [lambda_{i-1}, V_i, W_i]
const label iL = 0, iV = 3, iW = 6;

inline void addTo(Matrix9& M, const label r, const label c, const tensor& T)
{
    for (label a = 0; a < 3; ++a)
    {
        for (label b = 0; b < 3; ++b)
        {
            M(r + a, c + b) += T(a, b);
        }
    }
}

inline void addTo(Vector9& b, const label r, const vector& v)
{
    for (label a = 0; a < 3; ++a)
    {
        b(r + a) += v[a];
    }
}

inline tensor crossOf(const vector& c)
{
    return fiberHydrodynamics::crossMatrix(c);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::flexibleChain::segmentLoad::segmentLoad()
:
    f(Zero),
    A(Zero),
    B(Zero),
    t(Zero),
    C(Zero),
    D(Zero)
{}


Foam::flexibleChain::flexibleChain
(
    const fiber& f,
    const scalar E,
    const scalar G
)
:
    z0_(f.nSegments()),
    l_(f.nSegments()),
    d_(f.nSegments()),
    m_(f.nSegments()),
    Iax_(f.nSegments()),
    Ip_(f.nSegments()),
    kb_(max(f.nSegments() - 1, label(0))),
    kt_(kb_.size()),
    t0_(kb_.size()),
    E_(E),
    G_(G),
    r_(f.nSegments()),
    q_(f.nSegments()),
    v_(f.nSegments()),
    w_(f.nSegments()),
    clamped_(false),
    xClamp_(Zero),
    qClamp_(quaternion::I)
{
    const label N = f.nSegments();
    const tensor R(f.R());
    const quaternion q(R);
    forAll(l_, i)
    {
        z0_[i] = f.bodyDirection(i);
        l_[i] = f.segmentLength(i);
        m_[i] = f.segmentMass(i);
        d_[i] = f.segmentDiameter(i);
        const scalar d2 = sqr(d_[i]);

        // Eq. 4
        Iax_[i] = m_[i]*d2/8;
        Ip_[i] = m_[i]*(d2/16 + sqr(l_[i])/12);

        const vector s(R & f.bodyOffset(i));
        r_[i] = f.position() + s;
        q_[i] = q;
        v_[i] = f.velocity() + (f.omega() ^ s);
        w_[i] = f.omega();
    }

    for (label j = 0; j + 1 < N; ++j)
    {
        const vector gap
        (
            f.bodyOffset(j) + 0.5*l_[j]*z0_[j]
          - f.bodyOffset(j + 1) + 0.5*l_[j + 1]*z0_[j + 1]
        );
        if (mag(gap) > 1e-9*(l_[j] + l_[j + 1]))
        {
            FatalErrorInFunction
                << "Segments " << j << " and " << j + 1 << " of fiber "
                << f.id() << " do not meet end to end (gap " << mag(gap)
                << "): a flexible fiber is a connected chain"
                << exit(FatalError);
        }
        const scalar lj = 0.5*(l_[j] + l_[j + 1]);
        const scalar d4 =
            pow4(min(f.segmentDiameter(j), f.segmentDiameter(j + 1)));
        kb_[j] = E*constant::mathematical::pi*d4/64/lj;
        kt_[j] = G*constant::mathematical::pi*d4/32/lj;
        t0_[j] = normalised(z0_[j] + z0_[j + 1]);
    }
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

void Foam::flexibleChain::moduli
(
    const dictionary& dict,
    scalar& E,
    scalar& G
)
{
    E = dict.get<scalar>("youngsModulus");
    if (!(E > 0))
    {
        FatalIOErrorInFunction(dict)
            << "youngsModulus " << E << " must be positive"
            << exit(FatalIOError);
    }
    const bool hasNu = dict.found("poissonRatio");
    const bool hasG = dict.found("shearModulus");
    if (hasNu == hasG)
    {
        FatalIOErrorInFunction(dict)
            << "A flexible fiber set needs exactly one of poissonRatio and"
            << " shearModulus" << exit(FatalIOError);
    }
    if (hasNu)
    {
        const scalar nu = dict.get<scalar>("poissonRatio");
        if (!(nu > -1 && nu <= 0.5))
        {
            FatalIOErrorInFunction(dict)
                << "poissonRatio " << nu << " must be in (-1, 0.5]"
                << exit(FatalIOError);
        }
        G = E/(2*(1 + nu));
    }
    else
    {
        G = dict.get<scalar>("shearModulus");
        if (!(G > 0))
        {
            FatalIOErrorInFunction(dict)
                << "shearModulus " << G << " must be positive"
                << exit(FatalIOError);
        }
    }
}


Foam::vector Foam::flexibleChain::rotationVector(const quaternion& q)
{
    // q and -q are the same rotation: take the angle in [0, pi]
    const scalar sgn = q.w() < 0 ? -1 : 1;
    const scalar w = sgn*q.w();
    const vector v(sgn*q.v());
    const scalar s = mag(v);
    if (s < 1e-8)
    {
        // 2 atan(s/w)/s by its series
        return (2/w)*(1 - sqr(s/w)/3)*v;
    }
    return (2*std::atan2(s, w)/s)*v;
}


void Foam::flexibleChain::joint
(
    const quaternion& qa,
    const quaternion& qb,
    const scalar kb,
    const scalar kt,
    const vector& t0,
    tensor& K,
    vector& theta
)
{
    const vector thetaBody(rotationVector(conjugate(qa)*qb));
    const tensor Ra(qa.R());
    theta = Ra & thetaBody;
    const tensor Rmid((qa*fiber::rotationQuaternion(0.5*thetaBody)).R());
    const vector t(Rmid & t0);
    const tensor tt(t*t);
    K = kb*(tensor::I - tt) + kt*tt;
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

Foam::scalar Foam::flexibleChain::clampBending() const
{
    return E_*constant::mathematical::pi*pow4(d_[0])/64/l_[0];
}


Foam::scalar Foam::flexibleChain::clampTwisting() const
{
    return G_*constant::mathematical::pi*pow4(d_[0])/32/l_[0];
}


Foam::tensor Foam::flexibleChain::inertia(const label i) const
{
    const vector z(direction(i));
    const tensor zz(z*z);
    return Iax_[i]*zz + Ip_[i]*(tensor::I - zz);
}


void Foam::flexibleChain::set
(
    const label i,
    const point& r,
    const quaternion& q,
    const vector& v,
    const vector& w
)
{
    r_[i] = r;
    q_[i] = normalize(q);
    v_[i] = v;
    w_[i] = w;
}


void Foam::flexibleChain::clamp()
{
    clamped_ = true;
    xClamp_ = r_[0] - 0.5*l_[0]*direction(0);
    qClamp_ = q_[0];
}


struct Foam::flexibleChain::blocks
{
    //- Diagonal, lower and upper blocks and right-hand sides
    List<Matrix9> D, L, U;
    List<Vector9> b;

    explicit blocks(const label N)
    :
        D(N), L(N), U(N), b(N)
    {
        for (label i = 0; i < N; ++i)
        {
            D[i].setZero();
            L[i].setZero();
            U[i].setZero();
            b[i].setZero();
        }
    }
};


void Foam::flexibleChain::assembleSegment
(
    const label i,
    const segmentLoad& ld,
    const scalar h,
    blocks& B
) const
{
    Matrix9& Di = B.D[i];
    Vector9& bi = B.b[i];
    const tensor I(inertia(i));

    // Linear momentum
    addTo(Di, iV, iV, (m_[i]/h)*tensor::I + ld.A);
    addTo(Di, iV, iW, ld.B);
    addTo(bi, iV, (m_[i]/h)*v_[i] + ld.f);

    // Angular momentum
    addTo(Di, iW, iV, ld.C);
    addTo(Di, iW, iW, I/h + ld.D);
    addTo(bi, iW, (I & w_[i])/h - (w_[i] ^ (I & w_[i])) + ld.t);

    if (i == 0 && !clamped_)
    {
        // No joint before: lambda_{-1} = 0
        addTo(Di, iL, iL, tensor::I);
    }
}


void Foam::flexibleChain::assembleJoint
(
    const label i,
    const scalar h,
    blocks& B
) const
{
    // The joint before segment i (i = 0: the clamp): its force lambda on
    // segment i at cm (the opposite on segment i - 1 at cp), its
    // constraint row, and its elastic moment, implicit
    Matrix9& Di = B.D[i];
    Vector9& bi = B.b[i];
    const vector cm(-0.5*l_[i]*direction(i));
    addTo(Di, iV, iL, -tensor::I);
    addTo(Di, iW, iL, -crossOf(cm));
    addTo(Di, iL, iV, -tensor::I);
    addTo(Di, iL, iW, crossOf(cm));

    tensor K;
    vector theta, gap;
    if (i > 0)
    {
        const vector cp(0.5*l_[i - 1]*direction(i - 1));
        gap = r_[i - 1] + cp - r_[i] - cm;
        joint(q_[i - 1], q_[i], kb_[i - 1], kt_[i - 1], t0_[i - 1], K, theta);

        Matrix9& Li = B.L[i];
        addTo(Li, iL, iV, tensor::I);
        addTo(Li, iL, iW, -crossOf(cp));
        addTo(Li, iW, iW, -h*K);

        Matrix9& Up = B.U[i - 1];
        Vector9& bp = B.b[i - 1];
        addTo(Up, iV, iL, tensor::I);
        addTo(Up, iW, iL, crossOf(cp));
        addTo(B.D[i - 1], iW, iW, h*K);
        addTo(Up, iW, iW, -h*K);
        addTo(bp, iW, K & theta);
    }
    else
    {
        gap = xClamp_ - r_[0] - cm;
        joint
        (
            qClamp_, q_[0], clampBending(), clampTwisting(), z0_[0], K, theta
        );
    }
    addTo(bi, iL, -gap/h);
    addTo(Di, iW, iW, h*K);
    addTo(bi, iW, -(K & theta));
}


void Foam::flexibleChain::step
(
    const UList<segmentLoad>& loads,
    const scalar h
)
{
    // Block i: rows and columns [lambda_{i-1}, V_i, W_i]
    const label N = nSegments();
    blocks B(N);
    for (label i = 0; i < N; ++i)
    {
        assembleSegment(i, loads[i], h, B);
        if (i > 0 || clamped_)
        {
            assembleJoint(i, h, B);
        }
    }

    // Block tridiagonal elimination (O(N))
    List<Eigen::PartialPivLU<Matrix9>> lu(N);
    lu[0].compute(B.D[0]);
    for (label i = 1; i < N; ++i)
    {
        const Matrix9 X(lu[i - 1].solve(B.U[i - 1]));
        const Vector9 y(lu[i - 1].solve(B.b[i - 1]));
        B.D[i] -= B.L[i]*X;
        B.b[i] -= B.L[i]*y;
        lu[i].compute(B.D[i]);
    }
    List<Vector9> x(N);
    x[N - 1] = lu[N - 1].solve(B.b[N - 1]);
    for (label i = N - 2; i >= 0; --i)
    {
        x[i] = lu[i].solve(B.b[i] - B.U[i]*x[i + 1]);
    }

    // Move
    for (label i = 0; i < N; ++i)
    {
        const vector V(x[i](iV), x[i](iV + 1), x[i](iV + 2));
        const vector W(x[i](iW), x[i](iW + 1), x[i](iW + 2));
        v_[i] = V;
        w_[i] = W;
        r_[i] += h*V;
        q_[i] = normalize(fiber::rotationQuaternion(h*W)*q_[i]);
    }
}


Foam::scalar Foam::flexibleChain::maxGap() const
{
    scalar g = 0;
    for (label j = 0; j + 1 < nSegments(); ++j)
    {
        g = max
        (
            g,
            mag
            (
                r_[j] + 0.5*l_[j]*direction(j)
              - r_[j + 1] + 0.5*l_[j + 1]*direction(j + 1)
            )
        );
    }
    if (clamped_)
    {
        g = max(g, mag(r_[0] - 0.5*l_[0]*direction(0) - xClamp_));
    }
    return g;
}


Foam::scalar Foam::flexibleChain::kineticEnergy() const
{
    scalar e = 0;
    forAll(r_, i)
    {
        e += 0.5*m_[i]*magSqr(v_[i]) + 0.5*(w_[i] & inertia(i) & w_[i]);
    }
    return e;
}


Foam::scalar Foam::flexibleChain::elasticEnergy() const
{
    scalar e = 0;
    tensor K;
    vector theta;
    for (label j = 0; j + 1 < nSegments(); ++j)
    {
        joint(q_[j], q_[j + 1], kb_[j], kt_[j], t0_[j], K, theta);
        e += 0.5*(theta & K & theta);
    }
    if (clamped_)
    {
        joint(qClamp_, q_[0], clampBending(), clampTwisting(), z0_[0], K,
            theta);
        e += 0.5*(theta & K & theta);
    }
    return e;
}


Foam::point Foam::flexibleChain::start() const
{
    return r_[0] - 0.5*l_[0]*direction(0);
}


Foam::point Foam::flexibleChain::end() const
{
    const label n = nSegments() - 1;
    return r_[n] + 0.5*l_[n]*direction(n);
}


Foam::point Foam::flexibleChain::centreOfMass() const
{
    point c(Zero);
    scalar m = 0;
    forAll(r_, i)
    {
        c += m_[i]*r_[i];
        m += m_[i];
    }
    return c/m;
}


Foam::vector Foam::flexibleChain::momentum() const
{
    vector p(Zero);
    forAll(r_, i)
    {
        p += m_[i]*v_[i];
    }
    return p;
}


Foam::vector Foam::flexibleChain::angularMomentum() const
{
    vector L(Zero);
    forAll(r_, i)
    {
        L += (r_[i] ^ (m_[i]*v_[i])) + (inertia(i) & w_[i]);
    }
    return L;
}


// ************************************************************************* //
