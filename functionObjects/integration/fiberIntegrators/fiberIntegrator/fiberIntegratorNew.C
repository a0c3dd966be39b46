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

#include "fiberIntegrator.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fiberIntegrator> Foam::fiberIntegrator::New
(
    const dictionary& dict
)
{
    const word schemeType
    (
        dict.getOrDefault<word>("integrator", "BDF2")
    );

    Info<< "    Selecting fiber integrator " << schemeType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(schemeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "integrator",
            schemeType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<fiberIntegrator>(cstrIter()(dict));
}


// ************************************************************************* //
