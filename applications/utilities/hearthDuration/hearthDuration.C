/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
-------------------------------------------------------------------------------
Application
    hearthDuration

Description
    The shortest fire that heats given points of the soil to a threshold:
    the minimal duration d of a fire at a given temperature, followed by
    its cooling, such that the maximum temperature reached (TMax) at every
    point reaches the threshold (e.g. 290 C, the reddening of the clay,
    observed down to some depth: Muhieddine 2009 §5.4).

    The heat keeps moving down after extinction, so TMax at depth is known
    only after a whole run (fire + cooling): each candidate duration is a
    forward run of the solver on a scratch copy of the case (forwardModel;
    the case itself is only read), and

        f(d) = min over the points of (TMax(d) - threshold)

    increases with d. The search evaluates the bracket (its upper end
    first; doubled up to maxDuration while f < 0; its lower end halved
    while f >= 0), then shrinks it by regula falsi with the Illinois
    modification, each new duration kept at least tolerance/2 inside the
    bracket so that both ends move, until the bracket is narrower than the
    tolerance. Durations are rounded to whole seconds.

    Prints one line per run (duration, TMax at the points, f, wall time),
    the bracket after each run, and the answer: the root of the secant of f
    over the final bracket, and the bracket [d_low, d_high] with
    f(d_low) < 0 <= f(d_high). Writes <workDir>/runs.csv (one line per run)
    and <workDir>/result.csv.

    Exit status: 0 with an answer (also when the threshold is reached by
    the shortest duration allowed: an upper bound); 1 when even
    maxDuration does not reach the threshold, when a forward run fails
    (its log is named) or after maxRuns runs.

    system/hearthDurationDict: times in h, temperatures in C, lengths in m
    (see the annotated example in this folder):

        solver          ahcFoam;     // default
        nProcs          1;           // > 1: decomposePar once, mpirun
        fire
        {
            patch           fire;
            temperature     700;
            // rampTime 0.1667; rampStartTemperature 20;   // optional ramp
        }
        cooling         { type exponential; Tair 20; tau 1; duration 18; }
        points          { pit4cm (0.0001 0 -0.04); }
        // or: line { start (0.0001 0 0); end (0.0001 0 -1); } depths (0.04);
        threshold       290;
        durationBracket (0.25 6);
        // maxDuration  24;          // default 4 x the upper bracket
        tolerance       0.0167;      // 1 min, >= 10 s
        // maxRuns      40;
        // workDir      "postProcessing/hearthDuration";  // in the case
        // mpirun       "mpirun --oversubscribe";   // + --allow-run-as-root
        // launcher     "srun -n {nProcs} {solver} -parallel -case {case}";
        //              // default '{solver} -case {case}' (nProcs 1) or
        //              // '<mpirun> -np {nProcs} {solver} -parallel -case
        //              // {case}' (see src/general/scratchCase)
                                                    //   when run by root

    Every entry is checked before the first run: bad input stops with a
    FatalIOError naming the file, the keyword and the valid range or
    choices; an unknown keyword, naming the nearest valid one; a workDir
    that is the case or lies inside its system, constant or start time
    (copied into workDir/scratchCase) is refused.

    Fit mode (keyword alterations instead of points or line): observed
    alteration depths z_i +/- sigma_i along lines at several places give
    the duration d (and with fitTemperature the fire temperature Tf) by
    weighted least squares through the same forward runs

        minimise  sum_i ((zModel_i(d, Tf) - z_i)/sigma_i)^2

    (zModel_i: alterationDepth of TMax along line i; the optimiser
    hearthFit::levenbergMarquardt with the sigmas known), with first-order
    intervals; Tf is reported not identifiable when the scaled
    sensitivities' singular values differ by more than 1e-3 (fitDuration.H).
    tests/hearthDurationFit measures their coverage.

    Uncertainty (sub-dictionary uncertainty, search mode): the soil
    parameters' standard deviations and correlation
    (Foam::uncertainParameters) propagated to d* by the implicit-function
    theorem at the root, d(d*)/dp_j = -(df/dp_j)/(df/dd), var(d*) = g^T C g
    (first order; central differences, 2n + 2 runs: propagateUncertainty.H);
    prints "The fire burned at least d h (95 %: a-b h)".
    tests/hearthDurationUncertainty checks it against full searches.
    The parameters, sds and correlation are written in the sub-dictionary
    or read from hearthFit's posterior (fitPosterior "<posterior.dict>";
    tests/hearthDurationFromFit).

Usage
    hearthDuration [-duration h] [-case dir]

    -duration h: one forward run of that duration; prints TMax at the
    points (no search), or in fit mode the modelled depths.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "meshSearch.H"
#include "checkedRead.H"
#include "casePaths.H"
#include "fireHistory.H"
#include "forwardModel.H"
#include "uncertainParameters.H"
#include "alterationDepth.H"
#include "levenbergMarquardt.H"
#include "Tuple2.H"
#include "OFstream.H"
#include "IOmanip.H"
#include "exitWithStatus.H"
#include <chrono>
#include <iomanip>
#include <sstream>
#include <unistd.h>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{

//- Absolute zero in C
static const scalar zeroCelsius = 273.15;

//- A number as text with the given decimals
std::string fixed(const scalar x, const int decimals)
{
    std::ostringstream os;
    os << std::fixed << std::setprecision(decimals) << x;
    return os.str();
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

//- A duration [s] as "1.5000 h (1 h 30 min)"
std::string hoursText(const scalar seconds)
{
    const label minutes = round(seconds/60);
    std::ostringstream os;
    os  << fixed(seconds/3600, 4) << " h (" << minutes/60 << " h "
        << std::setw(2) << std::setfill('0') << minutes % 60 << " min)";
    return os.str();
}

//- Stop with an exit status (exitWithStatus: v1912 loses the status
//  returned by main)
void stop(const int status)
{
    Info<< endl;
    exitWithStatus(status);
}

//- One forward run
struct runRecord
{
    label index;
    scalar duration;        // s
    scalarField TMax;       // K
    scalar f;               // K
    scalar wallTime;        // s
    fileName log;
};

//- Write all runs so far to the CSV file
void writeRuns
(
    const fileName& file,
    const wordList& pointNames,
    const UList<runRecord>& runs
)
{
    OFstream os(file);
    os  << "run,duration_h";
    for (const word& name : pointNames)
    {
        os  << ",TMax_" << name << "_C";
    }
    os  << ",f_K,wallTime_s,log" << nl;

    for (const runRecord& r : runs)
    {
        os  << r.index << ',' << fixed(r.duration/3600, 6).c_str();
        for (const scalar T : r.TMax)
        {
            os  << ',' << fixed(T - zeroCelsius, 6).c_str();
        }
        os  << ',' << fixed(r.f, 6).c_str() << ','
            << fixed(r.wallTime, 2).c_str() << ',' << r.log << nl;
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Minimal duration of a fire (then its cooling) for the maximum"
        " temperature at given points to reach a threshold: repeated runs"
        " of the solver on a scratch copy of the case"
        " (system/hearthDurationDict)"
    );
    argList::noParallel();
    argList::addOption
    (
        "duration",
        "h",
        "One forward run of this fire duration: print TMax at the points"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readHearthDurationDict.H"

    // Forward runs ------------------------------------------------------------

    forwardModel model
    (
        runTime, firePatch, fire, points, solver, nProcs, mpirun, workDir
    );
    scratchCase::catchInterrupts();

    DynamicList<runRecord> runs;
    const auto wallStart = std::chrono::steady_clock::now();

    const fileName runsFile(workDir/"runs.csv");

    // f(d) of a fire of duration d [s], rounded to a second; one line
    auto f = [&](const scalar duration) -> scalar
    {
        const scalar d = round(duration);
        const auto start = std::chrono::steady_clock::now();

        fileName log;
        boolList stillRising;
        const scalarField TMax
        (
            model.run(d, runs.size() + 1, log, stillRising)
        );

        runRecord r;
        r.index = runs.size() + 1;
        r.duration = d;
        r.TMax = TMax;
        r.f = min(TMax) - thresholdK;
        r.wallTime =
            std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - start
            ).count();
        r.log = log;
        runs.append(r);

        Info<< "run " << setw(2) << r.index << ": "
            << hoursText(d).c_str() << "  TMax [C]:";
        forAll(pointNames, i)
        {
            Info<< ' ' << pointNames[i] << ' '
                << fixed(TMax[i] - zeroCelsius, 2).c_str()
                << (stillRising[i] ? " (still rising!)" : "");
        }
        Info<< "  f = " << (r.f >= 0 ? "+" : "")
            << fixed(r.f, 3).c_str() << " K  "
            << fixed(r.wallTime, 1).c_str() << " s" << endl;

        if (stillRising.found(true))
        {
            Info<< "        Warning: T = TMax at the end at a point marked"
                << " 'still rising': the heat wave has not passed it;"
                << " follow the cooling longer (cooling.duration)" << endl;
        }

        writeRuns(runsFile, pointNames, runs);

        return r.f;
    };

    if (fitMode)
    {
        #include "fitDuration.H"
    }

    if (singleDuration > 0)
    {
        f(singleDuration);
        Info<< "\nruns: " << runsFile << nl << "\nEnd\n" << endl;
        return 0;
    }

    #include "searchDuration.H"

    return 0;
}


// ************************************************************************* //
