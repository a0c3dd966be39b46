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

#include "fiberTracking.H"
#include "contact.H"
#include "fiberFlocs.H"
#include "keywordCheck.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "fvcGrad.H"
#include "transportModel.H"
#include "turbulenceModel.H"
#include "fvOptions.H"
#include "fiberMomentumSource.H"
#include "addToRunTimeSelectionTable.H"

#include <ctime>
#include <cmath>
#include <string>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(fiberTracking, 0);
    addToRunTimeSelectionTable(functionObject, fiberTracking, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// In post-processing OpenFOAM catches the errors of a function object,
// prints them as warnings and goes on without it: while one lives, errors
// end the run instead (a mistake in the dictionary must stop it)
class errorsEndTheRun
{
    const bool throwing_;
    const bool throwingIO_;

public:

    errorsEndTheRun()
    :
        throwing_(Foam::FatalError.throwExceptions(false)),
        throwingIO_(Foam::FatalIOError.throwExceptions(false))
    {}

    ~errorsEndTheRun()
    {
        Foam::FatalError.throwExceptions(throwing_);
        Foam::FatalIOError.throwExceptions(throwingIO_);
    }
};


// The coupled patches of a field evaluated: their values the neighbour
// cells' (a field read from disk holds what decomposePar wrote there; a
// solver evaluates them within its step)
void evaluateCoupled(Foam::volVectorField& f)
{
    using namespace Foam;
    volVectorField::Boundary& bf = f.boundaryFieldRef();
    const label nReq = Pstream::nRequests();
    forAll(bf, patchi)
    {
        if (bf[patchi].coupled())
        {
            bf[patchi].initEvaluate(Pstream::commsTypes::nonBlocking);
        }
    }
    if (Pstream::parRun())
    {
        Pstream::waitRequests(nReq);
    }
    forAll(bf, patchi)
    {
        if (bf[patchi].coupled())
        {
            bf[patchi].evaluate(Pstream::commsTypes::nonBlocking);
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::word Foam::functionObjects::fiberTracking::modelWithoutK
(
    const dictionary& turbulence
)
{
    // turbulenceProperties' own keywords (not entries of this object)
    const word simulationType("simulationType");
    const word type
    (
        turbulence.getOrDefault<word>(simulationType, "laminar")
    );
    if (type == "laminar")
    {
        return "laminar";
    }
    const word model
    (
        turbulence.subOrEmptyDict(type).getOrDefault<word>
        (
            type + "Model", word::null
        )
    );
    // The Spalart-Allmaras family transports nuTilda only: no k
    if (model.starts_with("SpalartAllmaras"))
    {
        return model;
    }
    return word::null;
}


void Foam::functionObjects::fiberTracking::checkFields
(
    const dictionary& dict
)
{
    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'U': no velocity field '" << UName_
            << "' in the case" << exit(FatalIOError);
    }

    if (nu_ <= 0 && !mesh_.foundObject<transportModel>("transportProperties"))
    {
        FatalIOErrorInFunction(dict)
            << "No transport model 'transportProperties' in the case:"
            << " give the kinematic viscosity as entry 'nu'"
            << exit(FatalIOError);
    }

    kFromModel_ = false;
    if (!cloud_->dispersion().active())
    {
        return;
    }

    // The solver's turbulence model, unless fields are named
    const turbulenceModel* tm =
        mesh_.findObject<turbulenceModel>(turbulenceModel::propertiesName);
    const bool named = dict.found("k") || dict.found("epsilon");
    const word noK(tm ? modelWithoutK(*tm) : word::null);
    if (tm && !named && noK.empty())
    {
        kFromModel_ = true;
        Info<< type() << " " << name() << ": k and epsilon of the random"
            << " walk from the turbulence model of the case";
        if (tm->lookupOrDefault<word>("simulationType", "") == "LES")
        {
            // The resolved velocity carries the large eddies: the walk adds
            // the fluctuation it does not (the subgrid scales)
            Info<< " (LES " << tm->type() << ": the subgrid k and epsilon,"
                << " the fluctuation the resolved velocity does not carry)";
        }
        Info<< endl;
        return;
    }
    if (tm && !named)
    {
        // Fields called k and epsilon may be left over from another model
        FatalIOErrorInFunction(dict)
            << "Entry 'dispersion " << dict.get<word>("dispersion")
            << "' needs k and epsilon: the turbulence model of the case ("
            << noK << ") has no turbulence kinetic energy k." << nl
            << "    The random walk needs a model that has (k-epsilon,"
            << " k-omega, k-omega SST, realizable k-epsilon, ...), or"
            << " fields named with entries 'k' and 'epsilon'." << nl
            << "    Use 'dispersion none' for a laminar case"
            << exit(FatalIOError);
    }

    wordList missing;
    for (const word& fld : {kName_, epsilonName_})
    {
        const bool onDisk =
            IOobject
            (
                fld, time_.timeName(), mesh_, IOobject::MUST_READ
            ).typeHeaderOk<volScalarField>(true);
        if (!mesh_.foundObject<volScalarField>(fld) && !onDisk)
        {
            missing.append(fld);
        }
    }
    if (missing.size())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'dispersion " << dict.get<word>("dispersion")
            << "' needs the turbulence fields (k epsilon); missing: "
            << missing << nl
            << "    They are neither fields of the case nor in "
            << time_.timePath() << ", and no turbulence model gives them."
            << nl
            << "    Use 'dispersion none' for a laminar case, or name"
            << " the fields with entries 'k' and 'epsilon'"
            << exit(FatalIOError);
    }
}


void Foam::functionObjects::fiberTracking::checkCouplingSource() const
{
    if (!cloud_->coupling())
    {
        return;
    }
    const fv::options* opts =
        mesh_.findObject<fv::options>(fv::options::typeName);
    if (opts)
    {
        const fv::optionList& list = *opts;
        forAll(list, i)
        {
            const fv::fiberMomentumSource* src =
                isA<fv::fiberMomentumSource>(list[i]);
            if (src && src->fiberTracking() == name())
            {
                return;
            }
        }
    }
    FatalIOErrorInFunction(dict_)
        << "Entry 'coupled': the fibers of '" << name() << "' act on the"
        << " fluid only through an fvOption, and none names them: the run"
        << " would be one-way." << nl
        << "    Add to system/fvOptions (or constant/fvOptions):" << nl
        << "    fiberDrag { type fiberMomentumSource; fiberTracking "
        << name() << "; }" << nl
        << "    or set 'coupled false'" << exit(FatalIOError);
}


Foam::tmp<Foam::scalarField>
Foam::functionObjects::fiberTracking::muCells() const
{
    if (nu_ > 0)
    {
        return tmp<scalarField>::New(mesh_.nCells(), rhoInf_*nu_);
    }

    const transportModel& tm =
        mesh_.lookupObject<transportModel>("transportProperties");

    return tmp<scalarField>::New(rhoInf_*tm.nu()().primitiveField());
}


const Foam::volScalarField&
Foam::functionObjects::fiberTracking::turbulenceField
(
    const word& fieldName,
    autoPtr<volScalarField>& disk
)
{
    if (mesh_.foundObject<volScalarField>(fieldName))
    {
        return mesh_.lookupObject<volScalarField>(fieldName);
    }
    // The latest time directory up to now that holds the field (a
    // transient run writes it only at write times)
    const word instance
    (
        time_.findInstance
        (
            fileName::null, fieldName, IOobject::READ_IF_PRESENT
        )
    );
    if (!disk.valid() || disk->instance() != instance)
    {
        disk.reset
        (
            new volScalarField
            (
                IOobject
                (
                    fieldName,
                    instance,
                    mesh_,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                mesh_
            )
        );
        Info<< type() << " " << name() << ": read " << fieldName
            << " from " << instance << endl;
    }
    return disk();
}


void Foam::functionObjects::fiberTracking::updateFields()
{
    const volVectorField& U = lookupObject<volVectorField>(UName_);
    if (functionObject::postProcess)
    {
        // Read from disk: processorCyclic patches hold what decomposePar
        // wrote, not the neighbour cells' values (docs/model.md D8)
        volVectorField Uc(U);
        evaluateCoupled(Uc);
        gradU_ = fvc::grad(Uc);
    }
    else
    {
        gradU_ = fvc::grad(U);
    }

    if (cloud_->dispersion().active() && kFromModel_)
    {
        const turbulenceModel& tm =
            lookupObject<turbulenceModel>(turbulenceModel::propertiesName);
        kModel_ = tm.k();
        epsilonModel_ = tm.epsilon();
        cloud_->sampler().update
        (
            U, gradU_(), muCells(), &kModel_(), &epsilonModel_()
        );
    }
    else if (cloud_->dispersion().active())
    {
        cloud_->sampler().update
        (
            U,
            gradU_(),
            muCells(),
            &turbulenceField(kName_, kDisk_),
            &turbulenceField(epsilonName_, epsilonDisk_)
        );
    }
    else
    {
        cloud_->sampler().update(U, gradU_(), muCells());
    }
}


void Foam::functionObjects::fiberTracking::advance
(
    const scalar dt,
    const bool logLine
)
{
    const std::clock_t c0 = std::clock();
    cloud_->evolve(fiberTime_, dt);
    const std::clock_t c1 = std::clock();
    cpuFibers_ += scalar(c1 - c0)/CLOCKS_PER_SEC;
    fiberTime_ += dt;
    if (cellFields_.valid())
    {
        cellFields_->add(cloud_->fibers(), dt);
    }

    writeStatistics();
    cpuOutput_ += scalar(std::clock() - c1)/CLOCKS_PER_SEC;
    if (logLine)
    {
        logStep();
    }
}


void Foam::functionObjects::fiberTracking::logStep() const
{
    const subStepStatistics& st = cloud_->stepStatistics();

    // Contacts: the pairs found touching at a window's start with a fiber
    // that had run through the last window on its own (collective)
    const fiberInteractions::contact* cm =
        dynamic_cast<const fiberInteractions::contact*>
        (
            &cloud_->interactions()
        );
    const label nMissed = cm ? cm->missedContacts() : 0;
    const label nJumped = cm ? cm->jumpedFibers() : 0;
    const label nAcross = cm && Pstream::parRun() ? cm->pairsAcross() : 0;
    const string bound
    (
        subStepStatistics::name(st.hMinLimit(), cloud_->control().ruleName())
    );
    Log << type() << " " << name() << " execute: fiber time " << fiberTime_
        << ", sub-steps " << cloud_->nSubMax()
        << " (median " << st.median() << " s, smallest " << st.hMin()
        << " s: " << bound.c_str() << "), fiber CPU time "
        << cpuFibers_ << " s for " << cloud_->nSegmentSteps()
        << " segment steps";
    if (cloud_->control().control() == subStepControl::mode::tolerance)
    {
        Log << " (" << cloud_->nRejected() << " sub-steps rejected)";
    }
    if (cloud_->interactions().active())
    {
        Log << ", interactions: " << cloud_->nIntervals()
            << " intervals in " << cloud_->nWindows() << " windows ("
            << cloud_->engagedFraction() << " of the fibers in them, ";
        if (nJumped > 0)
        {
            Log << nJumped << " fibers put back from walls unchecked, ";
        }
        if (nAcross > 0)
        {
            Log << nAcross << " constraint pairs solved across processors, ";
        }
        Log << nMissed << " contacts missed), CPU time "
            << cloud_->cpuInteractions() << " s";
    }
    if (Pstream::parRun())
    {
        Log << ", remote segment samples " << cloud_->nRemote();
        if (cloud_->nForwarded())
        {
            Log << " (" << cloud_->nForwarded() << " forwarded into a"
                << " further part)";
        }
        if (cloud_->nFurther())
        {
            Log << " (" << cloud_->nFurther() << " of them approximated"
                << " at a further processor boundary)";
        }
        Log << ", fibers transferred " << cloud_->nTransferred()
            << " (" << cloud_->nOnward() << " on into a further part)";
    }
    if (cloud_->hydrodynamics().autoBound() > 0)
    {
        Log << ", inertial drag in " << cloud_->nInertial() << " of "
            << cloud_->nInertial() + cloud_->nInertialSkipped()
            << " segment steps";
    }
    for (const fiberPatchInjection& feed : cloud_->feeds())
    {
        Log << ", set " << feed.name() << " released " << feed.nReleased()
            << " (" << feed.nRedrawn() << " candidates placed again)";
    }
    if (cloud_->nOutside())
    {
        Log << ", segment samples outside the mesh " << cloud_->nOutside()
            << " (data on the outlet face of a fiber straddling it)";
    }
    Log << ", output CPU time " << cpuOutput_ << " s" << endl;

    // Implicit contacts: what set the intervals' lengths (their cost)
    if (cm)
    {
        typedef fiberInteractions::contact ct;
        const FixedList<label, 7>& n = cm->limitedIntervals();
        label nAll = 0;
        for (const label k : n)
        {
            nAll += k;
        }
        if (nAll > 0)
        {
            Log << type() << " " << name() << " intervals so far, set by:"
                << " pairs touching and approaching " << n[ct::touching]
                << ", sliding contacts " << n[ct::sliding]
                << ", pairs approaching across a gap " << n[ct::approaching]
                << ", the far pairs (skin) " << n[ct::far]
                << ", growth (twice the last) " << n[ct::growth]
                << ", the first (a contact time) " << n[ct::first]
                << ", the step's end " << n[ct::stepEnd] << endl;
        }
    }
}


Foam::fileName Foam::functionObjects::fiberTracking::restartFile() const
{
    return time_.path()/time_.timeName()/"uniform"/"fiberTracking"/name();
}


void Foam::functionObjects::fiberTracking::writeRestart() const
{
    const fileName file(restartFile());
    mkDir(file.path());
    OFstream os(file);
    os.precision(17);
    os  << "fiberTime " << fiberTime_ << nl;
    cloud_->writeRestart(os);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write the fiber restart file " << file
            << exit(FatalError);
    }
}


void Foam::functionObjects::fiberTracking::progress(const bool last)
{
    // One decision for all processors (the lines are collective); the
    // CPU times differ between processors
    if
    (
        !last
     && !returnReduce(cpuFibers_ - cpuProgress_ >= 5, orOp<bool>())
    )
    {
        return;
    }
    cpuProgress_ = cpuFibers_;
    logStep();
    const fiberCloud::statistics s(cloud_->stats());
    Info<< type() << " " << name() << " progress: fiber time " << fiberTime_
        << " of " << duration_ << " s ("
        << label(100*fiberTime_/duration_ + 0.5) << " %), active "
        << s.nActive << ", escaped " << s.nEscaped << ", deposited "
        << s.nDeposited;
    if (cloud_->rules().wires().size())
    {
        Info<< ", in the mat " << s.nMat;
        if (cloud_->rules().anyMoving())
        {
            Info<< " (carried out " << s.nCarried << ")";
        }
    }
    Info<< "; " << cpuFibers_ << " s of CPU so far, "
        << (fiberTime_ > 0 ? cpuFibers_/fiberTime_ : 0)
        << " s of CPU per second of fiber time" << endl;
    if (!last)
    {
        reportCost();
    }
}


void Foam::functionObjects::fiberTracking::liveProgress()
{
    // One decision for all processors (reportCost is collective)
    if (!returnReduce(cpuFibers_ - cpuProgress_ >= 60, orOp<bool>()))
    {
        return;
    }
    cpuProgress_ = cpuFibers_;
    reportCost();
}


void Foam::functionObjects::fiberTracking::reportCost() const
{
    const string rule(cloud_->control().ruleName());
    const subStepStatistics& st = cloud_->runStatistics();
    const scalarList top(cloud_->costliest());
    Info<< type() << " " << name() << " sub-steps so far: ";
    st.report(Info, rule);
    Info<< endl;
    const label m = fiberCloud::costlySize;
    for (label k = 0; k < top.size()/m; ++k)
    {
        const scalar* r = &top[m*k];
        scalar n = 0;
        label lMax = 0;
        for (label l = 0; l < subStepStatistics::nLimits; ++l)
        {
            n += r[1 + l];
            if (r[1 + l] > r[1 + lMax])
            {
                lMax = l;
            }
        }
        const label j = 1 + subStepStatistics::nLimits;
        Info<< type() << " " << name() << " most sub-steps: fiber "
            << label(r[0]) << ", " << std::to_string(std::llround(n)).c_str()
            << " ("
            << subStepStatistics::name(lMax, rule).c_str() << " "
            << 0.1*std::round(1000*r[1 + lMax]/max(n, scalar(1)))
            << " %), at (" << r[j] << ' ' << r[j + 1] << ' ' << r[j + 2]
            << ") in cell " << label(r[j + 3]) << " at fiber time "
            << r[j + 4] << endl;
    }
}


void Foam::functionObjects::fiberTracking::writeSheets(const word& tag)
{
    if (!sheetWriter_.valid())
    {
        return;
    }
    const scalarList records(cloud_->gatherMatSegments());
    if (Pstream::master() && sheetFilePtr_.valid())
    {
        sheetWriter_->write
        (
            records, fiberTime_, startTimeDir()/"mat"/tag, sheetFilePtr_()
        );
    }
}


void Foam::functionObjects::fiberTracking::writeVtk(const word& tag)
{
    // Collective: every processor sends its segments if the master writes
    if (!returnReduce(vtkWriter_.valid(), orOp<bool>()))
    {
        return;
    }
    const scalarList records(cloud_->gatherSegments());
    if (vtkWriter_.valid())
    {
        vtkWriter_->write
        (
            records,
            fiberTime_,
            tag,
            isA<fiberInteractions::contact>(cloud_->interactions())
          ? &flocOf_ : nullptr
        );
    }
}


void Foam::functionObjects::fiberTracking::writeStatistics()
{
    const fiberCloud::statistics s(cloud_->stats());

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        os  << fiberTime_ << tab << s.nInjected << tab << s.nActive
            << tab << s.nEscaped << tab << s.nDeposited;
        for (direction k = 0; k < 3; ++k)
        {
            os << tab << s.absP[k];
        }
        for (direction k = 0; k < 6; ++k)
        {
            os << tab << s.pp[k];
        }
        if (cloud_->rules().wires().size())
        {
            os << tab << s.nMat;
        }
        if (cloud_->rules().anyMoving())
        {
            os << tab << s.nCarried;
        }
        os << endl;
    }

    writeCounts(s);

    // Deposits since the last call
    if (cloud_->rules().any(wallRules::rule::deposit))
    {
        const List<fiberCloud::state> dep(cloud_->gatherDeposits());
        if (Pstream::master() && depositFilePtr_.valid())
        {
            writeStates(dep, depositFilePtr_());
        }
    }

    writeExchange();
    writeContacts();

    // Events since the last call
    if (cloud_->loggingEvents())
    {
        const scalarList ev(cloud_->gatherEvents());
        if (Pstream::master() && eventFilePtr_.valid())
        {
            writeEvents(ev, eventFilePtr_());
        }
    }
}


void Foam::functionObjects::fiberTracking::writeCounts
(
    const fiberCloud::statistics& s
)
{
    // Per set, when there are two or more (collective)
    if (cloud_->setNames().size() > 1)
    {
        const List<FixedList<label, 5>> c(cloud_->setCounts());
        const label nCols = cloud_->rules().wires().size() ? 5 : 4;
        forAll(c, k)
        {
            if (c[k][0] != c[k][1] + c[k][2] + c[k][3] + c[k][4])
            {
                FatalErrorInFunction
                    << "Fiber count of set " << cloud_->setNames()[k]
                    << " broken: " << c[k] << exit(FatalError);
            }
        }
        if (Pstream::master() && setFilePtr_.valid())
        {
            OFstream& os = setFilePtr_();
            os  << fiberTime_;
            for (const FixedList<label, 5>& ck : c)
            {
                for (label j = 0; j < nCols; ++j)
                {
                    os << tab << ck[j];
                }
            }
            os << endl;
        }
    }

    if (Pstream::master() && outletFilePtr_.valid())
    {
        OFstream& os = outletFilePtr_();
        os  << fiberTime_;
        for (const label n : cloud_->nEscapedOutlet())
        {
            os << tab << n;
        }
        os << endl;
    }

    if
    (
        s.nInjected != s.nActive + s.nEscaped + s.nDeposited + s.nMat
     || s.nEscaped != sum(cloud_->nEscapedOutlet())
    )
    {
        FatalErrorInFunction
            << "Fiber count broken: injected " << s.nInjected
            << " != active " << s.nActive << " + escaped " << s.nEscaped
            << " + deposited " << s.nDeposited << " + in the mat "
            << s.nMat << ", or escaped != "
            << cloud_->nEscapedOutlet() << " summed over the outlets"
            << exit(FatalError);
    }
}


void Foam::functionObjects::fiberTracking::createContactFiles()
{
    if (!isA<fiberInteractions::contact>(cloud_->interactions()))
    {
        return;
    }
    contactFilePtr_ = newFileAtStart("fiberContacts");
    writeHeader
    (
        contactFilePtr_(),
        "Contacts between fibers and flocs (fiberTracking)"
    );
    writeCommented
    (
        contactFilePtr_(),
        "Time nFibers nPairs contactsPerFiber collisions collisionRate"
        " nFlocs largestFloc meanFlocSize fibersInFlocs"
    );
    contactFilePtr_() << endl;

    contactCountFilePtr_ = newFileAtStart("fiberContactCounts");
    writeHeader
    (
        contactCountFilePtr_(),
        "Fibers with k contacts, k = 0 ... 15, then 16 or more"
        " (fiberTracking)"
    );
    string columns("Time");
    for (label k = 0; k <= 16; ++k)
    {
        columns += " n" + Foam::name(k);
    }
    writeCommented(contactCountFilePtr_(), columns);
    contactCountFilePtr_() << endl;

    flocSizeFilePtr_ = newFileAtStart("fiberFlocSizes");
    writeHeader
    (
        flocSizeFilePtr_(),
        "Flocs per size at write times, a block per time (fiberTracking)"
    );
    writeCommented(flocSizeFilePtr_(), "Time size count");
    flocSizeFilePtr_() << endl;
}


Foam::labelList Foam::functionObjects::fiberTracking::localContacts
(
    const fiberInteractions::contact& cm,
    DynamicList<label>& ids
) const
{
    // The free fibers, and of a mat's stored fibers only those touching:
    // the rest have none (their count alone, not a walk over them at
    // every step)
    labelList count(17, 0);
    for (const fiber& f : cloud_->fibers())
    {
        ids.append(f.id());
        ++count[min(cm.contacts(f.id()), label(16))];
    }
    label nTouching = 0;
    forAllConstIters(cm.touchingFibers(), it)
    {
        if (cloud_->mats().find(it.key()) >= 0)
        {
            ids.append(it.key());
            ++count[min(it.val(), label(16))];
            ++nTouching;
        }
    }
    count[0] += cloud_->mats().size() - nTouching;
    return count;
}


void Foam::functionObjects::fiberTracking::writeContacts()
{
    fiberInteractions::contact* cm =
        dynamic_cast<fiberInteractions::contact*>(&cloud_->interactions());
    if (!cm || cloud_->nIntervals() == 0)
    {
        // No contacts searched yet (the start): no row
        return;
    }

    // The fibers, the pairs touching, the contacts per fiber (collective)
    List<labelList> ids(Pstream::nProcs());
    List<List<FixedList<label, 2>>> pairs(Pstream::nProcs());
    pairs[Pstream::myProcNo()] = cm->pairs();
    DynamicList<label> myIds(cloud_->fibers().size());
    labelList count(localContacts(*cm, myIds));
    ids[Pstream::myProcNo()] = myIds;
    label n = cloud_->fibers().size() + cloud_->mats().size();
    Pstream::gatherList(ids);
    Pstream::gatherList(pairs);
    reduce(count, sumOp<labelList>());
    reduce(n, sumOp<label>());
    const label nCollisions = cm->collisions();
    const scalar V = gSum(mesh_.V());
    const scalar dt = fiberTime_ - contactTime_;
    contactTime_ = fiberTime_;
    if (!Pstream::master())
    {
        return;
    }

    const labelList allIds(ListListOps::combine<labelList>
    (
        ids, accessOp<labelList>()
    ));
    const List<FixedList<label, 2>> allPairs
    (
        ListListOps::combine<List<FixedList<label, 2>>>
        (
            pairs, accessOp<List<FixedList<label, 2>>>()
        )
    );
    const fiberFlocs flocs(allIds, allPairs);
    flocOf_ = flocs.flocOf();
    if (!contactFilePtr_.valid())
    {
        return;
    }
    contactFilePtr_()
        << fiberTime_ << tab << n << tab << allPairs.size() << tab
        << (n ? 2.0*allPairs.size()/n : 0) << tab << nCollisions << tab
        << (dt > 0 ? nCollisions/(V*dt) : 0) << tab << flocs.nFlocs()
        << tab << flocs.largest() << tab
        << (flocs.nFlocs() ? scalar(flocs.nInFlocs())/flocs.nFlocs() : 0)
        << tab << flocs.nInFlocs() << endl;
    contactCountFilePtr_() << fiberTime_;
    for (const label c : count)
    {
        contactCountFilePtr_() << tab << c;
    }
    contactCountFilePtr_() << endl;
    if (time_.writeTime() || functionObject::postProcess)
    {
        for (const FixedList<label, 2>& s : flocs.sizes())
        {
            flocSizeFilePtr_()
                << fiberTime_ << tab << s[0] << tab << s[1] << nl;
        }
        flocSizeFilePtr_() << endl;
    }
}


void Foam::functionObjects::fiberTracking::writeExchange()
{
    // Momentum exchange: the source summed over the cells against the
    // fibers' hydrodynamic forces
    if (cloud_->coupling() && Pstream::master() && momentumFilePtr_.valid())
    {
        const vector& S = cloud_->coupling()->fluidForce();
        const vector& F = cloud_->coupling()->fiberForce();
        OFstream& os = momentumFilePtr_();
        os  << fiberTime_;
        for (direction k = 0; k < 3; ++k)
        {
            os << tab << S[k];
        }
        for (direction k = 0; k < 3; ++k)
        {
            os << tab << F[k];
        }
        os  << tab << mag(S + F)/max(mag(F), VSMALL);
        const vector& R = cloud_->coupling()->returned();
        for (direction k = 0; k < 3; ++k)
        {
            os << tab << R[k];
        }
        os  << endl;
    }
}


void Foam::functionObjects::fiberTracking::writeEvents
(
    const scalarList& ev,
    OFstream& os
) const
{
    static const char* kinds[5] =
        {"injected", "escaped", "deposited", "mat", "carried"};
    const label m = fiberCloud::eventSize;
    const wordList& sets = cloud_->setNames();
    for (label k = 0; k < ev.size()/m; ++k)
    {
        const scalar* e = &ev[m*k];
        const label patchi = label(e[4]);
        os  << e[0] << tab << label(e[1]) << tab << sets[label(e[2])]
            << tab << kinds[label(e[3])] << tab
            << (patchi >= 0 ? mesh_.boundaryMesh()[patchi].name() : "-")
            << tab << label(e[5]);
        for (label i = 6; i < m; ++i)
        {
            os << tab << e[i];
        }
        os << nl;
    }
    os.flush();
}


void Foam::functionObjects::fiberTracking::writeStates
(
    const UList<fiberCloud::state>& states,
    OFstream& os
) const
{
    for (const fiberCloud::state& s : states)
    {
        os  << fiberTime_ << tab << s.id;
        for (const vector& v : {s.x, s.p, s.v, s.omega})
        {
            for (direction k = 0; k < 3; ++k)
            {
                os << tab << v[k];
            }
        }
        os << tab << s.chord << nl;
    }
    os.flush();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::fiberTracking::fiberTracking
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    // fiberStatistics.dat is made with the others (createFiles), after
    // the files of an earlier run from the same time are gone
    fiberCompat::writeFile(mesh_, name, "fiberStatistics", true),
    UName_("U"),
    rhoInf_(0),
    nu_(-1),
    steady_(false),
    timePerIteration_(0),
    fiberTime_(runTime.value()),
    kName_("k"),
    epsilonName_("epsilon"),
    duration_(0),
    outputInterval_(0),
    started_(false),
    sourceChecked_(false),
    statesAtWriteTimes_(!dict.found("writeControl")),
    cpuFibers_(0),
    cpuOutput_(0),
    cpuProgress_(0),
    dict_(dict),
    cloud_(),
    gradU_(),
    kDisk_(),
    epsilonDisk_(),
    kFromModel_(false),
    kModel_(),
    epsilonModel_(),
    stateFilePtr_(),
    depositFilePtr_(),
    outletFilePtr_(),
    setFilePtr_(),
    vtkWriter_()
{
    contactTime_ = fiberTime_;
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::functionObjects::fiberTracking::checkKeywords
(
    const dictionary& dict
) const
{
    // The keywords of this object (Usage table) and those OpenFOAM reads
    // for every function object
    wordList known
    ({
        "type", "libs", "rhoInf", "U", "k", "epsilon", "nu",
        "interpolationScheme", "integrator", "viscousDrag", "inertialDrag",
        "inertialDragBound", "dragCoefficient", "subStepControl",
        "shearStepFactor", "tolerance", "maxRotation", "maxCo",
        "gravity", "jefferyCorrection", "dispersion", "wallInteraction",
        "restitution", "timePerIteration", "duration", "outputInterval",
        "vtk", "eventLog", "coupled", "buoyancy", "cellFields",
        "injection", "interactions",
        "functionObjectLibs", "region", "enabled", "log", "timeStart",
        "timeEnd", "executeControl", "executeInterval", "writeControl",
        "writeInterval", "outputControl", "writePrecision", "writeToFile",
        "useUserTime", "updateHeader", "subRegion"
    });
    const word model(dict.getOrDefault<word>("dispersion", "none"));
    known.append(model + "Coeffs");
    keywordCheck::warnUnknown(dict, known, "fiberTracking " + name());

    if (dict.getOrDefault<scalar>("writeInterval", 1) < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'writeInterval' must not be negative, not "
            << dict.get<scalar>("writeInterval") << exit(FatalIOError);
    }
}


bool Foam::functionObjects::fiberTracking::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);

    if (cloud_.valid())
    {
        // A re-read (modified controlDict) must not re-inject the fibers
        Info<< type() << " " << name() << ": dictionary changed; the fiber"
            << " settings are read once, restart the run to change them"
            << endl;
        return true;
    }

    Info<< type() << " " << name() << ":" << nl;

    const errorsEndTheRun guard;
    checkKeywords(dict);
    readFluid(dict);
    readTimeControl(dict);
    makeCloud(dict, readGravity(dict));
    reportModels(dict);
    cloud_->checkInteractionCost(dict, firstStep());

    // The fields exist now, except in post-processing, where the solver
    // builds them for each selected time (checked at the first execute)
    if (!functionObject::postProcess)
    {
        checkFields(dict);
    }
    readCellFields(dict);
    if (cloud_->rules().wires().size())
    {
        sheetWriter_.reset(new matSheetWriter(mesh_, cloud_->rules()));
    }

    if (Pstream::master() && writeToFile())
    {
        createFiles(dict);
        createCloudFiles(dict);
    }

    if (!functionObject::postProcess)
    {
        writeStatistics();
    }

    return true;
}


void Foam::functionObjects::fiberTracking::readFluid(const dictionary& dict)
{
    UName_ = dict.getOrDefault<word>("U", "U");
    kName_ = dict.getOrDefault<word>("k", "k");
    epsilonName_ = dict.getOrDefault<word>("epsilon", "epsilon");

    rhoInf_ = dict.get<scalar>("rhoInf");
    if (!(rhoInf_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'rhoInf' must be positive, not " << rhoInf_
            << exit(FatalIOError);
    }

    nu_ = -1;
    if (dict.found("nu"))
    {
        nu_ = dict.get<scalar>("nu");
        if (!(nu_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'nu' must be positive, not " << nu_
                << exit(FatalIOError);
        }
        Info<< "    Kinematic viscosity from entry 'nu': " << nu_ << nl;
    }
}


void Foam::functionObjects::fiberTracking::readTimeControl
(
    const dictionary& dict
)
{
    if (functionObject::postProcess)
    {
        duration_ = dict.getOrDefault<scalar>("duration", 0);
        if (duration_ < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'duration' must be positive, not " << duration_
                << exit(FatalIOError);
        }
        outputInterval_ =
            dict.getOrDefault<scalar>("outputInterval", duration_/100);
        if (duration_ > 0 && !(outputInterval_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'outputInterval' must be positive, not "
                << outputInterval_ << exit(FatalIOError);
        }
        if (duration_ > 0)
        {
            Info<< "    Post-processing: " << duration_ << " s of fiber time"
                << " on each selected time, output every "
                << outputInterval_ << " s" << nl;
        }
        else
        {
            Info<< "    Post-processing: fibers advance from one selected"
                << " time to the next" << nl;
        }
        if (dict.found("timePerIteration"))
        {
            Info<< "    Entry 'timePerIteration' is not used in"
                << " post-processing" << nl;
        }
    }
    else
    {
        for (const word key : {"duration", "outputInterval"})
        {
            if (dict.found(key))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry '" << key << "' is for post-processing"
                    << " (-postProcess) only; remove it"
                    << exit(FatalIOError);
            }
        }

        steady_ = mesh_.steady();
        if (steady_)
        {
            timePerIteration_ = dict.get<scalar>("timePerIteration");
            if (!(timePerIteration_ > 0))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'timePerIteration' must be positive, not "
                    << timePerIteration_ << exit(FatalIOError);
            }
            Info<< "    Steady solver: fibers advance " << timePerIteration_
                << " s per iteration" << nl;
        }
        else if (dict.found("timePerIteration"))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'timePerIteration' is for steady solvers only;"
                << " this solver is transient and the fibers advance by its"
                << " time step. Remove the entry." << exit(FatalIOError);
        }
    }
}


Foam::vector Foam::functionObjects::fiberTracking::readGravity
(
    const dictionary& dict
) const
{
    vector g(Zero);
    if (dict.found("gravity"))
    {
        g = dict.get<vector>("gravity");
        Info<< "    Gravity " << g << nl;
    }
    else
    {
        Info<< "    No 'gravity' entry: gravity term left out" << nl;
    }
    return g;
}


Foam::scalar Foam::functionObjects::fiberTracking::firstStep() const
{
    if (steady_)
    {
        return timePerIteration_;
    }
    if (functionObject::postProcess)
    {
        // An output interval, or unknown (the selected times' spacing)
        return
            duration_ > 0
          ? duration_
           /max(1, label(std::ceil(duration_/outputInterval_*(1 - 1e-9))))
          : 0;
    }
    return time_.deltaTValue();
}


void Foam::functionObjects::fiberTracking::makeCloud
(
    const dictionary& dict,
    const vector& g
)
{
    // A run started from a time with the fibers' restart file goes on from
    // it instead of injecting (live runs)
    const fileName restart(restartFile());
    const bool here = !functionObject::postProcess && isFile(restart);
    if (returnReduce(here, orOp<bool>()) != returnReduce(here, andOp<bool>()))
    {
        FatalErrorInFunction
            << "Fiber restart file " << restart.name() << " of time "
            << time_.timeName() << " present on some processors only"
            << exit(FatalError);
    }
    if (here)
    {
        IFstream is(restart);
        word key;
        is >> key >> fiberTime_;
        cloud_.reset(new fiberCloud(mesh_, dict, rhoInf_, g, &is));
        Info<< "    Restart from " << restart << ", fiber time "
            << fiberTime_ << nl;
    }
    else
    {
        cloud_.reset(new fiberCloud(mesh_, dict, rhoInf_, g));
    }

    const bool eventLog = dict.getOrDefault<Switch>("eventLog", false);
    if (eventLog)
    {
        cloud_->logEvents();
    }
}


void Foam::functionObjects::fiberTracking::reportModels
(
    const dictionary& dict
)
{
    if (cloud_->coupling())
    {
        Info<< "    Two-way coupling: the fibers' drag goes to the fluid as "
            << fiberCoupling::forceName(name()) << " and "
            << fiberCoupling::dragRateName(name())
            << " (fvOption fiberMomentumSource)" << nl;
    }
    if (dict.getOrDefault<Switch>("buoyancy", false))
    {
        Info<< "    Buoyancy: gravity on each fiber less the fluid it"
            << " displaces, (1 - rhoInf/density) g" << nl;
    }

    const fiberHydrodynamics& hydro = cloud_->hydrodynamics();
    if (!hydro.viscous())
    {
        Info<< "    viscousDrag off: viscous force and torque left out" << nl;
    }
    Info<< "    Interpolation " << cloud_->sampler().scheme()
        << ", inertial drag ";
    if (!hydro.inertial())
    {
        Info<< "off: left out";
    }
    else if (hydro.autoBound() > 0)
    {
        Info<< "auto: left out for a segment and step where its bound is"
            << " below " << hydro.autoBound() << " of the viscous drag";
    }
    else
    {
        Info<< "on";
    }
    Info<< " (C_D " << hydro.CD() << ")" << nl << endl;
}


void Foam::functionObjects::fiberTracking::readCellFields
(
    const dictionary& dict
)
{
    if (dict.getOrDefault<Switch>("cellFields", false))
    {
        if (functionObject::postProcess)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'cellFields' is for live runs (fields at the"
                << " case's write times); post-processing writes none:"
                << " remove it" << exit(FatalIOError);
        }
        cellFields_.reset(new fiberCellFields(mesh_, name()));
        Info<< "    Per-cell fields at write times: "
            << cellFields_->fieldName("fiberNumberDensity") << ", "
            << cellFields_->fieldName("fiberVolumeFraction") << ", "
            << cellFields_->fieldName("fiberOrientation") << ", "
            << cellFields_->fieldName("fiberVelocity") << endl;
    }
}


void Foam::functionObjects::fiberTracking::replaceEarlierRun() const
{
    // The .dat files this object writes, and the <name>_<time>.dat that
    // writeFile makes beside one that exists
    static const wordList names
    ({
        "fiberStatistics", "fiberState", "fiberDeposits", "fiberSets",
        "momentumExchange", "fiberEvents", "fiberOutlets", "fiberContacts",
        "fiberContactCounts", "fiberFlocSizes"
    });
    const fileName dir(startTimeDir());
    if (!isDir(dir))
    {
        return;
    }
    wordList removed;
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        for (const word& n : names)
        {
            const bool ours =
                f == n + ".dat"
             || (
                    f.size() > n.size() + 5
                 && f.compare(0, n.size() + 1, n + "_") == 0
                 && f.compare(f.size() - 4, 4, ".dat") == 0
                );
            if (ours && rm(dir/f))
            {
                removed.append(f);
            }
        }
    }
    if (isDir(dir/"vtk") && rmDir(dir/"vtk"))
    {
        removed.append("vtk/");
    }
    if (removed.size())
    {
        Info<< "    Output of an earlier run from the same time replaced"
            << " in " << dir << ": " << removed << endl;
    }
}


void Foam::functionObjects::fiberTracking::createFiles
(
    const dictionary& dict
)
{
    // Every file of this run in one folder, none of an earlier one
    replaceEarlierRun();
    resetFile("fiberStatistics");
    OFstream& os = file();
    writeHeader(os, "Rigid fiber statistics (fiberTracking)");
    writeCommented
    (
        os,
        "Time nInjected nActive nEscaped nDeposited absP1 absP2 absP3"
        " pp_xx pp_xy pp_xz pp_yy pp_yz pp_zz"
      + string(cloud_->rules().wires().size() ? " nMat" : "")
      + string(cloud_->rules().anyMoving() ? " nCarried" : "")
    );
    os << endl;

    const string stateColumns
    (
        "Time id cx cy cz px py pz vx vy vz wx wy wz chord"
    );
    stateFilePtr_ = newFileAtStart("fiberState");
    writeHeader
    (
        stateFilePtr_(),
        "Fiber state (fiberTracking; p: end-to-end direction, chord:"
        " end-to-end distance/contour length)"
    );
    writeCommented(stateFilePtr_(), stateColumns);
    stateFilePtr_() << endl;

    if (cloud_->rules().any(wallRules::rule::deposit))
    {
        depositFilePtr_ = newFileAtStart("fiberDeposits");
        writeHeader(depositFilePtr_(), "Deposited fibers (fiberTracking)");
        writeCommented(depositFilePtr_(), stateColumns);
        depositFilePtr_() << endl;
    }

    if (dict.getOrDefault<Switch>("vtk", true))
    {
        vtkWriter_.reset
        (
            new fiberVtkWriter(startTimeDir()/"vtk", name())
        );
    }

    const wordList& sets = cloud_->setNames();
    if (sets.size() > 1)
    {
        setFilePtr_ = newFileAtStart("fiberSets");
        OFstream& os = setFilePtr_();
        writeHeader(os, "Fibers per set (fiberTracking)");
        string columns("Time");
        for (const word& set : sets)
        {
            for (const char* c : {"injected", "active", "escaped"})
            {
                columns += " " + set + "_" + c;
            }
            columns += " " + set + "_deposited";
            if (cloud_->rules().wires().size())
            {
                columns += " " + set + "_mat";
            }
        }
        writeCommented(os, columns);
        os << endl;
    }
}


void Foam::functionObjects::fiberTracking::createCloudFiles
(
    const dictionary& dict
)
{
    if (cloud_->coupling())
    {
        momentumFilePtr_ = newFileAtStart("momentumExchange");
        OFstream& os = momentumFilePtr_();
        writeHeader
        (
            os,
            "Momentum exchange, time averages over each step [N]"
            " (fiberTracking)"
        );
        writeCommented
        (
            os,
            "Time fluidSource_x fluidSource_y fluidSource_z fiberForce_x"
            " fiberForce_y fiberForce_z mismatch returned_x returned_y"
            " returned_z"
        );
        os << endl;
    }

    if (cloud_->loggingEvents())
    {
        eventFilePtr_ = newFileAtStart("fiberEvents");
        OFstream& os = eventFilePtr_();
        writeHeader
        (
            os,
            "Fibers injected, escaped, deposited (fiberTracking)"
        );
        writeCommented
        (
            os,
            "Time id set event patch nSegments length diameter cx cy cz"
            " px py pz"
        );
        os << endl;
    }

    const labelList& outlets = cloud_->outlets();
    if (outlets.size())
    {
        outletFilePtr_ = newFileAtStart("fiberOutlets");
        OFstream& os = outletFilePtr_();
        writeHeader(os, "Fibers escaped per outlet patch (fiberTracking)");
        string columns("Time");
        for (const label patchi : outlets)
        {
            columns += " " + mesh_.boundaryMesh()[patchi].name();
        }
        writeCommented(os, columns);
        os << endl;
    }

    createContactFiles();

    if (sheetWriter_.valid())
    {
        sheetFilePtr_ = newFileAtStart("matSheet");
        OFstream& os = sheetFilePtr_();
        writeHeader(os, "Sheets of the mats on the wires (fiberTracking)");
        writeCommented(os, matSheetWriter::columns());
        os << endl;
    }
}


bool Foam::functionObjects::fiberTracking::execute()
{
    if (!functionObject::postProcess)
    {
        executeLive();
        return true;
    }

    // Post-processing: the solver has built the fields of this time
    if (!started_)
    {
        startPostProcessing();
        if (duration_ <= 0)
        {
            return true;
        }
    }

    updateFields();

    if (duration_ > 0)
    {
        const label nOut =
            max(1, label(std::ceil(duration_/outputInterval_*(1 - 1e-9))));
        for (label k = 0; k < nOut; ++k)
        {
            advance(duration_/nOut, false);
            progress(k + 1 == nOut);
            writeStates(time_.timeName() + "_" + Foam::name(k + 1));
        }
    }
    else
    {
        const scalar dt = time_.value() - fiberTime_;
        if (dt > 0)
        {
            advance(dt);
            writeStates(time_.timeName());
        }
    }

    return true;
}


void Foam::functionObjects::fiberTracking::executeLive()
{
    // The flow's step where the fiber time keeps up with it: a run
    // restarted from a write time reads that time rounded to its name,
    // and the difference of the two clocks would then differ from the
    // uninterrupted run's in the last bits (and could take a sub-step
    // more)
    scalar dt =
        steady_
      ? timePerIteration_
      : time_.value() - fiberTime_;
    if (!steady_ && mag(dt - time_.deltaTValue()) < 1e-9*dt)
    {
        dt = time_.deltaTValue();
    }

    if (!sourceChecked_)
    {
        sourceChecked_ = true;
        const errorsEndTheRun guard;
        checkCouplingSource();
    }
    if (dt > 0)
    {
        updateFields();
        advance(dt);
        liveProgress();
    }
    if (time_.writeTime())
    {
        writeRestart();
        writeVtk(time_.timeName());
        writeSheets(time_.timeName());
        if (cellFields_.valid())
        {
            cellFields_->write();
        }
    }
}


void Foam::functionObjects::fiberTracking::startPostProcessing()
{
    {
        const errorsEndTheRun guard;
        checkFields(dict_);
    }

    // With a duration the fiber time starts at zero on the frozen field
    // (the time of a steady run counts iterations); without, it follows
    // the selected times
    started_ = true;
    fiberTime_ = duration_ > 0 ? 0 : time_.value();
    contactTime_ = fiberTime_;
    writeStatistics();
    if (Pstream::master() && stateFilePtr_.valid())
    {
        writeStates(cloud_->gatherStates(), stateFilePtr_());
    }
    else
    {
        cloud_->gatherStates();
    }
}


void Foam::functionObjects::fiberTracking::writeStates(const word& tag)
{
    const List<fiberCloud::state> st(cloud_->gatherStates());
    if (Pstream::master() && stateFilePtr_.valid())
    {
        writeStates(st, stateFilePtr_());
    }
    writeVtk(tag);
    writeSheets(tag);
}


bool Foam::functionObjects::fiberTracking::end()
{
    if (cloud_.valid())
    {
        reportCost();
    }
    return true;
}


bool Foam::functionObjects::fiberTracking::write()
{
    // Post-processing writes its states in execute()
    if (functionObject::postProcess)
    {
        return true;
    }

    // By default at the case's write times, as OpenFOAM's clouds write
    if (statesAtWriteTimes_ && !time_.writeTime())
    {
        return true;
    }

    const List<fiberCloud::state> states(cloud_->gatherStates());

    if (Pstream::master() && stateFilePtr_.valid())
    {
        writeStates(states, stateFilePtr_());
    }

    return true;
}


// ************************************************************************* //
