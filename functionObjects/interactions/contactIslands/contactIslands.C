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

#include "contactIslands.H"

#include <Eigen/Dense>
#include <vector>
#include <map>
#include <cmath>
#include <Eigen/Sparse>

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

typedef Eigen::Matrix<double, 3, 3> mat3;
typedef Eigen::Matrix<double, 3, 1> vec3;

struct localResult;

vector springTrial
(
    const contactIslands::contact& c,
    const vector& u,
    const scalar h
);

localResult splitUpdate
(
    const contactIslands::contact& c,
    const vector& u,
    const vector& f,
    const mat3& W,
    const scalar h
);

//- One side of a contact: a body's piece, the lever, the sign of the force
//  on it (+1: A, -1: B) and the velocity change of its body per unit
//  force of each direction (mobility times the generalized force)
struct side
{
    label body;
    label piece;
    vector r;
    scalar sign;
    Eigen::MatrixXd G;

    //- Turns the body's vectors into the contact's frame (G takes the
    //  contact's force: turned back into the body's frame)
    tensor R;

    //- The velocity of the side's point, in the contact's frame
    vector at(const scalarList& v) const;
};


//- Union-find: the root of i, halving the path
label findRoot(labelList& parent, label i)
{
    while (parent[i] != i)
    {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}


//- The velocity of the point at lever r of piece p (V + w x r)
vector velocityAt(const scalarList& v, const label p, const vector& r)
{
    const label o = 6*p;
    const vector V(v[o], v[o + 1], v[o + 2]);
    const vector w(v[o + 3], v[o + 4], v[o + 5]);
    return V + (w ^ r);
}


vector side::at(const scalarList& v) const
{
    return R & velocityAt(v, piece, r);
}


//- Add G df to the body's velocities (a side's force changed by df)
void push(contactIslands::body& B, const side& s, const vector& df)
{
    const vec3 d(df.x(), df.y(), df.z());
    const Eigen::VectorXd dv(s.G*d);
    forAll(B.vEnd, i)
    {
        B.vEnd[i] += dv(i);
    }
}


//- The velocity change of a body per unit force at lever r of piece p:
//  column k is the mobility times the generalized force of e_k (the force
//  on the piece, its moment r x e_k)
Eigen::MatrixXd unitResponse
(
    const contactIslands::body& B,
    const label p,
    const vector& r
)
{
    const label n = 6*B.pieces;
    Eigen::Map
    <
        const Eigen::Matrix
        <
            double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor
        >
    > M(B.mobility.cdata(), n, n);
    Eigen::MatrixXd G(n, 3);
    for (label k = 0; k < 3; ++k)
    {
        vector e(Zero);
        e[k] = 1;
        const vector m(r ^ e);
        G.col(k) = M.col(6*p + k);
        for (label j = 0; j < 3; ++j)
        {
            G.col(k) += m[j]*M.col(6*p + 3 + j);
        }
    }
    return G;
}


//- What a contact's law gives against the rest of the island: the
//  relative end velocity u0 without its own force, W its response
struct localResult
{
    vector f;
    scalar fn;
    bool sticks;
    bool pressed;
    vector s;
};


vec3 toEigen(const vector& v)
{
    return vec3(v.x(), v.y(), v.z());
}


vector fromEigen(const vec3& v)
{
    return vector(v(0), v(1), v(2));
}


//- The sides of a contact: A's (force +f), B's (-f) where B moves
std::vector<side> contactSides
(
    const UList<contactIslands::body>& bodies,
    const contactIslands::contact& c
)
{
    // The response to the contact's force: to the force turned into the
    // body's frame (G R^T)
    const auto turned = [](const Eigen::MatrixXd& G, const tensor& R)
    {
        if (R == tensor::I)
        {
            return G;
        }
        Eigen::Matrix3d Rt;
        for (label i = 0; i < 3; ++i)
        {
            for (label j = 0; j < 3; ++j)
            {
                Rt(i, j) = R(j, i);
            }
        }
        return Eigen::MatrixXd(G*Rt);
    };
    std::vector<side> s;
    s.push_back
    (
        side
        {
            c.a, c.pa, c.ra, 1,
            turned(unitResponse(bodies[c.a], c.pa, c.ra), c.Ra), c.Ra
        }
    );
    if (c.b >= 0)
    {
        s.push_back
        (
            side
            {
                c.b, c.pb, c.rb, -1,
                -turned(unitResponse(bodies[c.b], c.pb, c.rb), c.Rb), c.Rb
            }
        );
    }
    return s;
}


//- The change of the relative end velocity at the contact of sides T
//  per unit force of the contact of sides O, through the bodies they share
//  (T = O: a contact's own response, a self-contact's cross terms too)
mat3 response
(
    const UList<contactIslands::body>& bodies,
    const std::vector<side>& T,
    const std::vector<side>& O
)
{
    mat3 w(mat3::Zero());
    for (const side& t : T)
    {
        scalarList dv(6*bodies[t.body].pieces);
        for (const side& o : O)
        {
            if (o.body != t.body)
            {
                continue;
            }
            for (label k = 0; k < 3; ++k)
            {
                forAll(dv, j)
                {
                    dv[j] = o.G(j, k);
                }
                w.col(k) += t.sign*toEigen(t.at(dv));
            }
        }
    }
    return w;
}


//- The relative velocity of a contact's point at the end (A's less B's)
vector relative
(
    const UList<contactIslands::body>& bodies,
    const contactIslands::contact& c,
    const std::vector<side>& sides
)
{
    vector u(Zero);
    for (const side& t : sides)
    {
        u += t.sign*t.at(bodies[t.body].vEnd);
    }
    return c.b >= 0 ? u : u - c.vB;
}

scalar finish
(
    const UList<contactIslands::body>& bodies,
    contactIslands::contact& c,
    const std::vector<side>& sides,
    const vector& f,
    const scalar h
)
{
    // The state at the end from the force: pressed, sticking (within the
    // cone), the spring (sliding: at the bound along the force); the
    // residual of the law at the end, relative to the force
    c.uEnd = relative(bodies, c, sides);
    c.f = f + c.fExtra;
    const scalar un = c.uEnd & c.n;
    const vector ut(c.uEnd - un*c.n);
    c.fn = max(f & c.n, 0);
    c.pressed = c.fn > 0;
    const vector ft(f - (f & c.n)*c.n);
    const vector trial(springTrial(c, c.uEnd, h));
    c.sticks = c.pressed && c.mu > 0 && mag(ft) < c.mu*c.fn*(1 - 1e-9);
    const vector xi0t(c.xi0 - (c.xi0 & c.n)*c.n);
    c.xiEnd =
        !c.pressed || !(c.mu > 0) ? vector(Zero)
      : c.sticks ? xi0t + h*ut
      : -ft/c.kt;
    const scalar law = c.kn*(c.delta0 - h*un) - c.cn*un;
    scalar err = c.pressed ? mag(c.fn - law) : mag(f) + max(law, 0);
    if (c.pressed && c.mu > 0)
    {
        err =
            c.sticks
          ? max(err, mag(ft + trial))
          : max
            (
                err,
                mag(ft + c.mu*c.fn*trial/max(mag(trial), VSMALL))
              + max(c.mu*c.fn - mag(trial), 0)
            );
    }
    return err/max(mag(f), c.kn*mag(c.delta0) + VSMALL);
}

//- The responses of the contacts of an island to each other: per pair of
//  contacts (row, column) that share a body, the change of the row's
//  relative end velocity per unit force of the column's
typedef std::map<std::pair<label, label>, mat3> blockMap;

blockMap couplings
(
    const UList<contactIslands::body>& bodies,
    const std::vector<std::vector<side>>& sides
)
{
    std::map<label, std::vector<label>> on;
    for (label i = 0; i < label(sides.size()); ++i)
    {
        for (const side& t : sides[i])
        {
            std::vector<label>& l = on[t.body];
            if (l.empty() || l.back() != i)
            {
                l.push_back(i);
            }
        }
    }
    blockMap W;
    for (const auto& b : on)
    {
        for (const label c : b.second)
        {
            // The row's sides on this body only: a pair of contacts that
            // share two bodies gets each body's part once
            std::vector<side> T;
            for (const side& t : sides[c])
            {
                if (t.body == b.first)
                {
                    T.push_back(t);
                }
            }
            for (const label j : b.second)
            {
                auto it = W.find({c, j});
                const mat3 w(response(bodies, T, sides[j]));
                if (it == W.end())
                {
                    W.emplace(std::make_pair(c, j), w);
                }
                else
                {
                    it->second += w;
                }
            }
        }
    }
    return W;
}


//- A contact's state in the active set
enum class state { apart, sticks, slides };


//- The tangential basis of a normal
void tangents(const vector& n, vector& t1, vector& t2)
{
    const vector e
    (
        mag(n.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)
    );
    t1 = normalised(n ^ e);
    t2 = n ^ t1;
}


//- The rows of one contact in the system of the present states (its law
//  as a linear equation in the island's forces): into triplets and b
void contactRows
(
    const contactIslands::contact& c,
    const label i,
    const state st,
    const vector& s,
    const mat3& Q,
    const blockMap& W,
    const vector& u,
    const vector& uk,
    const scalar h,
    std::vector<Eigen::Triplet<double>>& A,
    Eigen::VectorXd& b
)
{
    const label r = 3*i;
    if (st == state::apart)
    {
        for (label k = 0; k < 3; ++k)
        {
            A.emplace_back(r + k, r + k, 1);
            b(r + k) = 0;
        }
        return;
    }
    const vec3 n(toEigen(c.n));
    const mat3 nn(n*n.transpose());
    const scalar a = c.kn*h + c.cn;
    const scalar bt = c.mu > 0 ? c.kt*h + c.ct : 0;
    const vector xi0t(c.xi0 - (c.xi0 & c.n)*c.n);

    // Sticking: all three rows of f + D (u + W f) = r; sliding: the
    // normal row, and the tangential force along -s at mu f_n, with s
    // the direction of the stick force's opposite (springTrial)
    // linearized about the last solve (Q: mu f_n times the change of s per
    // change of the relative velocity, zero where the contact has just
    // begun to slide)
    mat3 D(a*nn + bt*(mat3::Identity() - nn));
    vec3 rhs(c.kn*c.delta0*n - (c.mu > 0 ? c.kt : 0)*toEigen(xi0t));
    mat3 own(mat3::Identity());
    if (st == state::slides)
    {
        vector t1, t2;
        tangents(c.n, t1, t2);
        D = mat3::Zero();
        D.row(0) = a*n.transpose();
        D.row(1) = toEigen(t1).transpose()*Q;
        D.row(2) = toEigen(t2).transpose()*Q;
        own.row(0) = n.transpose();
        own.row(1) = (toEigen(t1) + c.mu*(s & t1)*n).transpose();
        own.row(2) = (toEigen(t2) + c.mu*(s & t2)*n).transpose();
        rhs = vec3(c.kn*c.delta0, 0, 0);
    }
    vec3 rb(rhs - D*toEigen(u));
    if (st == state::slides)
    {
        vector t1, t2;
        tangents(c.n, t1, t2);
        rb(1) += toEigen(t1).dot(Q*toEigen(uk));
        rb(2) += toEigen(t2).dot(Q*toEigen(uk));
    }
    for (auto it = W.lower_bound({i, 0}); it != W.end(); ++it)
    {
        if (it->first.first != i)
        {
            break;
        }
        const label col = 3*it->first.second;
        const mat3 blk
        (
            (it->first.second == i ? own : mat3::Zero()) + D*it->second
        );
        for (label p = 0; p < 3; ++p)
        {
            for (label q = 0; q < 3; ++q)
            {
                A.emplace_back(r + p, col + q, blk(p, q));
            }
        }
    }
    b.segment<3>(r) = rb;
}

//- The opposite of the force a contact would take sticking, from its
//  relative end velocity u: k_t xi0 + (k_t h + c_t) u_t
vector springTrial
(
    const contactIslands::contact& c,
    const vector& u,
    const scalar h
)
{
    const vector xi0t(c.xi0 - (c.xi0 & c.n)*c.n);
    const vector ut(u - (u & c.n)*c.n);
    return c.kt*xi0t + (c.kt*h + c.ct)*ut;
}


//- A contact's next state from the result of the present ones (f its
//  force, u its relative end velocity): false if it keeps its state (and
//  its slip direction s)
bool nextState
(
    const contactIslands::contact& c,
    const vector& f,
    const vector& u,
    const scalar h,
    state& st,
    vector& s
)
{
    const scalar fn = f & c.n;
    if (st == state::apart)
    {
        const scalar law = c.kn*(c.delta0 - h*(u & c.n)) - c.cn*(u & c.n);
        if (law > 0)
        {
            st = state::sticks;
            return true;
        }
        return false;
    }
    if (!(fn > 0))
    {
        st = state::apart;
        return true;
    }
    const vector ft(f - fn*c.n);
    if (st == state::sticks)
    {
        if (c.mu > 0 && mag(ft) > c.mu*fn*(1 + 1e-10))
        {
            st = state::slides;
            s = -ft/mag(ft);
            return true;
        }
        return false;
    }
    const vector trial(springTrial(c, u, h));
    if (!(mag(trial) > c.mu*fn))
    {
        st = state::sticks;
        return true;
    }
    const vector sNew(trial/mag(trial));
    const bool moved = mag(sNew - s) > 1e-12;
    s = sNew;
    return moved;
}


//- The forces of the linear system of the present states
bool solveStates
(
    const UList<contactIslands::contact>& contacts,
    const labelList& cs,
    const blockMap& W,
    const std::vector<vector>& uFree,
    const std::vector<state>& st,
    const std::vector<vector>& s,
    const std::vector<mat3>& Q,
    const std::vector<vector>& uk,
    const scalar h,
    std::vector<vector>& f
)
{
    const label m = cs.size();
    std::vector<Eigen::Triplet<double>> A;
    Eigen::VectorXd b(3*m);
    for (label i = 0; i < m; ++i)
    {
        contactRows
        (
            contacts[cs[i]], i, st[i], s[i], Q[i], W, uFree[i], uk[i], h,
            A, b
        );
    }
    Eigen::SparseMatrix<double> S(3*m, 3*m);
    S.setFromTriplets(A.begin(), A.end());
    Eigen::VectorXd x;
    if (m <= 40)
    {
        x = Eigen::MatrixXd(S).partialPivLu().solve(b);
    }
    else
    {
        Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
        lu.compute(S);
        if (lu.info() != Eigen::Success)
        {
            return false;
        }
        x = lu.solve(b);
    }
    for (label i = 0; i < m; ++i)
    {
        // Apart: none (not the round-off of the solve)
        f[i] =
            st[i] == state::apart
          ? vector(Zero)
          : vector(x(3*i), x(3*i + 1), x(3*i + 2));
    }
    return x.allFinite();
}


//- The island's forces by active sets: each contact starts in the state
//  it takes alone; the system of the present states is solved, and every
//  contact moves to the state its result calls for, until none moves (and
//  the slip directions settle): the passes, negative if that does not
//  happen within 10 (then the sweeps take over)
label activeSet
(
    const UList<contactIslands::contact>& contacts,
    const labelList& cs,
    const blockMap& W,
    const std::vector<vector>& uFree,
    const scalar h,
    std::vector<vector>& f
)
{
    const label m = cs.size();
    std::vector<state> st(m, state::apart);
    std::vector<vector> s(m, Zero);
    for (label i = 0; i < m; ++i)
    {
        const contactIslands::contact& c = contacts[cs[i]];
        const localResult res
        (
            splitUpdate(c, uFree[i], Zero, W.at({i, i}), h)
        );
        st[i] =
            !res.pressed ? state::apart
          : res.sticks || !(c.mu > 0) ? state::sticks
          : state::slides;
        s[i] = res.s;
    }
    std::vector<mat3> Q(m, mat3::Zero());
    std::vector<vector> uk(m, Zero);
    for (label pass = 0; pass < 10; ++pass)
    {
        if (!solveStates(contacts, cs, W, uFree, st, s, Q, uk, h, f))
        {
            return -(pass + 1);
        }
        bool moved = false;
        for (label i = 0; i < m; ++i)
        {
            const contactIslands::contact& c = contacts[cs[i]];
            vector u(uFree[i]);
            for (auto it = W.lower_bound({i, 0}); it != W.end(); ++it)
            {
                if (it->first.first != i)
                {
                    break;
                }
                u += fromEigen(it->second*toEigen(f[it->first.second]));
            }
            const state was = st[i];
            moved = nextState(c, f[i], u, h, st[i], s[i]) || moved;
            Q[i] = mat3::Zero();
            uk[i] = u;
            if (was == state::slides && st[i] == state::slides)
            {
                // The slip direction's change per change of the relative
                // velocity, times mu f_n (Newton on the direction)
                const vec3 n(toEigen(c.n));
                const vec3 e(toEigen(s[i]));
                const vector trial(springTrial(c, u, h));
                Q[i] =
                    (c.mu*(f[i] & c.n)*(c.kt*h + c.ct)/mag(trial))
                   *(mat3::Identity() - e*e.transpose())
                   *(mat3::Identity() - n*n.transpose());
            }
        }
        if (!moved)
        {
            return pass + 1;
        }
    }
    return -10;
}

//- Sliding at the normal force f_n: the direction e of the tangential
//  force -mu f_n e for which e is the direction of k_t xi0 + b u_t at the
//  end, with u_t = u_t0 + Wt f_t: (lambda I + kappa Wt) e = c0 (c0 that
//  vector without the force, kappa = mu f_n b), |e| = 1, lambda > 0 (the
//  length of that vector), found by bisection on lambda (|e| falls with
//  lambda where Wt is positive)
vec3 slipDirection
(
    const vector& normal,
    const vec3& c0,
    const mat3& Wt,
    const scalar kappa
)
{
    vector t1, t2;
    tangents(normal, t1, t2);
    Eigen::Matrix<double, 3, 2> B;
    B.col(0) = toEigen(t1);
    B.col(1) = toEigen(t2);
    const Eigen::Matrix2d W2(B.transpose()*Wt*B);
    const Eigen::Vector2d c2(B.transpose()*c0);
    // The 2x2 inverse in closed form; Newton on |e|^2 - 1 (falling and
    // convex in lambda), kept within the bracket [lo, hi] by bisection
    auto inverse = [&](const scalar lambda)
    {
        Eigen::Matrix2d A(kappa*W2);
        A(0, 0) += lambda;
        A(1, 1) += lambda;
        const scalar det = A(0, 0)*A(1, 1) - A(0, 1)*A(1, 0);
        Eigen::Matrix2d Ai;
        Ai << A(1, 1), -A(0, 1), -A(1, 0), A(0, 0);
        return Eigen::Matrix2d(Ai/det);
    };
    scalar lo = 0;
    scalar hi = c2.norm() + kappa*W2.norm();
    scalar lambda = hi;
    for (label it = 0; it < 100 && hi - lo > 1e-15*hi; ++it)
    {
        const Eigen::Matrix2d Ai(inverse(lambda));
        const Eigen::Vector2d e(Ai*c2);
        const scalar phi = e.squaredNorm() - 1;
        (phi > 0 ? lo : hi) = lambda;
        const scalar dphi = -2*e.dot(Ai*e);
        const scalar next = dphi < 0 ? lambda - phi/dphi : -1;
        if (mag(phi) < 1e-14)
        {
            break;
        }
        lambda = next > lo && next < hi ? next : 0.5*(lo + hi);
    }
    const Eigen::Vector2d e(inverse(lambda)*c2);
    return B*(e/max(e.norm(), VSMALL));
}


//- A sweep's update of one contact, its normal force first, then its
//  tangential one at that normal force (each against its own response,
//  the rest held): u its relative end velocity and f its force now
localResult splitUpdate
(
    const contactIslands::contact& c,
    const vector& u,
    const vector& f,
    const mat3& W,
    const scalar h
)
{
    const vec3 n(toEigen(c.n));
    const mat3 P(mat3::Identity() - n*n.transpose());
    const scalar a = c.kn*h + c.cn;
    const scalar fnOld = f & c.n;
    const vec3 ftOld(P*toEigen(f));
    const scalar Wnn = n.dot(W*n);
    const scalar fn =
        max((c.kn*c.delta0 - a*((u & c.n) - Wnn*fnOld))/(1 + a*Wnn), 0);
    if (!(fn > 0))
    {
        return localResult{Zero, 0, false, false, Zero};
    }
    if (!(c.mu > 0))
    {
        return localResult{fn*c.n, fn, false, true, Zero};
    }

    // The tangential velocity with the new normal force, and its response
    // in the tangent plane
    const vec3 uNow(toEigen(u) + W*n*(fn - fnOld));
    const mat3 Wt(P*W*P);
    const scalar b = c.kt*h + c.ct;
    const vec3 xi0t(P*toEigen(c.xi0));
    auto trialAt = [&](const vec3& ft)
    {
        const vec3 ut(P*uNow + Wt*(ft - ftOld));
        return vec3(c.kt*xi0t + b*ut);
    };
    const vec3 ft
    (
        (mat3::Identity() + b*Wt).lu().solve
        (
            -c.kt*xi0t - b*(P*uNow - Wt*ftOld)
        )
    );
    if (ft.norm() <= c.mu*fn)
    {
        return localResult{fn*c.n + fromEigen(ft), fn, true, true, Zero};
    }
    const vec3 e
    (
        slipDirection(c.n, trialAt(vec3::Zero()), Wt, c.mu*fn*b)
    );
    return
        localResult
        {
            fn*c.n - fromEigen(c.mu*fn*e), fn, false, true, fromEigen(e)
        };
}

//- Projected Gauss-Seidel sweeps over the contacts from the forces f (the
//  bodies' end velocities with them): each contact's force against the
//  others' as they stand (splitUpdate), relaxed where a sweep changed the
//  forces more than the last, until none changes by more than tolerance
//  times the largest: the sweeps, negative if more than maxSweeps
label sweeps
(
    UList<contactIslands::body>& bodies,
    const UList<contactIslands::contact>& contacts,
    const labelList& cs,
    const std::vector<std::vector<side>>& sides,
    const blockMap& W,
    const scalar h,
    const scalar tolerance,
    const label maxSweeps,
    std::vector<vector>& f
)
{
    scalar omega = 1;
    scalar lastChange = GREAT;
    for (label sweep = 0; sweep < maxSweeps; ++sweep)
    {
        scalar change = 0;
        scalar largest = 0;
        forAll(cs, i)
        {
            const contactIslands::contact& c = contacts[cs[i]];
            const vector u(relative(bodies, c, sides[i]));
            const localResult res
            (
                splitUpdate(c, u, f[i], W.at({i, i}), h)
            );
            const vector df(omega*(res.f - f[i]));
            for (const side& t : sides[i])
            {
                push(bodies[t.body], t, df);
            }
            change = max(change, mag(res.f - f[i]));
            f[i] += df;
            largest = max(largest, mag(res.f));
        }
        if (!(change > tolerance*largest))
        {
            return sweep + 1;
        }
        if (change > lastChange)
        {
            omega = max(0.7*omega, 0.1);
        }
        lastChange = change;
    }
    return -maxSweeps;
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactIslands::contactIslands
(
    const scalar tolerance,
    const label sweeps,
    const bool activeSets
)
:
    tolerance_(tolerance),
    maxSweeps_(sweeps),
    activeSets_(activeSets)
{}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::List<Foam::labelList> Foam::contactIslands::islands() const
{
    labelList parent(identity(bodies_.size()));
    for (const contact& c : contacts_)
    {
        if (c.b >= 0)
        {
            const label ra = findRoot(parent, c.a);
            const label rb = findRoot(parent, c.b);
            if (ra != rb)
            {
                parent[max(ra, rb)] = min(ra, rb);
            }
        }
    }

    // Numbered by their first contact, each contact in the order given
    labelList islandOf(bodies_.size(), -1);
    DynamicList<DynamicList<label>> members;
    forAll(contacts_, ci)
    {
        const label root = findRoot(parent, contacts_[ci].a);
        if (islandOf[root] < 0)
        {
            islandOf[root] = members.size();
            members.append(DynamicList<label>());
        }
        members[islandOf[root]].append(ci);
    }
    List<labelList> result(members.size());
    forAll(members, i)
    {
        result[i].transfer(members[i]);
    }
    return result;
}


//- The most contacts of an island solved by active sets: beyond, their
//  sparse LU (each pass a factorization of the island's system) costs more
//  than the sweeps (cases/fiberFlocs at N = 60, one island of thousands of
//  contacts: over 300 s for 0.003 s of fiber time, 90 % in the LU; with
//  the sweeps alone 13 s)
static const Foam::label maxActiveSetContacts = 200;


void Foam::contactIslands::solveIsland(const labelList& cs, const scalar h)
{
    // The explicit forces first; then sweeps (cheap where they converge
    // fast), active sets where a hundred do not settle (exact where they
    // settle, as they do where the sweeps crawl: long stiff chains), and
    // the rest of the sweeps where they fail too
    const label m = cs.size();
    std::vector<std::vector<side>> sides(m);
    std::vector<vector> uFree(m);
    forAll(cs, i)
    {
        sides[i] = contactSides(bodies_, contacts_[cs[i]]);
        for (const side& t : sides[i])
        {
            push(bodies_[t.body], t, contacts_[cs[i]].fExtra);
        }
    }
    forAll(cs, i)
    {
        uFree[i] = relative(bodies_, contacts_[cs[i]], sides[i]);
    }
    const blockMap W(couplings(bodies_, sides));
    std::vector<vector> f(m, Zero);
    const label first = activeSets_ ? min(100, maxSweeps_) : maxSweeps_;
    label n = sweeps(bodies_, contacts_, cs, sides, W, h, tolerance_, first, f);
    stats_.iterations += mag(n);
    if (n < 0 && activeSets_ && m <= maxActiveSetContacts)
    {
        std::vector<vector> fa(m, Zero);
        const label passes = activeSet(contacts_, cs, W, uFree, h, fa);
        stats_.iterations += mag(passes);
        if (passes > 0)
        {
            // The bodies' velocities with these forces instead
            forAll(cs, i)
            {
                for (const side& t : sides[i])
                {
                    push(bodies_[t.body], t, fa[i] - f[i]);
                }
            }
            f = fa;
            n = 1;
        }
        else
        {
            n = sweeps(bodies_, contacts_, cs, sides, W, h, tolerance_,
                max(maxSweeps_ - first, 1), f);
            stats_.iterations += mag(n);
        }
    }
    stats_.unconverged += n < 0;
    forAll(cs, i)
    {
        stats_.residual =
            max
            (
                stats_.residual,
                finish(bodies_, contacts_[cs[i]], sides[i], f[i], h)
            );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::contactIslands::clear()
{
    bodies_.clear();
    contacts_.clear();
    stats_ = statistics();
}


Foam::label Foam::contactIslands::addBody(const label pieces)
{
    body B;
    B.pieces = pieces;
    B.vFree.setSize(6*pieces, 0);
    B.mobility.setSize(36*pieces*pieces, 0);
    bodies_.append(B);
    return bodies_.size() - 1;
}


Foam::label Foam::contactIslands::addContact(const contact& c)
{
    contacts_.append(c);
    return contacts_.size() - 1;
}


void Foam::contactIslands::solve(const scalar h)
{
    stats_ = statistics();
    for (body& B : bodies_)
    {
        B.vEnd = B.vFree;
    }
    const List<labelList> isl(islands());
    stats_.islands = isl.size();
    for (const labelList& cs : isl)
    {
        solveIsland(cs, h);
    }
}


Foam::vector Foam::contactIslands::pointVelocity
(
    const label i,
    const label p,
    const vector& r
) const
{
    return velocityAt(bodies_[i].vEnd, p, r);
}


// ************************************************************************* //
