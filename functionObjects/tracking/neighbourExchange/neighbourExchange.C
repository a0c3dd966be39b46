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

#include "neighbourExchange.H"
#include "processorPolyPatch.H"
#include "Pstream.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::neighbourExchange::neighbourExchange(const polyMesh& mesh)
:
    neighbours_(),
    isNeighbour_(Pstream::nProcs(), false),
    send_(Pstream::nProcs()),
    recv_(Pstream::nProcs()),
    recvPos_(Pstream::nProcs(), 0)
{
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<processorPolyPatch>(pp))
        {
            isNeighbour_
            [
                refCast<const processorPolyPatch>(pp).neighbProcNo()
            ] = true;
        }
    }
    DynamicList<label> nbr;
    forAll(isNeighbour_, proci)
    {
        if (isNeighbour_[proci])
        {
            nbr.append(proci);
        }
    }
    neighbours_.transfer(nbr);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::autoPtr<Foam::UOPstream> Foam::neighbourExchange::sendStream
(
    const label proci
)
{
    if (!isNeighbour_[proci])
    {
        FatalErrorInFunction
            << "Processor " << proci << " is not a neighbour of "
            << Pstream::myProcNo() << exit(FatalError);
    }
    return autoPtr<UOPstream>
    (
        new UOPstream
        (
            UPstream::commsTypes::nonBlocking,
            proci,
            send_[proci],
            tag_,
            UPstream::worldComm,
            false
        )
    );
}


void Foam::neighbourExchange::exchange()
{
    const label nProcs = Pstream::nProcs();

    // One size to every neighbour
    List<labelList> sizeOut(nProcs);
    List<labelList> sizeIn(nProcs);
    labelList one(nProcs, 0);
    for (const label proci : neighbours_)
    {
        sizeOut[proci] = labelList(1, send_[proci].size());
        sizeIn[proci].setSize(1);
        one[proci] = 1;
    }
    Pstream::exchange<labelList, label>
    (
        sizeOut, one, sizeIn, tag_, UPstream::worldComm
    );

    // The buffers that are not empty
    labelList recvSizes(nProcs, 0);
    for (const label proci : neighbours_)
    {
        recvSizes[proci] = sizeIn[proci][0];
    }
    forAll(recv_, proci)
    {
        recv_[proci].setSize(recvSizes[proci]);
        recvPos_[proci] = 0;
    }
    Pstream::exchange<DynamicList<char>, char>
    (
        send_, recvSizes, recv_, tag_ + 1, UPstream::worldComm
    );
    for (DynamicList<char>& buf : send_)
    {
        buf.clear();
    }
}


Foam::autoPtr<Foam::UIPstream> Foam::neighbourExchange::recvStream
(
    const label proci
)
{
    return autoPtr<UIPstream>
    (
        new UIPstream
        (
            UPstream::commsTypes::nonBlocking,
            proci,
            recv_[proci],
            recvPos_[proci],
            tag_,
            UPstream::worldComm,
            false
        )
    );
}


// ************************************************************************* //
