/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitForwardRuns.H"
#include "checkedRead.H"
#include "thermocouples.H"
#include "casePaths.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <chrono>
#include <cstdlib>
#include <unistd.h>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitForwardRuns::fitForwardRuns
(
    const dictionary& fwdDict,
    const Time& runTime
)
:
    slots_(),
    decomposeEachRun_(false),
    csvRel_(),
    nProcs(1),
    timeLimit(0),
    maxConcurrent(1),
    runs(0),
    failedRuns(0),
    timedOutRuns(0),
    reusedRuns(0),
    batchWall{0, 0},
    batchRuns{0, 0}
{
    checkedRead::checkKeywords
    (
        fwdDict,
        wordList
        ({
            "solver", "nProcs", "mpirun", "launcher", "timeLimit",
            "maxConcurrentRuns", "functionObject", "workDir"
        })
    );
    solver =
        fwdDict.lookupOrDefault<fileName>("solver", fileName("ahcFoam")).expand();
    // 1: serial forward runs, N > 1: each run on N MPI ranks
    nProcs = checkedRead::getLabelOrDefault(fwdDict, "nProcs", 1, 1);
    // Parallel forward runs: each scratch copy is decomposed (decomposePar,
    // system/decomposeParDict of the case) and run as
    // '<mpirun> -np N <solver> -parallel -case <copy>', or through the
    // launcher template
    launcher = scratchCase::launcher
    (
        fwdDict, nProcs, runTime.path(), wordList({"decomposePar"})
    );
    timeLimit = scratchCase::readTimeLimit(fwdDict);
    maxConcurrent =
        checkedRead::getLabelOrDefault(fwdDict, "maxConcurrentRuns", 1, 1);
    foName = fwdDict.lookupOrDefault<word>("functionObject", "thermocouples");
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
        // Its sensors, read as the function object reads them (the
        // observed sensors are checked against them before any run)
        const dictionary& foDict = fos->subDict(foName);
        if (foDict.getOrDefault<word>("type", word()) != "thermocouples")
        {
            FatalIOErrorInFunction(foDict)
                << "functionObject " << foName << " of "
                << runTime.controlDict().name() << " is of type "
                << foDict.getOrDefault<word>("type", "(none)")
                << ": hearthFit reads the sensors.csv of a function object"
                << " of type thermocouples" << exit(FatalIOError);
        }
        sensorFile =
            functionObjects::thermocouples::sensorFilePath
            (
                foDict, runTime.path()
            );
        pointField positions;
        labelList lines, errorLines;
        List<string> errors;
        functionObjects::thermocouples::readSensorFile
        (
            sensorFile, positions, caseSensors, lines, errorLines, errors
        );
        if (!errors.empty())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, sensorFile, errorLines[0]
            )   << "the sensor file of function object " << foName << ": "
                << errors[0].c_str() << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitForwardRuns::readWorkDir
(
    const dictionary& fwdDict,
    const fileName& casePath,
    const word& startName,
    const fileName& writeCasePath
)
{
    workDir =
        fwdDict.lookupOrDefault<fileName>
        (
            "workDir", fileName("postProcessing/hearthFit")
        ).expand();
    if (!workDir.isAbsolute()) workDir = casePath/workDir;
    workDir = casePaths::canonical(workDir);

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
}


void Foam::fitForwardRuns::makeCopies
(
    const Time& runTime,
    const fitParameters& params
)
{
    const fileName casePath(runTime.path());
    const word startName(runTime.timeName());
    csvRel_ = "postProcessing/" + foName + "/" + startName + "/sensors.csv";

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

    slots_.setSize(maxConcurrent);
    forAll(slots_, k)
    {
        slots_.set
        (
            k,
            new scratchCase
            (
                casePath, startName, runTime.startTime().value(),
                workDir/word("scratch" + Foam::name(k)), nProcs, launcher
            )
        );
        slots_[k].timeLimit(timeLimit);
    }

    // Parallel forward runs: the parameters live in dictionaries, which
    // the ranks read from the copy itself (system, constant) and the
    // sensors file too, so a copy is decomposed once (mesh and start-time
    // fields); only a parameter in a file of the start-time directory
    // needs a decomposition before every run
    decomposeEachRun_ = params.inDirectory(startName);
    if (nProcs > 1)
    {
        for (scratchCase& copy : slots_)
        {
            if (!copy.decompose())
            {
                FatalErrorInFunction << "decomposePar failed on the scratch"
                    << " copy " << copy.path() << ": see "
                    << copy.path()/"log.decomposePar" << exit(FatalError);
            }
        }
        Info<< "Scratch copies decomposed for " << nProcs << " ranks"
            << (decomposeEachRun_ ? " (again before each run: a parameter"
                " lives in the start-time directory)" : "") << endl;
    }
}


bool Foam::fitForwardRuns::collect
(
    const fileName& dir,
    const int status,
    hearthFit::Vector& r,
    std::string& why,
    const fitObservations& obs
) const
{
    if (status == -1000)
    {
        why = "decomposePar failed (see " + dir/"log.decomposePar" + ")";
        return false;
    }
    why = scratchCase::failure(status, dir/"log.run");
    if (why.size())
    {
        // A launcher writing the solver's log itself: its own message too
        const fileName launcherLog(dir/"log.run.launcher");
        if (isFile(launcherLog))
        {
            why += "\n    the launcher's output:\n"
              + scratchCase::errorMessage(launcherLog);
        }
        return false;
    }
    return obs.residuals(dir/csvRel_, r, why);
}


void Foam::fitForwardRuns::evaluate
(
    std::vector<hearthFit::Evaluation>& batch,
    const fitParameters& params,
    const fitObservations& obs
)
{
    const auto tBatch = std::chrono::steady_clock::now();

    // The runs to make: parameters not run successfully before, each once
    auto key = [](const hearthFit::Vector& p)
    {
        return std::vector<double>(p.data(), p.data() + p.size());
    };
    std::vector<size_t> todo;
    {
        std::map<std::vector<double>, size_t> inBatch;
        for (size_t b = 0; b < batch.size(); ++b)
        {
            const std::vector<double> k(key(batch[b].parameters));
            if (!made_.count(k) && inBatch.emplace(k, b).second)
            {
                todo.push_back(b);
            }
        }
    }

    for (size_t t0 = 0; t0 < todo.size(); t0 += maxConcurrent)
    {
        const size_t t1 =
            std::min(todo.size(), t0 + size_t(maxConcurrent));
        std::vector<int> status(t1 - t0, -1);
        const int decomposeFailed = -1000;
        // Prepare the copies (serial: OpenFOAM IO)
        for (size_t t = t0; t < t1; ++t)
        {
            scratchCase& copy = slots_[t - t0];
            copy.removeResults();
            rm(copy.path()/"log.run");
            params.write(copy.path(), batch[todo[t]].parameters);
            if (nProcs > 1 && decomposeEachRun_ && !copy.decompose())
            {
                status[t - t0] = decomposeFailed;
            }
        }
        // Run concurrently, each in its own process group
        for (size_t t = t0; t < t1; ++t)
        {
            scratchCase& copy = slots_[t - t0];
            if (status[t - t0] == decomposeFailed) continue;
            copy.startSolver(solver, copy.path()/"log.run");
        }
        for (size_t t = t0; t < t1; ++t)
        {
            if (status[t - t0] == decomposeFailed) continue;
            status[t - t0] = slots_[t - t0].wait();
        }
        // SIGINT/SIGTERM: the runs were killed, not failed
        if (scratchCase::interrupted())
        {
            throw fitInterrupted();
        }
        // Collect
        for (size_t t = t0; t < t1; ++t)
        {
            hearthFit::Evaluation& ev = batch[todo[t]];
            ++runs;
            std::string why;
            const fileName& dir = slots_[t - t0].path();
            ev.ok = collect(dir, status[t - t0], ev.residuals, why, obs);
            if (ev.ok)
            {
                made_[key(ev.parameters)] = ev.residuals;
            }
            else
            {
                ++failedRuns;
                if (status[t - t0] == scratchCase::timedOut) ++timedOutRuns;
                // The reason, then the run's own error message
                const std::string::size_type eol = why.find('\n');
                Info<< "    forward run " << runs << " failed ("
                    << why.substr(0, eol).c_str() << "), parameters";
                for (label j = 0; j < ev.parameters.size(); ++j)
                {
                    Info<< ' ' << ev.parameters(j);
                }
                Info<< "; log kept as "
                    << workDir/word("failed." + Foam::name(runs)
                     + ".log") << endl;
                if (eol != std::string::npos)
                {
                    Info<< "    its log says:" << nl
                        << why.substr(eol + 1).c_str();
                }
                cp(dir/"log.run",
                   workDir/word("failed." + Foam::name(runs) + ".log"));
            }
        }
    }

    // The others: from the runs made (before, or in this batch)
    {
        std::vector<bool> ran(batch.size(), false);
        for (const size_t b : todo) ran[b] = true;
        for (size_t b = 0; b < batch.size(); ++b)
        {
            if (ran[b]) continue;
            const auto it = made_.find(key(batch[b].parameters));
            ++reusedRuns;
            batch[b].ok = it != made_.end();
            if (batch[b].ok)
            {
                batch[b].residuals = it->second;
            }
        }
    }

    const int kind = batch.size() > 1 ? 0 : 1;
    batchWall[kind] += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - tBatch
    ).count();
    batchRuns[kind] += todo.size();
}


bool Foam::fitForwardRuns::runIn
(
    scratchCase& copy,
    hearthFit::Vector& r,
    std::string& why,
    const fitObservations& obs
) const
{
    rm(copy.path()/"log.run");
    copy.startSolver(solver, copy.path()/"log.run");
    const int status = copy.wait();
    if (scratchCase::interrupted())
    {
        throw fitInterrupted();
    }
    return collect(copy.path(), status, r, why, obs);
}


void Foam::fitForwardRuns::clean() const
{
    for (const scratchCase& copy : slots_)
    {
        copy.clean();
    }
}


// ************************************************************************* //
