/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | fiberTracking: rigid fibers for OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
License
    This file is part of fiberTracking, distributed under GPL-3.0-or-later.

Description
    fiberCloud: the restart file (counts, feeds, the coupling's averages,
    every fiber with its mesh locations).

\*---------------------------------------------------------------------------*/

#include "fiberCloud.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

void writeLocation(Ostream& os, const trackedPoint& tp)
{
    os  << tp.celli << token::SPACE << tp.tetFacei << token::SPACE
        << tp.tetPti;
    for (direction k = 0; k < 4; ++k)
    {
        os << token::SPACE << tp.coordinates[k];
    }
}


void readLocation(Istream& is, trackedPoint& tp)
{
    is >> tp.celli >> tp.tetFacei >> tp.tetPti;
    for (direction k = 0; k < 4; ++k)
    {
        is >> tp.coordinates[k];
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberCloud::writeRestart(Ostream& os) const
{
    os  << "nProcs " << Pstream::nProcs() << " proc " << Pstream::myProcNo()
        << " cells " << mesh_.nCells() << nl;
    counters_.write(os, feeds_.size());
    for (const fiberPatchInjection& feed : feeds_)
    {
        os << token::SPACE;
        feed.writeRestart(os);
    }
    os  << nl << "coupled " << label(coupling_.valid());
    if (coupling_.valid())
    {
        os  << nl << coupling_->force().field() << nl
            << coupling_->dragRate().field();
    }
    os  << nl
        << "nFibers " << fibers_.size() + mats_.size() << nl;
    for (const PtrList<fiber>* fs : {&fibers_, &mats_.fibers()})
    {
        for (const fiber& f : *fs)
        {
            os << f << nl;
            writeLocation(os, f.location());
            for (const trackedPoint& tp : f.segmentLocations())
            {
                os << token::SPACE;
                writeLocation(os, tp);
            }
            os << nl;
        }
    }
    interactions_->writeRestart(os);
    os.check(FUNCTION_NAME);
}


void Foam::fiberCloud::readRestart(Istream& is)
{
    // Written by this decomposition of this mesh?
    word key;
    label nProcs, proc, nCells;
    is >> key >> nProcs >> key >> proc >> key >> nCells;
    if
    (
        nProcs != Pstream::nProcs() || proc != Pstream::myProcNo()
     || nCells != mesh_.nCells()
    )
    {
        FatalIOErrorInFunction(is)
            << "The fiber restart file " << is.name() << " was written by"
            << " processor " << proc << " of " << nProcs << " on a mesh of "
            << nCells << " cells; this is processor " << Pstream::myProcNo()
            << " of " << Pstream::nProcs() << " with " << mesh_.nCells()
            << " cells. Restart with the decomposition the file was written"
            << " with (docs: restart)" << exit(FatalIOError);
    }
    counters_.read(is, feeds_.size());
    for (fiberPatchInjection& feed : feeds_)
    {
        feed.readRestart(is);
    }
    readCoupling(is);

    // The fibers; those in a mat at rest go to mats_
    label n;
    is >> key >> n;
    fibers_.setSize(n);
    PtrList<fiber> resting(n);
    label nF = 0;
    label nR = 0;
    for (label fi = 0; fi < n; ++fi)
    {
        fiber* fPtr = new fiber(is);
        readLocation(is, fPtr->location());
        for (trackedPoint& tp : fPtr->segmentLocations())
        {
            readLocation(is, tp);
        }
        if (restsInMat(*fPtr))
        {
            resting.set(nR++, fPtr);
        }
        else
        {
            fibers_.set(nF++, fPtr);
        }
    }
    fibers_.setSize(nF);
    resting.setSize(nR);
    mats_.add(resting);
    interactions_->readRestart(is);
    is.check(FUNCTION_NAME);
    checkLocations();

    Info<< "    Restart: " << returnReduce(n, sumOp<label>())
        << " fibers read (injected " << counters_.nInjected()
        << ", escaped " << counters_.nEscaped() << ", deposited "
        << counters_.nDeposited() << "); the injection is not repeated"
        << endl;
}


void Foam::fiberCloud::readCoupling(Istream& is)
{
    // The coupling's averages of the last step (written by a coupled run)
    word key;
    label wasCoupled;
    is  >> key >> wasCoupled;
    if (wasCoupled)
    {
        const vectorField S(is);
        const scalarField beta(is);
        if (coupling_.valid())
        {
            coupling_->restore(S, beta);
        }
    }
    else if (coupling_.valid())
    {
        Info<< "    Restart: the file was written without coupling; the"
            << " fibers act on the fluid from the first step on" << endl;
    }
}

// ************************************************************************* //
