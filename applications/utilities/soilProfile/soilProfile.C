/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    soilProfile

Description
    Writes the cell fields that override the uniform soil values of
    constant/soilProperties (or porousProperties) in ahcFoam (README "The soil"):

        porosity        [-]         [0, 1)
        waterContent    [-]         volumetric, [0, porosity]
        rhoCpSolid      [J/(m3 K)]  > 0
        kappaSolid      [W/(m K)]   > 0

    each as a function of the depth of the cell centre, given in
    system/soilProfileDict (or -dict FILE) per property either by layers
    (depth intervals, each with its value) or by a continuous profile. Every
    value is an OpenFOAM Function1 of the depth [m]: a number, or
    polynomial, table, tableFile, csvFile, ... (a layer's value may itself
    be a profile, e.g. a water content rising linearly in a graded layer
    over a uniform substrate). Depth = (C - origin) . direction/|direction|,
    by default the distance below the plane z = 0 (origin (0 0 0),
    direction (0 0 -1)).

        origin      (0 0 0);        // a point of the ground surface [m]
        direction   (0 0 -1);       // downward; need not be normalised

        porosity                    // layers: named, top to bottom
        {
            layers
            {
                topsoil { from 0;   to 0.3; value 0.30; }
                subsoil { from 0.3;         value 0.25; }  // last: 'to'
            }                                   // omitted = all depths below
        }
        waterContent                // a continuous profile
        {
            profile     table ((0 0.05) (1 0.2));    // (depth value) rows
        }
        rhoCpSolid                  // layers with profiles as values
        {
            layers
            {
                graded    { from 0; to 1; value polynomial ((1.3e6 0) (1.3e6 1)); }
                substrate { from 1;       value 2.6e6; }
            }
        }
        kappaSolid { profile tableFile; profileCoeffs { file "<constant>/k.dat"; } }

    Cells are assigned to the layer with from <= depth < to (the last
    layer also takes depth = to). Values are those of the Function1 at the
    cell centres (no averaging over the cell): align the mesh with the
    layer interfaces for sharp layers. Tables (table, tableFile, csvFile)
    hold their end values outside their rows by default (OpenFOAM's
    'outOfBounds clamp'); the utility prints where that happens, and with
    'outOfBounds error' in the coefficients stops with an error naming the
    file and keyword.

    Checks, all before anything is written, each a FatalIOError naming the
    file (and line) and the keyword:
    - unknown keywords (a misspelt property name);
    - a property with both or neither of 'layers' and 'profile';
    - layers: 'to' <= 'from', a gap or an overlap between consecutive
      layers, a 'to' missing except on the last layer, cells above the
      first layer or below the last one;
    - a table with 'outOfBounds error' that does not cover the cells;
    - values: not finite, or outside the valid range at any cell (the
      depth and the position of the first bad cell are named); the water
      content is checked against the porosity of each cell: the one
      written by the same run, else the porosity field of the time
      profiled, else of the start time (a case restarted from a later
      time keeps its material fields there, as the solvers read them:
      src/general/propertyField), else the porosity of
      constant/soilProperties (or porousProperties); a porosity written alone is checked
      against the existing water content in the same way;
    - existing fields (a FatalError listing them): a field of the start
      time not written by soilProfile (no 'note "soilProfile ..."' in its
      header) is never replaced unless -overwrite is given; fields
      written by an earlier soilProfile run are replaced.

    The fields go to the time directory the solver would start from
    (controlDict startFrom: usually startTime, 0/; latestTime on a
    restarted case), with zeroGradient on the non-constraint patches (ahcFoam
    uses the cell values only). -parallel writes each processor's part.

    Reading, checking and evaluation: src/soil/soilProfileFields.

Usage
    soilProfile [-dict file] [-overwrite] [-case dir] [-parallel]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "soilProfileFields.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write the soil property fields porosity, waterContent, rhoCpSolid"
        " and kappaSolid of the start time from layers or profiles of depth"
        " (system/soilProfileDict)"
    );
    argList::noFunctionObjects();
    argList::addOption
    (
        "dict",
        "file",
        "Read this dictionary instead of system/soilProfileDict"
        " (relative to the case directory)"
    );
    argList::addBoolOption
    (
        "overwrite",
        "Replace existing fields that soilProfile did not write"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    using namespace Foam;

    // Dictionary, from the (global) case directory
    const fileName caseDir(args.rootPath()/args.globalCaseName());
    const fileName dictArg
    (
        args.getOrDefault<fileName>("dict", "system/soilProfileDict")
    );
    fileName dictFile(dictArg);
    dictFile.expand();
    if (!dictFile.isAbsolute())
    {
        dictFile = caseDir/dictFile;
    }
    const dictionary dict(checkedRead::readDictionary(dictFile));
    Info<< "Reading " << dictFile << nl << endl;

    // Messages and the summary with 10 digits, whatever the writePrecision
    // (restored for writing the fields)
    const unsigned writePrecision = IOstream::defaultPrecision();
    IOstream::defaultPrecision(10);
    Sout.precision(10);
    Pout.precision(10);
    FatalError().precision(10);
    FatalIOError.error::operator()().precision(10);

    // Read and evaluate, check everything, then write
    const soilProfileFields profile(mesh, dict, dictArg);
    profile.checkRanges();
    profile.checkExisting(args.found("overwrite"));

    IOstream::defaultPrecision(writePrecision);
    profile.write();

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
