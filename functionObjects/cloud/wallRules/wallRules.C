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

#include "wallRules.H"
#include "polyPatch.H"
#include "SubField.H"
#include "keywordCheck.H"
#include "wordRes.H"
#include "ListOps.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::wallRules::rule> Foam::wallRules::ruleNames
{
    { rule::rebound, "rebound" },
    { rule::deposit, "deposit" },
    { rule::mat, "mat" },
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wallRules::rule Foam::wallRules::readRule
(
    const dictionary& dict,
    const entry& e,
    wire& w
) const
{
    const keyType& key = e.keyword();
    const dictionary* sub = e.isDict() ? &e.dict() : nullptr;
    word name;
    if (sub)
    {
        name = sub->get<word>("type");
    }
    else
    {
        e.stream() >> name;
    }
    if (!ruleNames.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wallInteraction': unknown rule '" << name
            << "' for '" << key << "'; valid rules: "
            << ruleNames.sortedToc() << exit(FatalIOError);
    }
    const rule r = ruleNames[name];
    w = wire{-1, Zero, false, -1, 0.01, 0, Zero, 20};
    if (!sub)
    {
        return r;
    }
    const wordList known
    (
        r == rule::mat
      ? wordList({"type", "velocity", "join", "restSpeed", "restFraction",
            "restTime", "machineDirection", "randomSheets"})
      : wordList({"type"})
    );
    for (const entry& se : *sub)
    {
        if (!known.found(se.keyword()))
        {
            FatalIOErrorInFunction(*sub)
                << "Entry 'wallInteraction': '" << se.keyword()
                << "' has no meaning for rule " << name << " of '" << key
                << "'; known: " << known << exit(FatalIOError);
        }
    }
    if (r == rule::mat)
    {
        const dictionary& md = *sub;
        w.U = md.getOrDefault<vector>("velocity", Zero);
        const word join(md.getOrDefault<word>("join", "rest"));
        if (join != "rest" && join != "contact")
        {
            FatalIOErrorInFunction(md)
                << "Entry 'join' of '" << key << "': 'rest' or 'contact',"
                << " not '" << join << "'" << exit(FatalIOError);
        }
        w.capture = (join == "contact");
        w.restSpeed =
            md.found("restSpeed") ? keywordCheck::positive(md, "restSpeed")
          : -1;
        w.restFraction = keywordCheck::positive(md, "restFraction", 0.01);
        w.restTime = md.getOrDefault<scalar>("restTime", 0);
        // MD: as given, else a belt's direction of motion
        w.md = mag(w.U) > 0 ? w.U/mag(w.U) : vector(Zero);
        if (md.found("machineDirection"))
        {
            w.md = keywordCheck::unitVector(md, "machineDirection");
        }
        w.nRandom = md.getOrDefault<label>("randomSheets", 20);
        if (w.nRandom < 2)
        {
            FatalIOErrorInFunction(md)
                << "Entry 'randomSheets' of '" << key << "' must be at"
                << " least 2 (the reference's spread), not " << w.nRandom
                << exit(FatalIOError);
        }
        if (w.restTime < 0)
        {
            FatalIOErrorInFunction(md)
                << "Entry 'restTime' of '" << key << "' must not be"
                << " negative, not " << w.restTime << exit(FatalIOError);
        }
    }
    return r;
}


Foam::labelList Foam::wallRules::patchesOf
(
    const dictionary& dict,
    const keyType& key,
    const polyBoundaryMesh& pbm
) const
{
    const labelHashSet ids
    (
        pbm.patchSet(List<wordRe>(1, wordRe(key)), false, true)
    );
    if (ids.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'wallInteraction': '" << key << "' names no patch"
            << " (nor patch group) of the mesh; its patches: "
            << pbm.names() << exit(FatalIOError);
    }
    return ids.sortedToc();
}


void Foam::wallRules::applyEntry
(
    const dictionary& rules,
    const entry& e,
    const polyBoundaryMesh& pbm,
    const labelUList& walls,
    const labelUList& outlets,
    List<wire>& wireOfPatch
)
{
    const keyType& key = e.keyword();
    wire w;
    const rule r = readRule(rules, e, w);
    for (const label patchi : patchesOf(rules, key, pbm))
    {
        const bool isWall = walls.found(patchi);
        if (!isWall && !outlets.found(patchi))
        {
            FatalIOErrorInFunction(rules)
                << "Entry 'wallInteraction': patch " << pbm[patchi].name()
                << " (of '" << key << "') is " << pbm[patchi].type()
                << ": fibers pass it or are mirrored there, no rule"
                << " applies" << exit(FatalIOError);
        }
        if (!isWall && r != rule::mat)
        {
            FatalIOErrorInFunction(rules)
                << "Entry 'wallInteraction': patch " << pbm[patchi].name()
                << " (of '" << key << "') is an outlet ("
                << pbm[patchi].type() << "): fibers leave through it, or"
                << " stop there with rule mat; not " << ruleNames[r]
                << exit(FatalIOError);
        }
        if (r == rule::mat)
        {
            checkTangent(rules, key, pbm[patchi], w.U);
        }
        rule_[patchi] = r;
        wireOfPatch[patchi] = w;
    }
}


void Foam::wallRules::checkTangent
(
    const dictionary& dict,
    const keyType& key,
    const polyPatch& pp,
    const vector& U
) const
{
    // A belt moves in its own surface: the velocity tangent to every face
    // of the patch (of every processor's part)
    scalar un = 0;
    for (const vector& Sf : pp.faceAreas())
    {
        un = max(un, mag(Sf & U)/max(mag(Sf), VSMALL));
    }
    reduce(un, maxOp<scalar>());
    if (un > 1e-6*mag(U))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'velocity' of '" << key << "': " << U << " is not"
            << " tangent to patch " << pp.name() << " (a normal component"
            << " of up to " << un << " m/s); a belt moves in its surface"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallRules::wallRules
(
    const dictionary& dict,
    const polyBoundaryMesh& pbm,
    const labelUList& walls,
    const labelUList& outlets
)
:
    rule_(pbm.size(), rule::rebound),
    wire_(pbm.size(), -1),
    applies_(pbm.size(), false),
    wires_()
{
    for (const label patchi : walls)
    {
        applies_[patchi] = true;
    }
    List<wire> wireOfPatch(pbm.size());
    wire w{-1, Zero, false, -1, 0.01, 0, Zero, 20};
    const dictionary* rulesPtr = dict.findDict("wallInteraction");
    if (!rulesPtr)
    {
        // One rule for every wall (a mat would be every wall's)
        const word name(dict.getOrDefault<word>("wallInteraction", "rebound"));
        if (!ruleNames.found(name))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wallInteraction': unknown rule '" << name
                << "'; valid rules: " << ruleNames.sortedToc()
                << exit(FatalIOError);
        }
        for (const label patchi : walls)
        {
            rule_[patchi] = ruleNames[name];
            wireOfPatch[patchi] = w;
        }
    }
    else
    {
        const dictionary& rules = *rulesPtr;
        if (rules.found("default"))
        {
            const entry* def = rules.findEntry("default", keyType::LITERAL);
            const rule r = readRule(rules, *def, w);
            for (const label patchi : walls)
            {
                rule_[patchi] = r;
                wireOfPatch[patchi] = w;
            }
        }

        // Groups and expressions first, then the literal names
        for (const bool literal : {false, true})
        {
            for (const entry& e : rules)
            {
                const keyType& key = e.keyword();
                const bool isName = pbm.findPatchID(key) >= 0;
                if (key != "default" && isName == literal)
                {
                    applyEntry(rules, e, pbm, walls, outlets, wireOfPatch);
                }
            }
        }
    }

    DynamicList<wire> wires;
    forAll(rule_, patchi)
    {
        if (rule_[patchi] == rule::mat)
        {
            applies_[patchi] = true;
            wire_[patchi] = wires.size();
            wires.append(wireOfPatch[patchi]);
            wires.last().patch = patchi;
        }
    }
    wires_.transfer(wires);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::wallRules::anyCapture() const
{
    for (const wire& w : wires_)
    {
        if (w.capture)
        {
            return true;
        }
    }
    return false;
}


bool Foam::wallRules::anyMoving() const
{
    for (const wire& w : wires_)
    {
        if (mag(w.U) > 0)
        {
            return true;
        }
    }
    return false;
}


bool Foam::wallRules::any(const rule r) const
{
    forAll(rule_, patchi)
    {
        if (applies_[patchi] && rule_[patchi] == r)
        {
            return true;
        }
    }
    return false;
}



void Foam::wallRules::report(const polyBoundaryMesh& pbm) const
{
    Info<< "    Wall interaction:";
    forAll(rule_, patchi)
    {
        if (applies_[patchi] && rule_[patchi] != rule::rebound)
        {
            Info<< ' ' << pbm[patchi].name() << ' '
                << ruleNames[rule_[patchi]];
        }
    }
    const bool special = wires_.size() || any(rule::deposit);
    Info<< (special ? "; rebound elsewhere" : " rebound") << endl;
}


// ************************************************************************* //
