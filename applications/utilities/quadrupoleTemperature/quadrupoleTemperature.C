/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    quadrupoleTemperature

Description
    Semi-analytical temperature history of a 1-D soil made of layers of
    uniform gradient factor gamma over a uniform semi-infinite substrate,
    under an imposed surface temperature or surface flux history: the
    thermal quadrupoles of Krapez & Profice for graded media (§2.1, eqs.
    1-12; see doc/references.md) with the de Hoog,
    Knight & Stokes (1982) inversion of the Laplace transform. No mesh, no
    OpenFOAM case: OpenFOAM is used only to read the dictionary.

    Equations (z downward from the surface, T the rise above the uniform
    initial temperature, phi the flux downward, p the Laplace variable):

        c(z) dT/dt = d/dz (k(z) dT/dz)          linear conduction only
        b = sqrt(k c), a = k/c,  xi = int_0^z du/sqrt(a)
        T'' + 2 gamma T' - p T = 0 (' = d/dxi),  gamma = (1/(2c)) db/dz
                                                (paper eqs. 4, 5)
        layer of uniform gamma, thickness x in xi, alpha = sqrt(gamma^2 + p):
        (T, phi/b)_top = exp(gamma x) [[ch - (gamma/alpha) sh, sh/alpha],
                          [(p/alpha) sh, ch + (gamma/alpha) sh]] (T, phi/b)_bottom
                                                (paper eq. 10, ch = cosh(alpha x))
        substrate: phi = b_s sqrt(p) T at its top

    Eq. 10 is right as printed once phi/b is read with the local
    effusivity of each face (b_top on the left, b_bottom = b_top
    exp(2 gamma x) on the right); the layers are chained in (T, phi).
    The initial-condition terms (eqs. 8, 11) vanish for the rise above a
    uniform initial temperature, the only initial state supported.

    (derivation, units, the gamma -> 0 limit and the numerically safe form
    in src/quadrupoles/thermalQuadrupoles). The step and ramp responses of
    each output point are inverted (src/numerics/deHoogInversion) and
    superposed over the piecewise-linear surface history
    (src/quadrupoles/historyResponse: the convolution of
    the step response with the history, exact for a piecewise-linear
    history).

    Limits: 1-D, linear (properties independent of T), no phase change
    (no evaporation of the soil water, no latent heat), properties fixed
    in time, uniform initial temperature, a single condition at the
    surface (temperature or flux; no convective/radiative exchange), the
    soil below the layers semi-infinite and uniform.

    Dictionary: system/quadrupoleDict of the case (the current directory
    by default), or the file given by -dict. Annotated example:
    quadrupoleDict in this folder. Units SI: m, s, W, J, K (temperatures
    in C or K alike: only differences matter, the output is in the unit of
    initialTemperature and of the surface temperatures).

        initialTemperature  20;     // uniform initial temperature; default 0
                                    // (the output is then the rise)
        layers                      // top to bottom; may be empty
        {
            topSoil
            {
                thickness       0.1;        // m, > 0
                // at the top of the layer, either
                effusivity      879;        // b [W s^0.5/(m2 K)], > 0
                diffusivity     4.57e-7;    // a [m2/s], > 0
                // or
                // conductivity           0.6;    // k [W/(m K)], > 0
                // volumetricHeatCapacity 1.3e6;  // c = rho C [J/(m3 K)], > 0

                // the variation down the layer, exactly one of
                gamma           1.1e-3;     // [s^-0.5], any sign; 0: uniform
                // effusivityBottom 1200;   // b at the bottom [W s^0.5/(m2 K)]
                // conductivityBottom 1.0; volumetricHeatCapacityBottom 1.8e6;
                //                          // (gives b and a at the bottom)
                // diffusivityBottom 5e-7;  // a at the bottom [m2/s]; default
                //                          // = diffusivity (uniform a); not
                //                          // with the conductivityBottom form
            }
            // more layers...
        }
        substrate                   // below the layers, semi-infinite, uniform
        {
            effusivity      2008;   // or conductivity and
            diffusivity     5.96e-7;// volumetricHeatCapacity
        }
        surface
        {
            condition   temperature;    // temperature | flux
            // history: (time value) rows, either inline or in a file
            table       ((0 20) (600 700) (21600 700) (30000 100));
            // file     "fire.csv";     // relative to the case directory;
            //                          // columns time, value (others
            //                          // ignored) in the common table
            //                          // format (README "Numeric table
            //                          // files"); times must not decrease
            // timeUnit s;              // s | min | h: unit of the history
            //                          // times (default s)
        }
        depths          (0.01 0.02 0.05);   // m, > 0 (may be in the substrate)
        // output times [s], either
        endTime         86400;      // > 0
        writeInterval   600;        // [1e-7, 1] x endTime: writeInterval,
                                    // 2 writeInterval, ..., and endTime
        // or
        // times        (60 120 3600);  // increasing, > 0
        // outputFile   "postProcessing/quadrupoleTemperature/temperature.csv";
        //                          // default; relative to the case directory
        inversion                   // optional: the de Hoog parameters
        {
            M           30;         // 2M+1 evaluations of the transform per
                                    // series, [2, 500] (default 30)
            tolerance   1e-12;      // aimed relative discretisation error,
                                    // (0, 1e-3]; sets the abscissa
                                    // -ln(tolerance)/(2T) (default 1e-12)
            Tfactor     1;          // half period T = Tfactor x the largest
                                    // time of each decade, [0.5, 10]
                                    // (default 1)
        }

    Layer model: the effusivity varies as b_top exp(2 gamma xi) and the
    diffusivity linearly in z from its top to its bottom value, hence
    c = b/sqrt(a) and k = b sqrt(a) at every depth; gamma 0 and equal
    diffusivities is the classical uniform layer. Given effusivityBottom
    (or conductivityBottom and volumetricHeatCapacityBottom) instead of
    gamma, gamma = ln(b_bottom/b_top)/(2 xi_L), xi_L the root diffusion
    time of the layer: the layer then has the given properties at both
    faces. To approximate a continuous profile (e.g. a water content
    rising with depth), split it into layers and give each its top and
    bottom values (Krapez & Profice report 0.1 K RMS on the surface
    temperature of their soil with two uniform-gamma layers, where 15
    uniform layers are needed: reproduced in tests/gradedSoilQuadrupole,
    0.084 K with layers exact in capacity and resistance, 0.21-0.52 K
    with face values).

    Surface history: theta(t) = 0 at t <= 0; the first row's value on
    (0, t_0]; linear between rows; the last value held after the last row;
    two rows with the same time make a jump. For condition temperature
    the values are temperatures (rise = value - initialTemperature), for
    flux they are the heat flux into the soil [W/m2] (positive heats).

    Output: a CSV file, one row per output time:
        time_s,T_surface,T_<depth>m,...
    temperatures = initialTemperature + rise (12 significant digits), the
    surface first (under an imposed temperature it is the history itself),
    then the depths in the order given. At the time of a jump of the
    history the value before the jump is written. The layers (properties
    at their faces), the history and the inversion are printed.

    Accuracy: the inversion is good to about 1e-11 of the response
    (tests/deHoogInversion, tests/quadrupoleExact); the superposition over
    a history multiplies this by about (output time)/(shortest history
    interval). Cost: about 2 us per distinct (output time - history time)
    and output point; the arguments recur with uniform steps and are
    computed once: 2000 output times x 2000 history rows x 7 points took
    4 s of CPU with uniform steps, 46 s when no argument recurs.

Usage
    quadrupoleTemperature [-case dir] [-dict file]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "IFstream.H"
#include "OFstream.H"
#include "Tuple2.H"
#include "checkedRead.H"
#include "numericTable.H"
#include "historyResponse.H"
#include <chrono>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{

// Dimensions
static const dimensionSet dimEffusivity(1, 0, -2.5, -1, 0, 0, 0);
static const dimensionSet dimDiffusivity(0, 2, -1, 0, 0, 0, 0);
static const dimensionSet dimConductivity(1, 1, -3, -1, 0, 0, 0);
static const dimensionSet dimVolHeatCapacity(1, -1, -2, -1, 0, 0, 0);
static const dimensionSet dimGamma(0, 0, -0.5, 0, 0, 0, 0);

//- A number as text with the given significant digits
std::string sig(const double x, const int digits = 6)
{
    std::ostringstream os;
    os << std::setprecision(digits) << x;
    return os.str();
}

//- Read (effusivity, diffusivity) given as such or as (conductivity,
//  volumetricHeatCapacity), keywords with the given suffix. False if none
//  of the four keywords is present; an error for a mixture or a half pair
bool readProperties
(
    const dictionary& dict,
    const word& suffix,
    scalar& b,
    scalar& a
)
{
    const word kb("effusivity" + suffix), ka("diffusivity" + suffix);
    const word kk("conductivity" + suffix),
        kc("volumetricHeatCapacity" + suffix);

    const bool fb = dict.found(kb), fa = dict.found(ka);
    const bool fk = dict.found(kk), fc = dict.found(kc);

    if ((fb || fa) && (fk || fc))
    {
        FatalIOErrorInFunction(dict)
            << "Both '" << (fb ? kb : ka) << "' and '" << (fk ? kk : kc)
            << "' in dictionary " << dict.name() << ": give either "
            << kb << " and " << ka << ", or " << kk << " and " << kc
            << nl << exit(FatalIOError);
    }
    if (fk || fc)
    {
        const scalar k =
            checkedRead::get(dict, kk, dimConductivity, checkedRead::positive())
           .value();
        const scalar c =
            checkedRead::get
            (
                dict, kc, dimVolHeatCapacity, checkedRead::positive()
            ).value();
        b = Foam::sqrt(k*c);
        a = k/c;
        return true;
    }
    if (fb || fa)
    {
        b = checkedRead::get
            (
                dict, kb, dimEffusivity, checkedRead::positive()
            ).value();
        a = checkedRead::get
            (
                dict, ka, dimDiffusivity, checkedRead::positive()
            ).value();
        return true;
    }
    return false;
}


//- Read a two-column history file (time, value) with the common table
//  reader (src/general/numericTable): errors name the file and line
void readHistoryFile
(
    const dictionary& surfaceDict,
    const fileName& file,
    List<Tuple2<scalar, scalar>>& rows,
    labelList& lines
)
{
    if (!isFile(file))
    {
        FatalIOErrorInFunction(surfaceDict)
            << "Keyword 'file': cannot read " << file << nl
            << exit(FatalIOError);
    }

    numericTable::settings s;
    s.numericColumns = labelList({0, 1});
    s.roles = {"a time", "a value"};
    s.columnsDescription = "the time (column 0) and the value (column 1)";
    s.orderedColumn = 0;
    s.ordering = numericTable::order::nonDecreasing;
    s.what = "the surface history file";
    s.context = "keyword 'file' of " + surfaceDict.name();
    const numericTable table(file, s);

    rows.setSize(table.size());
    lines.setSize(table.size());
    forAll(rows, i)
    {
        rows[i] = Tuple2<scalar, scalar>(table.value(i, 0), table.value(i, 1));
        lines[i] = table.line(i);
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    using namespace Foam;

    argList::addNote
    (
        "Temperature history at given depths of a 1-D soil of layers of"
        " uniform gradient factor gamma over a semi-infinite substrate,"
        " under an imposed surface temperature or flux history: thermal"
        " quadrupoles (Krapez & Profice) and de Hoog Laplace inversion"
        " (system/quadrupoleDict; no mesh)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "dict",
        "file",
        "Read this dictionary instead of system/quadrupoleDict"
        " (relative to the case directory)"
    );

    #include "setRootCase.H"

    const auto wallStart = std::chrono::steady_clock::now();

    fileName dictFile(args.getOrDefault<fileName>("dict", "system/quadrupoleDict"));
    dictFile.expand();
    if (!dictFile.isAbsolute())
    {
        dictFile = args.path()/dictFile;
    }
    if (!isFile(dictFile))
    {
        FatalErrorInFunction
            << "Cannot read the dictionary " << dictFile << nl
            << exit(FatalError);
    }
    IFstream dictStream(dictFile);
    const dictionary dict(dictStream);

    // Unknown keywords (a misspelt 'writeInterval' would be ignored)
    checkedRead::checkKeywords
    (
        dict,
        wordList
        ({
            "initialTemperature", "layers", "substrate", "surface", "depths",
            "times", "endTime", "writeInterval", "outputFile", "inversion"
        }),
        "quadrupoleTemperature"
    );
    const wordList materialKeywords
    ({
        "effusivity", "diffusivity", "conductivity", "volumetricHeatCapacity"
    });

    Info<< "Reading " << dictFile << nl << endl;

    using quadrupole::real;

    const scalar Tinit =
        checkedRead::getOrDefault
        (
            dict, "initialTemperature", dimTemperature, 0,
            validRange{-GREAT, GREAT, true, true}
        ).value();

    // Layers -----------------------------------------------------------------

    std::vector<quadrupole::gradedLayer> layers;
    if (!dict.isDict("layers"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary 'layers' (name { thickness ...; }"
            << " entries, top to bottom; may be empty: layers {})" << nl
            << exit(FatalIOError);
    }
    for (const entry& e : dict.subDict("layers"))
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(dict.subDict("layers"))
                << "Entry '" << e.keyword() << "' of 'layers' is not a"
                << " dictionary: expected name { thickness ...; }" << nl
                << exit(FatalIOError);
        }
        const dictionary& ld = e.dict();
        quadrupole::gradedLayer L;
        L.name = e.keyword();
        {
            wordList known({"thickness", "gamma"});
            for (const word& k : materialKeywords)
            {
                known.append(k);
                known.append(word(k + "Bottom"));
            }
            checkedRead::checkKeywords(ld, known, "layer " + L.name);
        }
        L.thickness =
            checkedRead::get(ld, "thickness", dimLength, checkedRead::positive())
           .value();
        scalar b, a;
        if (!readProperties(ld, "", b, a))
        {
            FatalIOErrorInFunction(ld)
                << "Layer '" << L.name.c_str() << "': missing 'effusivity' and"
                << " 'diffusivity' (or 'conductivity' and"
                << " 'volumetricHeatCapacity') at its top" << nl
                << exit(FatalIOError);
        }
        L.bTop = b;
        L.aTop = a;
        L.aBottom = a;

        // The variation down the layer: exactly one of gamma,
        // effusivityBottom, (conductivityBottom, volumetricHeatCapacityBottom)
        const bool hasGamma = ld.found("gamma");
        const bool hasBBottom = ld.found("effusivityBottom");
        const bool hasKcBottom =
            ld.found("conductivityBottom")
         || ld.found("volumetricHeatCapacityBottom");
        if (label(hasGamma) + label(hasBBottom) + label(hasKcBottom) != 1)
        {
            FatalIOErrorInFunction(ld)
                << "Layer '" << L.name.c_str() << "': give exactly one of 'gamma'"
                << " [s^-0.5] (0 for a uniform layer), 'effusivityBottom',"
                << " or 'conductivityBottom' and"
                << " 'volumetricHeatCapacityBottom'" << nl
                << exit(FatalIOError);
        }
        scalar bBottom = 0;
        if (hasKcBottom)
        {
            scalar aBottom = 0;
            readProperties(ld, "Bottom", bBottom, aBottom);
            L.aBottom = aBottom;
        }
        else
        {
            L.aBottom =
                checkedRead::getOrDefault
                (
                    ld, "diffusivityBottom", dimDiffusivity, a,
                    checkedRead::positive()
                ).value();
        }
        if (hasGamma)
        {
            L.gamma =
                checkedRead::get
                (
                    ld, "gamma", dimGamma,
                    validRange{-GREAT, GREAT, true, true}
                ).value();
        }
        else
        {
            if (hasBBottom)
            {
                bBottom =
                    checkedRead::get
                    (
                        ld, "effusivityBottom", dimEffusivity,
                        checkedRead::positive()
                    ).value();
            }
            L.gamma = std::log(bBottom/L.bTop)/(2*L.xi(L.thickness));
        }
        // exp(2 gamma xi_L) must stay representable
        if (std::fabs(2*L.gamma*L.xi(L.thickness)) > 200)
        {
            FatalIOErrorInFunction(ld)
                << "Layer '" << L.name.c_str() << "': gamma = "
                << sig(L.gamma).c_str()
                << " s^-0.5 makes the effusivity vary by exp("
                << sig(2*L.gamma*L.xi(L.thickness)).c_str()
                << ") across the layer (at most exp(200))"
                << nl << exit(FatalIOError);
        }
        layers.push_back(L);
    }

    quadrupole::uniformSubstrate substrate;
    {
        if (!dict.isDict("substrate"))
        {
            FatalIOErrorInFunction(dict)
                << "Missing sub-dictionary 'substrate' (effusivity and"
                << " diffusivity, or conductivity and"
                << " volumetricHeatCapacity)" << nl
                << exit(FatalIOError);
        }
        const dictionary& sd = dict.subDict("substrate");
        checkedRead::checkKeywords(sd, materialKeywords, "substrate");
        scalar b, a;
        if (!readProperties(sd, "", b, a))
        {
            FatalIOErrorInFunction(sd)
                << "Substrate: missing 'effusivity' and 'diffusivity' (or"
                << " 'conductivity' and 'volumetricHeatCapacity')" << nl
                << exit(FatalIOError);
        }
        substrate.b = b;
        substrate.a = a;
    }

    // Surface ----------------------------------------------------------------

    if (!dict.isDict("surface"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary 'surface' (condition, table or file)"
            << nl << exit(FatalIOError);
    }
    const dictionary& surfaceDict = dict.subDict("surface");
    checkedRead::checkKeywords
    (
        surfaceDict, wordList({"condition", "timeUnit", "table", "file"}),
        "surface history"
    );
    const word condition(surfaceDict.get<word>("condition"));
    if (condition != "temperature" && condition != "flux")
    {
        FatalIOErrorInFunction(surfaceDict)
            << "Keyword 'condition' = " << condition
            << ": valid choices are temperature, flux" << nl
            << exit(FatalIOError);
    }
    const quadrupole::surfaceCondition bc =
        condition == "flux"
      ? quadrupole::surfaceCondition::flux
      : quadrupole::surfaceCondition::temperature;

    const word timeUnit(surfaceDict.getOrDefault<word>("timeUnit", "s"));
    scalar timeFactor = 1;
    if (timeUnit == "min") timeFactor = 60;
    else if (timeUnit == "h") timeFactor = 3600;
    else if (timeUnit != "s")
    {
        FatalIOErrorInFunction(surfaceDict)
            << "Keyword 'timeUnit' = " << timeUnit
            << ": valid choices are s, min, h" << nl
            << exit(FatalIOError);
    }

    List<Tuple2<scalar, scalar>> rows;
    const bool hasTable = surfaceDict.found("table");
    const bool hasFile = surfaceDict.found("file");
    if (hasTable == hasFile)
    {
        FatalIOErrorInFunction(surfaceDict)
            << "Give exactly one of 'table' ((time value) rows) and 'file'"
            << " (a CSV of time, value)" << nl
            << exit(FatalIOError);
    }
    std::string historySource;
    fileName historyFile;           // (a file: its name and the lines)
    labelList historyLines;
    if (hasTable)
    {
        checkedRead::checkNumbers
        (
            surfaceDict, "table",
            "(time value) rows, times >= 0 in timeUnit, e.g. ((0 20) (600 700))"
        );
        rows = surfaceDict.get<List<Tuple2<scalar, scalar>>>("table");
        historySource = "table of " + surfaceDict.name();
        if (rows.empty())
        {
            FatalIOErrorInFunction(surfaceDict)
                << "Keyword 'table' is empty: expected (time value) rows"
                << nl << exit(FatalIOError);
        }
    }
    else
    {
        fileName file(surfaceDict.get<fileName>("file"));
        file.expand();
        if (!file.isAbsolute())
        {
            file = args.path()/file;
        }
        historySource = file;
        historyFile = file;
        readHistoryFile(surfaceDict, file, rows, historyLines);
    }

    quadrupole::piecewiseLinearHistory history;
    forAll(rows, i)
    {
        const scalar t = rows[i].first()*timeFactor;
        const scalar v = rows[i].second();
        if (!std::isfinite(t) || !std::isfinite(v) || t < 0)
        {
            if (historyFile.size())
            {
                FatalIOError
                (
                    FUNCTION_NAME, __FILE__, __LINE__, historyFile,
                    historyLines[i]
                )   << "Line " << historyLines[i] << " of the surface history"
                    << " file: time " << rows[i].first() << " " << timeUnit
                    << " (" << t << " s), value " << v << ": times must be"
                    << " >= 0 and finite in s" << nl
                    << "    in keyword 'file' of " << surfaceDict.name()
                    << nl << exit(FatalIOError);
            }
            FatalIOErrorInFunction(surfaceDict)
                << "History (" << historySource.c_str() << ") row " << i + 1
                << ": time " << rows[i].first() << " " << timeUnit
                << ", value " << v << ": times must be finite and >= 0,"
                << " values finite" << nl << exit(FatalIOError);
        }
        if (i > 0 && t < history.t.back())
        {
            FatalIOErrorInFunction(surfaceDict)
                << "History (" << historySource.c_str() << ") rows " << i
                << " and " << i + 1 << ": time " << rows[i].first()
                << " after " << rows[i - 1].first() << " " << timeUnit
                << ": times must not decrease (a repeated time is a jump)"
                << nl << exit(FatalIOError);
        }
        history.t.push_back(t);
        history.v.push_back
        (
            bc == quadrupole::surfaceCondition::temperature ? v - Tinit : v
        );
    }

    // Depths and times -------------------------------------------------------

    const scalarList depths
    (
        checkedRead::getList
        (
            dict, "depths", checkedRead::positive(),
            "depths [m] below the surface in (0, inf), e.g. (0.01 0.05)"
        )
    );
    std::vector<real> depthList;
    forAll(depths, j)
    {
        checkedRead::check(dict, "depths", depths[j], checkedRead::positive());
        for (label i = 0; i < j; ++i)
        {
            if (depths[i] == depths[j])
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword 'depths': " << depths[j] << " m given twice"
                    << nl << exit(FatalIOError);
            }
        }
        depthList.push_back(depths[j]);
    }

    std::vector<real> times;
    if (dict.found("times"))
    {
        if (dict.found("endTime") || dict.found("writeInterval"))
        {
            FatalIOErrorInFunction(dict)
                << "Give either 'times' or 'endTime' and 'writeInterval'"
                << nl << exit(FatalIOError);
        }
        const scalarList tl
        (
            checkedRead::getList
            (
                dict, "times", checkedRead::positive(),
                "output times [s] in (0, inf), increasing"
            )
        );
        if (tl.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Keyword 'times' is empty" << nl << exit(FatalIOError);
        }
        forAll(tl, i)
        {
            checkedRead::check(dict, "times", tl[i], checkedRead::positive());
            if (i > 0 && !(tl[i] > tl[i - 1]))
            {
                FatalIOErrorInFunction(dict)
                    << "Keyword 'times': " << tl[i] << " after "
                    << tl[i - 1] << ": times must increase" << nl
                    << exit(FatalIOError);
            }
            times.push_back(tl[i]);
        }
    }
    else
    {
        const scalar endTime =
            checkedRead::get(dict, "endTime", dimTime, checkedRead::positive())
           .value();
        const scalar dt =
            checkedRead::get
            (
                dict, "writeInterval", dimTime,
                validRange{endTime*1e-7, endTime, false, false}
            ).value();
        const label n = label(std::floor(endTime/dt*(1 + 1e-12)));
        for (label i = 1; i <= n; ++i)
        {
            times.push_back(i*dt);
        }
        if (times.empty() || endTime - times.back() > 1e-9*endTime)
        {
            times.push_back(endTime);
        }
        else
        {
            times.back() = endTime;
        }
    }

    const fileName outputFile
    (
        [&]()
        {
            fileName f
            (
                dict.getOrDefault<fileName>
                (
                    "outputFile",
                    "postProcessing/quadrupoleTemperature/temperature.csv"
                )
            );
            f.expand();
            return f.isAbsolute() ? f : args.path()/f;
        }()
    );

    // Inversion parameters ---------------------------------------------------

    quadrupole::deHoogParameters par;
    {
        const dictionary& id = dict.optionalSubDict("inversion");
        if (dict.isDict("inversion"))
        {
            checkedRead::checkKeywords
            (
                id, wordList({"M", "tolerance", "Tfactor"}),
                "de Hoog inversion"
            );
        }
        if (id.found("M"))
        {
            checkedRead::checkNumbers(id, "M", "an integer in [2, 500]");
        }
        const label M = checkedRead::getLabelOrDefault(id, "M", par.M, 2, 500);
        par.M = M;
        par.tolerance =
            checkedRead::getOrDefault
            (
                id, "tolerance", dimless, par.tolerance,
                validRange{0, 1e-3, true, false}
            ).value();
        par.Tfactor =
            checkedRead::getOrDefault
            (
                id, "Tfactor", dimless, par.Tfactor,
                checkedRead::closed(0.5, 10)
            ).value();
    }

    // Summary ----------------------------------------------------------------

    Info<< "Soil (z down from the surface; k [W/(m K)], c [J/(m3 K)],"
        << " a [m2/s], b [W s^0.5/(m2 K)], xi [s^0.5], gamma [s^-0.5])"
        << nl;
    {
        real top = 0;
        for (const quadrupole::gradedLayer& L : layers)
        {
            const real H = L.thickness;
            Info<< "    layer " << L.name.c_str() << ": z " << sig(top).c_str()
                << " to " << sig(top + H).c_str() << " m, xi_L "
                << sig(L.xi(H)).c_str() << ", gamma "
                << sig(L.gamma).c_str() << nl
                << "        top:    k " << sig(L.k(0)).c_str()
                << "  c " << sig(L.c(0)).c_str()
                << "  a " << sig(L.a(0)).c_str()
                << "  b " << sig(L.b(0)).c_str() << nl
                << "        bottom: k " << sig(L.k(H)).c_str()
                << "  c " << sig(L.c(H)).c_str()
                << "  a " << sig(L.a(H)).c_str()
                << "  b " << sig(L.b(H)).c_str() << nl;
            top += H;
        }
        Info<< "    substrate: z > " << sig(top).c_str() << " m, k "
            << sig(substrate.b*std::sqrt(substrate.a)).c_str()
            << "  c " << sig(substrate.b/std::sqrt(substrate.a)).c_str()
            << "  a " << sig(substrate.a).c_str()
            << "  b " << sig(substrate.b).c_str() << nl;
    }
    Info<< "Surface: imposed " << condition << " ("
        << (bc == quadrupole::surfaceCondition::flux
            ? "W/m2 into the soil" : "unit of initialTemperature")
        << "), " << history.t.size() << " rows from " << historySource.c_str()
        << ", t from " << sig(history.t.front()).c_str() << " to "
        << sig(history.t.back()).c_str() << " s (value held after)" << nl
        << "Initial temperature " << Tinit << nl
        << "Output: " << times.size() << " times from "
        << sig(times.front()).c_str() << " to " << sig(times.back()).c_str()
        << " s, surface and " << depthList.size() << " depths" << nl
        << "de Hoog inversion: M " << par.M << " (" << 2*par.M + 1
        << " transform values per series), tolerance "
        << sig(par.tolerance).c_str() << ", T = " << sig(par.Tfactor).c_str()
        << " x largest time of each decade" << nl << endl;

    // Solve ------------------------------------------------------------------

    const quadrupole::layeredSoil soil(layers, substrate, depthList);
    const quadrupole::historyResponse response(soil, bc, par);
    size_t nPairs = 0;
    std::vector<std::vector<real>> rise;
    try
    {
        rise = response.rise(history, times, nPairs);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Laplace inversion failed: " << err.what() << nl
            << exit(FatalError);
    }

    // Write ------------------------------------------------------------------

    mkDir(outputFile.path());
    {
        OFstream os(outputFile);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << outputFile << nl << exit(FatalError);
        }
        os  << "time_s,T_surface";
        for (const real d : depthList)
        {
            os  << ",T_" << sig(d, 10).c_str() << 'm';
        }
        os  << nl;
        for (size_t n = 0; n < times.size(); ++n)
        {
            os  << sig(times[n], 12).c_str();
            for (size_t j = 0; j < rise.size(); ++j)
            {
                os  << ',' << sig(Tinit + rise[j][n], 12).c_str();
            }
            os  << nl;
        }
    }

    const double wall =
        std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - wallStart
        ).count();

    Info<< "Wrote " << outputFile << nl
        << "    " << nPairs << " (time, history event) pairs, "
        << sig(wall, 3).c_str() << " s" << nl;

    Info<< "\nEnd\n" << endl;

    return 0;
}


// ************************************************************************* //
