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

#include "fiberCounters.H"
#include "Pstream.H"
#include "ListOps.H"
#include "labelField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberCounters::fiberCounters
(
    const labelList& outlets,
    const label nPatches
)
:
    nInjected_(0),
    nEscaped_(0),
    nDeposited_(0),
    nCarried_(0),
    outlets_(outlets),
    outletIndex_(nPatches, -1),
    nEscapedOutlet_(outlets.size(), 0),
    setNames_(),
    nInjectedSet_(),
    nEscapedSet_(),
    nDepositedSet_(),
    nCarriedSet_(),
    nEscapedStep_(0),
    nDepositedStep_(0),
    nEscapedOutletStep_(outlets.size(), 0),
    nEscapedSetStep_(),
    nDepositedSetStep_(),
    nCarriedStep_(0),
    nCarriedSetStep_()
{
    forAll(outlets_, i)
    {
        outletIndex_[outlets_[i]] = i;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCounters::setSets(const wordList& names)
{
    setNames_ = names;
    nInjectedSet_.setSize(names.size(), 0);
    nEscapedSet_.setSize(names.size(), 0);
    nDepositedSet_.setSize(names.size(), 0);
    nEscapedSetStep_.setSize(names.size(), 0);
    nDepositedSetStep_.setSize(names.size(), 0);
    nCarriedSet_.setSize(names.size(), 0);
    nCarriedSetStep_.setSize(names.size(), 0);
}


void Foam::fiberCounters::injectedAtStart(const labelUList& setIndex)
{
    nInjected_ = setIndex.size();
    nInjectedSet_ = 0;
    for (const label k : setIndex)
    {
        ++nInjectedSet_[k];
    }
}


void Foam::fiberCounters::beginStep()
{
    nEscapedStep_ = 0;
    nEscapedOutletStep_ = 0;
    nDepositedStep_ = 0;
    nEscapedSetStep_ = 0;
    nDepositedSetStep_ = 0;
    nCarriedStep_ = 0;
    nCarriedSetStep_ = 0;
}


void Foam::fiberCounters::endStep()
{
    nEscaped_ += returnReduce(nEscapedStep_, sumOp<label>());
    reduce(nEscapedOutletStep_, sumOp<labelList>());
    forAll(nEscapedOutlet_, i)
    {
        nEscapedOutlet_[i] += nEscapedOutletStep_[i];
    }
    nDeposited_ += returnReduce(nDepositedStep_, sumOp<label>());
    reduce(nEscapedSetStep_, sumOp<labelList>());
    reduce(nDepositedSetStep_, sumOp<labelList>());
    nCarried_ += returnReduce(nCarriedStep_, sumOp<label>());
    reduce(nCarriedSetStep_, sumOp<labelList>());
    forAll(setNames_, k)
    {
        nEscapedSet_[k] += nEscapedSetStep_[k];
        nDepositedSet_[k] += nDepositedSetStep_[k];
        nCarriedSet_[k] += nCarriedSetStep_[k];
    }
}


Foam::List<Foam::FixedList<Foam::label, 5>> Foam::fiberCounters::setCounts
(
    const labelUList& active,
    const labelUList& mat
) const
{
    List<FixedList<label, 5>> c(setNames_.size());
    forAll(c, k)
    {
        c[k][0] = nInjectedSet_[k];
        c[k][1] = active[k];
        c[k][2] = nEscapedSet_[k];
        c[k][3] = nDepositedSet_[k];
        c[k][4] = mat[k] + nCarriedSet_[k];
    }
    return c;
}


void Foam::fiberCounters::write(Ostream& os, const label nFeeds) const
{
    os  << "nInjected " << nInjected_ << " nEscaped " << nEscaped_
        << " nDeposited " << nDeposited_ << " nCarried " << nCarried_
        << nl
        << "nEscapedOutlet " << nEscapedOutlet_ << nl
        << "sets " << setNames_ << token::SPACE << nInjectedSet_
        << token::SPACE << nEscapedSet_ << token::SPACE << nDepositedSet_
        << token::SPACE << nCarriedSet_ << nl
        << "feeds " << nFeeds;
}


void Foam::fiberCounters::read(Istream& is, const label nFeeds)
{
    word key;
    is  >> key >> nInjected_ >> key >> nEscaped_ >> key >> nDeposited_
        >> key >> nCarried_;
    labelList outlets;
    is  >> key >> outlets;
    if (outlets.size() != nEscapedOutlet_.size())
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " counts "
            << outlets.size() << " outlet patches, the mesh has "
            << nEscapedOutlet_.size() << exit(FatalIOError);
    }
    nEscapedOutlet_ = outlets;
    const wordList names(setNames_);
    is  >> key >> setNames_ >> nInjectedSet_ >> nEscapedSet_
        >> nDepositedSet_ >> nCarriedSet_;
    label nFeedsFile;
    is  >> key >> nFeedsFile;
    if (setNames_ != names || nFeedsFile != nFeeds)
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " has the fiber"
            << " sets " << setNames_ << " (" << nFeedsFile << " fed through"
            << " patches); the dictionary has " << names << " ("
            << nFeeds << "). Restart with the sets of the run that"
            << " wrote it" << exit(FatalIOError);
    }
}


// ************************************************************************* //
