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
#include "syncTools.H"
#include "pointConstraints.H"
#include "emptyPolyPatch.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::coupledPointValues::correct
(
    const GeometricField<Type, fvPatchField, volMesh>& vf,
    GeometricField<Type, pointPatchField, pointMesh>& pf
) const
{
    if (!any_)
    {
        return;
    }

    const labelList& meshPoints =
        mesh_.globalData().coupledPatch().meshPoints();
    const Map<label>& index =
        mesh_.globalData().coupledPatch().meshPointMap();
    const pointField& points = mesh_.points();
    const vectorField& C = mesh_.cellCentres();
    const vectorField& Cf = mesh_.faceCentres();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const surfaceScalarField& magSf = mesh_.magSf();

    // A non-coupled, non-empty patch (volPointInterpolation's test;
    // cyclicAMI counts as coupled)
    auto proper = [&](const label patchi)
    {
        return
            !isA<emptyPolyPatch>(pbm[patchi])
         && !magSf.boundaryField()[patchi].coupled();
    };

    // Patch points: on such a patch on any processor
    boolList onPatch(meshPoints.size(), false);
    forAll(pbm, patchi)
    {
        if (!proper(patchi))
        {
            continue;
        }
        for (const face& f : pbm[patchi])
        {
            for (const label pointi : f)
            {
                const auto iter = index.cfind(pointi);
                if (iter.found())
                {
                    onPatch[*iter] = true;
                }
            }
        }
    }
    syncTools::syncPointList
    (
        mesh_, meshPoints, onPatch, orEqOp<bool>(), false
    );

    // Weighted sums of this processor's copy
    List<Type> sum(meshPoints.size(), Zero);
    scalarList weight(meshPoints.size(), Zero);
    forAll(meshPoints, i)
    {
        const label pointi = meshPoints[i];
        if (onPatch[i])
        {
            for (const label facei : mesh_.pointFaces()[pointi])
            {
                if (mesh_.isInternalFace(facei))
                {
                    continue;
                }
                const label patchi = pbm.whichPatch(facei);
                if (!proper(patchi))
                {
                    continue;
                }
                const label patchFacei = facei - pbm[patchi].start();
                const scalar w = 1.0/mag(points[pointi] - Cf[facei]);
                sum[i] += w*vf.boundaryField()[patchi][patchFacei];
                weight[i] += w;
            }
        }
        else
        {
            for (const label celli : mesh_.pointCells()[pointi])
            {
                const scalar w = 1.0/mag(points[pointi] - C[celli]);
                sum[i] += w*vf[celli];
                weight[i] += w;
            }
        }
    }

    // Over all copies, each once (the cyclics' transforms applied)
    syncTools::syncPointList
    (
        mesh_, meshPoints, sum, plusEqOp<Type>(), Type(Zero)
    );
    syncTools::syncPointList
    (
        mesh_, meshPoints, weight, plusEqOp<scalar>(), scalar(0)
    );

    Field<Type>& pfi = pf.primitiveFieldRef();
    forAll(meshPoints, i)
    {
        pfi[meshPoints[i]] = sum[i]/weight[i];
    }

    // The patch constraints (symmetry, wedge) as volPointInterpolation
    // applies them
    pointConstraints::New(pf.mesh()).constrain(pf, false);
}


// ************************************************************************* //
