/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitRefinement.H"
#include "fitParameters.H"
#include "fitObservations.H"
#include "fitForwardRuns.H"
#include "scratchCase.H"
#include "checkedRead.H"
#include "estimateShift.H"
#include "IFstream.H"
#include "ITstream.H"
#include "OSspecific.H"
#include "exitWithStatus.H"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sys/wait.h>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::scalar Foam::fitRefinement::warnAbove = 0.5;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitRefinement::fitRefinement
(
    const dictionary& dict,
    const Time& runTime
)
:
    dict_(dict),
    meshCommand_(),
    timeStepFactor_(1),
    timeLimit_(0)
{
    checkedRead::checkKeywords
    (
        dict,
        wordList({"meshCommand", "timeStepFactor", "timeLimit"}),
        "refinementCheck"
    );
    // A command in quotes, or a word: none or a command without arguments
    meshCommand_ = "refineMesh -overwrite";
    if (dict.found("meshCommand"))
    {
        ITstream& is = dict.lookup("meshCommand");
        const token t(is);
        if (t.isWord()) meshCommand_ = t.wordToken();
        else if (t.isString()) meshCommand_ = t.stringToken();
        else
        {
            FatalIOErrorInFunction(dict)
                << "refinementCheck: meshCommand " << t << ": expected a"
                << " command in quotes (default \"refineMesh -overwrite\")"
                << " or none" << exit(FatalIOError);
        }
    }
    if (meshCommand_ == "none")
    {
        meshCommand_.clear();
    }
    else
    {
        const std::string::size_type b =
            meshCommand_.find_first_not_of(" \t");
        const std::string exe
        (
            b == std::string::npos
          ? std::string()
          : meshCommand_.substr(b, meshCommand_.find_first_of(" \t;&|", b) - b)
        );
        if (exe.empty() || !scratchCase::onPath(exe))
        {
            FatalIOErrorInFunction(dict)
                << "refinementCheck: meshCommand \"" << meshCommand_.c_str()
                << "\": its program '" << exe.c_str() << "' is not on the"
                << " PATH. Expected a command making the finer mesh in the"
                << " copy (default \"refineMesh -overwrite\"), or none"
                << exit(FatalIOError);
        }
    }
    timeStepFactor_ =
        checkedRead::getOrDefault
        (
            dict, "timeStepFactor", dimless, 1, validRange{0, 1, true, false}
        ).value();
    timeLimit_ = scratchCase::readTimeLimit(dict);

    if (meshCommand_.empty() && timeStepFactor_ == 1)
    {
        FatalIOErrorInFunction(dict)
            << "refinementCheck: meshCommand none and timeStepFactor 1: the"
            << " finer model would be the fit's own. Give a meshCommand"
            << " (default \"refineMesh -overwrite\") or a timeStepFactor in"
            << " (0, 1)" << exit(FatalIOError);
    }
    const dictionary& cd = runTime.controlDict();
    if
    (
        timeStepFactor_ < 1
     && cd.lookupOrDefault<bool>("adjustTimeStep", true)
     && !cd.found("maxDeltaTemperature")
    )
    {
        FatalIOErrorInFunction(dict)
            << "refinementCheck: timeStepFactor " << timeStepFactor_
            << " with adjustTimeStep on needs maxDeltaTemperature in "
            << cd.name() << " (the adaptive step's target, whose default"
            << " is the solver's) to scale it" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

std::unique_ptr<Foam::fitRefinement> Foam::fitRefinement::New
(
    const dictionary& fitDict,
    const Time& runTime
)
{
    if (!fitDict.found("refinementCheck"))
    {
        return nullptr;
    }
    const dictionary* dict = fitDict.findDict("refinementCheck");
    if (!dict)
    {
        FatalIOErrorInFunction(fitDict)
            << "refinementCheck must be a sub-dictionary { meshCommand"
            << " \"refineMesh -overwrite\"; timeStepFactor f; }"
            << exit(FatalIOError);
    }
    return std::unique_ptr<fitRefinement>(new fitRefinement(*dict, runTime));
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fitRefinement::scaleTimeStep(const fileName& dir) const
{
    const fileName file(dir/"system"/"controlDict");
    dictionary cd;
    {
        IFstream is(file);
        cd.read(is);
    }
    cd.remove("FoamFile");
    cd.set("deltaT", timeStepFactor_*cd.get<scalar>("deltaT"));
    if (cd.lookupOrDefault<bool>("adjustTimeStep", true))
    {
        for (const word key : {"maxDeltaT", "maxDeltaTemperature"})
        {
            if (cd.found(key))
            {
                cd.set(key, timeStepFactor_*cd.get<scalar>(key));
            }
        }
    }
    scratchCase::writeDictionary
    (
        file, cd,
        "time step x " + Foam::name(timeStepFactor_)
      + " by hearthFit's refinementCheck"
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitRefinement::check
(
    const hearthFit::FitResult& res,
    const fitForwardRuns& fwd,
    const fitParameters& params,
    const fitObservations& obs,
    const Time& runTime,
    const bool keepScratch
) const
{
    const label n = params.size(), nData = obs.size();
    const std::string model
    (
        (meshCommand_.size() ? "mesh by \"" + meshCommand_ + "\"" : "mesh kept")
      + ", time step x " + std::string(Foam::name(timeStepFactor_))
    );
    Info<< nl << "Refinement check: the forward model at the estimate on a"
        << " finer model (" << model.c_str() << ")" << endl;
    if
    (
        res.jacobian.cols() != n
     || res.jacobian.rows() != res.residuals.size()
     || res.residuals.size() < nData
    )
    {
        WarningInFunction << "refinement check not made: the fit has no"
            << " final Jacobian" << endl;
        return;
    }

    const fileName dir(fwd.workDir/"refined");
    scratchCase copy
    (
        runTime.path(), runTime.timeName(), runTime.startTime().value(), dir,
        fwd.nProcs, fwd.launcher
    );
    copy.timeLimit(timeLimit_);
    params.write(dir, res.parameters);

    hearthFit::Vector rFine;
    std::string why;
    fileName failedLog;
    try
    {
        if (meshCommand_.size())
        {
            const fileName log(dir/"log.meshCommand");
            const int status = copy.execute(meshCommand_, log);
            if (scratchCase::interrupted()) throw fitInterrupted();
            if (status != 0)
            {
                why = "meshCommand failed (exit status "
                    + std::to_string
                      (
                          WIFEXITED(status) ? WEXITSTATUS(status) : status
                      )
                    + "):\n"
                    + scratchCase::errorMessage(log);
                failedLog = log;
            }
        }
        if (why.empty() && timeStepFactor_ < 1)
        {
            scaleTimeStep(dir);
        }
        if (why.empty() && fwd.nProcs > 1 && !copy.decompose())
        {
            why = "decomposePar failed";
            failedLog = dir/"log.decomposePar";
        }
        if (why.empty() && !fwd.runIn(copy, rFine, why, obs))
        {
            why = "the finer run failed (" + why + ")";
            failedLog = dir/"log.run";
        }
    }
    catch (const fitInterrupted&)
    {
        const int sig = scratchCase::interrupted();
        Info<< "Refinement check interrupted (signal " << sig << ")" << endl;
        if (!keepScratch)
        {
            copy.clean();
            fwd.clean();
        }
        exitWithStatus(128 + sig);
    }
    if (why.size() && isFile(failedLog))
    {
        cp(failedLog, fwd.workDir/"refinementCheck.failed.log");
        why += "\n    log kept as "
          + fwd.workDir/"refinementCheck.failed.log";
    }
    if (!keepScratch) copy.clean();
    if (why.size())
    {
        WarningInFunction << "refinement check not made: " << why.c_str()
            << endl;
        return;
    }

    // The residuals' change at fixed parameters: the data rows only
    hearthFit::Vector dr(hearthFit::Vector::Zero(res.residuals.size()));
    dr.head(nData) = rFine.head(nData) - res.residuals.head(nData);
    const hearthFit::Vector dp(hearthFit::estimateShift(res.jacobian, dr));

    Info<< "    cost S on the finer model " << rFine.head(nData).squaredNorm()
        << " (fit's " << res.residuals.head(nData).squaredNorm() << ", data"
        << " rows); estimate shift dp = -(J^T J)^-1 J^T (r_fine - r):" << nl
        << "    parameter  estimate  shift  std_error  shift/se  refined"
        << endl;
    std::ofstream csv(fwd.workDir/"refinementCheck.csv");
    csv << std::setprecision(17)
        << "parameter,estimate,shift,std_error,shift_se,refined_estimate\n";
    for (label j = 0; j < n; ++j)
    {
        const std::string& name = params.pars[j].name;
        const double p = res.parameters(j), se = res.standardErrors(j);
        const double inSe = dp(j)/se;
        Info<< "    " << name.c_str() << "  " << p << "  " << dp(j) << "  "
            << se << "  " << inSe << "  " << p + dp(j) << endl;
        csv << name << ',' << p << ',' << dp(j) << ',' << se << ','
            << inSe << ',' << p + dp(j) << '\n';
        if (!std::isfinite(inSe))
        {
            WarningInFunction
                << "refinement check: the shift of parameter "
                << name.c_str() << " in standard errors is not defined"
                << " (standard error " << se << ")" << endl;
        }
        else if (std::abs(inSe) > warnAbove)
        {
            WarningInFunction
                << "refinement check: parameter " << name.c_str()
                << " moves by " << inSe << " standard errors (" << dp(j)
                << ") on the finer forward model: the discretisation bias"
                << " is not small against its interval. Refine the forward"
                << " mesh (or the time step) of the fit" << endl;
        }
    }
    Info<< "Written " << fwd.workDir/"refinementCheck.csv" << endl;
}


// ************************************************************************* //
