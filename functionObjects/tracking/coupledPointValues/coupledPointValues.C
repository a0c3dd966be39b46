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

#include "coupledPointValues.H"
#include "globalMeshData.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coupledPointValues::coupledPointValues(const fvMesh& mesh)
:
    mesh_(mesh),
    any_
    (
        returnReduce
        (
            mesh.globalData().coupledPatch().nPoints() > 0,
            orOp<bool>()
        )
    )
{}


// ************************************************************************* //
