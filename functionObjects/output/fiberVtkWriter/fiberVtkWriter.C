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

#include "fiberVtkWriter.H"
#include "OSspecific.H"
#include "error.H"
#include <fstream>
#include <sstream>
#include <cstdint>
#include <iomanip>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- One appended array: its XML element and its bytes
struct vtkArray
{
    std::string type, name;
    label nComponents;
    std::string bytes;
};


template<class T>
void append(std::string& bytes, const T v)
{
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
}


//- Float64 array of nComponents from the records, starting at column c
vtkArray doubles
(
    const std::string& name,
    const scalarList& rec,
    const label n,
    const label c,
    const label nComponents
)
{
    vtkArray a{"Float64", name, nComponents, std::string()};
    for (label i = 0; i < n; ++i)
    {
        for (label k = 0; k < nComponents; ++k)
        {
            append<double>(a.bytes, rec[i*fiberVtkWriter::recordSize + c + k]);
        }
    }
    return a;
}

//- The VTK PolyData file of n segments (lines) to os: the XML part, with
//  the offsets of the appended arrays, then the arrays
void writePiece
(
    std::ostream& os,
    const label n,
    const vtkArray& points,
    const vtkArray& conn,
    const vtkArray& offs,
    const UList<vtkArray>& cellData
)
{
    uint64_t offset = 0;
    auto element = [&offset](std::ostream& os, const vtkArray& a)
    {
        os  << "<DataArray type=\"" << a.type << "\" Name=\"" << a.name
            << "\" NumberOfComponents=\"" << a.nComponents
            << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
        offset += sizeof(uint64_t) + a.bytes.size();
    };

    os  << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"1.0\""
        << " byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        << "<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << 2*n << "\" NumberOfVerts=\"0\""
        << " NumberOfLines=\"" << n << "\" NumberOfStrips=\"0\""
        << " NumberOfPolys=\"0\">\n"
        << "<Points>\n";
    element(os, points);
    os  << "</Points>\n<Lines>\n";
    element(os, conn);
    element(os, offs);
    os  << "</Lines>\n<CellData Scalars=\"diameter\">\n";
    for (const vtkArray& a : cellData)
    {
        element(os, a);
    }
    os  << "</CellData>\n</Piece>\n</PolyData>\n"
        << "<AppendedData encoding=\"raw\">\n_";
    for (const vtkArray* a : {&points, &conn, &offs})
    {
        const uint64_t nBytes = a->bytes.size();
        os.write(reinterpret_cast<const char*>(&nBytes), sizeof(nBytes));
        os.write(a->bytes.data(), a->bytes.size());
    }
    for (const vtkArray& a : cellData)
    {
        const uint64_t nBytes = a.bytes.size();
        os.write(reinterpret_cast<const char*>(&nBytes), sizeof(nBytes));
        os.write(a.bytes.data(), a.bytes.size());
    }
    os  << "\n</AppendedData>\n</VTKFile>\n";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fiberVtkWriter::fiberVtkWriter(const fileName& dir, const word& name)
:
    dir_(dir),
    name_(name),
    files_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fiberVtkWriter::write
(
    const scalarList& rec,
    const scalar t,
    const word& tag,
    const Map<label>* flocOf
)
{
    const label n = rec.size()/recordSize;
    mkDir(dir_);

    // Points: the two ends of every segment
    vtkArray points{"Float64", "Points", 3, std::string()};
    for (label i = 0; i < n; ++i)
    {
        for (label k = 1; k <= 6; ++k)
        {
            append<double>(points.bytes, rec[i*recordSize + k]);
        }
    }
    vtkArray conn{"Int64", "connectivity", 1, std::string()};
    vtkArray offs{"Int64", "offsets", 1, std::string()};
    vtkArray ids{"Int64", "fiberId", 1, std::string()};
    for (label i = 0; i < n; ++i)
    {
        append<int64_t>(conn.bytes, 2*i);
        append<int64_t>(conn.bytes, 2*i + 1);
        append<int64_t>(offs.bytes, 2*i + 2);
        append<int64_t>(ids.bytes, int64_t(rec[i*recordSize]));
    }
    List<vtkArray> cellData
    ({
        ids,
        doubles("velocity", rec, n, 7, 3),
        doubles("fiberVelocity", rec, n, 10, 3),
        doubles("angularVelocity", rec, n, 13, 3),
        doubles("orientation", rec, n, 16, 3),
        doubles("diameter", rec, n, 19, 1)
    });
    bool anyMat = false;
    for (label i = 0; i < n && !anyMat; ++i)
    {
        anyMat = rec[i*recordSize + 20] >= 0;
    }
    if (anyMat)
    {
        vtkArray mat{"Int64", "matPatch", 1, std::string()};
        for (label i = 0; i < n; ++i)
        {
            append<int64_t>(mat.bytes, int64_t(rec[i*recordSize + 20]));
        }
        cellData.append(mat);
        cellData.append(doubles("landTime", rec, n, 21, 1));
    }
    if (flocOf)
    {
        vtkArray flocs{"Int64", "flocId", 1, std::string()};
        for (label i = 0; i < n; ++i)
        {
            const label id(rec[i*recordSize]);
            append<int64_t>(flocs.bytes, int64_t(flocOf->lookup(id, -1)));
        }
        cellData.append(flocs);
    }

    const word file(name_ + "_" + tag + ".vtp");
    std::ofstream os((dir_/file).c_str(), std::ios::binary);
    writePiece(os, n, points, conn, offs, cellData);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write " << dir_/file << exit(FatalError);
    }
    os.close();
    writeSeries(t, file);
}


void Foam::fiberVtkWriter::writeSeries(const scalar t, const word& file)
{
    // The series, every file so far
    files_.append(Tuple2<scalar, word>(t, file));
    std::ofstream js(seriesFile().c_str());
    js  << std::setprecision(12)
        << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    forAll(files_, i)
    {
        js  << "    { \"name\" : \"" << files_[i].second().c_str()
            << "\", \"time\" : " << files_[i].first() << " }"
            << (i + 1 < files_.size() ? "," : "") << "\n";
    }
    js  << "  ]\n}\n";
}


// ************************************************************************* //
