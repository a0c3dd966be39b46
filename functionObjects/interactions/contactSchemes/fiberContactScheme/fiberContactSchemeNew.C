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

#include "fiberContactScheme.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

bool Foam::fiberContactScheme::found(const word& scheme)
{
    return modelConstructorTablePtr_->found(scheme);
}


Foam::autoPtr<Foam::fiberContactScheme> Foam::fiberContactScheme::New
(
    const word& scheme,
    const dictionary& dict,
    contact& model
)
{
    auto cstrIter = modelConstructorTablePtr_->cfind(scheme);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "scheme",
            scheme,
            *modelConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<fiberContactScheme>(cstrIter()(model));
}


// ************************************************************************* //
