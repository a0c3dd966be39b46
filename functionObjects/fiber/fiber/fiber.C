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

#include "fiber.H"
#include "openfoamCompat.H"
#include "spheroidResistance.H"
#include "mathematicalConstants.H"

using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fiber::calcProperties()
{
    const label n = l_.size();

    mSeg_.setSize(n);
    kAx_.setSize(n);
    kAp_.setSize(n);
    kCx_.setSize(n);
    kCp_.setSize(n);
    kH_.setSize(n);

    m_ = 0;
    I0_ = Zero;

    for (label i = 0; i < n; ++i)
    {
        const scalar l = l_[i];
        const scalar d = d_[i];
        const scalar mi = rho_[i]*pi*sqr(d)*l/4;
        mSeg_[i] = mi;
        m_ += mi;

        // Eq. 8-11 with a = l/2
        const scalar re = spheroidResistance::coxAspectRatio(l/d);
        const spheroidResistance res(re);
        const scalar a = l/2;
        kAx_[i] = 6*pi*a*res.XA;
        kAp_[i] = 6*pi*a*res.YA;
        kCx_[i] = 8*pi*pow3(a)*res.XC;
        kCp_[i] = alpha_*8*pi*pow3(a)*res.YC;
        kH_[i] = alpha_*8*pi*pow3(a)*res.YH;
    }
    calcInertia();
}


void Foam::fiber::calcInertia()
{
    I0_ = Zero;
    forAll(l_, i)
    {
        const scalar l = l_[i];
        const scalar d = d_[i];
        const scalar mi = mSeg_[i];

        // Eq. 4: segment about its own centre
        const symmTensor zz(sqr(z0_[i]));
        const symmTensor Ii =
            (mi*sqr(d)/8)*zz
          + (mi*sqr(d)/16 + mi*sqr(l)/12)*(symmTensor::I - zz);

        // Eq. 5: parallel-axis theorem about the centre of mass
        const vector& r = s0_[i];
        I0_ += Ii + mi*((r & r)*symmTensor::I - sqr(r));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiber::fiber
(
    const label id,
    const vectorList& centres,
    const vectorList& directions,
    const scalarList& lengths,
    const scalarList& diameters,
    const scalarList& densities,
    const vector& referenceDirection
)
:
    id_(id),
    setIndex_(0),
    s0_(centres),
    z0_(directions),
    l_(lengths),
    d_(diameters),
    rho_(densities),
    p0_(referenceDirection/mag(referenceDirection)),
    mSeg_(),
    m_(0),
    I0_(Zero),
    alpha_(1),
    x_(Zero),
    q_(quaternion::I),
    v_(Zero),
    omega_(Zero),
    dxPrev_(Zero),
    dthetaPrev_(Zero),
    vPrev_(Zero),
    omegaPrev_(Zero),
    hPrev_(0),
    hNext_(0),
    jumped_(true),
    psi_(Zero),
    eddyTime_(0),
    nDraws_(0),
    nSubSteps_(Zero),
    E_(0),
    G_(0),
    z0Rest_(),
    Q_(),
    vSeg_(),
    wSeg_(),
    matPatch_(-1),
    landTime_(0),
    restSince_(-1),
    restEnds_(point::zero),
    location_(),
    segmentLocations_(lengths.size())
{
    forAll(z0_, i)
    {
        z0_[i] /= mag(z0_[i]);
    }

    // Eq. 1: centre of mass
    scalar m = 0;
    vector mr(Zero);
    forAll(s0_, i)
    {
        const scalar mi = rho_[i]*pi*sqr(d_[i])*l_[i]/4;
        m += mi;
        mr += mi*s0_[i];
    }
    x_ = mr/m;
    forAll(s0_, i)
    {
        s0_[i] -= x_;
    }

    calcProperties();
}


Foam::fiber Foam::fiber::straight
(
    const label id,
    const point& centre,
    const vector& direction,
    const label nSegments,
    const scalar segmentLength,
    const scalar diameter,
    const scalar density
)
{
    const vector p(direction/mag(direction));
    vectorList centres(nSegments);
    forAll(centres, i)
    {
        centres[i] =
            centre + (i - 0.5*(nSegments - 1))*segmentLength*p;
    }

    return fiber
    (
        id,
        centres,
        vectorList(nSegments, p),
        scalarList(nSegments, segmentLength),
        scalarList(nSegments, diameter),
        scalarList(nSegments, density),
        p
    );
}


Foam::fiber Foam::fiber::arc
(
    const label id,
    const point& centre,
    const vector& direction,
    const vector& normal,
    const label nSegments,
    const scalar segmentLength,
    const scalar diameter,
    const scalar density,
    const scalar kappa
)
{
    const vector p(direction/mag(direction));
    vector n(normal - (normal & p)*p);
    n /= mag(n);
    const scalar alpha = kappa*segmentLength;

    // Segment i turned by (i - (N - 1)/2) alpha, chained end to end
    vectorList centres(nSegments), dirs(nSegments);
    point end(Zero);
    forAll(centres, i)
    {
        const scalar theta = (i - 0.5*(nSegments - 1))*alpha;
        dirs[i] = std::cos(theta)*p + std::sin(theta)*n;
        centres[i] = end + 0.5*segmentLength*dirs[i];
        end += segmentLength*dirs[i];
    }
    // Equal masses: the centre of mass is the mean of the centres
    point mean(Zero);
    for (const point& c : centres)
    {
        mean += c/nSegments;
    }
    for (point& c : centres)
    {
        c += centre - mean;
    }

    return fiber
    (
        id,
        centres,
        dirs,
        scalarList(nSegments, segmentLength),
        scalarList(nSegments, diameter),
        scalarList(nSegments, density),
        p
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::fiber::endToEnd() const
{
    const label n = l_.size() - 1;
    return
        R()
      & (
            s0_[n] + 0.5*l_[n]*z0_[n]
          - s0_[0] + 0.5*l_[0]*z0_[0]
        );
}


Foam::scalar Foam::fiber::chordRatio() const
{
    return mag(endToEnd())/sum(l_);
}


Foam::scalar Foam::fiber::length() const
{
    scalar ext = 0;
    forAll(s0_, i)
    {
        ext = max(ext, mag(s0_[i]) + 0.5*l_[i]);
    }
    return 2*ext;
}


Foam::scalar Foam::fiber::minDiameter() const
{
    scalar dMin = GREAT;
    forAll(d_, i)
    {
        dMin = min(dMin, d_[i]);
    }
    return dMin;
}


bool Foam::fiber::straight() const
{
    forAll(z0_, i)
    {
        if (mag(z0_[i] ^ p0_) > 1e-9 || mag(s0_[i] ^ p0_) > 1e-9*length())
        {
            return false;
        }
    }
    return true;
}


Foam::scalar Foam::fiber::chainBretherton() const
{
    scalar num = 0, den = 0;
    forAll(s0_, i)
    {
        const scalar s2 = magSqr(s0_[i]);
        num += kH_[i] + kAp_[i]*s2;
        den += kCp_[i] + kAp_[i]*s2;
    }
    return num/den;
}


bool Foam::fiber::jefferyCorrection()
{
    if (!straight())
    {
        return false;
    }

    // B(alpha) = (alpha H + S)/(alpha C + S), H = sum kH, C = sum kCp,
    // S = sum kAp s^2 (at alpha = 1); solve B(alpha) = B_target
    scalar H = 0, C = 0, S = 0;
    forAll(s0_, i)
    {
        H += kH_[i]/alpha_;
        C += kCp_[i]/alpha_;
        S += kAp_[i]*magSqr(s0_[i]);
    }
    const scalar re =
        spheroidResistance::coxAspectRatio(length()/minDiameter());
    const scalar B = spheroidResistance::bretherton(re);

    // A single segment is Cox's spheroid already (S = 0)
    alpha_ = S > 0 ? (1 - B)*S/(B*C - H) : 1;
    calcProperties();
    return true;
}


void Foam::fiber::segmentCentres(List<point>& pts) const
{
    const tensor Rt(R());
    pts.setSize(s0_.size());
    forAll(s0_, i)
    {
        pts[i] = x_ + (Rt & s0_[i]);
    }
}


void Foam::fiber::move
(
    const vector& V,
    const vector& omega,
    const scalar dt
)
{
    moveBy(dt*V, dt*omega, V, omega, dt);
}


Foam::FixedList<Foam::point, 2> Foam::fiber::ends() const
{
    const tensor R(this->R());
    const label n = nSegments() - 1;
    return
        FixedList<point, 2>
        {
            x_ + segmentOffset(R, 0)
          - 0.5*segmentLength(0)*segmentDirection(R, 0),
            x_ + segmentOffset(R, n)
          + 0.5*segmentLength(n)*segmentDirection(R, n)
        };
}


void Foam::fiber::joinMat
(
    const label patchi,
    const scalar t,
    const vector& U
)
{
    matPatch_ = patchi;
    landTime_ = t;
    restSince_ = -1;
    setVelocity(U);
    setOmega(Zero);
    for (vector& wi : wSeg_)
    {
        wi = Zero;
    }
    for (vector& vi : vSeg_)
    {
        vi = U;
    }
    clearHistory();
}


void Foam::fiber::transform(const vectorTensorTransform& T)
{
    clearSegmentLocations();
    x_ = T.transformPosition(x_);
    if (!T.hasR())
    {
        return;
    }
    const tensor& R = T.R();
    q_ = fiberCompat::normalised(quaternion(R)*q_);
    v_ = R & v_;
    omega_ = R & omega_;
    dxPrev_ = R & dxPrev_;
    dthetaPrev_ = R & dthetaPrev_;
    vPrev_ = R & vPrev_;
    omegaPrev_ = R & omegaPrev_;
    psi_ = R & psi_;
    for (vector& vi : vSeg_)
    {
        vi = R & vi;
    }
    for (vector& wi : wSeg_)
    {
        wi = R & wi;
    }
}


void Foam::fiber::makeFlexible(const scalar E, const scalar G)
{
    // The segments' velocities of the rigid motion, while still rigid
    vSeg_.setSize(l_.size());
    wSeg_.setSize(l_.size());
    const tensor R(this->R());
    forAll(l_, i)
    {
        vSeg_[i] = segmentVelocity(R, i);
        wSeg_[i] = omega_;
    }
    E_ = E;
    G_ = G;
    z0Rest_ = z0_;
    Q_.setSize(l_.size());
    Q_ = quaternion::I;
}


void Foam::fiber::setShape
(
    const vectorList& s0,
    const List<quaternion>& Q,
    const vectorList& vSeg,
    const vectorList& wSeg
)
{
    s0_ = s0;
    Q_ = Q;
    vSeg_ = vSeg;
    wSeg_ = wSeg;
    forAll(z0_, i)
    {
        z0_[i] = Q_[i].R() & z0Rest_[i];
    }
    calcInertia();
}


void Foam::fiber::restoreShape(const motion& m)
{
    setShape(m.s0, m.Q, m.vSeg, m.wSeg);
}


void Foam::fiber::setFlexibleState
(
    const point& x,
    const quaternion& q,
    const vector& v,
    const vector& omega,
    const vectorList& s0,
    const List<quaternion>& Q,
    const vectorList& z0,
    const symmTensor& I0,
    const vectorList& vSeg,
    const vectorList& wSeg,
    const scalar h
)
{
    // The frame's motion, recorded as a rigid step; its rotation exact
    moveBy(x - x_, R() & rotationVectorOf(conjugate(q_)*q), v, omega, h);
    x_ = x;
    q_ = q;
    s0_ = s0;
    Q_ = Q;
    z0_ = z0;
    I0_ = I0;
    vSeg_ = vSeg;
    wSeg_ = wSeg;
}


void Foam::fiber::moveBy
(
    const vector& dx,
    const vector& dtheta,
    const vector& V,
    const vector& omega,
    const scalar h
)
{
    x_ += dx;

    // Exact rotation by the angle |dtheta| about dtheta
    q_ = fiberCompat::normalised(rotationQuaternion(dtheta)*q_);

    dxPrev_ = dx;
    dthetaPrev_ = dtheta;
    vPrev_ = v_;
    omegaPrev_ = omega_;
    hPrev_ = h;

    v_ = V;
    omega_ = omega;
}


Foam::quaternion Foam::fiber::rotationQuaternion(const vector& theta)
{
    // cos(phi/2) and sin(phi/2)/phi; below phi = 0.1 by their series in
    // y = (phi/2)^2 < 0.0025 to y^4 (the next terms below 3e-20): no root,
    // no sine or cosine
    const scalar phi2 = magSqr(theta);
    if (phi2 < 0.01)
    {
        const scalar y = 0.25*phi2;
        const scalar c =
            1 - y*(1./2 - y*(1./24 - y*(1./720 - y*(1./40320))));
        const scalar sinc =
            0.5*(1 - y*(1./6 - y*(1./120 - y*(1./5040 - y*(1./362880)))));
        return quaternion(c, sinc*theta);
    }
    const scalar phi = std::sqrt(phi2);
    return quaternion(std::cos(0.5*phi), (std::sin(0.5*phi)/phi)*theta);
}


Foam::tensor Foam::fiber::rotation(const vector& theta)
{
    return rotationQuaternion(theta).R();
}


// ************************************************************************* //
