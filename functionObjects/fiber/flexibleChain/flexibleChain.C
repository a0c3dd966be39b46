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
#include "openfoamCompat.H"
#include "fiberHydrodynamics.H"
#include "mathematicalConstants.H"

#include <Eigen/Dense>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

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

//- crossOf(c) & T, by columns (c x T's columns)
inline tensor crossTimes(const vector& c, const tensor& T)
{
    return tensor
    (
        c.y()*T.zx() - c.z()*T.yx(),
        c.y()*T.zy() - c.z()*T.yy(),
        c.y()*T.zz() - c.z()*T.yz(),
        c.z()*T.xx() - c.x()*T.zx(),
        c.z()*T.xy() - c.x()*T.zy(),
        c.z()*T.xz() - c.x()*T.zz(),
        c.x()*T.yx() - c.y()*T.xx(),
        c.x()*T.yy() - c.y()*T.xy(),
        c.x()*T.yz() - c.y()*T.xz()
    );
}

//- The inverse by OpenFOAM's cofactors, with one division
inline tensor inverse(const tensor& t)
{
    return (1/det(t))*inv(t, scalar(1));
}

} // End anonymous namespace


struct Foam::flexibleChain::blocks
{
    // The system, segment i: [P Q; R S] [V_i; W_i] + [I; Cp_i] lambda_i
    // - [0; hK_i] W_{i+1} - [I; Cm_{i-1}] lambda_{i-1}
    // - [0; hK_{i-1}] W_{i-1} = [rV_i; rW_i]; joint j (segments j, j+1):
    // V_j - Cp_j W_j - V_{j+1} + Cm_j W_{j+1} = gh_j; with Cp_j, Cm_j the
    // cross-product matrices of the levers c+_j, c-_{j+1}.  The clamp:
    // -[I; Cm0] lambda_c in segment 0's rows, -V_0 + Cm0 W_0 = ghc

        //- Segment blocks (overwritten by the elimination) and rows
        List<tensor> P, Q, R, S;
        vectorList rV, rW;

        //- Joints: h K_j, the levers c+_j and c-_{j+1}, the right-hand
        //  side
        List<tensor> hK;
        vectorList cp, cm, gh;

        //- The clamp
        bool clamped;
        vector cm0, ghc;


    // The elimination from segment N - 1 on (factor): per segment the
    // blocks of [P Q; R S]^-1 (Pi = P^-1, PiQ, RPi, Sci the Schur
    // complement's inverse); per joint j, after segment i = j + 1:
    // x_i = y_i + Y_j lambda_j + Z_j W_j (VY, WY, VZ, WZ: the rows of
    // Y_j and Z_j), lambda_j = Ti_j (gh_j - J- y_i) - Ti_j V_j + Ew_j W_j,
    // so x_i = y_i + Y_j (a_j + Ew_j W_j - Ti_j V_j) + Z_j W_j with
    // a_j = Ti_j (gh_j - J- y_i)

        List<tensor> Pi, PiQ, RPi, Sci, VY, WY, VZ, WZ, Ti, Ew;

        //- The clamp's force eliminated: x_0 -= Yc Tci (J_c x_0 - ghc)
        tensor VYc, WYc, Tci;


    // A solve (solveRHS)

        //- The solution
        vectorList V, W;

        //- Per joint j of the elimination: y_i and Ti_j (gh_j - J- y_i)
        //  of segment i = j + 1
        vectorList yV, yW, ya;


    //- Sized for N segments
    void setSize(const label N)
    {
        const label nJ = max(N - 1, label(0));
        for
        (
            List<tensor>* l
          : {&P, &Q, &R, &S, &Pi, &PiQ, &RPi, &Sci}
        )
        {
            l->setSize(N);
        }
        for
        (
            List<tensor>* l
          : {&hK, &VY, &WY, &VZ, &WZ, &Ti, &Ew}
        )
        {
            l->setSize(nJ);
        }
        for (vectorList* l : {&rV, &rW, &V, &W})
        {
            l->setSize(N);
        }
        for (vectorList* l : {&cp, &cm, &gh, &yV, &yW, &ya})
        {
            l->setSize(nJ);
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
    geometryOf_(nullptr),
    geometryId_(-1),
    zCurrent_(false),
    clamped_(false),
    xClamp_(Zero),
    qClamp_(quaternion::I),
    xG_(Zero),
    IG_(Zero),
    IGCurrent_(false)
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
    geometryOf_(nullptr),
    geometryId_(-1),
    zCurrent_(false),
    clamped_(false),
    xClamp_(Zero),
    qClamp_(quaternion::I),
    xG_(Zero),
    IG_(Zero),
    IGCurrent_(false)
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
    const vector& e,
    const scalar h,
    segmentLoad& ld
)
{
    // The explicit force and its moment about the segment's centre c; the
    // implicit springs on the segment's displacement at the step's end,
    // dX + h V, and dashpots on its velocity (fiberIntegrator::load)
    ld.f += l.F;
    ld.t += l.heldTorque(e, l.M - (c ^ l.F));
    if (!l.implicit)
    {
        return;
    }
    const tensor A(l.heldRows(e));
    const tensor At(A.T());
    const vector dT(At & l.dTheta);
    const scalar tau = l.tau + h;
    ld.A += h*l.Kxx + l.Cxx;
    ld.B += (h*l.Kxt + l.Cxt) & At;
    ld.C += A & (h*l.Ktx + l.Ctx);
    ld.D += A & (h*l.Ktt + l.Ctt) & At;
    ld.f += tau*l.P - (l.Kxx & l.dX) - (l.Kxt & dT);
    ld.t += A & (tau*l.Q - (l.Ktx & l.dX) - (l.Ktt & dT));
}


void Foam::flexibleChain::hydroLoads
(
    const fiber& f,
    const UList<fluidSample>& s,
    const fiberHydrodynamics& hydro,
    const vector& g,
    vectorList* Fh
)
{
    // Per segment the hydrodynamic law linearised about its own velocity
    // (the force f + A v + B w, the torque t + C v + D w), and gravity
    const label N = f.nSegments();
    const tensor R(f.R());
    loads_.setSize(N);
    forAll(loads_, i)
    {
        fiberHydrodynamics::segmentLaw k;
        hydro.law
        (
            f, i, R, s[i], f.segmentVelocity(R, i), f.segmentOmega(i), k
        );
        const vector Omega(s[i].Omega());
        segmentLoad& ld = loads_[i];
        ld.f = (k.Kuu & s[i].U) + (k.Kuw & Omega) + k.f0;
        ld.A = k.Kuu;
        ld.B = k.Kuw;
        ld.t = (k.Kwu & s[i].U) + (k.Kww & Omega) + k.t0;
        ld.C = k.Kwu;
        ld.D = k.Kww;
        if (Fh)
        {
            (*Fh)[i] = ld.f;
        }
        ld.f += f.segmentMass(i)*g;
    }
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
    vectorList& Fh = Fh_;
    Fh.setSize(N);
    hydroLoads(f, s, hydro, g, forces ? &Fh : nullptr);
    if (segLoads)
    {
        forAll(loads, i)
        {
            const point c(f.position() + f.segmentOffset(R, i));
            addInteraction
            (
                ext->seg[i], c, f.segmentDirection(R, i), h, loads[i]
            );
        }
    }

    const bool linked = segLoads && !ext->links.empty();
    if (linked)
    {
        addLinkForces(*ext, loads);
    }
    // The joints' closing keeps the angular momentum but under implicit
    // springs (their records follow the step's own motion); contacts as
    // constraints hold forces only (implicit: one step per interval)
    bool springs = linked;
    if (segLoads)
    {
        for (const fiberIntegrator::load& l : ext->seg)
        {
            springs =
                springs || l.Kxx != tensor::zero || l.Ktt != tensor::zero
             || l.Cxx != tensor::zero || l.Ctt != tensor::zero;
        }
    }
    assign(f);
    step
    (
        loads, h, !(ext && ext->implicit && springs),
        linked ? &ext->links : nullptr
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


void Foam::flexibleChain::response
(
    const fiber& f,
    const UList<fluidSample>& s,
    const fiberHydrodynamics& hydro,
    const vector& g,
    const scalar h,
    scalarList& mobility,
    scalarList& vFree
)
{
    // The system of step, assembled and factored in the present
    // configuration; its solution without loads (free), then with a unit
    // force and a unit moment on each segment in turn (the joints'
    // constraints homogeneous: the difference is linear in the load)
    const label N = f.nSegments();
    hydroLoads(f, s, hydro, g, nullptr);
    assign(f);
    blocks& B = assemble(loads_, h);
    factor(B);
    solveRHS(B, B.rV, B.rW, B.gh, B.ghc);
    const label n = 6*N;
    vFree.setSize(n);
    mobility.setSize(n*n);
    const auto store = [&](scalarList& v, const label stride, const label o)
    {
        for (label i = 0; i < N; ++i)
        {
            for (label k = 0; k < 3; ++k)
            {
                v[stride*(6*i + k) + o] = B.V[i][k];
                v[stride*(6*i + 3 + k) + o] = B.W[i][k];
            }
        }
    };
    store(vFree, 1, 0);
    vectorList rV(N, Zero), rW(N, Zero), gh(max(N - 1, label(0)), Zero);
    for (label col = 0; col < n; ++col)
    {
        const label i = col/6, k = col % 6;
        (k < 3 ? rV : rW)[i][k % 3] = 1;
        solveRHS(B, rV, rW, gh, Zero);
        (k < 3 ? rV : rW)[i][k % 3] = 0;
        store(mobility, n, col);
    }
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
    // The rotation from a to b in the world frame, qb qa^-1
    theta = fiber::rotationVectorOf(qb*conjugate(qa));

    // The joint's tangent t: the bisector of the two directions;
    // K = kb (I - t t) + kt t t
    vector t(za + zb);
    scalar t2 = magSqr(t);
    if (t2 < 1e-24)
    {
        t = za;
        t2 = 1;
    }
    K = ((kt - kb)/t2)*(t*t);
    K.xx() += kb;
    K.yy() += kb;
    K.zz() += kb;
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
    // The geometry of the fiber of the last call is kept (a fiber's
    // sub-steps follow each other)
    const bool same =
        geometryOf_ == &f && geometryId_ == f.id()
     && l_.size() == f.nSegments()
     && E_ == f.youngsModulus() && G_ == f.shearModulus();
    E_ = f.youngsModulus();
    G_ = f.shearModulus();
    clamped_ = false;
    if (!same)
    {
        geometry(f);
        geometryOf_ = &f;
        geometryId_ = f.id();
    }
    stateFrom(f);
}


void Foam::flexibleChain::stateFrom(const fiber& f)
{
    // A rigid fiber's segments all turn with its frame
    const tensor R(f.R());
    const quaternion q(R);
    const bool flex = f.flexible();
    z_.setSize(l_.size());
    forAll(l_, i)
    {
        // (unit quaternions: their product is one to round-off)
        r_[i] = f.position() + (R & f.bodyOffset(i));
        q_[i] = flex ? q*f.segmentRotation(i) : q;
        z_[i] = R & f.bodyDirection(i);
        v_[i] = f.segmentVelocity(R, i);
        w_[i] = f.segmentOmega(i);
    }
    zCurrent_ = true;
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
    q_[i] = fiberCompat::normalised(q);
    v_[i] = v;
    w_[i] = w;
    zCurrent_ = false;
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
    const tensor I(inertia(i, z_[i]));

    // Linear momentum
    const scalar ih = 1/h;
    const scalar mh = m_[i]*ih;
    B.P[i] = mh*tensor::I + ld.A;
    B.Q[i] = ld.B;
    B.rV[i] = mh*v_[i] + ld.f;

    // Angular momentum
    B.R[i] = ld.C;
    B.S[i] = I/h + ld.D;
    B.rW[i] = (I & w_[i])/h - (w_[i] ^ (I & w_[i])) + ld.t;
}


Foam::flexibleChain::blocks& Foam::flexibleChain::assemble
(
    const UList<segmentLoad>& loads,
    const scalar h
)
{
    // The step's system in the present configuration: every segment's
    // rows, then every joint's (the clamp's where clamped)
    if (!work_)
    {
        work_.reset(new blocks());
    }
    blocks& B = *work_;
    B.setSize(nSegments());
    B.ghc = Zero;
    forAll(loads, i)
    {
        assembleSegment(i, loads[i], h, B);
    }
    for (label i = clamped_ ? 0 : 1; i < nSegments(); ++i)
    {
        assembleJoint(i, h, B);
    }
    return B;
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
    const vector cm(-0.5*l_[i]*z_[i]);
    tensor K;
    vector theta;
    if (i > 0)
    {
        const label j = i - 1;
        const vector cp(0.5*l_[j]*z_[j]);
        joint(q_[j], q_[i], z_[j], z_[i], kb_[j], kt_[j], K, theta);
        B.cp[j] = cp;
        B.cm[j] = cm;
        B.hK[j] = h*K;
        B.gh[j] = (r_[i] + cm - r_[j] - cp)*(1/h);
        B.S[j] += B.hK[j];
        B.rW[j] += K & theta;
    }
    else
    {
        joint
        (
            qClamp_, q_[0], qClamp_.R() & z0_[0], z_[0], clampBending(),
            clampTwisting(), K, theta
        );
        B.cm0 = cm;
        B.ghc = (r_[0] + cm - xClamp_)*(1/h);
    }
    B.S[i] += h*K;
    B.rW[i] -= K & theta;
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


void Foam::flexibleChain::factor(blocks& B) const
{
    // Segment by segment from the free end N - 1 (the articulated-body
    // recursion): the segment's 6x6 block inverted by its 3x3 blocks (the
    // Schur complement of P), its velocities written in the force and the
    // angular velocity of the segment before (joint i - 1's), and
    // eliminated from that segment's rows.  Each block is then the mass,
    // drag and stiffness of a free chain (no pivoting); the clamp, at
    // segment 0, comes last.  O(N), 3x3 blocks only
    const label N = nSegments();
    B.clamped = clamped_;
    for (label i = N - 1; i >= 0; --i)
    {
        const tensor Pi(inverse(B.P[i]));
        const tensor PiQ(Pi & B.Q[i]);
        const tensor RPi(B.R[i] & Pi);
        const tensor Sci(inverse(B.S[i] - (RPi & B.Q[i])));
        B.Pi[i] = Pi;
        B.PiQ[i] = PiQ;
        B.RPi[i] = RPi;
        B.Sci[i] = Sci;
        if (i == 0)
        {
            // The clamp's force [I; Cm0] lambda_c and its constraint
            if (clamped_)
            {
                B.WYc = Sci & (crossOf(B.cm0) - RPi);
                B.VYc = Pi - (PiQ & B.WYc);
                B.Tci = inverse(crossTimes(B.cm0, B.WYc) - B.VYc);
            }
            break;
        }

        // The responses to joint j's force ([I; Cm_j]) and to W_j
        // ([0; hK_j])
        const label j = i - 1;
        const tensor& hK = B.hK[j];
        const vector& cp = B.cp[j];
        const vector& cm = B.cm[j];
        const tensor WY(Sci & (crossOf(cm) - RPi));
        const tensor VY(Pi - (PiQ & WY));
        const tensor WZ(Sci & hK);
        const tensor VZ(-(PiQ & WZ));

        // Joint j's constraint: its force in segment j's velocities
        const tensor Ti(inverse(crossTimes(cm, WY) - VY));
        const tensor Ew(Ti & (crossOf(cp) - (crossTimes(cm, WZ) - VZ)));
        B.VY[j] = VY;
        B.WY[j] = WY;
        B.VZ[j] = VZ;
        B.WZ[j] = WZ;
        B.Ti[j] = Ti;
        B.Ew[j] = Ew;

        // ... eliminated from segment j's rows: W_i = yW_j + WY_j (a_j
        // + Ew W_j - Ti V_j) + WZ_j W_j in its moments c+ x lambda_j
        // - hK W_i
        const tensor X(crossOf(cp) - (hK & WY));
        B.P[j] -= Ti;
        B.Q[j] += Ew;
        B.R[j] -= X & Ti;
        B.S[j] += (X & Ew) - (hK & WZ);
    }
}


void Foam::flexibleChain::solveRHS
(
    blocks& B,
    const vectorList& rV,
    const vectorList& rW,
    const vectorList& gh,
    const vector& ghc
) const
{
    // The factor's recursion on a right-hand side, then back from
    // segment 0
    const label N = nSegments();
    vector a(Zero), pW(Zero);
    for (label i = N - 1; i >= 0; --i)
    {
        vector rv(rV[i]);
        vector rw(rW[i]);
        if (i + 1 < N)
        {
            rv -= a;
            rw += (B.hK[i] & pW) - (B.cp[i] ^ a);
        }
        vector Wy(B.Sci[i] & (rw - (B.RPi[i] & rv)));
        vector Vy((B.Pi[i] & rv) - (B.PiQ[i] & Wy));
        if (i == 0)
        {
            if (B.clamped)
            {
                const vector lc(B.Tci & (ghc - ((B.cm0 ^ Wy) - Vy)));
                Vy += B.VYc & lc;
                Wy += B.WYc & lc;
            }
            B.V[0] = Vy;
            B.W[0] = Wy;
            break;
        }
        const label j = i - 1;
        a = B.Ti[j] & (gh[j] - ((B.cm[j] ^ Wy) - Vy));
        pW = Wy + (B.WY[j] & a);
        B.yV[j] = Vy;
        B.yW[j] = Wy;
        B.ya[j] = a;
    }
    for (label i = 1; i < N; ++i)
    {
        // x_i = y_i + Y_j (a_j + Ew_j W_j - Ti_j V_j) + Z_j W_j
        const label j = i - 1;
        const vector& W0 = B.W[j];
        const vector u(B.ya[j] + (B.Ew[j] & W0) - (B.Ti[j] & B.V[j]));
        B.V[i] = B.yV[j] + (B.VY[j] & u) + (B.VZ[j] & W0);
        B.W[i] = B.yW[j] + (B.WY[j] & u) + (B.WZ[j] & W0);
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
    // Z = T^-1 U: x = y - Z M (I + U^T Z M)^-1 U^T y; T factored once
    const label N = nSegments();
    const label n = 3*label(links.size());
    factor(B);
    solveRHS(B, B.rV, B.rW, B.gh, B.ghc);
    const vectorList V0(B.V);
    const vectorList W0(B.W);

    // U^T x, component a (link a/3, direction a%3)
    auto project =
        [&links](const vectorList& V, const vectorList& W, const label a)
    {
        const fiberIntegrator::link& k = links[a/3];
        return
        (
            (V[k.i] + (W[k.i] ^ k.rA)) - (V[k.j] + (W[k.j] ^ k.rB))
        ).component(a % 3);
    };

    List<vectorList> ZV(n), ZW(n);
    Eigen::MatrixXd S(n, n), M(Eigen::MatrixXd::Zero(n, n));
    Eigen::VectorXd Uy(n);
    vectorList uV(N), uW(N), gh0(B.gh.size(), Zero);
    for (label a = 0; a < n; ++a)
    {
        const fiberIntegrator::link& k = links[a/3];
        vector e(Zero);
        e.component(a % 3) = 1;
        uV = vector::zero;
        uW = vector::zero;
        uV[k.i] += e;
        uW[k.i] += k.rA ^ e;
        uV[k.j] -= e;
        uW[k.j] -= k.rB ^ e;
        solveRHS(B, uV, uW, gh0, Zero);
        ZV[a] = B.V;
        ZW[a] = B.W;
        Uy(a) = project(V0, W0, a);
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
            S(a, c) = project(ZV[c], ZW[c], a);
        }
    }
    const Eigen::VectorXd coef
    (
        M*(Eigen::MatrixXd::Identity(n, n) + S*M).partialPivLu().solve(Uy)
    );
    for (label i = 0; i < N; ++i)
    {
        B.V[i] = V0[i];
        B.W[i] = W0[i];
        for (label a = 0; a < n; ++a)
        {
            B.V[i] -= coef(a)*ZV[a][i];
            B.W[i] -= coef(a)*ZW[a][i];
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
    const label N = nSegments();
    if (!zCurrent_)
    {
        updateDirections();
    }
    IGCurrent_ = false;
    blocks& B = assemble(loads, h);

    if (links && !links->empty())
    {
        solveLinked(B, *links, h);
    }
    else
    {
        factor(B);
        solveRHS(B, B.rV, B.rW, B.gh, B.ghc);
    }

    // The joint forces cancel in the chain's momentum balance, but the
    // recursion never forms them: their round-off would change the
    // momentum.  A uniform velocity (which keeps the joints) takes the
    // balance's residual out
    if (!clamped_)
    {
        vector d(Zero);
        tensor Psum(Zero);
        const scalar ih = 1/h;
        for (label i = 0; i < N; ++i)
        {
            // The momentum rows as assembled: (m/h + A) V + B W = rV
            const segmentLoad& ld = loads[i];
            const scalar mh = m_[i]*ih;
            d += mh*B.V[i] + (ld.A & B.V[i]) + (ld.B & B.W[i]) - B.rV[i];
            Psum += ld.A;
            Psum.xx() += mh;
            Psum.yy() += mh;
            Psum.zz() += mh;
        }
        const vector u(inverse(Psum) & d);
        for (label i = 0; i < N; ++i)
        {
            B.V[i] -= u;
        }
    }

    // Move
    for (label i = 0; i < N; ++i)
    {
        v_[i] = B.V[i];
        w_[i] = B.W[i];
        r_[i] += h*B.V[i];
        q_[i] =
            fiberCompat::normalised
            (
                fiber::rotationQuaternion(h*B.W[i])*q_[i]
            );
    }
    updateDirections();
    closeJoints(keepAngularMomentum);
}


void Foam::flexibleChain::updateDirections()
{
    z_.setSize(q_.size());
    forAll(q_, i)
    {
        // v + 2 w (u x v) + 2 u x (u x v) of q = (w, u)
        const vector& u = q_[i].v();
        const vector t(2*(u ^ z0_[i]));
        z_[i] = z0_[i] + q_[i].w()*t + (u ^ t);
    }
    zCurrent_ = true;
}


void Foam::flexibleChain::closeJoints(const bool keepAngularMomentum)
{
    // The linearised step leaves each joint open by at most
    // (l/2)(h |W_j|^2 + h |W_j+1|^2)/2: the segments are moved (not
    // turned) to close them, the centre of mass (or the clamp) held
    const label N = nSegments();
    const point xG(clamped_ ? point(Zero) : centreOfMass());
    if (clamped_)
    {
        r_[0] = xClamp_ + 0.5*l_[0]*z_[0];
    }

    // Segment j + 1 placed at the end of j; along: the new centre of mass
    // and the angular momentum the moves change, sum dr x m v (with the
    // shift below, the same for all segments: shift x P)
    scalar m = m_[0];
    point mr(m_[0]*r_[0]);
    vector P(m_[0]*v_[0]);
    vector dL(Zero);
    for (label j = 0; j + 1 < N; ++j)
    {
        const label i = j + 1;
        const point r(r_[j] + 0.5*l_[j]*z_[j] + 0.5*l_[i]*z_[i]);
        const vector mv(m_[i]*v_[i]);
        dL += (r - r_[i]) ^ mv;
        r_[i] = r;
        m += m_[i];
        mr += m_[i]*r;
        P += mv;
    }
    if (!clamped_)
    {
        const vector shift(xG - mr/m);
        for (point& r : r_)
        {
            r += shift;
        }
        dL += shift ^ P;
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
        tensor IG(Zero);
        Ii_.setSize(N);
        forAll(r_, i)
        {
            const vector s(r_[i] - xG);
            Ii_[i] = inertia(i, z_[i]);
            IG += Ii_[i] + m_[i]*((s & s)*tensor::I - s*s);
        }
        IG_ = IG;
        xG_ = xG;
        IGCurrent_ = true;
        const scalar scale = tr(IG);
        Eigen::Matrix3d A;
        for (label r = 0; r < 3; ++r)
        {
            for (label c = 0; c < 3; ++c)
            {
                A(r, c) = 0.5*(IG(r, c) + IG(c, r))/scale;
            }
        }
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
        es.computeDirect(A);
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
    // (after step(): the directions z_ are current, and the inertia
    // about the centre of mass is closeJoints()' where it formed it)
    const label N = nSegments();
    const point xG(IGCurrent_ ? xG_ : centreOfMass());
    scalar m = 0;
    vector P(Zero), LG(Zero);
    tensor IG(IGCurrent_ ? IG_ : tensor::zero);
    for (label i = 0; i < N; ++i)
    {
        const vector s(r_[i] - xG);
        const tensor Ii(IGCurrent_ ? Ii_[i] : inertia(i, z_[i]));
        m += m_[i];
        P += m_[i]*v_[i];
        LG += (s ^ (m_[i]*v_[i])) + (Ii & w_[i]);
        if (!IGCurrent_)
        {
            IG += Ii + m_[i]*((s & s)*tensor::I - s*s);
        }
    }
    const quaternion q(q_[N/2]);
    const tensor R(q.R());
    const tensor RT(R.T());
    const quaternion qc(conjugate(q));
    vectorList& s0 = s0Back_;
    List<quaternion>& Q = QBack_;
    vectorList& z0 = z0Back_;
    s0.setSize(N);
    Q.setSize(N);
    z0.setSize(N);
    for (label i = 0; i < N; ++i)
    {
        // (unit quaternions: their product is one to round-off)
        s0[i] = RT & (r_[i] - xG);
        Q[i] = qc*q_[i];
        z0[i] = RT & z_[i];
    }
    f.setFlexibleState
    (
        xG, q, P/m, inv(IG) & LG, s0, Q, z0, symm(RT & IG & R), v_, w_, h
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
