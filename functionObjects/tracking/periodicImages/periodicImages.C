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

#include "periodicImages.H"
#include "treeDataCell.H"
#include "indexedOctree.H"
#include "openfoamCompat.H"
#include "fiberTracker.H"
#include "cyclicPolyPatch.H"
#include "cyclicAMIPolyPatch.H"
#include "processorCyclicPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Whether a and b are the same transform (to round-off of the domain)
bool sameTransform
(
    const vectorTensorTransform& a,
    const vectorTensorTransform& b,
    const scalar len
)
{
    if (a.hasR() != b.hasR())
    {
        return false;
    }
    if (a.hasR() && mag(a.R() - b.R()) > 1e-9)
    {
        return false;
    }
    return mag(a.t() - b.t()) <= 1e-9*len;
}

//- The distinct transforms into the periodic patches (cyclic, cyclicAMI
//  with a transform, processorCyclic) of all processors
List<vectorTensorTransform> distinctTransforms
(
    const polyMesh& mesh,
    const scalar len
)
{
    // The transforms into each periodic patch of this processor (cyclic,
    // cyclicAMI with a transform, processorCyclic), of all processors
    DynamicList<vectorTensorTransform> mine;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if
        (
            (isA<cyclicPolyPatch>(pp) || isA<cyclicAMIPolyPatch>(pp)
          || isA<processorCyclicPolyPatch>(pp))
         && pp.size()
        )
        {
            const vectorTensorTransform T
            (
                fiberTracker::receiving
                (
                    refCast<const coupledPolyPatch>(pp), 0
                )
            );
            if (T.hasR() || magSqr(T.t()) > 0)
            {
                mine.append(T);
            }
        }
    }
    List<List<vectorTensorTransform>> all(Pstream::nProcs());
    all[Pstream::myProcNo()] = mine;
    fiberCompat::allGatherList(all);

    // Distinct ones
    DynamicList<vectorTensorTransform> base;
    for (const List<vectorTensorTransform>& l : all)
    {
        for (const vectorTensorTransform& T : l)
        {
            bool known = false;
            for (const vectorTensorTransform& B : base)
            {
                known = known || sameTransform(T, B, len);
            }
            if (!known)
            {
                base.append(T);
            }
        }
    }
    return List<vectorTensorTransform>(std::move(base));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vectorTensorTransform> Foam::periodicImages::transforms
(
    const polyMesh& mesh,
    label& nBase
)
{
    // Distinct transforms in pairs {T, T^-1} (one pair per periodic
    // direction), and the images of every combination of at most one of
    // each pair (faces, edges and corners of a box periodic in three
    // directions: 26)
    const scalar len = mag(mesh.bounds().span());
    const List<vectorTensorTransform> base(distinctTransforms(mesh, len));
    DynamicList<label> group(base.size(), -1);
    label nGroups = 0;
    forAll(base, i)
    {
        if (group[i] >= 0)
        {
            continue;
        }
        group[i] = nGroups;
        forAll(base, j)
        {
            const vectorTensorTransform TT
            (
                fiberTracker::after(base[j], base[i])
            );
            if
            (
                j != i && group[j] < 0
             && !TT.hasR() && magSqr(TT.t()) <= sqr(1e-9*len)
            )
            {
                group[j] = nGroups;
            }
        }
        ++nGroups;
    }
    DynamicList<vectorTensorTransform> comp;
    DynamicList<labelList> used;
    forAll(base, i)
    {
        const label n = comp.size();
        comp.append(base[i]);
        used.append(labelList(1, group[i]));
        for (label k = 0; k < n; ++k)
        {
            if (used[k].found(group[i]))
            {
                continue;
            }
            comp.append(fiberTracker::after(base[i], comp[k]));
            labelList u(used[k]);
            u.append(group[i]);
            used.append(u);
        }
    }
    nBase = base.size();
    return List<vectorTensorTransform>(std::move(comp));
}


Foam::label Foam::periodicImages::findCell
(
    const polyMesh& mesh,
    const point& p
)
{
    return mesh.cellTree().bb().contains(p) ? mesh.findCell(p) : -1;
}


bool Foam::periodicImages::inside
(
    const polyMesh& mesh,
    const UList<vectorTensorTransform>& images,
    const point& p
)
{
    if (findCell(mesh, p) >= 0)
    {
        return true;
    }
    for (const vectorTensorTransform& T : images)
    {
        if (findCell(mesh, T.transformPosition(p)) >= 0)
        {
            return true;
        }
    }
    return false;
}


// ************************************************************************* //
