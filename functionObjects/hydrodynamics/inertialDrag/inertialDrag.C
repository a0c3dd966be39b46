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
        // |a + s b| is analytic on the segment and in the ellipse about
        // it reaching |s| = 4h (its branch points, the complex roots of
        // |a + s b|^2, lie at |s| >= |a|/|b| >= 4h): ten-point
        // Gauss-Legendre converges there like (4 + sqrt(15))^-20, about
        // 1e-18 of the moments' scales (Trefethen, Approximation Theory
        // and Approximation Practice, Thm. 19.3).  Pairs of nodes +-s;
        // the difference of their speeds taken without cancellation:
        // f+ - f- = 4 (a.b) s/(f+ + f-).
        static const scalar x[5] =
        {
            0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
            0.8650633666889845, 0.9739065285171717
        };
        static const scalar w[5] =
        {
            0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
            0.1494513491505806, 0.0666713443086881
        };
        const scalar A = magA*magA;
        const scalar B2 = 2*(a & b);
        const scalar C = beta*beta;

        scalar m0 = 0, m1 = 0, m2 = 0;
        for (int i = 0; i < 5; ++i)
        {
            const scalar s = h*x[i];
            const scalar even = A + C*s*s;
            const scalar fp = std::sqrt(max(even + B2*s, scalar(0)));
            const scalar fm = std::sqrt(max(even - B2*s, scalar(0)));
            const scalar sum = fp + fm;
            m0 += w[i]*sum;
            m1 += (sum > 0 ? w[i]*s*(2*B2*s)/sum : 0);
            m2 += w[i]*s*s*sum;
        }
        M0 = h*m0;
        M1 = h*m1;
        M2 = h*m2;
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
