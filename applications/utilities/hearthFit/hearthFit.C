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
    progress.csv, parameters.csv, posterior.dict (the estimates of
    case-file parameters with sds and correlation, for hearthDuration's
    uncertainty { fitPosterior ...; }), sensitivities.csv: the scaled
    sensitivities p_j dT/dp_j [C] per sensor from the final Jacobian, and with gnuplot
    fitted.png and sensitivities.png, script plots.gp; state.dict: the
    fit state after each accepted iteration, from which -resume restarts
    an interrupted fit, appending to progress.csv); scratch copies are
    removed at the end (-keepScratch keeps them).  -writeCase DIR writes a copy of the case with the best
    parameters.

    Optimiser: hearthFit::levenbergMarquardt (src/numerics/leastSquares).
    Parts: fitParameters, fitObservations, fitForwardRuns (scratch copies:
    src/general/scratchCase), fitMethod, fitState (-resume), fitReport,
    firstEstimate (laloyMassard), fitRefinement.

    A given sigma (sigma or sigmas) is the noise of the measurements: the
    intervals are computed from it (not scaled by s^2) and s^2 is tested
    against its chi-square band (a warning names model error or a wrong
    sigma); without it the intervals are scaled by s^2. SIGINT or SIGTERM
    kill the running forward runs, save the state and exit with 128 +
    signal: -resume continues. A failed forward run is printed with its
    own error message.

    Priors (priors: value, sd per parameter) are residual rows
    (p - value)/sd, the covariance then the first-order posterior,
    reported against the prior; observation groups (observations/groups)
    carry their own sigma; predictions (TMax, isothermDepth) are computed
    from each run's histories and reported with intervals by linear
    propagation of the covariance (hearthFit::fitPosterior,
    fitPredictions).

    The fire itself may be unknown (sub-dictionary fire, fitFire): its
    surface temperature on knots, Tikhonov-regularised (weight by the
    discrepancy principle or the L-curve, printed: hearthFit::tikhonov),
    or the duration and plateau temperature of the fire law.

    Discretisation bias (sub-dictionary refinementCheck, fitRefinement):
    after the fit, one run at the estimate on a finer model (refined mesh
    and/or smaller time step) and the estimate's shift that the finer
    model would give, one Gauss-Newton step with the final Jacobian,
    reported in standard errors with a warning above 0.5.

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
#include "Time.H"
#include "IOdictionary.H"
#include "OSspecific.H"

#include "levenbergMarquardt.H"
#include "checkedRead.H"
#include "scratchCase.H"
#include "fitMethod.H"
#include "fitParameters.H"
#include "fitObservations.H"
#include "fitPredictions.H"
#include "fitPosterior.H"
#include "fitForwardRuns.H"
#include "fitState.H"
#include "fitReport.H"
#include "firstEstimate.H"
#include "fitFire.H"
#include "fitRefinement.H"
#include "tikhonov.H"
#include "exitWithStatus.H"

#include <csignal>
#include <memory>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

void addOptions()
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
}

} // End anonymous namespace

// * * * * * * * * * * * * * * * * * * Main  * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    addOptions();
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
    const fileName writeCasePath
    (
        fitReport::writeCasePath(args, casePath, startName)
    );

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
    // (named after its file on every rank in a parallel run)
    checkedRead::nameAfterFile(fitDict);
    checkedRead::checkKeywords
    (
        fitDict,
        wordList
        ({
            "parameters", "observations", "forwardModel", "method",
            "firstEstimate", "priors", "predictions", "fire",
            "refinementCheck"
        })
    );

    // ---- The set-up, every input checked before any run
    hearthFit::FitOptions opts(readFitMethod(fitDict));
    fitParameters params(fitDict, casePath, startName);
    fitObservations obs(fitDict.subDict("observations"), runTime, params.size());
    params.readPriors(fitDict, obs.sigmaGiven);
    const dictionary& fwdDict = fitDict.subDict("forwardModel");
    fitForwardRuns fwd(fwdDict, runTime);
    obs.checkCaseSensors
    (
        fitDict.subDict("observations"), fwd.sensorFile, fwd.caseSensors
    );
    const auto refinement(fitRefinement::New(fitDict, runTime));

    const dictionary* firstDict = fitDict.findDict("firstEstimate");
    const dictionary* predDict = fitDict.findDict("predictions");
    if (params.anyOffset() || firstDict || predDict)
    {
        params.readSensorFile
        (
            runTime.controlDict().subDict("functions").subDict(fwd.foName),
            fwd.foName, casePath, startName,
            fitParameters::parametersDict(fitDict)
        );
    }
    if (firstDict)
    {
        firstEstimate(*firstDict, runTime, obs, params, args.found("resume"));
    }
    if (args.found("firstEstimateOnly"))
    {
        if (!firstDict)
        {
            FatalIOErrorInFunction(fitDict) << "-firstEstimateOnly: no"
                << " firstEstimate sub-dictionary" << exit(FatalIOError);
        }
        Info<< "End" << nl << endl;
        exitWithStatus(0);
    }

    fwd.readWorkDir(fwdDict, casePath, startName, writeCasePath);

    // Predictions from each run's histories, priors as residual rows
    fitPredictions preds(predDict, params);
    obs.predictions = &preds;
    hearthFit::fitPosterior post(params.priors, obs.size(), preds.size());
    const auto reg(params.regularisation(obs.sigmaGiven));

    // A given sigma is the noise: intervals from it, s^2 tested against its
    // chi-square band; none: intervals scaled by s^2
    opts.knownSigma = obs.sigmaGiven;
    if (args.found("maxIterations"))
    {
        opts.maxIterations = args.get<label>("maxIterations");
    }

    fitState state(fwd.workDir, args.found("resume"));
    if (state.resume)
    {
        state.read(params, opts, fwd);
    }

    std::unique_ptr<hearthFit::levenbergMarquardt> lm;
    try
    {
        lm.reset(new hearthFit::levenbergMarquardt(params.pars, opts));
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(fitDict) << e.what() << exit(FatalIOError);
    }

    // ---- The fit
    if (!state.resume) rm(state.path);      // a state of an earlier fit
    fwd.makeCopies(runTime, params);
    fitReport report(params, obs, fwd, state);

    lm->setBatchResidual
    (
        [&](std::vector<hearthFit::Evaluation>& batch)
        {
            fwd.evaluate(batch, params, obs);
            post.absorb(batch);
            if (reg) reg->absorb(batch);
        }
    );
    lm->setProgress
    (
        [&](const hearthFit::FitProgress& pr)
        {
            report.progress(pr);
            if
            (
                pr.event.compare(0, 8, "accepted") == 0
             || (pr.iteration == 0 && !state.resume)
            )
            {
                state.write
                (
                    pr, pr.iteration + state.iterOffset, fwd,
                    report.elapsed(), params
                );
            }
        }
    );
    report.header(opts);

    // SIGINT, SIGTERM: the running forward runs are killed (their process
    // groups), the state is saved again with the runs made, the exit
    // status is 128 + signal
    scratchCase::catchInterrupts();
    hearthFit::FitResult res;
    try
    {
        // The fire's regularisation weight, chosen on the linearisation
        // at the initial (or resumed) values: the fit's first Jacobian,
        // whose n + 1 runs the fit reuses
        if (reg) params.fire->chooseWeight(*reg, *lm, obs.size());
        res = lm->solve();
    }
    catch (const fitInterrupted&)
    {
        const int sig = scratchCase::interrupted();
        state.interrupted(sig, fwd, report.elapsed(), params);
        if (!args.found("keepScratch")) fwd.clean();
        exitWithStatus(128 + sig);
    }

    // ---- Report, the case with the best parameters
    if (reg) params.fire->checkAtEstimate(*reg, res, obs.size());
    report.write(res, opts);
    report.writePosterior(res, post, preds);
    if (refinement)
    {
        refinement->check
        (
            res, fwd, params, obs, runTime, args.found("keepScratch")
        );
    }

    if (writeCasePath.size())
    {
        params.writeCase(writeCasePath, casePath, startName, res.parameters);
    }

    if (!args.found("keepScratch")) fwd.clean();

    Info<< "End" << nl << endl;

    // The exit status says whether the fit converged (exitWithStatus: v1912
    // loses the status returned by main)
    exitWithStatus(res.converged ? 0 : 1);
}


// ************************************************************************* //
