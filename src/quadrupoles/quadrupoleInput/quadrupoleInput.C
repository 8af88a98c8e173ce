/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "quadrupoleInput.H"
#include "Tuple2.H"
#include "checkedRead.H"
#include "numericTable.H"
#include "OSspecific.H"
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * //

namespace Foam
{

// Dimensions
static const dimensionSet dimEffusivity(1, 0, -2.5, -1, 0, 0, 0);
static const dimensionSet dimDiffusivity(0, 2, -1, 0, 0, 0, 0);
static const dimensionSet dimConductivity(1, 1, -3, -1, 0, 0, 0);
static const dimensionSet dimVolHeatCapacity(1, -1, -2, -1, 0, 0, 0);
static const dimensionSet dimGamma(0, 0, -0.5, 0, 0, 0, 0);

static const wordList materialKeywords
({
    "effusivity", "diffusivity", "conductivity", "volumetricHeatCapacity"
});


//- Read (effusivity, diffusivity) given as such or as (conductivity,
//  volumetricHeatCapacity), keywords with the given suffix. False if none
//  of the four keywords is present; an error for a mixture or a half pair
static bool readProperties
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
static void readHistoryFile
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


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

std::string Foam::quadrupoleInput::sig(const double x, const int digits)
{
    std::ostringstream os;
    os << std::setprecision(digits) << x;
    return os.str();
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::quadrupoleInput::readLayers(const dictionary& dict)
{
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
        layers_.push_back(L);
    }
}


void Foam::quadrupoleInput::readSubstrate(const dictionary& dict)
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
    substrate_.b = b;
    substrate_.a = a;
}


void Foam::quadrupoleInput::readSurface
(
    const dictionary& dict,
    const fileName& caseDir
)
{
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
    condition_ = surfaceDict.get<word>("condition");
    if (condition_ != "temperature" && condition_ != "flux")
    {
        FatalIOErrorInFunction(surfaceDict)
            << "Keyword 'condition' = " << condition_
            << ": valid choices are temperature, flux" << nl
            << exit(FatalIOError);
    }
    bc_ =
        condition_ == "flux"
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
        historySource_ = "table of " + surfaceDict.name();
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
            file = caseDir/file;
        }
        historySource_ = file;
        historyFile = file;
        readHistoryFile(surfaceDict, file, rows, historyLines);
    }

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
                << "History (" << historySource_.c_str() << ") row " << i + 1
                << ": time " << rows[i].first() << " " << timeUnit
                << ", value " << v << ": times must be finite and >= 0,"
                << " values finite" << nl << exit(FatalIOError);
        }
        if (i > 0 && t < history_.t.back())
        {
            FatalIOErrorInFunction(surfaceDict)
                << "History (" << historySource_.c_str() << ") rows " << i
                << " and " << i + 1 << ": time " << rows[i].first()
                << " after " << rows[i - 1].first() << " " << timeUnit
                << ": times must not decrease (a repeated time is a jump)"
                << nl << exit(FatalIOError);
        }
        history_.t.push_back(t);
        history_.v.push_back
        (
            bc_ == quadrupole::surfaceCondition::temperature ? v - Tinit_ : v
        );
    }
}


void Foam::quadrupoleInput::readDepthsAndTimes(const dictionary& dict)
{
    const scalarList depths
    (
        checkedRead::getList
        (
            dict, "depths", checkedRead::positive(),
            "depths [m] below the surface in (0, inf), e.g. (0.01 0.05)"
        )
    );
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
        depths_.push_back(depths[j]);
    }

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
            times_.push_back(tl[i]);
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
            times_.push_back(i*dt);
        }
        if (times_.empty() || endTime - times_.back() > 1e-9*endTime)
        {
            times_.push_back(endTime);
        }
        else
        {
            times_.back() = endTime;
        }
    }
}


void Foam::quadrupoleInput::readInversion(const dictionary& dict)
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
    const label M =
        checkedRead::getLabelOrDefault(id, "M", inversion_.M, 2, 500);
    inversion_.M = M;
    inversion_.tolerance =
        checkedRead::getOrDefault
        (
            id, "tolerance", dimless, inversion_.tolerance,
            validRange{0, 1e-3, true, false}
        ).value();
    inversion_.Tfactor =
        checkedRead::getOrDefault
        (
            id, "Tfactor", dimless, inversion_.Tfactor,
            checkedRead::closed(0.5, 10)
        ).value();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::quadrupoleInput::quadrupoleInput
(
    const fileName& dictFile,
    const fileName& caseDir
)
:
    Tinit_(0),
    bc_(quadrupole::surfaceCondition::temperature)
{
    const dictionary dict(checkedRead::readDictionary(dictFile));

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

    Info<< "Reading " << dictFile << nl << endl;

    Tinit_ =
        checkedRead::getOrDefault
        (
            dict, "initialTemperature", dimTemperature, 0,
            validRange{-GREAT, GREAT, true, true}
        ).value();

    readLayers(dict);
    readSubstrate(dict);
    readSurface(dict, caseDir);
    readDepthsAndTimes(dict);

    fileName f
    (
        dict.getOrDefault<fileName>
        (
            "outputFile",
            "postProcessing/quadrupoleTemperature/temperature.csv"
        )
    );
    f.expand();
    outputFile_ = f.isAbsolute() ? f : caseDir/f;

    readInversion(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::quadrupoleInput::report() const
{
    Info<< "Soil (z down from the surface; k [W/(m K)], c [J/(m3 K)],"
        << " a [m2/s], b [W s^0.5/(m2 K)], xi [s^0.5], gamma [s^-0.5])"
        << nl;
    {
        real top = 0;
        for (const quadrupole::gradedLayer& L : layers_)
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
            << sig(substrate_.b*std::sqrt(substrate_.a)).c_str()
            << "  c " << sig(substrate_.b/std::sqrt(substrate_.a)).c_str()
            << "  a " << sig(substrate_.a).c_str()
            << "  b " << sig(substrate_.b).c_str() << nl;
    }
    Info<< "Surface: imposed " << condition_ << " ("
        << (bc_ == quadrupole::surfaceCondition::flux
            ? "W/m2 into the soil" : "unit of initialTemperature")
        << "), " << history_.t.size() << " rows from "
        << historySource_.c_str()
        << ", t from " << sig(history_.t.front()).c_str() << " to "
        << sig(history_.t.back()).c_str() << " s (value held after)" << nl
        << "Initial temperature " << Tinit_ << nl
        << "Output: " << times_.size() << " times from "
        << sig(times_.front()).c_str() << " to "
        << sig(times_.back()).c_str()
        << " s, surface and " << depths_.size() << " depths" << nl
        << "de Hoog inversion: M " << inversion_.M << " ("
        << 2*inversion_.M + 1
        << " transform values per series), tolerance "
        << sig(inversion_.tolerance).c_str() << ", T = "
        << sig(inversion_.Tfactor).c_str()
        << " x largest time of each decade" << nl << endl;
}


// ************************************************************************* //
