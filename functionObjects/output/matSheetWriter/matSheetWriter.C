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

#include "matSheetWriter.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "SubField.H"
#include "scalarField.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::matSheetWriter::matSheetWriter
(
    const polyMesh& mesh,
    const wallRules& rules
)
:
    mesh_(mesh),
    wires_(rules.wires()),
    frames_(wires_.size())
{
    forAll(wires_, k)
    {
        frames_[k] = frameOf(wires_[k]);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::matSheet::frame Foam::matSheetWriter::frameOf
(
    const wallRules::wire& w
) const
{
    const polyPatch& pp = mesh_.boundaryMesh()[w.patch];
    vector S(Zero);
    vector Sx(Zero);
    scalar A = 0;
    forAll(pp, i)
    {
        const vector& Sf = pp.faceAreas()[i];
        S += Sf;
        Sx += mag(Sf)*pp.faceCentres()[i];
        A += mag(Sf);
    }
    reduce(S, sumOp<vector>());
    reduce(Sx, sumOp<vector>());
    reduce(A, sumOp<scalar>());
    matSheet::frame fr;
    fr.n = -S/max(mag(S), VSMALL);
    fr.o = Sx/max(A, VSMALL);
    vector md(w.md);
    if (magSqr(md) == 0)
    {
        md = mag(fr.n.x()) < std::cos(25*constant::mathematical::pi/180)
          ? vector(1, 0, 0) : vector(0, 0, 1);
    }
    md -= (md & fr.n)*fr.n;
    fr.e1 = md/max(mag(md), VSMALL);
    fr.e2 = fr.n ^ fr.e1;
    fr.u0 = fr.v0 = GREAT;
    fr.u1 = fr.v1 = -GREAT;
    for (const point& x : pp.localPoints())
    {
        const scalar u = (x - fr.o) & fr.e1;
        const scalar v = (x - fr.o) & fr.e2;
        fr.u0 = min(fr.u0, u);
        fr.u1 = max(fr.u1, u);
        fr.v0 = min(fr.v0, v);
        fr.v1 = max(fr.v1, v);
    }
    reduce(fr.u0, minOp<scalar>());
    reduce(fr.v0, minOp<scalar>());
    reduce(fr.u1, maxOp<scalar>());
    reduce(fr.v1, maxOp<scalar>());
    return fr;
}


void Foam::matSheetWriter::writeCurves
(
    const matSheet& sheet,
    const List<matSheet::zone>& z,
    const fileName& dir,
    const word& patch
) const
{
    {
        OFstream os(dir/patch + "_formation.dat");
        os  << "# zoneSize nZones meanGrammage CV CVrandom sdRandom"
            << " formationIndex" << nl;
        for (const matSheet::zone& zk : z)
        {
            os  << zk.a << tab << zk.n << tab << zk.mean << tab << zk.cv
                << tab << zk.cvRandom << tab << zk.sdRandom << tab
                << (zk.cvRandom > 0 ? zk.cv/zk.cvRandom : 0) << nl;
        }
    }
    {
        OFstream os(dir/patch + "_grammage.dat");
        os  << "# u v grammage (zones of side " << 0.1*sheet.meanLength()
            << " m)" << nl;
        const List<FixedList<scalar, 3>> map
        (
            sheet.grammageMap(0.1*sheet.meanLength())
        );
        forAll(map, i)
        {
            if (i > 0 && map[i][0] != map[i - 1][0])
            {
                os << nl;
            }
            os << map[i][0] << tab << map[i][1] << tab << map[i][2] << nl;
        }
    }
    {
        OFstream os(dir/patch + "_orientation.dat");
        os  << "# angleToMD[deg] fraction randomFraction" << nl;
        const labelList n(sheet.angleClasses());
        const label N = max(sum(n), label(1));
        forAll(n, k)
        {
            os  << (k + 0.5)*180.0/n.size() << tab << scalar(n[k])/N << tab
                << 1.0/n.size() << nl;
        }
    }
    {
        OFstream os(dir/patch + "_profile.dat");
        os  << "# height solidFraction" << nl;
        scalar thickness;
        const scalar dz = sheet.layer();
        const scalarList phi(sheet.solidFraction(dz, thickness));
        forAll(phi, j)
        {
            os << (j + 0.5)*dz << tab << phi[j] << nl;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::matSheetWriter::columns()
{
    return
        "Time patch nFibers mass meanGrammage zoneAtL CVatL CVrandomAtL"
        " sdRandomAtL formationIndexAtL a_MDMD a_MDCD a_CDCD anisotropyMDCD"
        " outOfPlaneDeg thickness solidFraction contactsPerFiber"
        " crossingsPerFiber crossingsRandom kallmesCorte";
}


void Foam::matSheetWriter::write
(
    const scalarList& records,
    const scalar t,
    const fileName& dir,
    OFstream& os
) const
{
    const label m = matSheet::recordSize + 1;
    mkDir(dir);
    forAll(wires_, k)
    {
        // This wire's segments
        DynamicList<scalar> mine;
        for (label i = 0; i < records.size()/m; ++i)
        {
            if (label(records[m*i]) == wires_[k].patch)
            {
                mine.append(SubList<scalar>(records, m - 1, m*i + 1));
            }
        }
        const matSheet sheet(frames_[k], scalarList(std::move(mine)));
        const word patch(mesh_.boundaryMesh()[wires_[k].patch].name());
        if (sheet.nFibers() == 0)
        {
            os  << t << tab << patch << tab << 0;
            for (label j = 0; j < 18; ++j)
            {
                os << tab << 0;
            }
            os << endl;
            continue;
        }
        scalar crossRandom = 0;
        const List<matSheet::zone> z
        (
            sheet.formation(wires_[k].nRandom, 1, crossRandom)
        );
        writeCurves(sheet, z, dir, patch);

        // The zone nearest the mean fiber length
        label kL = -1;
        forAll(z, j)
        {
            if
            (
                kL < 0
             || mag(std::log(z[j].a/sheet.meanLength()))
              < mag(std::log(z[kL].a/sheet.meanLength()))
            )
            {
                kL = j;
            }
        }
        const matSheet::zone zL =
            kL >= 0 ? z[kL] : matSheet::zone{0, 0, 0, 0, 0, 0};
        const FixedList<scalar, 3> a(sheet.orientationTensor());
        // The mean solid fraction over the thickness
        scalar thickness = 0;
        const scalarList phi(sheet.solidFraction(sheet.layer(), thickness));
        const scalar A = sheet.area();
        const scalar solid =
            thickness > 0 ? sum(phi)*sheet.layer()/thickness : 0;
        os  << t << tab << patch << tab << sheet.nFibers() << tab
            << sheet.totalMass() << tab << (A > 0 ? sheet.totalMass()/A : 0)
            << tab << zL.a << tab << zL.cv << tab << zL.cvRandom << tab
            << zL.sdRandom << tab
            << (zL.cvRandom > 0 ? zL.cv/zL.cvRandom : 0) << tab << a[0]
            << tab << a[1] << tab << a[2] << tab
            << (a[2] > 1e-12 ? a[0]/a[2] : 0) << tab
            << sheet.outOfPlane()*180/constant::mathematical::pi << tab
            << thickness << tab << solid << tab
            << sheet.contactsPerFiber() << tab << sheet.crossingsPerFiber()
            << tab << crossRandom << tab << sheet.kallmesCorte() << endl;
    }
}


// ************************************************************************* //
