/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    hearthFit

Description
    Least-squares estimation of case parameters (soil properties, ...) from
    thermocouple histories, by running the solver itself.

    Reads system/hearthFitDict of the case (annotated example: the file
    hearthFitDict next to this source).  Each parameter names a keyword
    path in a case dictionary (file + entry, e.g. constant/porousProperties
    and solid/kappa); the value written is scale*parameter.  Or it is an
    offset of a sensor's position (sensor + component x, y or z): the
    sensors file of the thermocouples function object is rewritten in
    each copy with that sensor moved by the offset.  The measured
    histories are a CSV (time_s, one column per sensor, C), as written by
    the thermocouples function object; the simulated ones are the
    thermocouples CSV of each forward run
    (postProcessing/<functionObject>/<startTime>/sensors.csv), linearly
    interpolated to the measured times inside the time window.  Residuals
    r = sqrt(weight)*(simulated - measured)/sigma.

    Forward runs: each in its own scratch copy (system, constant, start
    time) of the case under <workDir>/scratch<k>; the runs of one batch
    (all finite-difference columns of an iteration) run concurrently up to
    maxConcurrentRuns; with nProcs N > 1 each copy is decomposed once
    (decomposePar) and each run is '<mpirun> -np N <solver> -parallel'.
    A run that fails (non-zero exit, no 'End' in its
    log, missing sensors CSV or a CSV not covering the time window) is a
    failed evaluation: the optimiser rejects the step.  The user's case is
    only read; results go to <workDir> (report.txt, fitted.csv,
    progress.csv, sensitivities.csv: the scaled sensitivities
    p_j dT/dp_j [C] per sensor from the final Jacobian, and with gnuplot
    fitted.png and sensitivities.png, script plots.gp; state.dict: the
    fit state after each accepted iteration, from which -resume restarts
    an interrupted fit, appending to progress.csv); scratch copies are
    removed at the end (-keepScratch keeps them).  -writeCase DIR writes a copy of the case with the best
    parameters.

    Optimiser: hearthFit::levenbergMarquardt (src/numerics/leastSquares).

    Nothing is written outside <workDir> but the -writeCase copy: an
    existing -writeCase directory is refused without -overwrite, the case
    itself and directories inside its system, constant or start time (they
    would be copied into themselves) always, and such a workDir too, all
    before any run. Unknown keywords of hearthFitDict are errors naming
    the nearest valid one. A zero-residual fit (s^2 = 0) reports
    zero-width intervals.

Usage
    hearthFit [-case DIR] [-writeCase DIR [-overwrite]] [-keepScratch]
        [-resume] [-maxIterations N]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "thermocouples.H"
#include "numericTable.H"
#include "Time.H"
#include "IOdictionary.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "HashTable.H"

#include "levenbergMarquardt.H"
#include "laloyMassard.H"
#include "checkedRead.H"
#include "casePaths.H"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <thread>
#include <array>
#include <iomanip>
#include <sstream>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

using namespace Foam;

// * * * * * * * * * * * * * * * * Local Types * * * * * * * * * * * * * * * //

namespace
{

struct ParameterSpec
{
    word name;
    fileName file;              // relative to the case
    string entry;               // keyword path, '/'-separated
    scalar scale = 1;
    word sensor;                // sensor offset: the sensor moved
    label component = -1;       // sensor offset: 0 x, 1 y, 2 z
};

// The sensors file of the thermocouples function object: its lines, and
// per sensor line its name and position (other lines kept as they are)
struct SensorFile
{
    fileName rel;               // relative to the case (and a copy)
    std::vector<std::string> lines;
    std::vector<std::string> names;     // "" for a line kept as it is
    std::vector<std::array<double, 3>> xyz;
};

struct Histories
{
    std::vector<double> times;
    std::vector<std::string> names;
    std::vector<std::vector<double>> values;   // [sensor][time]
};


std::string quoted(const std::string& s)
{
    return "'" + s + "'";
}


//- Read a sensor-history CSV (a header: time, then one name per sensor;
//  rows of numbers, as many as the names) with the common table reader
//  (src/general/numericTable). Observations: any error (also duplicate
//  names, times that do not increase strictly, nan, inf) is a
//  FatalIOError naming the file and line. A run's CSV: false with the
//  first error in err; the rows of a restarted run replace the later ones
bool readCsv
(
    const std::string& path,
    Histories& h,
    std::string& err,
    const bool observations = false
)
{
    numericTable::settings s;
    s.nColumns = -2;
    s.uniqueNames = true;
    s.roles = {"a time"};
    s.collect = !observations;
    if (observations)
    {
        s.orderedColumn = 0;
        s.what = "the observations file";
        s.context = "observations of system/hearthFitDict";
    }
    else
    {
        s.what = "the sensors CSV of the run";
    }
    const numericTable table(fileName(path), s);

    if (table.errors().size())
    {
        const numericTable::error& e = table.errors()[0];
        err = path + (e.line > 0 ? " line " + std::to_string(e.line) : "")
            + ": " + e.message;
        return false;
    }
    if (table.names().size() < 2)
    {
        err = path + ": the header needs a time and a sensor column";
        if (observations)
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, path)
                << "observations: " << err.c_str() << nl
                << exit(FatalIOError);
        }
        return false;
    }

    h.names.assign(table.names().begin() + 1, table.names().end());
    h.values.assign(h.names.size(), std::vector<double>());
    h.times.clear();
    forAll(table, rowi)
    {
        const double t = table.value(rowi, 0);
        // Restarted run (not for observations: checked increasing)
        while (h.times.size() && h.times.back() >= t)
        {
            h.times.pop_back();
            for (auto& v : h.values) v.pop_back();
        }
        h.times.push_back(t);
        for (size_t i = 0; i < h.names.size(); ++i)
        {
            h.values[i].push_back(table.value(rowi, i + 1));
        }
    }
    return true;
}


//- Linear interpolation; false if t is outside the times
bool interpolate
(
    const std::vector<double>& t,
    const std::vector<double>& y,
    const double x,
    double& v
)
{
    const double tol = 1e-9*std::max(1.0, std::abs(x));
    if (t.empty() || x < t.front() - tol || x > t.back() + tol) return false;
    if (t.size() == 1) { v = y[0]; return true; }
    size_t i = std::upper_bound(t.begin(), t.end(), x) - t.begin();
    if (i == 0) i = 1;
    if (i >= t.size()) i = t.size() - 1;
    const double t0 = t[i - 1], t1 = t[i];
    const double w = (t1 > t0) ? (x - t0)/(t1 - t0) : 0;
    v = y[i - 1] + std::min(1.0, std::max(0.0, w))*(y[i] - y[i - 1]);
    return true;
}


//- The dictionary holding the last keyword of path, or nullptr
dictionary* parentDict
(
    dictionary& dict,
    const string& path,
    word& key
)
{
    wordList parts;
    {
        std::stringstream ss(path);
        std::string p;
        while (std::getline(ss, p, '/'))
        {
            if (p.size()) parts.append(word(p));
        }
    }
    if (parts.empty()) return nullptr;
    dictionary* d = &dict;
    for (label i = 0; i < parts.size() - 1; ++i)
    {
        d = d->subDictPtr(parts[i]);
        if (!d) return nullptr;
    }
    key = parts.last();
    if (!d->found(key, keyType::LITERAL) || d->isDict(key)) return nullptr;
    return d;
}


void writeDictFile(const fileName& path, const dictionary& dict)
{
    OFstream os(path);
    os.precision(17);
    os  << "FoamFile" << nl
        << "{" << nl
        << "    version     2.0;" << nl
        << "    format      ascii;" << nl
        << "    class       dictionary;" << nl
        << "    object      " << path.name() << ";" << nl
        << "}" << nl
        << "// Written by hearthFit (parameters set)" << nl << nl;
    dict.write(os, false);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Least-squares fit of case parameters to thermocouple histories"
        " (system/hearthFitDict)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "writeCase", "dir", "write a copy of the case with the best parameters"
    );
    argList::addBoolOption
    (
        "overwrite",
        "let -writeCase write into an existing directory (never the case"
        " itself)"
    );
    argList::addBoolOption("keepScratch", "keep the scratch copies");
    argList::addBoolOption
    (
        "resume",
        "resume an interrupted fit from <workDir>/state.dict (the state"
        " after its last accepted iteration)"
    );
    argList::addBoolOption
    (
        "firstEstimateOnly",
        "print the Laloy-Massard first estimate (firstEstimate) and stop"
        " before any forward run"
    );
    argList::addOption
    (
        "maxIterations", "N",
        "override method/maxIterations (total, counting resumed iterations)"
    );

    #include "setRootCase.H"

    Time runTime
    (
        Time::controlDictName,
        args.rootPath(),
        args.caseName(),
        word("system"),
        word("constant"),
        false
    );

    // Parameter values are written into dictionaries at full precision
    // (dictionary::set formats through a string stream)
    IOstream::defaultPrecision(17);

    const fileName casePath(runTime.path());
    const word startName(runTime.timeName());

    // ---- -writeCase: checked before anything is run. The copy (system,
    //      constant, start time, parameter dictionaries rewritten) must not
    //      replace what the user wrote: an existing directory only with
    //      -overwrite, never the case itself, never inside a directory that
    //      is copied (the copy would contain itself)
    fileName writeCasePath;
    if (args.found("writeCase"))
    {
        writeCasePath = casePaths::canonical(args.get<fileName>("writeCase"));
        const fileName holder
        (
            casePaths::copiedDirHolding(casePath, startName, writeCasePath)
        );
        if (casePaths::inside(casePath, writeCasePath))
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << " (" << writeCasePath << ") is the case " << casePath
                << " or contains it: its system, constant and "
                << startName << " would be overwritten. Give a new"
                << " directory outside the case" << exit(FatalError);
        }
        if (!holder.empty())
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << " (" << writeCasePath << ") lies inside " << holder
                << ", which is itself copied into it: the copy would"
                << " contain itself. Give a directory outside the case's"
                << " system, constant and " << startName << exit(FatalError);
        }
        if (exists(writeCasePath) && !args.found("overwrite"))
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << ": " << writeCasePath << " exists; its system, constant"
                << " and " << startName << " would be replaced and its"
                << " parameter dictionaries rewritten without their"
                << " comments. Give a new directory, or add -overwrite"
                << exit(FatalError);
        }
    }

    IOdictionary fitDict
    (
        IOobject
        (
            "hearthFitDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    // Unknown keywords (a misspelt one would silently take its default)
    checkedRead::checkKeywords
    (
        fitDict,
        wordList
        ({
            "parameters", "observations", "forwardModel", "method",
            "firstEstimate"
        })
    );

    if (fitDict.isDict("method"))
    {
        checkedRead::checkKeywords
        (
            fitDict.subDict("method"),
            wordList
            ({
                "type", "difference", "solverNoise", "relativeStep",
                "maxIterations", "tolStep", "tolGradient", "tolCost",
                "initialDamping", "confidence"
            })
        );
    }

    // ---- Parameters
    const dictionary& parsDict = fitDict.subDict("parameters");
    std::vector<hearthFit::FitParameter> fitPars;
    std::vector<ParameterSpec> specs;
    HashTable<dictionary> caseDicts;    // by file (relative)
    std::vector<double> initialFactor;  // initialFrom laloyMassard: factor
                                        // times the median a (0: none)

    for (const entry& e : parsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(parsDict)
                << "parameters: '" << e.keyword() << "' is not a dictionary"
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        ParameterSpec s;
        s.name = e.keyword();
        checkedRead::checkKeywords
        (
            d,
            wordList
            ({
                "file", "entry", "scale", "sensor", "component", "initial",
                "min", "max", "typical", "transform", "initialFrom",
                "initialFactor"
            }),
            "parameter " + s.name
        );
        if (d.found("sensor"))
        {
            // An offset [m] of a sensor's position along x, y or z
            if (d.found("file") || d.found("entry") || d.found("scale"))
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": a sensor offset takes"
                    << " no file, entry or scale" << exit(FatalIOError);
            }
            s.sensor = d.get<word>("sensor");
            const word comp(d.get<word>("component"));
            if (comp == "x") s.component = 0;
            else if (comp == "y") s.component = 1;
            else if (comp == "z") s.component = 2;
            else
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": component " << comp
                    << ": valid are x, y, z" << exit(FatalIOError);
            }
        }
        else
        {
            s.file = d.get<fileName>("file");
            s.entry = d.get<fileName>("entry");
            s.scale = d.lookupOrDefault<scalar>("scale", 1);
        }

        double factor = 0;
        if (d.found("initialFrom"))
        {
            const word from(d.get<word>("initialFrom"));
            if (from != "laloyMassard")
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": initialFrom " << from
                    << ": valid is laloyMassard" << exit(FatalIOError);
            }
            factor = d.lookupOrDefault<scalar>("initialFactor", 1);
            if (!(factor > 0))
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": initialFactor must be"
                    << " > 0" << exit(FatalIOError);
            }
        }
        initialFactor.push_back(factor);

        hearthFit::FitParameter p;
        p.name = s.name;
        p.initial = d.get<scalar>("initial");
        p.lower = d.get<scalar>("min");
        p.upper = d.get<scalar>("max");
        p.typical = d.lookupOrDefault<scalar>("typical", 0);
        const word tr(d.lookupOrDefault<word>("transform", "linear"));
        if (tr == "log") p.transform = hearthFit::Transform::log;
        else if (tr != "linear")
        {
            FatalIOErrorInFunction(d)
                << "transform " << tr << ": valid are linear, log"
                << exit(FatalIOError);
        }
        if (!(p.lower < p.upper) || p.initial < p.lower || p.initial > p.upper)
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": need min < max and initial"
                << " within [min, max] (min " << p.lower << ", max "
                << p.upper << ", initial " << p.initial << ")"
                << exit(FatalIOError);
        }
        if (p.initial == 0 && !(p.typical > 0))
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": initial 0 needs a typical"
                << " > 0 (the finite-difference step floor and scale, e.g."
                << " 1e-3 for a sensor offset in m)" << exit(FatalIOError);
        }
        if (p.typical < 0)
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": typical " << p.typical
                << " < 0" << exit(FatalIOError);
        }
        if (s.component >= 0)
        {
            specs.push_back(s);
            fitPars.push_back(p);
            continue;
        }

        if (!caseDicts.found(s.file))
        {
            IFstream is(casePath/s.file);
            if (!is.good())
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": cannot read "
                    << casePath/s.file << exit(FatalIOError);
            }
            dictionary cd(is);
            cd.remove("FoamFile");
            caseDicts.insert(s.file, cd);
        }
        word key;
        if (!parentDict(caseDicts[s.file], s.entry, key))
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": no keyword path '" << s.entry.c_str()
                << "' (a non-dictionary entry) in " << casePath/s.file
                << exit(FatalIOError);
        }
        specs.push_back(s);
        fitPars.push_back(p);
    }
    const label nPar = specs.size();
    if (!nPar)
    {
        FatalIOErrorInFunction(parsDict) << "no parameters"
            << exit(FatalIOError);
    }

    // ---- Observations
    const dictionary& obsDict = fitDict.subDict("observations");
    checkedRead::checkKeywords
    (
        obsDict,
        wordList
        ({
            "file", "timeUnit", "timeWindow", "sensors", "sigma", "sigmas",
            "weights"
        })
    );
    const fileName obsFile(obsDict.get<fileName>("file").expand());
    const fileName obsPath(obsFile.isAbsolute() ? obsFile : casePath/obsFile);
    Histories measured;
    {
        std::string err;
        if (!readCsv(obsPath, measured, err, true))
        {
            FatalIOErrorInFunction(obsDict)
                << "observations: " << err.c_str() << exit(FatalIOError);
        }
    }
    // The file's time unit (s, min or h; default s): the times, and the
    // timeWindow, converted to the case's seconds at once
    const word timeUnit(obsDict.getOrDefault<word>("timeUnit", "s"));
    const HashTable<scalar> secondsPer({{"s", 1}, {"min", 60}, {"h", 3600}});
    if (!secondsPer.found(timeUnit))
    {
        FatalIOErrorInFunction(obsDict)
            << "timeUnit " << timeUnit << ": valid units are s, min and h"
            << exit(FatalIOError);
    }
    for (double& t : measured.times)
    {
        t *= secondsPer[timeUnit];
    }
    // Times in minutes or hours read as seconds would all fall in the first
    // minutes of the run and be fitted there without a word: unless the
    // unit is given, observations that end within the first 1/60 of the
    // run stop the fit
    const scalar simulated =
        runTime.endTime().value() - runTime.startTime().value();
    if
    (
        !obsDict.found("timeUnit") && !measured.times.empty()
     && measured.times.back() - runTime.startTime().value() <= simulated/60
    )
    {
        FatalIOErrorInFunction(obsDict)
            << "the observations in " << obsPath << " end at t = "
            << measured.times.back() << " s, within the first 1/60 of the "
            << simulated << " s simulated: are the file's times in minutes"
            << " or hours? Give timeUnit min or h (or timeUnit s if they"
            << " are seconds)" << exit(FatalIOError);
    }
    scalar t0 = -GREAT, t1 = GREAT;
    if (obsDict.found("timeWindow"))
    {
        const Pair<scalar> w(obsDict.get<Pair<scalar>>("timeWindow"));
        t0 = secondsPer[timeUnit]*w.first();
        t1 = secondsPer[timeUnit]*w.second();
        if (!(t0 < t1))
        {
            FatalIOErrorInFunction(obsDict) << "timeWindow: need start < end"
                << exit(FatalIOError);
        }
    }
    wordList sensors;
    if (obsDict.found("sensors"))
    {
        sensors = obsDict.get<wordList>("sensors");
    }
    else
    {
        for (const auto& n : measured.names) sensors.append(word(n));
    }
    std::vector<label> measCol(sensors.size(), -1);
    std::vector<double> sigma(sensors.size(), 1), weight(sensors.size(), 1);
    const scalar sigmaAll = obsDict.lookupOrDefault<scalar>("sigma", 1);
    const dictionary* sigmasDict = obsDict.findDict("sigmas");
    const dictionary* weightsDict = obsDict.findDict("weights");
    // Their keywords are the observed sensors (a misspelt name would
    // silently keep the default)
    for (const dictionary* sw : {sigmasDict, weightsDict})
    {
        if (sw)
        {
            checkedRead::checkKeywords(*sw, sensors, "observed sensors");
        }
    }
    forAll(sensors, si)
    {
        for (size_t c = 0; c < measured.names.size(); ++c)
        {
            if (measured.names[c] == sensors[si]) measCol[si] = c;
        }
        if (measCol[si] < 0)
        {
            FatalIOErrorInFunction(obsDict)
                << "sensor " << sensors[si] << " is not a column of "
                << obsPath << exit(FatalIOError);
        }
        sigma[si] = sigmaAll;
        if (sigmasDict) sigma[si] =
            sigmasDict->lookupOrDefault<scalar>(sensors[si], sigmaAll);
        if (weightsDict) weight[si] =
            weightsDict->lookupOrDefault<scalar>(sensors[si], 1);
        if (!(sigma[si] > 0) || !(weight[si] > 0))
        {
            FatalIOErrorInFunction(obsDict)
                << "sensor " << sensors[si] << ": sigma and weight must be"
                << " > 0" << exit(FatalIOError);
        }
    }
    std::vector<double> obsTimes;
    std::vector<size_t> obsRows;
    for (size_t k = 0; k < measured.times.size(); ++k)
    {
        if (measured.times[k] >= t0 && measured.times[k] <= t1)
        {
            obsTimes.push_back(measured.times[k]);
            obsRows.push_back(k);
        }
    }
    if (obsTimes.size()*sensors.size() <= size_t(nPar))
    {
        FatalIOErrorInFunction(obsDict)
            << "fewer observations (" << obsTimes.size()*sensors.size()
            << ") inside the time window than parameters + 1"
            << exit(FatalIOError);
    }
    const scalar endTime = runTime.endTime().value();
    if (obsTimes.back() > endTime + 1e-9*max(1, mag(endTime))
     || obsTimes.front() < runTime.startTime().value())
    {
        FatalIOErrorInFunction(obsDict)
            << "observation times [" << obsTimes.front() << ", "
            << obsTimes.back() << "] outside the simulated window ["
            << runTime.startTime().value() << ", " << endTime << "]"
            << exit(FatalIOError);
    }

    // ---- Forward model
    const dictionary& fwdDict = fitDict.subDict("forwardModel");
    checkedRead::checkKeywords
    (
        fwdDict,
        wordList
        ({
            "solver", "nProcs", "mpirun", "maxConcurrentRuns",
            "functionObject", "workDir"
        })
    );
    const string solver
    (
        fwdDict.lookupOrDefault<fileName>("solver", fileName("ahcFoam")).expand()
    );
    const label nProcs = fwdDict.getOrDefault<label>("nProcs", 1);
    if (nProcs < 1)
    {
        FatalIOErrorInFunction(fwdDict)
            << "forwardModel: nProcs " << nProcs << ": valid is >= 1"
            << " (1: serial forward runs, N > 1: each run on N MPI ranks)"
            << exit(FatalIOError);
    }
    // Parallel forward runs: each scratch copy is decomposed (decomposePar,
    // system/decomposeParDict of the case) and run as
    // '<mpirun> -np N <solver> -parallel -case <copy>'
    const string mpirun
    (
        fwdDict.getOrDefault<string>
        (
            "mpirun",
            ::geteuid() == 0
          ? "mpirun --allow-run-as-root --oversubscribe"
          : "mpirun --oversubscribe"
        )
    );
    if (nProcs > 1)
    {
        const std::string launcher(mpirun.substr(0, mpirun.find(' ')));
        for (const std::string& exe : {launcher, std::string("decomposePar")})
        {
            const std::string cmd
            (
                "command -v '" + exe + "' > /dev/null 2>&1"
            );
            if (exe.empty() || std::system(cmd.c_str()) != 0)
            {
                FatalIOErrorInFunction(fwdDict)
                    << "forwardModel: nProcs " << nProcs << " needs "
                    << exe.c_str() << ", not found on the PATH (keyword"
                    << " mpirun: '" << mpirun.c_str() << "')"
                    << exit(FatalIOError);
            }
        }
        label nDomains = 0;
        const fileName decFile(casePath/"system"/"decomposeParDict");
        if (isFile(decFile))
        {
            IFstream is(decFile);
            const dictionary dd(is);
            nDomains = dd.getOrDefault<label>("numberOfSubdomains", 0);
        }
        if (nDomains != nProcs)
        {
            FatalIOErrorInFunction(fwdDict)
                << "forwardModel: nProcs " << nProcs << " but " << decFile
                << " has numberOfSubdomains " << nDomains << " (0: no such"
                << " file or keyword): valid are 1 (serial) or"
                << " numberOfSubdomains" << exit(FatalIOError);
        }
    }
    const label maxConcurrent =
        max(1, fwdDict.lookupOrDefault<label>("maxConcurrentRuns", 1));
    const word foName
    (
        fwdDict.lookupOrDefault<word>("functionObject", "thermocouples")
    );
    {
        const dictionary* fos = runTime.controlDict().findDict("functions");
        if (!fos || !fos->findDict(foName))
        {
            FatalIOErrorInFunction(fwdDict)
                << "functionObject " << foName << ": no such entry in the"
                << " functions of " << runTime.controlDict().name()
                << " (the thermocouples function object whose"
                << " sensors.csv holds the simulated histories)"
                << exit(FatalIOError);
        }
    }

    // ---- Sensor offsets: the thermocouples sensors file, rewritten in
    //      each copy with the sensors moved (the user's file untouched)
    SensorFile sensorFile;
    bool anyOffset = false;
    for (const ParameterSpec& s : specs) anyOffset = anyOffset || s.component >= 0;
    const dictionary* firstDict = fitDict.findDict("firstEstimate");
    if (anyOffset || firstDict)
    {
        const dictionary& foDict =
            runTime.controlDict().subDict("functions").subDict(foName);
        const std::string raw(foDict.get<string>("file"));
        std::string rel;
        auto starts = [&](const std::string& pre)
        {
            return raw.compare(0, pre.size(), pre) == 0;
        };
        if (starts("<system>/")) rel = "system/" + raw.substr(9);
        else if (starts("<constant>/")) rel = "constant/" + raw.substr(11);
        else if (starts("<case>/")) rel = raw.substr(7);
        else if (raw.find_first_of("<$~") == std::string::npos && !starts("/"))
        {
            rel = raw;
        }
        fileName relName(rel);
        relName.clean();
        const wordList parts(relName.components());
        if
        (
            rel.empty() || relName.find("..") != string::npos
         || parts.size() < 2
         || (
                parts[0] != "system" && parts[0] != "constant"
             && parts[0] != startName
            )
        )
        {
            FatalIOErrorInFunction(foDict)
                << "sensor offsets and first estimate: the sensor file '" << raw.c_str() << "' of the "
                << foName << " function object must lie in the case's"
                << " system, constant or " << startName << " directory"
                << " (given as <system>/..., <constant>/... or relative to"
                << " the case), the directories copied for each run"
                << exit(FatalIOError);
        }
        sensorFile.rel = relName;

        // The sensors as the thermocouples function object reads them
        pointField positions;
        wordList names;
        labelList sensorLines;
        labelList errorLines;
        List<string> errors;
        functionObjects::thermocouples::readSensorFile
        (
            casePath/relName, positions, names, sensorLines, errorLines,
            errors
        );
        if (!errors.empty())
        {
            FatalIOErrorInFunction(foDict)
                << "sensor file " << casePath/relName
                << (errorLines[0] > 0 ? " line " : "")
                << (errorLines[0] > 0 ? Foam::name(errorLines[0]) : word())
                << ": " << errors[0].c_str() << exit(FatalIOError);
        }

        // Its lines as they are (comments, header), the sensor lines
        // marked with their sensor, to be rewritten in the copies
        std::ifstream in(casePath/relName);
        std::string line;
        while (std::getline(in, line))
        {
            sensorFile.lines.push_back(line);
            sensorFile.names.push_back(std::string());
            sensorFile.xyz.push_back(std::array<double, 3>{{0, 0, 0}});
        }
        forAll(names, i)
        {
            const size_t li = sensorLines[i] - 1;
            sensorFile.names[li] = names[i];
            sensorFile.xyz[li] =
                {{positions[i].x(), positions[i].y(), positions[i].z()}};
        }
        for (const ParameterSpec& s : specs)
        {
            if (s.component < 0) continue;
            if
            (
                std::find
                (
                    sensorFile.names.begin(), sensorFile.names.end(),
                    std::string(s.sensor)
                ) == sensorFile.names.end()
            )
            {
                FatalIOErrorInFunction(parsDict)
                    << "parameter " << s.name << ": sensor " << s.sensor
                    << " is not in the sensors file " << casePath/relName
                    << exit(FatalIOError);
            }
        }
    }
    // ---- First estimate: Laloy-Massard diffusivity (laloyMassard.H)
    if (firstDict)
    {
        const dictionary& fd = *firstDict;
        checkedRead::checkKeywords
        (
            fd,
            wordList
            ({
                "surfaceTemperature", "initialTemperature", "sensors",
                "surfaceZ", "timeOrigin"
            })
        );
        const scalar T0 = fd.get<scalar>("surfaceTemperature");
        const scalar Ti = fd.get<scalar>("initialTemperature");
        const scalar zSurf = fd.lookupOrDefault<scalar>("surfaceZ", 0);
        const scalar tOrigin = fd.lookupOrDefault<scalar>
        (
            "timeOrigin", runTime.startTime().value()
        );
        const wordList feSensors
        (
            fd.found("sensors") ? fd.get<wordList>("sensors") : sensors
        );
        if (T0 == Ti)
        {
            FatalIOErrorInFunction(fd) << "firstEstimate: surfaceTemperature"
                << " equals initialTemperature" << exit(FatalIOError);
        }
        std::vector<double> tAll, zs, aPer;
        std::vector<std::vector<double>> Ts;
        for (size_t k : obsRows) tAll.push_back(measured.times[k] - tOrigin);
        Info<< nl << "first estimate (Laloy-Massard, Mansour 5.2.2.1: 1-D"
            << " semi-infinite dry soil, surface at " << T0 << " C from t = "
            << tOrigin << " s, initially " << Ti << " C; erfc history fit):"
            << endl;
        for (const word& sn : feSensors)
        {
            label col = -1;
            for (size_t c = 0; c < measured.names.size(); ++c)
            {
                if (measured.names[c] == sn) col = c;
            }
            label li = -1;
            for (size_t i = 0; i < sensorFile.names.size(); ++i)
            {
                if (sensorFile.names[i] == std::string(sn)) li = i;
            }
            if (col < 0 || li < 0)
            {
                FatalIOErrorInFunction(fd) << "firstEstimate: sensor " << sn
                    << " is not " << (col < 0 ? "a column of " : "in ")
                    << (col < 0 ? obsPath : casePath/sensorFile.rel)
                    << exit(FatalIOError);
            }
            const double z = std::abs(sensorFile.xyz[li][2] - zSurf);
            std::vector<double> T;
            for (size_t k : obsRows) T.push_back(measured.values[col][k]);
            int nUsed = 0;
            const double a = hearthFit::laloyMassard::exactEstimate
            (
                z, tAll, T, T0, Ti, nUsed
            );
            std::ostringstream os;
            os << std::setprecision(8);
            os << "    " << std::string(sn) << ": depth " << z << " m, ";
            if (a > 0)
            {
                os << "diffusivity a = " << a << " m2/s (" << nUsed
                    << " readings)";
                aPer.push_back(a);
                zs.push_back(z);
                Ts.push_back(T);
            }
            else
            {
                os << "no usable reading (depth 0 or temperatures outside"
                    << " (Ti, T0))";
            }
            Info<< os.str().c_str() << endl;
        }
        if (aPer.empty())
        {
            FatalIOErrorInFunction(fd) << "firstEstimate: no sensor gives"
                << " an estimate" << exit(FatalIOError);
        }
        const double aMed = hearthFit::laloyMassard::median(aPer);
        const double aPrinted = hearthFit::laloyMassard::printedRecipe
        (
            zs, tAll, Ts, T0, Ti
        );
        {
            std::ostringstream os;
            os << std::setprecision(8)
                << "first estimate: diffusivity a = " << aMed
                << " m2/s (median of " << aPer.size() << " sensors)";
            if (aPrinted > 0)
            {
                os << "; printed recipe (5.6, geometric-mean approximation)"
                    << " a = " << aPrinted << " m2/s";
            }
            Info<< os.str().c_str() << endl;
        }
        if (!args.found("resume"))
        {
            for (label j = 0; j < nPar; ++j)
            {
                if (!(initialFactor[j] > 0)) continue;
                hearthFit::FitParameter& p = fitPars[j];
                double v = initialFactor[j]*aMed;
                if (v < p.lower || v > p.upper)
                {
                    const double c = std::min(std::max(v, p.lower), p.upper);
                    Info<< "    parameter " << specs[j].name << ": "
                        << initialFactor[j] << " x a = " << v
                        << " outside [" << p.lower << ", " << p.upper
                        << "], clipped to " << c << endl;
                    v = c;
                }
                if (p.typical == 0) p.typical = std::abs(p.initial)/100;
                Info<< "    initial " << specs[j].name << " = "
                    << initialFactor[j] << " x a = " << v
                    << " (instead of " << p.initial << ")" << endl;
                p.initial = v;
            }
        }
        Info<< endl;
    }
    if (args.found("firstEstimateOnly"))
    {
        if (!firstDict)
        {
            FatalIOErrorInFunction(fitDict) << "-firstEstimateOnly: no"
                << " firstEstimate sub-dictionary" << exit(FatalIOError);
        }
        Info<< "End" << nl << endl;
        Pstream::exit(0);
        return 0;
    }

    fileName workDir
    (
        fwdDict.lookupOrDefault<fileName>
        (
            "workDir", fileName("postProcessing/hearthFit")
        ).expand()
    );
    if (!workDir.isAbsolute()) workDir = casePath/workDir;
    workDir = casePaths::canonical(workDir);
    const bool keepScratch = args.found("keepScratch");

    // The work folder receives a copy of system, constant and the start
    // time per concurrent run: inside one of them it would copy itself
    // (until the path is too long)
    {
        const fileName holder
        (
            casePaths::copiedDirHolding(casePath, startName, workDir)
        );
        if (!holder.empty())
        {
            FatalIOErrorInFunction(fwdDict)
                << "Keyword 'workDir' = " << workDir << " lies inside "
                << holder << ", which is copied into workDir for each"
                << " forward run: the copy would contain itself. Expected"
                << " a directory outside the case's system, constant and "
                << startName << " (default postProcessing/hearthFit)"
                << exit(FatalIOError);
        }
        if (workDir == casePaths::canonical(casePath))
        {
            FatalIOErrorInFunction(fwdDict)
                << "Keyword 'workDir' = " << workDir << " is the case"
                << " itself: its outputs would mix with the case's files."
                << " Expected a directory of its own (default"
                << " postProcessing/hearthFit)" << exit(FatalIOError);
        }
        if
        (
            writeCasePath.size()
         && (
                casePaths::inside(writeCasePath, workDir)
             || casePaths::inside(workDir, writeCasePath)
            )
        )
        {
            FatalIOErrorInFunction(fwdDict)
                << "-writeCase " << writeCasePath << " and keyword"
                << " 'workDir' = " << workDir << " overlap: the scratch"
                << " copies would be mixed with the written case. Give"
                << " separate directories" << exit(FatalIOError);
        }
    }

    // ---- Method
    hearthFit::FitOptions opts;
    const dictionary methodDict
    (
        fitDict.found("method") ? fitDict.subDict("method") : dictionary()
    );
    {
        const word type
        (
            methodDict.lookupOrDefault<word>("type", "levenbergMarquardt")
        );
        if (type == "gaussNewton") opts.method = hearthFit::Method::gaussNewton;
        else if (type != "levenbergMarquardt")
        {
            FatalIOErrorInFunction(methodDict) << "method type " << type
                << ": valid are levenbergMarquardt, gaussNewton"
                << exit(FatalIOError);
        }
        const word diff(methodDict.lookupOrDefault<word>("difference", "forward"));
        if (diff == "central") opts.difference = hearthFit::Difference::central;
        else if (diff != "forward")
        {
            FatalIOErrorInFunction(methodDict) << "difference " << diff
                << ": valid are forward, central" << exit(FatalIOError);
        }
        const scalar noise =
            methodDict.lookupOrDefault<scalar>("solverNoise", 1e-6);
        opts.hRel = methodDict.lookupOrDefault<scalar>
        (
            "relativeStep",
            hearthFit::levenbergMarquardt::recommendedRelativeStep
            (
                noise, opts.difference
            )
        );
        opts.tolStep = methodDict.lookupOrDefault<scalar>("tolStep", 1e-6);
        opts.tolGradient =
            methodDict.lookupOrDefault<scalar>("tolGradient", 1e-6);
        opts.tolCost = methodDict.lookupOrDefault<scalar>("tolCost", 1e-10);
        opts.maxIterations =
            methodDict.lookupOrDefault<label>("maxIterations", 30);
        opts.initialDamping =
            methodDict.lookupOrDefault<scalar>("initialDamping", 1e-3);
        opts.confidence =
            methodDict.lookupOrDefault<scalar>("confidence", 0.95);
    }

    if (args.found("maxIterations"))
    {
        opts.maxIterations = args.get<label>("maxIterations");
    }

    // ---- Resume: the state after the last accepted iteration
    // (parameters, damping, iteration, runs, failed runs, elapsed time),
    // written by every accepted iteration to <workDir>/state.dict.  The
    // optimiser restarts from those parameters with that damping (the
    // damping of the last progress line is the one the next iteration
    // uses); only More's scaling (the running maximum of the Jacobian
    // column norms) restarts from the first Jacobian after resuming.
    const fileName statePath(workDir/"state.dict");
    const bool resume = args.found("resume");
    int iterOffset = 0;
    long runs = 0;
    long failedRuns = 0;
    double elapsedOffset = 0;
    std::vector<double> initial0;   // the initial values of the dict
    for (const auto& fp : fitPars) initial0.push_back(fp.initial);
    if (resume)
    {
        if (!isFile(statePath))
        {
            FatalErrorInFunction << "-resume: no fit state " << statePath
                << " (it is written after each accepted iteration)"
                << exit(FatalError);
        }
        IFstream is(statePath);
        const dictionary st(is);
        const dictionary& sp = st.subDict("parameters");
        for (label j = 0; j < nPar; ++j)
        {
            if (!sp.found(specs[j].name))
            {
                FatalIOErrorInFunction(st) << "-resume: parameter "
                    << specs[j].name << " not in " << statePath
                    << exit(FatalIOError);
            }
            // Keep the step floor of the original start
            if (fitPars[j].typical == 0)
            {
                fitPars[j].typical = std::abs(fitPars[j].initial)/100;
            }
            fitPars[j].initial = sp.get<scalar>(specs[j].name);
        }
        const scalar damping = st.get<scalar>("damping");
        if (damping > 0) opts.initialDamping = damping;
        iterOffset = st.get<label>("iteration");
        runs = st.get<label>("runs");
        failedRuns = st.get<label>("failedRuns");
        elapsedOffset = st.get<scalar>("elapsed");
        if (opts.maxIterations - iterOffset < 1)
        {
            FatalErrorInFunction << "-resume: " << iterOffset
                << " iterations done, maxIterations " << opts.maxIterations
                << ": nothing left (raise -maxIterations)"
                << exit(FatalError);
        }
        opts.maxIterations -= iterOffset;
        Info<< "Resuming from " << statePath << ": iteration "
            << iterOffset << ", " << runs << " runs so far, damping "
            << opts.initialDamping << endl;
    }

    std::unique_ptr<hearthFit::levenbergMarquardt> lm;
    try
    {
        lm.reset(new hearthFit::levenbergMarquardt(fitPars, opts));
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(fitDict) << e.what() << exit(FatalIOError);
    }

    // ---- Scratch copies
    if
    (
        workDir.find('\'') != string::npos
     || casePath.find('\'') != string::npos
    )
    {
        FatalErrorInFunction << "Quotes in paths are not supported"
            << exit(FatalError);
    }
    mkDir(workDir);
    if (!resume) rm(statePath);     // a state of an earlier fit
    std::vector<fileName> slots(maxConcurrent);
    for (label k = 0; k < maxConcurrent; ++k)
    {
        slots[k] = workDir/word("scratch" + Foam::name(k));
        if (isDir(slots[k])) rmDir(slots[k]);
        if
        (
            !mkDir(slots[k])
         || !cp(casePath/"system", slots[k])
         || !cp(casePath/"constant", slots[k])
         || !cp(casePath/startName, slots[k])
        )
        {
            FatalErrorInFunction << "Cannot copy the case " << casePath
                << " to " << slots[k] << exit(FatalError);
        }
    }

    // Parallel forward runs: the parameters live in dictionaries, which
    // the ranks read from the copy itself (system, constant) and the
    // sensors file too, so a copy is decomposed once (mesh and start-time
    // fields); only a parameter in a file of the start-time directory
    // needs a decomposition before every run
    bool decomposeEachRun = false;
    for (const ParameterSpec& s : specs)
    {
        if (s.component < 0 && s.file.components()[0] == startName)
        {
            decomposeEachRun = true;
        }
    }
    auto decompose = [&](const fileName& dir) -> bool
    {
        const std::string cmd
        (
            "decomposePar -force -case " + quoted(dir)
          + " > " + quoted(dir/"log.decomposePar") + " 2>&1"
        );
        return std::system(cmd.c_str()) == 0;
    };
    if (nProcs > 1)
    {
        for (const fileName& dir : slots)
        {
            if (!decompose(dir))
            {
                FatalErrorInFunction << "decomposePar failed on the scratch"
                    << " copy " << dir << ": see " << dir/"log.decomposePar"
                    << exit(FatalError);
            }
        }
        Info<< "Scratch copies decomposed for " << nProcs << " ranks"
            << (decomposeEachRun ? " (again before each run: a parameter"
                " lives in the start-time directory)" : "") << endl;
    }

    // Write the parameter values into the dictionaries of a case copy
    auto writeParameters = [&](const fileName& dir, const hearthFit::Vector& p)
    {
        HashTable<dictionary> dicts(caseDicts);
        std::vector<std::array<double, 3>> xyz(sensorFile.xyz);
        for (label j = 0; j < nPar; ++j)
        {
            if (specs[j].component >= 0)
            {
                for (size_t i = 0; i < xyz.size(); ++i)
                {
                    if (sensorFile.names[i] == std::string(specs[j].sensor))
                    {
                        xyz[i][specs[j].component] += p(j);
                    }
                }
                continue;
            }
            word key;
            dictionary* d = parentDict(dicts[specs[j].file], specs[j].entry, key);
            d->set(key, specs[j].scale*p(j));
        }
        forAllConstIters(dicts, iter)
        {
            writeDictFile(dir/iter.key(), iter.val());
        }
        if (!sensorFile.rel.empty())
        {
            std::ofstream out(dir/sensorFile.rel);
            out << std::setprecision(17);
            for (size_t i = 0; i < sensorFile.lines.size(); ++i)
            {
                if (sensorFile.names[i].empty())
                {
                    out << sensorFile.lines[i] << '\n';
                }
                else
                {
                    out << sensorFile.names[i] << ", " << xyz[i][0] << ", "
                        << xyz[i][1] << ", " << xyz[i][2] << '\n';
                }
            }
        }
    };

    const auto clock0 = std::chrono::steady_clock::now();
    const std::string csvRel
    (
        "postProcessing/" + foName + "/" + startName + "/sensors.csv"
    );

    // Residuals of a finished run in slot dir; false: failed
    auto collect = [&]
    (
        const fileName& dir,
        const int status,
        hearthFit::Vector& r,
        std::string& why
    ) -> bool
    {
        if (status == -1000)
        {
            why = "decomposePar failed (see " + dir/"log.decomposePar" + ")";
            return false;
        }
        if (status != 0)
        {
            why =
                (status > 0 && WIFEXITED(status))
              ? "exit status " + std::to_string(WEXITSTATUS(status))
              : "system() status " + std::to_string(status);
            return false;
        }
        {
            std::ifstream lg(dir/"log.run");
            std::string line;
            bool ended = false;
            while (std::getline(lg, line)) if (line == "End") ended = true;
            if (!ended) { why = "no 'End' in the log"; return false; }
        }
        Histories sim;
        if (!readCsv(dir/csvRel, sim, why)) return false;
        r.resize(obsTimes.size()*sensors.size());
        label n = 0;
        forAll(sensors, si)
        {
            label col = -1;
            for (size_t c = 0; c < sim.names.size(); ++c)
            {
                if (sim.names[c] == sensors[si]) col = c;
            }
            if (col < 0)
            {
                why = "sensor " + sensors[si] + " not in " + dir/csvRel;
                return false;
            }
            for (size_t k = 0; k < obsTimes.size(); ++k)
            {
                double v;
                if (!interpolate(sim.times, sim.values[col], obsTimes[k], v))
                {
                    why = "simulated times do not cover the observations";
                    return false;
                }
                const double m = measured.values[measCol[si]][obsRows[k]];
                r(n++) = std::sqrt(weight[si])*(v - m)/sigma[si];
            }
        }
        return true;
    };

    // Wall time in forward runs (this session): batches of 2 or more runs
    // (Jacobian columns) and single runs (trial steps), for the report
    double batchWall[2] = {0, 0};
    long batchRuns[2] = {0, 0};
    lm->setBatchResidual
    (
        [&](std::vector<hearthFit::Evaluation>& batch)
        {
            const auto tBatch = std::chrono::steady_clock::now();
            for (size_t b0 = 0; b0 < batch.size(); b0 += maxConcurrent)
            {
                const size_t b1 =
                    std::min(batch.size(), b0 + size_t(maxConcurrent));
                std::vector<int> status(b1 - b0, -1);
                const int decomposeFailed = -1000;
                // Prepare the copies (serial: OpenFOAM IO)
                for (size_t b = b0; b < b1; ++b)
                {
                    const fileName& dir = slots[b - b0];
                    fileNameList dirs(1, dir);
                    for (label proci = 0; nProcs > 1 && proci < nProcs; ++proci)
                    {
                        dirs.append(dir/word("processor" + Foam::name(proci)));
                    }
                    for (const fileName& d : dirs)
                    {
                        for (const instant& t : Time::findTimes(d))
                        {
                            if (t.name() != startName
                             && t.value() > runTime.startTime().value())
                            {
                                rmDir(d/t.name());
                            }
                        }
                    }
                    if (isDir(dir/"postProcessing"))
                    {
                        rmDir(dir/"postProcessing");
                    }
                    rm(dir/"log.run");
                    writeParameters(dir, batch[b].parameters);
                    if (nProcs > 1 && decomposeEachRun && !decompose(dir))
                    {
                        status[b - b0] = decomposeFailed;
                    }
                }
                // Run concurrently
                std::vector<std::thread> threads;
                for (size_t b = b0; b < b1; ++b)
                {
                    const std::string dir(slots[b - b0]);
                    int* st = &status[b - b0];
                    if (*st == decomposeFailed) continue;
                    const std::string cmd
                    (
                        "cd " + quoted(dir) + " && "
                      + (
                            nProcs > 1
                          ? mpirun + " -np " + std::to_string(nProcs) + " "
                          + solver + " -parallel"
                          : std::string(solver)
                        )
                      + " -case " + quoted(dir) + " > log.run 2>&1"
                    );
                    threads.emplace_back
                    (
                        [cmd, st]() { *st = std::system(cmd.c_str()); }
                    );
                }
                for (auto& th : threads) th.join();
                // Collect
                for (size_t b = b0; b < b1; ++b)
                {
                    ++runs;
                    std::string why;
                    batch[b].ok =
                        collect(slots[b - b0], status[b - b0], batch[b].residuals, why);
                    if (!batch[b].ok)
                    {
                        ++failedRuns;
                        Info<< "    forward run " << runs << " failed ("
                            << why.c_str() << "), parameters";
                        for (label j = 0; j < nPar; ++j)
                        {
                            Info<< ' ' << batch[b].parameters(j);
                        }
                        Info<< "; log kept as "
                            << workDir/word("failed." + Foam::name(runs)
                             + ".log") << endl;
                        cp(slots[b - b0]/"log.run",
                           workDir/word("failed." + Foam::name(runs) + ".log"));
                    }
                }
            }
            const int kind = batch.size() > 1 ? 0 : 1;
            batchWall[kind] += std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - tBatch
            ).count();
            batchRuns[kind] += batch.size();
        }
    );

    auto elapsed = [&]()
    {
        return elapsedOffset + std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - clock0
        ).count();
    };

    std::ofstream progressCsv
    (
        workDir/"progress.csv",
        resume ? std::ios::app : std::ios::trunc
    );
    progressCsv << std::setprecision(8);
    if (!resume)
    {
        progressCsv << "iteration,cost";
        for (const auto& s : specs) progressCsv << ',' << s.name;
        progressCsv << ",damping,elapsed_s,runs,event" << std::endl;
    }

    // Fit state after an accepted iteration (see -resume)
    auto writeState = [&](const hearthFit::FitProgress& pr, int iteration)
    {
        const fileName tmp(statePath + ".tmp");
        {
            std::ofstream os(tmp);
            os  << std::setprecision(17)
                << "FoamFile\n{\n    version 2.0;\n    format ascii;\n"
                << "    class dictionary;\n    object state;\n}\n\n"
                << "// hearthFit state after an accepted iteration:"
                << " hearthFit -resume restarts here\n"
                << "iteration   " << iteration << ";\n"
                << "cost        " << pr.cost << ";\n"
                << "damping     " << pr.damping << ";\n"
                << "runs        " << runs << ";\n"
                << "failedRuns  " << failedRuns << ";\n"
                << "elapsed     " << elapsed() << ";\n"
                << "parameters\n{\n";
            for (label j = 0; j < nPar; ++j)
            {
                os << "    " << specs[j].name << ' ' << pr.parameters(j)
                   << ";\n";
            }
            os  << "}\n";
        }
        Foam::mv(tmp, statePath);
    };

    Info<< "hearthFit: " << nPar << " parameters, " << sensors.size()
        << " sensors x " << obsTimes.size() << " times = "
        << sensors.size()*obsTimes.size() << " residuals" << nl
        << "    solver " << solver;
    if (nProcs > 1) Info<< " on " << nProcs << " ranks (" << mpirun << ")";
    Info<< ", up to " << maxConcurrent
        << " concurrent runs, relative step " << opts.hRel << ", "
        << (opts.difference == hearthFit::Difference::forward
            ? "forward" : "central")
        << " differences" << nl
        << "    work directory " << workDir << nl << nl
        << "iter  cost          ";
    {
        std::ostringstream os;
        for (const auto& s : specs) os << std::setw(14) << s.name << ' ';
        Info<< os.str().c_str();
    }
    Info<< "damping     elapsed_s  runs  event" << endl;

    lm->setProgress
    (
        [&](const hearthFit::FitProgress& pr)
        {
            const double el = elapsed();
            const int iteration = pr.iteration + iterOffset;
            const bool resumedLine = resume && pr.iteration == 0;
            std::ostringstream os;
            os  << std::setw(4) << iteration << "  "
                << std::setw(12) << std::setprecision(6) << pr.cost << "  ";
            for (label j = 0; j < nPar; ++j)
            {
                os << std::setw(14) << std::setprecision(8)
                   << pr.parameters(j) << ' ';
            }
            os  << std::setw(10) << std::setprecision(3) << pr.damping << "  "
                << std::setw(9) << std::fixed << std::setprecision(1) << el
                << "  " << std::setw(4) << runs << "  "
                << (resumedLine ? std::string("resumed") : pr.event);
            if (pr.rejected)
            {
                os << " (" << pr.rejected << " trial step"
                   << (pr.rejected > 1 ? "s" : "") << " rejected)";
            }
            Info<< os.str().c_str() << endl;

            if (resumedLine) return;    // its line is already written
            progressCsv << iteration << ',' << pr.cost;
            for (label j = 0; j < nPar; ++j) progressCsv << ',' << pr.parameters(j);
            progressCsv << ',' << pr.damping << ',' << el << ',' << runs
                << ",\"" << pr.event << '"' << std::endl;
            if (pr.event.compare(0, 8, "accepted") == 0)
            {
                writeState(pr, iteration);
            }
        }
    );

    const hearthFit::FitResult res = lm->solve();

    // ---- Report
    std::ostringstream rep;
    rep << std::setprecision(8);
    rep << "hearthFit report" << "\n"
        << "status: " << hearthFit::statusName(res.status)
        << (res.converged ? " (converged)" : " (NOT converged)") << ": "
        << res.message << "\n"
        << "iterations " << res.iterations + iterOffset
        << (resume ? " (resumed)" : "") << ", forward runs " << runs
        << " (" << failedRuns << " failed), elapsed "
        << std::fixed << std::setprecision(1) << elapsed() << " s\n"
        << "wall time in forward runs" << (resume ? " (since resumed)" : "")
        << ": " << batchWall[0] << " s for " << batchRuns[0]
        << " runs in batches (Jacobians, up to " << maxConcurrent
        << " at once), " << batchWall[1] << " s for " << batchRuns[1]
        << " single runs (trial steps)\n";
    rep.unsetf(std::ios::floatfield);
    rep << std::setprecision(8)
        << "cost (weighted residual sum of squares) " << res.cost
        << ", residuals " << res.residuals.size() << ", dof " << res.dof
        << ", s^2 " << res.sigma2 << "\n";
    if (res.dof > 0 && res.sigma2 == 0)
    {
        rep << "s^2 = 0: the model reproduces every observation exactly"
            << " (noise-free data made by the model itself?): the standard"
            << " errors are 0 and the intervals have zero width (they"
            << " measure the noise, and there is none); the correlation"
            << " matrix is that of (J^T J)^-1\n";
    }
    rep << "\n";
    const int pct = int(std::round(100*opts.confidence));
    rep << std::setprecision(10) << std::left << std::setw(12) << "parameter" << std::right
        << std::setw(18) << "estimate" << std::setw(18) << "std error"
        << std::setw(18) << ("lower " + std::to_string(pct) + "%")
        << std::setw(18) << ("upper " + std::to_string(pct) + "%")
        << std::setw(18) << "initial" << "\n";
    for (label j = 0; j < nPar; ++j)
    {
        auto val = [](const hearthFit::Vector& v, label j)
        {
            return v.size() > j ? v(j) : std::nan("");
        };
        rep << std::left << std::setw(12) << specs[j].name.c_str()
            << std::right
            << std::setw(18) << res.parameters(j)
            << std::setw(18) << val(res.standardErrors, j)
            << std::setw(18) << val(res.lowerConfidence, j)
            << std::setw(18) << val(res.upperConfidence, j)
            << std::setw(18) << initial0[j]
            << ((res.atBound.size() > size_t(j) && res.atBound[j])
                ? "  at bound" : "")
            << "\n";
    }
    rep << "\ncorrelation matrix\n";
    for (label i = 0; i < nPar; ++i)
    {
        rep << std::left << std::setw(12) << specs[i].name.c_str() << std::right;
        for (label j = 0; j < nPar; ++j)
        {
            rep << std::setw(12) << std::setprecision(4)
                << (res.correlation.rows() > i ? res.correlation(i, j)
                                                : std::nan(""));
        }
        rep << "\n";
    }
    rep << std::setprecision(6)
        << "\nsingular values of the scaled Jacobian J diag(|p|):";
    for (label j = 0; j < res.singularValues.size(); ++j)
    {
        rep << ' ' << res.singularValues(j);
    }
    rep << "\n\nRMS residual per sensor [C]\n";

    // Fitted histories from the residuals at the best parameters
    std::vector<std::vector<double>> fitted
    (
        sensors.size(), std::vector<double>(obsTimes.size(), std::nan(""))
    );
    const bool haveRes =
        res.residuals.size() == label(obsTimes.size()*sensors.size());
    forAll(sensors, si)
    {
        double ss = 0;
        for (size_t k = 0; k < obsTimes.size(); ++k)
        {
            const double m = measured.values[measCol[si]][obsRows[k]];
            if (haveRes)
            {
                const double r =
                    res.residuals(si*obsTimes.size() + k)
                   *sigma[si]/std::sqrt(weight[si]);
                fitted[si][k] = m + r;
                ss += r*r;
            }
        }
        rep << "    " << std::left << std::setw(12) << sensors[si].c_str()
            << std::right << std::setw(14)
            << (haveRes ? std::sqrt(ss/obsTimes.size()) : std::nan(""))
            << "\n";
    }

    Info<< nl << rep.str().c_str() << endl;
    {
        std::ofstream os(workDir/"report.txt");
        os << rep.str();
    }
    {
        std::ofstream os(workDir/"fitted.csv");
        os << std::setprecision(10) << "time_s";
        for (const word& s : sensors) os << ',' << s << "_measured," << s << "_fitted";
        os << "\n";
        for (size_t k = 0; k < obsTimes.size(); ++k)
        {
            os << obsTimes[k];
            forAll(sensors, si)
            {
                os << ',' << measured.values[measCol[si]][obsRows[k]]
                   << ',' << fitted[si][k];
            }
            os << "\n";
        }
    }
    {
        std::ofstream os(workDir/"parameters.csv");
        os << std::setprecision(12)
           << "name,estimate,std_error,lower,upper\n";
        for (label j = 0; j < nPar; ++j)
        {
            os << specs[j].name << ',' << res.parameters(j) << ','
               << (res.standardErrors.size() > j ? res.standardErrors(j) : std::nan("")) << ','
               << (res.lowerConfidence.size() > j ? res.lowerConfidence(j) : std::nan("")) << ','
               << (res.upperConfidence.size() > j ? res.upperConfidence(j) : std::nan(""))
               << "\n";
        }
    }
    Info<< "Written " << workDir/"report.txt" << ", "
        << workDir/"fitted.csv" << ", " << workDir/"parameters.csv" << ", "
        << workDir/"progress.csv" << endl;

    // Scaled sensitivities p_j dT/dp_j [C] from the final Jacobian
    // (dr/dp with r = sqrt(w)(T - m)/sigma: dT/dp = J sigma/sqrt(w))
    const bool haveJac =
        res.jacobian.rows() == label(obsTimes.size()*sensors.size())
     && res.jacobian.cols() == nPar
     && res.parameters.size() == nPar;
    if (haveJac)
    {
        std::ofstream os(workDir/"sensitivities.csv");
        os << std::setprecision(10) << "time_s";
        for (const word& s : sensors)
        {
            for (const auto& sp : specs) os << ',' << s << '_' << sp.name;
        }
        os << "\n";
        for (size_t k = 0; k < obsTimes.size(); ++k)
        {
            os << obsTimes[k];
            forAll(sensors, si)
            {
                for (label j = 0; j < nPar; ++j)
                {
                    os << ','
                       << res.jacobian(si*obsTimes.size() + k, j)
                         *sigma[si]/std::sqrt(weight[si])
                         *res.parameters(j);
                }
            }
            os << "\n";
        }
        Info<< "Written " << workDir/"sensitivities.csv" << endl;
    }
    else
    {
        WarningInFunction
            << "No final Jacobian: sensitivities.csv/png not written" << endl;
    }

    // Plots with gnuplot (fitted.png, sensitivities.png); a missing
    // gnuplot or a failing plot is a warning only
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        WarningInFunction
            << "gnuplot not found: fitted.png and sensitivities.png not"
            << " written" << endl;
    }
    else
    {
        std::ofstream gp(workDir/"plots.gp");
        gp  << "set datafile separator ','\n"
            << "set key outside right\n"
            << "set grid\n"
            << "set xlabel 'time [h]'\n"
            << "set terminal pngcairo noenhanced size 1000,650\n"
            << "set output 'fitted.png'\n"
            << "set title 'hearthFit: measured (points) and fitted (lines)'\n"
            << "set ylabel 'T [C]'\n"
            << "plot ";
        forAll(sensors, si)
        {
            gp  << (si ? ", \\\n     " : "")
                << "'fitted.csv' every ::1 using ($1/3600):" << 2 + 2*si
                << " with points pt 7 ps 0.5 lc " << si + 1
                << " title '" << sensors[si] << " measured', "
                << "'' every ::1 using ($1/3600):" << 3 + 2*si
                << " with lines lw 2 lc " << si + 1
                << " title '" << sensors[si] << " fitted'";
        }
        gp  << "\nunset output\n";
        if (haveJac)
        {
            gp  << "set output 'sensitivities.png'\n"
                << "set title 'scaled sensitivities p_j dT/dp_j'\n"
                << "set ylabel 'p dT/dp [C]'\n"
                << "plot ";
            label col = 2;
            const char* dts[] = {"1", "2", "3", "4", "5"};
            bool first = true;
            forAll(sensors, si)
            {
                for (label j = 0; j < nPar; ++j, ++col)
                {
                    // Curves identically zero (the offset of another
                    // sensor) are left out of the plot (not of the CSV)
                    bool zero = true;
                    for (size_t k = 0; zero && k < obsTimes.size(); ++k)
                    {
                        zero = res.jacobian(si*obsTimes.size() + k, j) == 0;
                    }
                    if (zero) continue;
                    gp  << (!first ? ", \\\n     " : "")
                        << (!first ? "''" : "'sensitivities.csv'")
                        << " every ::1 using ($1/3600):" << col
                        << " with lines lw 2 lc " << j + 1
                        << " dt " << dts[si % 5]
                        << " title '" << sensors[si] << " "
                        << specs[j].name << "'";
                    first = false;
                }
            }
            gp  << "\nunset output\n";
        }
        gp.close();
        const std::string cmd
        (
            "cd " + quoted(workDir) + " && gnuplot plots.gp > plots.log 2>&1"
        );
        if (std::system(cmd.c_str()) != 0)
        {
            WarningInFunction
                << "gnuplot failed (see " << workDir/"plots.log" << ")"
                << endl;
        }
        else
        {
            Info<< "Written " << workDir/"fitted.png";
            if (haveJac) Info<< ", " << workDir/"sensitivities.png";
            Info<< endl;
        }
    }

    if (args.found("writeCase"))
    {
        const fileName& out = writeCasePath;
        if
        (
            !mkDir(out)
         || !cp(casePath/"system", out)
         || !cp(casePath/"constant", out)
         || !cp(casePath/startName, out)
        )
        {
            FatalErrorInFunction << "Cannot write the case copy " << out
                << exit(FatalError);
        }
        writeParameters(out, res.parameters);
        Info<< "Best parameters written into the case copy " << out << endl;
    }

    if (!keepScratch)
    {
        for (const fileName& s : slots) rmDir(s);
    }

    Info<< "End" << nl << endl;

    // The exit status must say whether the fit converged: a plain return
    // from main is lost (argList's destructor calls Pstream::exit(0))
    Pstream::exit(res.converged ? 0 : 1);
    return res.converged ? 0 : 1;
}


// ************************************************************************* //
