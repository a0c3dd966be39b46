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

#include "counterRandom.H"
#include "mathematicalConstants.H"

#include <cmath>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// SplitMix64 finaliser (a bijective 64-bit mixing function)
inline std::uint64_t mix64(std::uint64_t z)
{
    z = (z ^ (z >> 30))*UINT64_C(0xBF58476D1CE4E5B9);
    z = (z ^ (z >> 27))*UINT64_C(0x94D049BB133111EB);
    return z ^ (z >> 31);
}

const std::uint64_t golden = UINT64_C(0x9E3779B97F4A7C15);

inline std::uint64_t bits
(
    const Foam::label seed,
    const Foam::label id,
    const Foam::label j
)
{
    const std::uint64_t stream =
        mix64(std::uint64_t(seed)*golden ^ mix64(std::uint64_t(id) + 1));
    return mix64(stream + (std::uint64_t(j) + 1)*golden);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::counterRandom::uniform
(
    const label seed,
    const label id,
    const label j
)
{
    // 53 random bits, shifted off 0 and 1
    return (double(bits(seed, id, j) >> 11) + 0.5)
       *(1.0/9007199254740992.0);
}


Foam::vector Foam::counterRandom::gaussian
(
    const label seed,
    const label id,
    const label draw
)
{
    const label j = 4*draw;
    const scalar r1 = std::sqrt(-2*std::log(uniform(seed, id, j)));
    const scalar a1 = constant::mathematical::twoPi*uniform(seed, id, j + 1);
    const scalar r2 = std::sqrt(-2*std::log(uniform(seed, id, j + 2)));
    const scalar a2 = constant::mathematical::twoPi*uniform(seed, id, j + 3);

    return vector(r1*std::cos(a1), r1*std::sin(a1), r2*std::cos(a2));
}


Foam::label Foam::counterRandom::seed31
(
    const label seed,
    const label id,
    const label j
)
{
    return label(bits(seed, id, j) >> 33);
}


// ************************************************************************* //
