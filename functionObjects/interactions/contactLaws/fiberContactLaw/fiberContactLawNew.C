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

#include "fiberContactLaw.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fiberContactLaw> Foam::fiberContactLaw::New
(
    const dictionary& dict
)
{
    const word lawType(dict.getOrDefault<word>("law", "linear"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "law",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<fiberContactLaw>(cstrIter()(dict));
}


// ************************************************************************* //
