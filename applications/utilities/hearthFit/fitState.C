/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitState.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <cmath>
#include <csignal>
#include <fstream>
#include <iomanip>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitState::fitState(const fileName& workDir, const bool resume)
:
    path(workDir/"state.dict"),
    resume(resume),
    iterOffset(0),
    elapsedOffset(0),
    last(),
    lastIteration(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitState::read
(
    fitParameters& params,
    hearthFit::FitOptions& opts,
    fitForwardRuns& fwd
)
{

    if (!isFile(path))
    {
        FatalErrorInFunction << "-resume: no fit state " << path
            << " (it is written after each accepted iteration)"
            << exit(FatalError);
    }
    IFstream is(path);
    const dictionary st(is);
    const dictionary& sp = st.subDict("parameters");
    for (label j = 0; j < params.size(); ++j)
    {
        if (!sp.found(params.specs[j].name))
        {
            FatalIOErrorInFunction(st) << "-resume: parameter "
                << params.specs[j].name << " not in " << path
                << exit(FatalIOError);
        }
        // Keep the step floor of the original start
        if (params.pars[j].typical == 0)
        {
            params.pars[j].typical = std::abs(params.pars[j].initial)/100;
        }
        params.pars[j].initial = sp.get<scalar>(params.specs[j].name);
    }
    // A parameter of the state removed from hearthFitDict since (a renamed
    // one is an error above): resumed without it, said so
    for (const entry& e : sp)
    {
        bool fitted = false;
        for (label j = 0; j < params.size(); ++j)
        {
            fitted = fitted || params.specs[j].name == e.keyword();
        }
        if (!fitted)
        {
            Info<< "Note: -resume: parameter " << e.keyword() << " of "
                << path << " (saved value "
                << sp.get<scalar>(e.keyword()) << ") is no longer in the"
                << " parameters of hearthFitDict: the fit goes on without"
                << " it, the forward runs taking its value from the case's"
                << " files" << endl;
        }
    }
    const scalar damping = st.get<scalar>("damping");
    if (damping > 0) opts.initialDamping = damping;
    iterOffset = st.get<label>("iteration");
    fwd.runs = st.get<label>("runs");
    fwd.failedRuns = st.get<label>("failedRuns");
    elapsedOffset = st.get<scalar>("elapsed");
    if (opts.maxIterations - iterOffset < 1)
    {
        FatalErrorInFunction << "-resume: " << iterOffset
            << " iterations done, maxIterations " << opts.maxIterations
            << ": nothing left (raise -maxIterations)"
            << exit(FatalError);
    }
    opts.maxIterations -= iterOffset;
    Info<< "Resuming from " << path << ": iteration "
        << iterOffset << ", " << fwd.runs << " runs so far, damping "
        << opts.initialDamping << endl;
}


void Foam::fitState::write
(
    const hearthFit::FitProgress& pr,
    const int iteration,
    const fitForwardRuns& fwd,
    const double elapsed,
    const fitParameters& params
)
{
    last = pr;
    lastIteration = iteration;
    const fileName tmp(path + ".tmp");
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
            << "runs        " << fwd.runs << ";\n"
            << "failedRuns  " << fwd.failedRuns << ";\n"
            << "elapsed     " << elapsed << ";\n"
            << "parameters\n{\n";
        for (label j = 0; j < params.size(); ++j)
        {
            os << "    " << params.specs[j].name << ' ' << pr.parameters(j)
               << ";\n";
        }
        os  << "}\n";
    }
    Foam::mv(tmp, path);
}


void Foam::fitState::interrupted
(
    const int sig,
    const fitForwardRuns& fwd,
    const double elapsed,
    const fitParameters& params
)
{
    Info<< nl << "hearthFit interrupted by signal " << sig
        << (sig == SIGINT ? " (SIGINT)" : sig == SIGTERM ? " (SIGTERM)" : "")
        << ": the running forward runs were killed; ";
    if (lastIteration >= 0)
    {
        write(last, lastIteration, fwd, elapsed, params);
        Info<< "the fit state of iteration " << lastIteration
            << " (" << fwd.runs << " runs so far) is saved in "
            << path << ": hearthFit -resume continues from it"
            << endl;
    }
    else if (resume)
    {
        Info<< "the state of iteration " << iterOffset << " in "
            << path << " is unchanged: hearthFit -resume continues"
            << " from it" << endl;
    }
    else
    {
        Info<< "no evaluation was complete (no state saved)" << endl;
    }
}


// ************************************************************************* //
