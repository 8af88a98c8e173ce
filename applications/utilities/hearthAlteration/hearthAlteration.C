/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    hearthAlteration

Description
    How deep, and how much of the soil, a fire heated above given
    temperatures: post-processing of the maximum temperature reached in each
    cell (TMax, written by ahcFoam) at the selected times. For each
    threshold of system/hearthAlterationDict (in C; e.g. 100 C drying,
    290 C reddening by oxidation of the clay, Muhieddine 2009 §5.4):

    - depth along each line: the farthest distance from the line's start
      at which TMax >= threshold. TMax is sampled along the line by the
      OpenFOAM sampledSet of the line (default 'uniform', nPoints 2001)
      and interpolated in the cells (default 'cellPoint': linear between
      cell centres on a 1-D column); the crossing of the threshold is
      linearly interpolated between the two samples around it. Measure
      from the start: put it on the soil surface (e.g. under the centre of
      the fire) and the end deep below. Depth 0: not reached at any sample.
      A depth flagged 'end' reaches the last sample of the line: the line
      is too short (or leaves the mesh) and the depth is a lower bound.
    - altered volume: the sum of the volumes of the cells whose TMax >=
      threshold (cells are counted whole: the volume is exact to within the
      cells cut by the isotherm). On a wedge (axisymmetric) mesh also the
      full-revolution volume, that of the mid-plane section revolved about
      the axis: sector volume x pi/tan(angle/2) (= 360/angle to 0.06 % at
      5 degrees), the angle taken from the two wedge patches.

    Writes, per time, postProcessing/hearthAlteration/<time>/
        alteration_<threshold>C.csv   line,depth_m
        summary.csv                   threshold_C,volume_m3
                                      [,volume360_m3],depth_<line>_m ...
    and prints the same table. Serial and parallel (-parallel on the
    decomposed case) give the same numbers (reductions over the ranks).

    Boundary values of TMax: the interpolation uses at each boundary face
    the larger of the written value and the adjacent cell's value (ahcFoam
    writes the maximum of the boundary temperature since commit b5b3f2d;
    results of earlier versions hold 0 there).

    system/hearthAlterationDict (see the annotated example in this folder):

        thresholds  (100 290 500);   // C, strictly increasing, > -273.15
        lines
        {
            axis
            {
                start   (0.0001 0 0);    // on the surface
                end     (0.0001 0 -0.5);
                // type    uniform;      // or face, midPoint, midPointAndFace
                // nPoints 2001;         // uniform only, >= 2
            }
        }
        // field               TMax;       // default: a temperature in K
        // interpolationScheme cellPoint;  // cell | cellPoint | cellPointFace

    Bad input (empty or unsorted thresholds, a line that misses the mesh,
    an unknown set type...) stops with a FatalIOError naming the file, the
    keyword and the valid range or choices before any time is processed.

Usage
    hearthAlteration [-latestTime | -time ranges | ...] [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "timeSelector.H"
#include "meshSearch.H"
#include "sampledSet.H"
#include "interpolation.H"
#include "wedgePolyPatch.H"
#include "globalIndex.H"
#include "OFstream.H"
#include "IOmanip.H"
#include <iomanip>
#include <sstream>
#include "unitConversion.H"
#include "checkedRead.H"
#include "alterationDepth.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{

//- Absolute zero in C
static const scalar zeroCelsius = 273.15;

//- The sampledSet types that sample along the straight line start -> end
static const wordList lineSetTypes
({"uniform", "face", "midPoint", "midPointAndFace"});

//- Threshold written as in the file names: 290 -> "290", 72.5 -> "72.5"
word thresholdName(const scalar thresholdC)
{
    return word(Foam::name(thresholdC));
}

//- A list of numbers as (a b c)
std::string listText(const UList<scalar>& values)
{
    std::ostringstream os;
    os << '(';
    forAll(values, i)
    {
        os << (i ? " " : "") << values[i];
    }
    os << ')';
    return os.str();
}

//- A number as text: 'digits' significant digits, or decimals if fixed
std::string formatted(const scalar x, const int digits, const bool fixed)
{
    std::ostringstream os;
    if (fixed)
    {
        os << std::fixed;
    }
    os << std::setprecision(digits) << x;
    return os.str();
}

#include "wedgeAngle.H"

} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Depth along lines and volume of the soil whose maximum temperature"
        " (TMax) reached each threshold of system/hearthAlterationDict"
    );

    timeSelector::addOptions();

    #include "setRootCase.H"
    #include "createTime.H"

    instantList timeDirs = timeSelector::select0(runTime, args);

    #include "createMesh.H"
    #include "readHearthAlterationDict.H"
    #include "createLines.H"

    // Wedge: the full-revolution volume of the soil the wedge represents
    // (its mid-plane section revolved about the axis) is the sector volume
    // x pi/tan(angle/2): a cell at radius r of the mid-plane is
    // 2 r tan(angle/2) thick, its ring 2 pi r (360/angle is 0.06 % larger
    // at 5 degrees)
    const scalar wedgeDeg = wedgeAngle(mesh);
    const scalar revolution =
        wedgeDeg > 0 ? constant::mathematical::pi/Foam::tan(degToRad(wedgeDeg/2)) : 0;

    if (wedgeDeg > 0)
    {
        Info<< "Wedge mesh of " << formatted(wedgeDeg, 6, false).c_str()
            << " degrees: full-revolution volume = sector volume x "
            << formatted(revolution, 6, false).c_str()
            << " (pi/tan(angle/2))" << nl << endl;
    }

    const fileName outputDir
    (
        runTime.globalPath()/"postProcessing"/"hearthAlteration"
    );

    label nProcessed = 0;

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);

        Info<< "Time = " << runTime.timeName() << endl;

        IOobject fieldHeader
        (
            fieldName,
            runTime.timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );

        if (!fieldHeader.typeHeaderOk<volScalarField>(true))
        {
            Info<< "    no field " << fieldName << ": skipped" << nl << endl;
            continue;
        }

        #include "computeAlteration.H"
        #include "writeAlteration.H"

        ++nProcessed;
    }

    if (!nProcessed)
    {
        WarningInFunction
            << "No selected time holds the field " << fieldName
            << ": nothing written" << endl;
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
