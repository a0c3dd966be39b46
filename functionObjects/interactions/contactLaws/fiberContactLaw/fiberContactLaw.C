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
#include "keywordCheck.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fiberContactLaw, 0);
    defineRunTimeSelectionTable(fiberContactLaw, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberContactLaw::fiberContactLaw(const dictionary& dict)
:
    mu_(dict.getOrDefault<scalar>("friction", 0)),
    cohesion_(0),
    range_(0)
{
    if (mu_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'friction' must not be negative, not " << mu_
            << exit(FatalIOError);
    }
    const dictionary* cohesionDict =
        keywordCheck::optionalSubDict
        (
            dict, "cohesion", "{ strength 1e-6; range 2e-6; }"
        );
    if (cohesionDict)
    {
        const dictionary& c = *cohesionDict;
        keywordCheck::warnUnknown
        (
            c,
            wordList({"strength", "range"}),
            "interactions/cohesion"
        );
        cohesion_ = keywordCheck::positive(c, "strength");
        range_ = keywordCheck::positive(c, "range");
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::wordList Foam::fiberContactLaw::commonKeywords()
{
    return wordList({"law", "friction", "cohesion"});
}


// ************************************************************************* //
