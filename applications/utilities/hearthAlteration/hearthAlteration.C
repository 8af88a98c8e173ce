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
      full-revolution volume: sector volume x 360/(wedge angle), the angle
      taken from the two wedge patches.

    Writes, per time, postProcessing/hearthAlteration/<time>/
        alteration_<threshold>C.csv   line,depth_m
        summary.csv                   threshold_C,volume_m3
                                      [,volume360_m3],depth_<line>_m ...
    and prints the same table. Serial and parallel (-parallel on the
    decomposed case) give the same numbers (reductions over the ranks).

    Boundary values of TMax: ahcFoam writes them as 'calculated' values
    that are not maxima over time; the interpolation uses at each boundary
    face the larger of the written value and the adjacent cell's value.

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
#include "unitConversion.H"
#include "checkedRead.H"

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

#include "alterationDepth.H"
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

    const scalar wedgeDeg = wedgeAngle(mesh);
    if (wedgeDeg > 0)
    {
        Info<< "Wedge mesh of " << wedgeDeg << " degrees: full-revolution"
            << " volumes = sector volumes x " << 360/wedgeDeg << nl << endl;
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
