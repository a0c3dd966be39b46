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

#include "fiberDispersion.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fiberDispersion> Foam::fiberDispersion::New
(
    const dictionary& dict
)
{
    const word modelType(dict.getOrDefault<word>("dispersion", "none"));

    Info<< "    Selecting fiber dispersion model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "dispersion",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    keywordCheck::optionalSubDict(dict, modelType + "Coeffs", "{ ... }");
    return autoPtr<fiberDispersion>
    (
        cstrIter()(dict.subOrEmptyDict(modelType + "Coeffs"))
    );
}


// ************************************************************************* //
