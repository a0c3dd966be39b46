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

#include "fiberInteraction.H"
#include "keywordCheck.H"

// * * * * * * * * * * * * * * * * Selector  * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::fiberInteraction> Foam::fiberInteraction::New
(
    const dictionary& dict,
    const polyMesh& mesh,
    const scalar rhoFluid
)
{
    keywordCheck::optionalSubDict
    (
        dict, "interactions", "{ type contact; stiffness 0.1; ... }"
    );
    const dictionary& iDict = dict.subOrEmptyDict("interactions");
    const word modelType(iDict.getOrDefault<word>("type", "none"));

    Info<< "    Selecting fiber interactions " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            iDict,
            "type",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<fiberInteraction>(cstrIter()(iDict, mesh, rhoFluid));
}


// ************************************************************************* //
