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

#include "keywordCheck.H"
#include "labelList.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::keywordCheck::distance
(
    const std::string& a,
    const std::string& b
)
{
    // One row of the dynamic-programming table at a time
    labelList prev(b.size() + 1), cur(b.size() + 1);
    forAll(prev, j)
    {
        prev[j] = j;
    }
    for (size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (size_t j = 1; j <= b.size(); ++j)
        {
            const label sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = min(sub, min(prev[j], cur[j - 1]) + 1);
        }
        prev.swap(cur);
    }
    return prev[b.size()];
}


Foam::word Foam::keywordCheck::nearest
(
    const word& key,
    const UList<word>& known
)
{
    word best;
    label dBest = labelMax;
    for (const word& k : known)
    {
        const label d = distance(key, k);
        if (d < dBest)
        {
            dBest = d;
            best = k;
        }
    }
    return best;
}


Foam::label Foam::keywordCheck::warnUnknown
(
    const dictionary& dict,
    const UList<word>& known,
    const word& where
)
{
    label nUnknown = 0;
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (known.found(key))
        {
            continue;
        }
        ++nUnknown;
        IOWarningInFunction(dict)
            << "Unknown entry '" << key << "' in " << where
            << ": ignored. Did you mean '" << nearest(key, known) << "'?"
            << endl;
    }
    return nUnknown;
}


Foam::scalar Foam::keywordCheck::positive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar v = dict.get<scalar>(key);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be positive, not " << v
            << exit(FatalIOError);
    }
    return v;
}


Foam::scalar Foam::keywordCheck::positive
(
    const dictionary& dict,
    const word& key,
    const scalar def
)
{
    return dict.found(key) ? positive(dict, key) : def;
}


void Foam::keywordCheck::noEffect
(
    const dictionary& dict,
    const word& key,
    const std::string& why
)
{
    if (dict.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' has no effect " << why.c_str()
            << "; remove it" << exit(FatalIOError);
    }
}


Foam::vector Foam::keywordCheck::unitVector
(
    const dictionary& dict,
    const word& key
)
{
    const vector p = dict.get<vector>(key);
    if (!(mag(p) > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be a non-zero vector, not " << p
            << exit(FatalIOError);
    }
    return p/mag(p);
}


Foam::label Foam::keywordCheck::seed(const dictionary& dict)
{
    const label s = dict.getOrDefault<label>("seed", 1);
    if (s < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'seed' must be at least 0, not " << s
            << exit(FatalIOError);
    }
    return s;
}


const Foam::dictionary* Foam::keywordCheck::optionalSubDict
(
    const dictionary& dict,
    const word& key,
    const string& example
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return nullptr;
    }
    if (!e->isDict())
    {
        // Not primitiveEntry::dict(), which aborts with a stack trace
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be a sub-dictionary, "
            << key << ' ' << example.c_str() << ", not a value ("
            << key;
        for (const token& t : e->stream())
        {
            FatalIOError << ' ' << t;
        }
        FatalIOError << ";)" << exit(FatalIOError);
    }
    return &e->dict();
}


const Foam::dictionary& Foam::keywordCheck::subDict
(
    const dictionary& dict,
    const word& key,
    const string& example
)
{
    const dictionary* d = optionalSubDict(dict, key, example);
    if (!d)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is missing: a sub-dictionary "
            << key << ' ' << example.c_str() << exit(FatalIOError);
    }
    return *d;
}


// ************************************************************************* //
