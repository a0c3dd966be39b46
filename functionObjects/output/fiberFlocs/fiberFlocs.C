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

#include "fiberFlocs.H"
#include "SortableList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberFlocs::fiberFlocs
(
    const labelUList& ids,
    const UList<FixedList<label, 2>>& pairs
)
{
    // Fibers by index; union-find over the pairs
    Map<label> index(2*ids.size());
    forAll(ids, i)
    {
        index.insert(ids[i], i);
    }
    labelList parent(identity(ids.size()));
    labelList n(ids.size(), 1);
    auto root = [&parent](label i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    };
    for (const FixedList<label, 2>& p : pairs)
    {
        const auto a = index.cfind(p[0]);
        const auto b = index.cfind(p[1]);
        if (!a.found() || !b.found())
        {
            continue;
        }
        label ra = root(*a);
        label rb = root(*b);
        if (ra == rb)
        {
            continue;
        }
        if (n[ra] < n[rb])
        {
            std::swap(ra, rb);
        }
        parent[rb] = ra;
        n[ra] += n[rb];
    }

    // Name each floc by its lowest id
    Map<label> name;
    forAll(ids, i)
    {
        const label r = root(i);
        if (n[r] < 2)
        {
            continue;
        }
        auto it = name.find(r);
        if (!it.found())
        {
            name.insert(r, ids[i]);
        }
        else if (ids[i] < *it)
        {
            *it = ids[i];
        }
    }
    forAll(ids, i)
    {
        const label r = root(i);
        if (n[r] >= 2)
        {
            flocOf_.insert(ids[i], name[r]);
            size_.set(name[r], n[r]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::fiberFlocs::largest() const
{
    label m = 0;
    forAllConstIters(size_, iter)
    {
        m = max(m, iter.val());
    }
    return m;
}


Foam::List<Foam::FixedList<Foam::label, 2>> Foam::fiberFlocs::sizes() const
{
    Map<label> count;
    forAllConstIters(size_, iter)
    {
        count(iter.val()) = count.lookup(iter.val(), 0) + 1;
    }
    SortableList<label> s(count.toc());
    List<FixedList<label, 2>> out(s.size());
    forAll(s, k)
    {
        out[k] = FixedList<label, 2>{s[k], count[s[k]]};
    }
    return out;
}


// ************************************************************************* //
