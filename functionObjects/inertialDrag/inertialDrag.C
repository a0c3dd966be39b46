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

#include "inertialDrag.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;

// Antiderivatives of t^k sqrt(q^2 + beta^2 t^2), k = 0, 1, 2
void antiderivatives
(
    const scalar t,
    const scalar q,
    const scalar beta,
    scalar I[3]
)
{
    const scalar b2 = beta*beta;
    const scalar Q = std::sqrt(q*q + b2*t*t);

    if (q > 0)
    {
        const scalar as = std::asinh(beta*t/q);
        I[0] = 0.5*t*Q + q*q/(2*beta)*as;
        I[2] =
            t*(2*b2*t*t + q*q)*Q/(8*b2)
          - q*q*q*q/(8*b2*beta)*as;
    }
    else
    {
        I[0] = 0.5*beta*t*std::abs(t);
        I[2] = 0.25*beta*t*t*t*std::abs(t);
    }
    I[1] = Q*Q*Q/(3*b2);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::inertialDrag::moments
(
    const vector& a,
    const vector& b,
    const scalar l,
    scalar& M0,
    scalar& M1,
    scalar& M2
)
{
    const scalar h = 0.5*l;
    const scalar magA = mag(a);
    const scalar beta = mag(b);

    if (beta*h <= 0.25*magA)
    {
        // Taylor series of sqrt(A + 2 B s + C s^2) about s = 0; the roots
        // of the quadratic lie at |s| = |a|/|b| >= 4h.
        M0 = M1 = M2 = 0;
        if (magA <= 0)
        {
            return;
        }

        const scalar P1 = 2*(a & b);
        const scalar P2 = beta*beta;

        // Terms needed: |a + s b| = |a| sqrt((1 - s/r1)(1 - s/r2)), the
        // roots at |r| = |a|/|b|; the binomial coefficients of sqrt(1 - x)
        // are at most 1/2 (k >= 1), so |c_n| h^n <= |a| rho^n (n + 3)/4,
        // rho = |b| h/|a| <= 1/4, and the terms beyond n = N add at most
        // rho^(N+1)/(1 - rho) of the moments' scales 2 h |a|, h^2 |a|,
        // 2 h^3 |a|/3: N from rho^(N+1) <= 1e-17 (1 - rho)
        const scalar rho = beta*h/magA;
        const int nMax = 40;
        int nTerms = 1;
        for (scalar r = rho; nTerms < nMax && r > 1e-17*(1 - rho); r *= rho)
        {
            ++nTerms;
        }
        scalar c[nMax];
        c[0] = magA;

        scalar hPow = h;   // h^(n+1)
        for (int n = 0; n < nTerms; ++n)
        {
            if (n > 0)
            {
                // c_n from sum_k c_k c_(n-k) = P_n (P_n = 0, n > 2), the
                // symmetric sum taken once
                scalar rhs = (n == 1 ? P1 : (n == 2 ? P2 : 0));
                for (int k = 1; 2*k < n; ++k)
                {
                    rhs -= 2*c[k]*c[n - k];
                }
                if (n % 2 == 0 && n > 1)
                {
                    rhs -= c[n/2]*c[n/2];
                }
                c[n] = rhs/(2*c[0]);
            }

            // integral of s^(n+k) over [-h, h]: 2 h^(n+k+1)/(n+k+1), even
            if (n % 2 == 0)
            {
                M0 += c[n]*2*hPow/(n + 1);
                M2 += c[n]*2*hPow*h*h/(n + 3);
            }
            else
            {
                M1 += c[n]*2*hPow*h/(n + 2);
            }
            hPow *= h;
        }
        return;
    }

    // Closed form about the point of smallest speed s0
    const scalar s0 = -(a & b)/(beta*beta);
    const scalar q = mag(a ^ b)/beta;

    scalar Iu[3], Il[3];
    antiderivatives(h - s0, q, beta, Iu);
    antiderivatives(-h - s0, q, beta, Il);

    const scalar J0 = Iu[0] - Il[0];
    const scalar J1 = Iu[1] - Il[1];
    const scalar J2 = Iu[2] - Il[2];

    M0 = J0;
    M1 = J1 + s0*J0;
    M2 = J2 + 2*s0*J1 + s0*s0*J0;
}


// ************************************************************************* //
