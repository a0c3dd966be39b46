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
#include "fvcGrad.H"
#include "transportModel.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(fiberTracking, 0);
    addToRunTimeSelectionTable(functionObject, fiberTracking, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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


void Foam::functionObjects::fiberTracking::writeStatistics()
{
    const fiberCloud::statistics s(cloud_->stats());

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        os  << fiberTime_ << tab
            << s.nInjected << tab << s.nActive << tab << s.nEscaped;
        for (direction k = 0; k < 3; ++k)
        {
            os << tab << s.absP[k];
        }
        for (direction k = 0; k < 6; ++k)
        {
            os << tab << s.pp[k];
        }
        os << endl;
    }

    if (s.nInjected != s.nActive + s.nEscaped)
    {
        FatalErrorInFunction
            << "Fiber count broken: injected " << s.nInjected
            << " != active " << s.nActive << " + escaped " << s.nEscaped
            << exit(FatalError);
    }
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
    writeFile(mesh_, name, "fiberStatistics", dict),
    UName_("U"),
    rhoInf_(0),
    nu_(-1),
    steady_(false),
    timePerIteration_(0),
    fiberTime_(runTime.value()),
    cloud_(),
    stateFilePtr_()
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

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

    UName_ = dict.getOrDefault<word>("U", "U");
    if (!mesh_.foundObject<volVectorField>(UName_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'U': no velocity field '" << UName_
            << "' in the case" << exit(FatalIOError);
    }

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
    else if (!mesh_.foundObject<transportModel>("transportProperties"))
    {
        FatalIOErrorInFunction(dict)
            << "No transport model 'transportProperties' in the case:"
            << " give the kinematic viscosity as entry 'nu'"
            << exit(FatalIOError);
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
            << "Entry 'timePerIteration' is for steady solvers only; this"
            << " solver is transient and the fibers advance by its time"
            << " step. Remove the entry." << exit(FatalIOError);
    }

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

    cloud_.reset(new fiberCloud(mesh_, dict, rhoInf_, g));

    Info<< "    Interpolation " << cloud_->sampler().scheme()
        << ", inertial drag "
        << (cloud_->hydrodynamics().inertial() ? "on" : "off")
        << " (C_D " << cloud_->hydrodynamics().CD() << ")" << nl << endl;

    if (Pstream::master() && writeToFile())
    {
        OFstream& os = file();
        writeHeader(os, "Rigid fiber statistics (fiberTracking)");
        writeCommented
        (
            os,
            "Time nInjected nActive nEscaped absP1 absP2 absP3"
            " pp_xx pp_xy pp_xz pp_yy pp_yz pp_zz"
        );
        os << endl;

        stateFilePtr_ = createFile("fiberState");
        writeHeader(stateFilePtr_(), "Rigid fiber state (fiberTracking)");
        writeCommented
        (
            stateFilePtr_(),
            "Time id cx cy cz px py pz vx vy vz wx wy wz"
        );
        stateFilePtr_() << endl;
    }

    writeStatistics();

    return true;
}


bool Foam::functionObjects::fiberTracking::execute()
{
    const scalar dt =
        steady_
      ? timePerIteration_
      : time_.value() - fiberTime_;

    if (dt <= 0)
    {
        return true;
    }

    const volVectorField& U = lookupObject<volVectorField>(UName_);
    const volTensorField gradU(fvc::grad(U));

    cloud_->sampler().update(U, gradU, muCells());
    cloud_->evolve(dt);
    fiberTime_ += dt;

    writeStatistics();

    Log << type() << " " << name() << " execute: fiber time " << fiberTime_
        << ", sub-steps " << cloud_->nSubMax()
        << " (smallest " << cloud_->dtSubMin() << " s)";
    if (Pstream::parRun())
    {
        Log << ", remote segment samples " << cloud_->nRemote()
            << ", fibers transferred " << cloud_->nTransferred();
    }
    if (cloud_->nOutside())
    {
        Log << ", segment samples outside the mesh " << cloud_->nOutside()
            << " (fluid data of the last cell reached)";
    }
    Log << endl;

    return true;
}


bool Foam::functionObjects::fiberTracking::write()
{
    const List<fiberCloud::state> states(cloud_->gatherStates());

    if (Pstream::master() && stateFilePtr_.valid())
    {
        OFstream& os = stateFilePtr_();
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
            os << nl;
        }
        os.flush();
    }

    return true;
}


// ************************************************************************* //
