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

#include "eigenBlocks.H"

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
    eigenBlocks::addTensor(M, r, c, T);
}

inline void addTo(Vector9& b, const label r, const vector& v)
{
    eigenBlocks::addVector(b, r, v);
}


//- Solve D [X y] = [U b] in place (X over U, y over b) by Gaussian
//  elimination with partial pivoting; U's columns V are zero (and so are
//  X's); without U (the last block) b only.  D is overwritten.
void solveBlock(Matrix9& D, Matrix9& U, Vector9& b, const bool withU)
{
    // The right-hand side columns that can be non-zero: lambda and W
    static const label cols[6] = {0, 1, 2, 6, 7, 8};
    const label nc = withU ? 6 : 0;
    for (label k = 0; k < 9; ++k)
    {
        label p = k;
        for (label r = k + 1; r < 9; ++r)
        {
            if (std::abs(D(r, k)) > std::abs(D(p, k)))
            {
                p = r;
            }
        }
        if (p != k)
        {
            D.row(k).swap(D.row(p));
            U.row(k).swap(U.row(p));
            std::swap(b(k), b(p));
        }
        const double inv = 1/D(k, k);
        for (label r = k + 1; r < 9; ++r)
        {
            const double f = D(r, k)*inv;
            if (f == 0)
            {
                continue;
            }
            for (label c = k + 1; c < 9; ++c)
            {
                D(r, c) -= f*D(k, c);
            }
            for (label j = 0; j < nc; ++j)
            {
                U(r, cols[j]) -= f*U(k, cols[j]);
            }
            b(r) -= f*b(k);
        }
    }
    for (label k = 8; k >= 0; --k)
    {
        const double inv = 1/D(k, k);
        for (label c = k + 1; c < 9; ++c)
        {
            const double d = D(k, c);
            if (d == 0)
            {
                continue;
            }
            for (label j = 0; j < nc; ++j)
            {
                U(k, cols[j]) -= d*U(c, cols[j]);
            }
            b(k) -= d*b(c);
        }
        for (label j = 0; j < nc; ++j)
        {
            U(k, cols[j]) *= inv;
        }
        b(k) *= inv;
    }
}


// The unknowns of a joint block left after V is eliminated: lambda, W
const label jointCols[6] = {0, 1, 2, 6, 7, 8};


//- Rows 0-2 of a joint block read -V + C_ll lambda + C_lW W = b_l: V
//  substituted into rows 3-8
void substituteV(Matrix9& D, Vector9& b)
{
    for (label r = 3; r < 9; ++r)
    {
        for (label v = 0; v < 3; ++v)
        {
            const double a = D(r, 3 + v);
            if (a == 0)
            {
                continue;
            }
            for (const label c : jointCols)
            {
                D(r, c) += a*D(v, c);
            }
            b(r) += a*b(v);
        }
    }
}


//- Forward elimination with partial pivoting of rows 3-8 over jointCols,
//  applied to the nc right-hand side columns jointCols of U and to b
void eliminate6(Matrix9& D, Matrix9& U, Vector9& b, const label nc)
{
    for (label k = 0; k < 6; ++k)
    {
        const label ck = jointCols[k];
        label p = 3 + k;
        for (label r = 4 + k; r < 9; ++r)
        {
            if (std::abs(D(r, ck)) > std::abs(D(p, ck)))
            {
                p = r;
            }
        }
        if (p != 3 + k)
        {
            D.row(3 + k).swap(D.row(p));
            U.row(3 + k).swap(U.row(p));
            std::swap(b(3 + k), b(p));
        }
        const double inv = 1/D(3 + k, ck);
        for (label r = 4 + k; r < 9; ++r)
        {
            const double f = D(r, ck)*inv;
            if (f == 0)
            {
                continue;
            }
            for (label j = k + 1; j < 6; ++j)
            {
                D(r, jointCols[j]) -= f*D(3 + k, jointCols[j]);
            }
            for (label j = 0; j < nc; ++j)
            {
                U(r, jointCols[j]) -= f*U(3 + k, jointCols[j]);
            }
            b(r) -= f*b(3 + k);
        }
    }
}


//- solveBlock for a block with its joint's constraint rows (U's rows 0-2
//  are zero): V eliminated first, a 6x6 system in [lambda, W] solved, V
//  recovered from the constraint rows
void solveJointBlock(Matrix9& D, Matrix9& U, Vector9& b, const bool withU)
{
    const label nc = withU ? 6 : 0;
    substituteV(D, b);
    eliminate6(D, U, b, nc);

    // Back substitution: the solution of unknown jointCols[k] (row 3 + k)
    double xs[6][7];
    for (label k = 5; k >= 0; --k)
    {
        const double inv = 1/D(3 + k, jointCols[k]);
        for (label j = 0; j <= nc; ++j)
        {
            double v = j < nc ? U(3 + k, jointCols[j]) : b(3 + k);
            for (label m = k + 1; m < 6; ++m)
            {
                v -= D(3 + k, jointCols[m])*xs[m][j];
            }
            xs[k][j] = v*inv;
        }
    }

    // V from the constraint rows; the solution into U and b
    double xv[3][7];
    for (label v = 0; v < 3; ++v)
    {
        for (label j = 0; j <= nc; ++j)
        {
            double s = j < nc ? 0 : -b(v);
            for (label m = 0; m < 6; ++m)
            {
                s += D(v, jointCols[m])*xs[m][j];
            }
            xv[v][j] = s;
        }
    }
    for (label j = 0; j <= nc; ++j)
    {
        for (label m = 0; m < 6; ++m)
        {
            (j < nc ? U(jointCols[m], jointCols[j]) : b(jointCols[m])) =
                xs[m][j];
        }
        for (label v = 0; v < 3; ++v)
        {
            (j < nc ? U(3 + v, jointCols[j]) : b(3 + v)) = xv[v][j];
        }
    }
}


//- D -= L X and b -= L y, with L's non-zero rows (lambda, W) and columns
//  (V, W) and X's non-zero columns (lambda, W)
void subtractProduct
(
    const Matrix9& L,
    const Matrix9& X,
    const Vector9& y,
    Matrix9& D,
    Vector9& b
)
{
    static const label rows[6] = {0, 1, 2, 6, 7, 8};
    static const label inner[6] = {3, 4, 5, 6, 7, 8};
    for (const label r : rows)
    {
        for (const label k : inner)
        {
            const double l = L(r, k);
            if (l == 0)
            {
                continue;
            }
            for (const label c : rows)
            {
                D(r, c) -= l*X(k, c);
            }
            b(r) -= l*y(k);
        }
    }
}


//- Joint stiffnesses of Euler-Bernoulli: bending E I/l, twisting G J/l
inline scalar kBending(const scalar E, const scalar d4, const scalar l)
{
    return E*constant::mathematical::pi*d4/64/l;
}

inline scalar kTwisting(const scalar G, const scalar d4, const scalar l)
{
    return G*constant::mathematical::pi*d4/32/l;
}

inline tensor crossOf(const vector& c)
{
    return fiberHydrodynamics::crossMatrix(c);
}

} // End anonymous namespace


struct Foam::flexibleChain::blocks
{
    //- Diagonal, lower and upper blocks and right-hand sides
    List<Matrix9> D, L, U;
    List<Vector9> b;

    //- Sized for N segments, zero
    void reset(const label N)
    {
        D.setSize(N);
        L.setSize(N);
        U.setSize(N);
        b.setSize(N);
        for (label i = 0; i < N; ++i)
        {
            D[i].setZero();
            L[i].setZero();
            U[i].setZero();
            b[i].setZero();
        }
    }
};


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
    E_(E),
    G_(G),
    clamped_(false),
    xClamp_(Zero),
    qClamp_(quaternion::I)
{
    checkConnected(f);
    geometry(f);
    stateFrom(f);
}


Foam::flexibleChain::flexibleChain(const fiber& f)
:
    flexibleChain()
{
    assign(f);
}


Foam::flexibleChain::flexibleChain()
:
    E_(0),
    G_(0),
    clamped_(false),
    xClamp_(Zero),
    qClamp_(quaternion::I)
{}


Foam::flexibleChain::flexibleChain(flexibleChain&&) = default;


Foam::flexibleChain::~flexibleChain() = default;


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


void Foam::flexibleChain::addInteraction
(
    const fiberIntegrator::load& l,
    const point& c,
    const scalar h,
    segmentLoad& ld
)
{
    // The explicit force and its moment about the segment's centre c; the
    // implicit springs on the segment's displacement at the step's end,
    // dX + h V, and dashpots on its velocity (fiberIntegrator::load)
    ld.f += l.F;
    ld.t += l.M - (c ^ l.F);
    if (!l.implicit)
    {
        return;
    }
    const scalar tau = l.tau + h;
    ld.A += h*l.Kxx + l.Cxx;
    ld.B += h*l.Kxt + l.Cxt;
    ld.C += h*l.Ktx + l.Ctx;
    ld.D += h*l.Ktt + l.Ctt;
    ld.f += tau*l.P - (l.Kxx & l.dX) - (l.Kxt & l.dTheta);
    ld.t += tau*l.Q - (l.Ktx & l.dX) - (l.Ktt & l.dTheta);
}


void Foam::flexibleChain::advance
(
    fiber& f,
    const UList<fluidSample>& s,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const scalar h,
    fiberIntegrator::segmentForces* forces,
    const fiberIntegrator::load* ext
)
{
    const label N = f.nSegments();
    const bool segLoads = ext && label(ext->seg.size()) == N;
    const tensor R(f.R());
    List<segmentLoad>& loads = loads_;
    loads.setSize(N);
    vectorList& Fh = Fh_;
    Fh.setSize(N);
    forAll(loads, i)
    {
        fiberHydrodynamics::segmentLaw k;
        hydro.law
        (
            f, i, R, s[i], f.segmentVelocity(R, i), f.segmentOmega(i), k
        );
        const vector Omega(s[i].Omega());
        segmentLoad& ld = loads[i];
        ld.f = (k.Kuu & s[i].U) + (k.Kuw & Omega) + k.f0;
        ld.A = k.Kuu;
        ld.B = k.Kuw;
        ld.t = (k.Kwu & s[i].U) + (k.Kww & Omega) + k.t0;
        ld.C = k.Kwu;
        ld.D = k.Kww;
        if (forces)
        {
            Fh[i] = ld.f;
        }
        ld.f += f.segmentMass(i)*g;
        if (segLoads)
        {
            const point c(f.position() + f.segmentOffset(R, i));
            addInteraction(ext->seg[i], c, h, ld);
        }
    }

    const bool linked = segLoads && !ext->links.empty();
    if (linked)
    {
        addLinkForces(*ext, loads);
    }
    assign(f);
    step
    (
        loads, h, !(ext && ext->implicit), linked ? &ext->links : nullptr
    );
    if (forces)
    {
        forces->F.setSize(N);
        forces->K.setSize(N);
        forAll(loads, i)
        {
            forces->F[i] =
                Fh[i] - (loads[i].A & v_[i]) - (loads[i].B & w_[i]);
            forces->K[i] = tr(loads[i].A)/3;
        }
    }
    writeBack(f, h);
}


void Foam::flexibleChain::joint
(
    const quaternion& qa,
    const quaternion& qb,
    const vector& za,
    const vector& zb,
    const scalar kb,
    const scalar kt,
    tensor& K,
    vector& theta
)
{
    theta = qa.transform(fiber::rotationVectorOf(conjugate(qa)*qb));

    // The joint's tangent: the bisector of the two directions
    vector t(za + zb);
    const scalar mt = mag(t);
    t = mt > 1e-12 ? t/mt : za;
    const tensor tt(t*t);
    K = kb*(tensor::I - tt) + kt*tt;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::flexibleChain::checkConnected(const fiber& f)
{
    for (label j = 0; j + 1 < f.nSegments(); ++j)
    {
        const vector gap
        (
            f.bodyOffset(j) + 0.5*f.segmentLength(j)*f.bodyDirection(j)
          - f.bodyOffset(j + 1)
          + 0.5*f.segmentLength(j + 1)*f.bodyDirection(j + 1)
        );
        if
        (
            mag(gap)
          > 1e-9*(f.segmentLength(j) + f.segmentLength(j + 1))
        )
        {
            FatalErrorInFunction
                << "Segments " << j << " and " << j + 1 << " of fiber "
                << f.id() << " do not meet end to end (gap " << mag(gap)
                << "): a flexible fiber is a connected chain"
                << exit(FatalError);
        }
    }
}


void Foam::flexibleChain::assign(const fiber& f)
{
    E_ = f.youngsModulus();
    G_ = f.shearModulus();
    clamped_ = false;
    geometry(f);
    stateFrom(f);
}


void Foam::flexibleChain::stateFrom(const fiber& f)
{
    // A rigid fiber's segments all turn with its frame
    const tensor R(f.R());
    const quaternion q(R);
    const bool flex = f.flexible();
    forAll(l_, i)
    {
        r_[i] = f.position() + (R & f.bodyOffset(i));
        q_[i] = flex ? normalize(q*f.segmentRotation(i)) : q;
        v_[i] = f.segmentVelocity(R, i);
        w_[i] = f.segmentOmega(i);
    }
}


void Foam::flexibleChain::geometry(const fiber& f)
{
    const label N = f.nSegments();
    const bool flex = f.flexible();
    z0_.setSize(N);
    l_.setSize(N);
    d_.setSize(N);
    m_.setSize(N);
    Iax_.setSize(N);
    Ip_.setSize(N);
    r_.setSize(N);
    q_.setSize(N);
    v_.setSize(N);
    w_.setSize(N);
    forAll(l_, i)
    {
        z0_[i] = flex ? f.restDirection(i) : f.bodyDirection(i);
        l_[i] = f.segmentLength(i);
        d_[i] = f.segmentDiameter(i);
        m_[i] = f.segmentMass(i);

        // Eq. 4
        Iax_[i] = m_[i]*sqr(d_[i])/8;
        Ip_[i] = m_[i]*(sqr(d_[i])/16 + sqr(l_[i])/12);
    }

    const label nJ = max(N - 1, label(0));
    kb_.setSize(nJ);
    kt_.setSize(nJ);
    for (label j = 0; j < nJ; ++j)
    {
        const scalar lj = 0.5*(l_[j] + l_[j + 1]);
        const scalar d4 = pow4(min(d_[j], d_[j + 1]));
        kb_[j] = kBending(E_, d4, lj);
        kt_[j] = kTwisting(G_, d4, lj);
    }
}


// * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * * //

Foam::scalar Foam::flexibleChain::clampBending() const
{
    return kBending(E_, pow4(d_[0]), l_[0]);
}


Foam::scalar Foam::flexibleChain::clampTwisting() const
{
    return kTwisting(G_, pow4(d_[0]), l_[0]);
}


Foam::tensor Foam::flexibleChain::inertia
(
    const label i,
    const vector& z
) const
{
    const tensor zz(z*z);
    return Iax_[i]*zz + Ip_[i]*(tensor::I - zz);
}


Foam::tensor Foam::flexibleChain::inertia(const label i) const
{
    return inertia(i, direction(i));
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
    const tensor I(inertia(i, z_[i]));

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
    const vector cm(-0.5*l_[i]*z_[i]);
    addTo(Di, iV, iL, -tensor::I);
    addTo(Di, iW, iL, -crossOf(cm));
    addTo(Di, iL, iV, -tensor::I);
    addTo(Di, iL, iW, crossOf(cm));

    tensor K;
    vector theta, gap;
    if (i > 0)
    {
        const vector cp(0.5*l_[i - 1]*z_[i - 1]);
        gap = r_[i - 1] + cp - r_[i] - cm;
        joint
        (
            q_[i - 1], q_[i], z_[i - 1], z_[i], kb_[i - 1], kt_[i - 1], K,
            theta
        );

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
            qClamp_, q_[0], qClamp_.R() & z0_[0], z_[0], clampBending(),
            clampTwisting(), K, theta
        );
    }
    addTo(bi, iL, -gap/h);
    addTo(Di, iW, iW, h*K);
    addTo(bi, iW, -(K & theta));
}


void Foam::flexibleChain::addLinkForces
(
    const fiberIntegrator::load& l,
    UList<segmentLoad>& loads
)
{
    for (const fiberIntegrator::link& k : l.links)
    {
        const fiberIntegrator::load& a = l.seg[k.i];
        const fiberIntegrator::load& b = l.seg[k.j];
        const vector F
        (
            -(
                k.K
              & ((a.dX + (a.dTheta ^ k.rA)) - (b.dX + (b.dTheta ^ k.rB)))
            )
        );
        loads[k.i].f += F;
        loads[k.i].t += k.rA ^ F;
        loads[k.j].f -= F;
        loads[k.j].t -= k.rB ^ F;
    }
}


void Foam::flexibleChain::solve(blocks& B) const
{
    // Block tridiagonal elimination: X_i = D_i'^-1 U_i,
    // y_i = D_i'^-1 b_i', D_{i+1}' = D_{i+1} - L_{i+1} X_i, ...; then
    // x_i = y_i - X_i x_{i+1}
    const label N = B.D.size();
    List<Matrix9>& X = B.U;
    for (label i = 0; i < N; ++i)
    {
        if (i > 0)
        {
            subtractProduct(B.L[i], X[i - 1], B.b[i - 1], B.D[i], B.b[i]);
        }
        if (i > 0 || clamped_)
        {
            solveJointBlock(B.D[i], X[i], B.b[i], i + 1 < N);
        }
        else
        {
            solveBlock(B.D[i], X[i], B.b[i], i + 1 < N);
        }
    }
    List<Vector9>& x = B.b;
    for (label i = N - 2; i >= 0; --i)
    {
        x[i] -= X[i]*x[i + 1];
    }
}


void Foam::flexibleChain::solveLinked
(
    blocks& B,
    const std::vector<fiberIntegrator::link>& links,
    const scalar h
) const
{
    // (T + U M U^T) x = b with T the chain's system, M = diag(h K + C)
    // and U's columns, per link and direction e: e and rA x e in the
    // rows of segment i, -e and -rB x e in those of j (U^T x is the
    // relative velocity of the contact points).  With y = T^-1 b and
    // Z = T^-1 U: x = y - Z M (I + U^T Z M)^-1 U^T y
    const label n = 3*label(links.size());
    const blocks T(B);
    solve(B);

    // U^T x, component a (link a/3, direction a%3)
    auto project = [&links](const List<Vector9>& x, const label a)
    {
        const fiberIntegrator::link& k = links[a/3];
        const auto part = [&x](const label s, const vector& r)
        {
            const vector V(x[s](iV), x[s](iV + 1), x[s](iV + 2));
            const vector W(x[s](iW), x[s](iW + 1), x[s](iW + 2));
            return V + (W ^ r);
        };
        return (part(k.i, k.rA) - part(k.j, k.rB)).component(a % 3);
    };

    List<List<Vector9>> Z(n);
    Eigen::MatrixXd S(n, n), M(Eigen::MatrixXd::Zero(n, n));
    Eigen::VectorXd Uy(n);
    blocks Ba;
    for (label a = 0; a < n; ++a)
    {
        const fiberIntegrator::link& k = links[a/3];
        vector e(Zero);
        e.component(a % 3) = 1;
        Ba = T;
        for (Vector9& b : Ba.b)
        {
            b.setZero();
        }
        addTo(Ba.b[k.i], iV, e);
        addTo(Ba.b[k.i], iW, k.rA ^ e);
        addTo(Ba.b[k.j], iV, -e);
        addTo(Ba.b[k.j], iW, -(k.rB ^ e));
        solve(Ba);
        Z[a].transfer(Ba.b);
        Uy(a) = project(B.b, a);
        const tensor Mk(h*k.K + k.C);
        for (label c = 0; c < 3; ++c)
        {
            M(a, 3*(a/3) + c) = Mk(a % 3, c);
        }
    }
    for (label a = 0; a < n; ++a)
    {
        for (label c = 0; c < n; ++c)
        {
            S(a, c) = project(Z[c], a);
        }
    }
    const Eigen::VectorXd coef
    (
        M*(Eigen::MatrixXd::Identity(n, n) + S*M).partialPivLu().solve(Uy)
    );
    forAll(B.b, i)
    {
        for (label a = 0; a < n; ++a)
        {
            B.b[i] -= coef(a)*Z[a][i];
        }
    }
}


void Foam::flexibleChain::step
(
    const UList<segmentLoad>& loads,
    const scalar h,
    const bool keepAngularMomentum,
    const std::vector<fiberIntegrator::link>* links
)
{
    // Block i: rows and columns [lambda_{i-1}, V_i, W_i]
    const label N = nSegments();
    updateDirections();
    if (!work_)
    {
        work_.reset(new blocks());
    }
    blocks& B = *work_;
    B.reset(N);
    for (label i = 0; i < N; ++i)
    {
        assembleSegment(i, loads[i], h, B);
        if (i > 0 || clamped_)
        {
            assembleJoint(i, h, B);
        }
    }

    if (links && !links->empty())
    {
        solveLinked(B, *links, h);
    }
    else
    {
        solve(B);
    }
    const List<Vector9>& x = B.b;

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
    updateDirections();
    closeJoints(keepAngularMomentum);
}


void Foam::flexibleChain::updateDirections()
{
    z_.setSize(q_.size());
    forAll(q_, i)
    {
        z_[i] = q_[i].R() & z0_[i];
    }
}


void Foam::flexibleChain::closeJoints(const bool keepAngularMomentum)
{
    // The linearised step leaves each joint open by at most
    // (l/2)(h |W_j|^2 + h |W_j+1|^2)/2: the segments are moved (not
    // turned) to close them, the centre of mass (or the clamp) held
    const label N = nSegments();
    const point xG(clamped_ ? point(Zero) : centreOfMass());
    vectorList& r0 = r0_;
    r0 = r_;
    if (clamped_)
    {
        r_[0] = xClamp_ + 0.5*l_[0]*z_[0];
    }
    for (label j = 0; j + 1 < N; ++j)
    {
        r_[j + 1] = r_[j] + 0.5*l_[j]*z_[j] + 0.5*l_[j + 1]*z_[j + 1];
    }
    if (!clamped_)
    {
        const vector shift(xG - centreOfMass());
        for (point& r : r_)
        {
            r += shift;
        }
    }
    if (!clamped_ && keepAngularMomentum)
    {
        // The move changed the angular momentum by sum dr x m v: a rigid
        // rotation of the velocities, O(h^2), gives it back (momentum and
        // centre of mass unchanged), so that closing the joints keeps the
        // angular momentum; about the principal axes of the chain's
        // inertia, leaving out the axis of a nearly straight chain (whose
        // inertia is the cross-section's), the inertia scaled to order
        // one (OpenFOAM's eigen solver has absolute tolerances)
        vector dL(Zero);
        tensor IG(Zero);
        forAll(r_, i)
        {
            const vector s(r_[i] - xG);
            dL += (r_[i] - r0[i]) ^ (m_[i]*v_[i]);
            IG += inertia(i) + m_[i]*((s & s)*tensor::I - s*s);
        }
        const scalar scale = tr(IG);
        Eigen::Matrix3d A;
        for (label r = 0; r < 3; ++r)
        {
            for (label c = 0; c < 3; ++c)
            {
                A(r, c) = 0.5*(IG(r, c) + IG(c, r))/scale;
            }
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(A);
        const Eigen::Vector3d ev(es.eigenvalues());
        vector dw(Zero);
        for (label k = 0; k < 3; ++k)
        {
            if (ev(k) > 1e-2*ev.maxCoeff())
            {
                const Eigen::Vector3d e(es.eigenvectors().col(k));
                const vector ek(e(0), e(1), e(2));
                dw -= ((ek & dL)/(scale*ev(k)))*ek;
            }
        }
        forAll(r_, i)
        {
            v_[i] += dw ^ (r_[i] - xG);
            w_[i] += dw;
        }
    }
}


void Foam::flexibleChain::writeBack(fiber& f, const scalar h) const
{
    // The fiber's frame: the centre of mass and the middle segment's
    // rotation; its velocities: those of the rigid motion with the
    // chain's momentum and angular momentum about the centre of mass
    const label N = nSegments();
    const point xG(centreOfMass());
    scalar m = 0;
    vector P(Zero), LG(Zero);
    tensor IG(Zero);
    for (label i = 0; i < N; ++i)
    {
        const vector s(r_[i] - xG);
        const tensor Ii(inertia(i));
        m += m_[i];
        P += m_[i]*v_[i];
        LG += (s ^ (m_[i]*v_[i])) + (Ii & w_[i]);
        IG += Ii + m_[i]*((s & s)*tensor::I - s*s);
    }
    const quaternion q(q_[N/2]);
    const tensor RT(q.R().T());
    const quaternion qc(conjugate(q));
    vectorList& s0 = s0Back_;
    List<quaternion>& Q = QBack_;
    s0.setSize(N);
    Q.setSize(N);
    for (label i = 0; i < N; ++i)
    {
        s0[i] = RT & (r_[i] - xG);
        Q[i] = normalize(qc*q_[i]);
    }
    f.setFlexibleState
    (
        xG, q, P/m, inv(IG) & LG, s0, Q, v_, w_, h
    );
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
        joint
        (
            q_[j], q_[j + 1], direction(j), direction(j + 1), kb_[j], kt_[j],
            K, theta
        );
        e += 0.5*(theta & K & theta);
    }
    if (clamped_)
    {
        joint
        (
            qClamp_, q_[0], qClamp_.R() & z0_[0], direction(0),
            clampBending(), clampTwisting(), K, theta
        );
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
