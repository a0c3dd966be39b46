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
    Unit tests of the sheet's crossings (matSheet::crossings) against a
    brute-force count over every pair of lines: random 2-D lines of one
    per fiber (a random sheet) and of one to four per fiber (a mat's
    segments, where two fibers may cross more than once and count once),
    binned in cells smaller and larger than the lines.  Part of
    Test-fiberModel.

\*---------------------------------------------------------------------------*/

#include "matSheet.H"
#include "DynamicList.H"

#include <random>
#include <set>
#include <sstream>

using namespace Foam;

// The harness of Test-fiberModel.C
void check(const std::string& name, const bool ok, const std::string& detail);

namespace
{

//- The segments (2-D) cross, by the signs of the orientations (exact
//  enough for random lines: no three points on a line)
bool cross(const FixedList<scalar, 4>& a, const FixedList<scalar, 4>& b)
{
    auto side = [](const FixedList<scalar, 4>& l, scalar x, scalar y)
    {
        return (l[2] - l[0])*(y - l[1]) - (l[3] - l[1])*(x - l[0]);
    };
    return
        side(a, b[0], b[1])*side(a, b[2], b[3]) <= 0
     && side(b, a[0], a[1])*side(b, a[2], a[3]) <= 0;
}

} // End anonymous namespace


void testMatSheet()
{
    std::mt19937 gen(23);
    std::uniform_real_distribution<scalar> u01(0, 1);
    const scalar pi = 3.14159265358979;

    for (const label maxLines : {1, 4})
    {
        // 600 fibers of length 1 on a 10 x 10 square; a fiber of several
        // lines is a chain turning by up to 60 degrees at each joint
        const label nFibers = 600;
        DynamicList<FixedList<scalar, 4>> lines;
        DynamicList<label> fiberOf;
        for (label f = 0; f < nFibers; ++f)
        {
            const label n = 1 + label(maxLines*u01(gen)) % maxLines;
            scalar x = 10*u01(gen);
            scalar y = 10*u01(gen);
            scalar th = pi*u01(gen);
            for (label k = 0; k < n; ++k)
            {
                const scalar l = 1.0/n;
                const FixedList<scalar, 4> li
                {
                    x, y, x + l*std::cos(th), y + l*std::sin(th)
                };
                lines.append(li);
                fiberOf.append(f);
                x = li[2];
                y = li[3];
                th += pi/3*(2*u01(gen) - 1);
            }
        }
        std::set<std::pair<label, label>> pairs;
        forAll(lines, a)
        {
            for (label b = a + 1; b < lines.size(); ++b)
            {
                if (fiberOf[a] != fiberOf[b] && cross(lines[a], lines[b]))
                {
                    pairs.insert
                    ({
                        min(fiberOf[a], fiberOf[b]),
                        max(fiberOf[a], fiberOf[b])
                    });
                }
            }
        }
        const scalar want = 2.0*pairs.size()/nFibers;
        for (const scalar cell : {0.3, 1.0, 4.0})
        {
            const scalar got =
                matSheet::crossings
                (
                    List<FixedList<scalar, 4>>(lines), labelList(fiberOf),
                    nFibers, cell
                );
            std::ostringstream nm;
            std::ostringstream d;
            nm << "matSheet.crossings.lines" << maxLines << ".cell" << cell;
            d << got << " per fiber, brute force " << want << " ("
              << pairs.size() << " pairs, " << lines.size() << " lines)";
            check(nm.str(), got == want && pairs.size() > 100, d.str());
        }
    }
}


// ************************************************************************* //
