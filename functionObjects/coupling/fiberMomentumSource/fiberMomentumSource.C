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

#include "fiberMomentumSource.H"
#include "fiberCoupling.H"
#include "fvMatrices.H"
#include "fvmSup.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace fv
{
    defineTypeNameAndDebug(fiberMomentumSource, 0);
    addToRunTimeSelectionTable(option, fiberMomentumSource, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fv::fiberMomentumSource::fiberMomentumSource
(
    const word& name,
    const word& modelType,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    option(name, modelType, dict, mesh),
    fiberTracking_(),
    semiImplicit_(true)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::fv::fiberMomentumSource::read(const dictionary& dict)
{
    if (!option::read(dict))
    {
        return false;
    }

    // The entries may be in the source's dictionary or its coeffs
    const dictionary& d = dict.found("fiberTracking") ? dict : coeffs_;
    fiberTracking_ = d.get<word>("fiberTracking");
    semiImplicit_ = d.getOrDefault<Switch>("semiImplicit", true);
    fieldNames_ =
        d.getOrDefault<wordList>("fields", wordList(1, word("U")));
    applied_.setSize(fieldNames_.size(), false);

    Info<< "    Fibers of '" << fiberTracking_ << "' act on "
        << fieldNames_ << (semiImplicit_ ? ", semi-implicit" : ", explicit")
        << endl;
    return true;
}


void Foam::fv::fiberMomentumSource::addSup
(
    fvMatrix<vector>& eqn,
    const label fieldi
)
{
    typedef DimensionedField<vector, volMesh> vectorDField;
    typedef DimensionedField<scalar, volMesh> scalarDField;

    const word forceName(fiberCoupling::forceName(fiberTracking_));
    if (!mesh_.foundObject<vectorDField>(forceName))
    {
        FatalErrorInFunction
            << "fvOption " << name_ << ": no fibers to couple: no"
            << " fiberTracking function object '" << fiberTracking_
            << "' with 'coupled true' (field " << forceName << ")."
            << nl << "    Set 'fiberTracking' to the object's name and"
            << " 'coupled true' in the object" << exit(FatalError);
    }
    const vectorDField& S = mesh_.lookupObject<vectorDField>(forceName);

    if (!semiImplicit_)
    {
        eqn += S;
        return;
    }

    const scalarDField& beta =
        mesh_.lookupObject<scalarDField>
        (
            fiberCoupling::dragRateName(fiberTracking_)
        );
    const volVectorField& U = eqn.psi();
    eqn += S + beta*U.internalField();
    eqn -= fvm::Sp(beta, U);

    // The velocity linearised about (the last call of a flow step wins),
    // stamped with the time: the coupling returns the implicit part after
    // the step (fiberCoupling)
    vectorDField& UStar =
        mesh_.lookupObjectRef<vectorDField>
        (
            fiberCoupling::linearisedName(fiberTracking_)
        );
    UStar.field() = U.primitiveField();
    UStar.instance() = mesh_.time().timeName();
}


// ************************************************************************* //
