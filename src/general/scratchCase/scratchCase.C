/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "scratchCase.H"
#include <cctype>
#include "Time.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "IFstream.H"
#include "checkedRead.H"

#include <chrono>
#include <csignal>
#include <cerrno>
#include <deque>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * * //

namespace
{
    //- The process groups running (0: free slot), for the signal handler
    const int maxGroups = 256;
    volatile sig_atomic_t groups[maxGroups] = {};

    //- The signal caught, or 0
    volatile sig_atomic_t caught = 0;

    void registerGroup(const pid_t pid)
    {
        for (int i = 0; i < maxGroups; ++i)
        {
            if (groups[i] == 0)
            {
                groups[i] = pid;
                return;
            }
        }
    }

    void unregisterGroup(const pid_t pid)
    {
        for (int i = 0; i < maxGroups; ++i)
        {
            if (groups[i] == pid)
            {
                groups[i] = 0;
            }
        }
    }

    extern "C" void killRunningGroups(int sig)
    {
        caught = sig;
        for (int i = 0; i < maxGroups; ++i)
        {
            if (groups[i] > 0)
            {
                ::kill(-pid_t(groups[i]), SIGTERM);
            }
        }
    }

    //- Seconds of the steady clock
    double now()
    {
        return std::chrono::duration<double>
        (
            std::chrono::steady_clock::now().time_since_epoch()
        ).count();
    }

    const char* const placeholders[] = {"solver", "nProcs", "case", "log"};

    //- The shortest time limit of a run [s]: a solver's start-up (its
    //  libraries loaded, the case's mesh and fields read) and a first
    //  step; a limit below it kills every run, a fit of failed runs
    //  (hostile testing 2026-12-05b, finding 6: 1e-9 accepted). Measured
    //  2026-12-05 at load 6-7: ahcFoam -help 0.6-0.9 s wall, ahcFoam on
    //  tests/hearthFitParallel's 748 cells to its first step (1 s) 1.0-1.2
    //  s; a launcher (mpirun, srun) adds to it. Above it the limit is the
    //  user's knowledge of a run's length
    const Foam::scalar minTimeLimit = 1;

    //- The shell's syntax error of command (empty if none): /bin/sh -n,
    //  the shell that runs it (scratchCase::start), reads it without
    //  running anything (an unbalanced quote, a dangling |, ...)
    std::string shellSyntaxError(const std::string& command)
    {
        int fds[2];
        if (::pipe(fds) != 0)
        {
            return std::string();
        }
        const pid_t pid = ::fork();
        if (pid == 0)
        {
            ::close(fds[0]);
            ::dup2(fds[1], 1);
            ::dup2(fds[1], 2);
            ::close(fds[1]);
            ::execl
            (
                "/bin/sh", "sh", "-n", "-c", command.c_str(),
                static_cast<char*>(nullptr)
            );
            ::_exit(127);
        }
        ::close(fds[1]);
        if (pid < 0)
        {
            // (no process to check it: the runs will say)
            ::close(fds[0]);
            return std::string();
        }
        std::string out;
        char buf[256];
        while (true)
        {
            const ssize_t n = ::read(fds[0], buf, sizeof(buf));
            if (n > 0)
            {
                out.append(buf, n);
            }
            else if (n == 0 || errno != EINTR)
            {
                break;
            }
        }
        ::close(fds[0]);
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
        {}
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
        {
            return std::string();
        }
        while (!out.empty() && std::isspace(out.back())) out.pop_back();
        return out.empty() ? std::string("rejected by /bin/sh -n") : out;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::scratchCase::scratchCase
(
    const fileName& casePath,
    const word& startName,
    const scalar startTime,
    const fileName& path,
    const label nProcs,
    const string& launcher
)
:
    path_(path),
    startName_(startName),
    startTime_(startTime),
    nProcs_(nProcs),
    launcher_
    (
        launcher.size() ? launcher
      : nProcs > 1
      ? string("mpirun --oversubscribe -np {nProcs} {solver} -parallel -case {case}")
      : string("{solver} -case {case}")
    ),
    timeLimit_(0),
    started_(0),
    pid_(0)
{
    if (path_.find('\'') != string::npos)
    {
        FatalErrorInFunction
            << "Quotes in paths are not supported: " << path_
            << exit(FatalError);
    }
    if (isDir(path_))
    {
        rmDir(path_);
    }
    if
    (
        !mkDir(path_)
     || !cp(casePath/"system", path_)
     || !cp(casePath/"constant", path_)
     || !cp(casePath/startName_, path_)
    )
    {
        FatalErrorInFunction
            << "Cannot copy system, constant and " << startName_ << " of "
            << casePath << " to " << path_ << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::scratchCase::~scratchCase()
{
    if (pid_ > 0)
    {
        ::kill(-pid_, SIGTERM);
        wait();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::scratchCase::removeResults() const
{
    fileNameList dirs(1, path_);
    for (label proci = 0; nProcs_ > 1 && proci < nProcs_; ++proci)
    {
        dirs.append(path_/word("processor" + Foam::name(proci)));
    }
    for (const fileName& dir : dirs)
    {
        for (const instant& t : Time::findTimes(dir))
        {
            if (t.name() != startName_ && t.value() > startTime_)
            {
                rmDir(dir/t.name());
            }
        }
    }
    if (isDir(path_/"postProcessing"))
    {
        rmDir(path_/"postProcessing");
    }
}


void Foam::scratchCase::writeDictionary
(
    const fileName& file,
    const dictionary& dict,
    const string& comment
)
{
    OFstream os(file);
    os  << "FoamFile" << nl
        << "{" << nl
        << "    version     2.0;" << nl
        << "    format      ascii;" << nl
        << "    class       dictionary;" << nl
        << "    object      " << file.name() << ";" << nl
        << "}" << nl
        << "// " << comment.c_str() << nl << nl;
    dict.write(os, false);
}


Foam::dictionary* Foam::scratchCase::parentDict
(
    dictionary& dict,
    const string& keywordPath,
    word& key
)
{
    wordList parts;
    {
        std::string::size_type b = 0;
        while (b <= keywordPath.size())
        {
            std::string::size_type e = keywordPath.find('/', b);
            if (e == std::string::npos) e = keywordPath.size();
            if (e > b) parts.append(word(keywordPath.substr(b, e - b)));
            b = e + 1;
        }
    }
    if (parts.empty())
    {
        return nullptr;
    }
    dictionary* d = &dict;
    for (label i = 0; i < parts.size() - 1; ++i)
    {
        d = d->subDictPtr(parts[i]);
        if (!d)
        {
            return nullptr;
        }
    }
    key = parts.last();
    if (!d->found(key, keyType::LITERAL) || d->isDict(key))
    {
        return nullptr;
    }
    return d;
}


void Foam::scratchCase::clean() const
{
    rmDir(path_);
}


std::string Foam::scratchCase::quoted(const std::string& s)
{
    return "'" + s + "'";
}


std::string Foam::scratchCase::solverCommand
(
    const string& solver,
    const fileName& log
) const
{
    string command(launcher_);
    command.replaceAll("{solver}", solver);
    command.replaceAll("{nProcs}", std::to_string(nProcs_));
    command.replaceAll("{case}", quoted(path_));
    command.replaceAll("{log}", quoted(log));
    return command;
}


Foam::fileName Foam::scratchCase::launcherLog(const fileName& log) const
{
    if (launcher_.find("{log}") != std::string::npos)
    {
        return log + ".launcher";
    }
    return log;
}


void Foam::scratchCase::startSolver
(
    const string& solver,
    const fileName& log
)
{
    if (launcherLog(log) != log)
    {
        rm(log);
    }
    start(solverCommand(solver, log), launcherLog(log));
}


void Foam::scratchCase::start(const std::string& command, const fileName& log)
{
    if (pid_ > 0)
    {
        FatalErrorInFunction
            << "A command is already running in " << path_
            << exit(FatalError);
    }

    // Block the caught signals until the group is registered: a signal in
    // between would miss it
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigprocmask(SIG_BLOCK, &block, &old);

    const pid_t pid = ::fork();
    if (pid == 0)
    {
        // The child: own group, default signals, output to the log
        ::setpgid(0, 0);
        ::signal(SIGINT, SIG_DFL);
        ::signal(SIGTERM, SIG_DFL);
        sigprocmask(SIG_SETMASK, &old, nullptr);
        const int fd = ::open(log.c_str(), O_WRONLY|O_CREAT|O_TRUNC, 0644);
        if (fd < 0 || ::chdir(path_.c_str()) != 0)
        {
            ::_exit(127);
        }
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    if (pid < 0)
    {
        sigprocmask(SIG_SETMASK, &old, nullptr);
        FatalErrorInFunction
            << "Cannot start a process for " << command.c_str()
            << exit(FatalError);
    }
    ::setpgid(pid, pid);
    pid_ = pid;
    started_ = now();
    registerGroup(pid_);
    sigprocmask(SIG_SETMASK, &old, nullptr);

    // A signal caught before: the run does not go on
    if (caught)
    {
        ::kill(-pid_, SIGTERM);
    }
}


int Foam::scratchCase::wait()
{
    if (pid_ <= 0)
    {
        return -1;
    }
    int status = -1;
    if (timeLimit_ > 0)
    {
        // Poll until the command ends or its time is up: then its whole
        // group is stopped (SIGTERM: srun and mpirun stop their tasks),
        // and killed below if it does not end
        while (true)
        {
            const pid_t w = ::waitpid(pid_, &status, WNOHANG);
            if (w == pid_ || (w < 0 && errno != EINTR))
            {
                break;
            }
            if (now() - started_ > timeLimit_)
            {
                ::kill(-pid_, SIGTERM);
                while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR)
                {}
                status = timedOut;
                break;
            }
            ::usleep(50000);
        }
    }
    else
    {
        while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR)
        {}
    }

    // Whatever the command left in its group (a solver whose shell was
    // killed, mpirun still stopping its ranks, which run in groups of
    // their own) gets 5 s to end, then is killed
    for (int i = 0; i < 100 && ::kill(-pid_, 0) == 0; ++i)
    {
        ::usleep(50000);
    }
    ::kill(-pid_, SIGKILL);
    unregisterGroup(pid_);
    pid_ = 0;
    return status;
}


int Foam::scratchCase::execute
(
    const std::string& command,
    const fileName& log
)
{
    start(command, log);
    return wait();
}


bool Foam::scratchCase::decompose()
{
    const fileName log(path_/"log.decomposePar");
    const int status =
        execute("decomposePar -force -case " + quoted(path_), log);
    return failure(status, log).empty();
}


std::string Foam::scratchCase::failure(const int status, const fileName& log)
{
    std::string why;
    if (status == timedOut)
    {
        why = "time limit (keyword timeLimit) exceeded: its process group"
            " killed";
    }
    else if (status != 0)
    {
        if (status > 0 && WIFEXITED(status))
        {
            why = "exit status " + std::to_string(WEXITSTATUS(status));
        }
        else if (status > 0 && WIFSIGNALED(status))
        {
            why = "killed by signal " + std::to_string(WTERMSIG(status));
        }
        else
        {
            why = "wait status " + std::to_string(status);
        }
    }
    else
    {
        IFstream is(log);
        bool ended = false;
        string line;
        while (is.good() && is.getLine(line))
        {
            if (line == "End")
            {
                ended = true;
            }
        }
        if (ended)
        {
            return std::string();
        }
        why = "no 'End' in the log";
    }

    const std::string message(errorMessage(log));
    if (message.size())
    {
        why += "\n" + message;
    }
    return why;
}


std::string Foam::scratchCase::errorMessage
(
    const fileName& log,
    const label maxLines
)
{
    IFstream is(log);
    if (!is.good())
    {
        return std::string();
    }

    std::deque<std::string> last;       // the last lines
    std::string block;                  // the first fatal-error block
    label blockLines = -1;              // -1: not in the block
    bool haveBlock = false;
    string line;
    while (is.getLine(line))
    {
        if (!haveBlock && line.find("FOAM FATAL") != string::npos)
        {
            blockLines = 0;
        }
        if (blockLines >= 0)
        {
            if
            (
                line.find("FOAM exiting") != string::npos
             || line.find("FOAM aborting") != string::npos
             || blockLines >= maxLines
            )
            {
                blockLines = -1;
                haveBlock = true;
            }
            else if (line.find_first_not_of(" \t") != string::npos)
            {
                block += "    " + line + "\n";
                ++blockLines;
            }
        }
        if (line.find_first_not_of(" \t") != string::npos)
        {
            last.push_back(line);
            if (label(last.size()) > maxLines)
            {
                last.pop_front();
            }
        }
    }
    if (block.size())
    {
        return block;
    }
    for (const std::string& l : last)
    {
        block += "    " + l + "\n";
    }
    return block;
}


bool Foam::scratchCase::onPath(const std::string& exe)
{
    const std::string path(getEnv("PATH"));
    std::string::size_type b = 0;
    while (b <= path.size())
    {
        std::string::size_type e = path.find(':', b);
        if (e == std::string::npos) e = path.size();
        if (e > b && isFile(fileName(path.substr(b, e - b))/exe, false))
        {
            return true;
        }
        b = e + 1;
    }
    return false;
}


Foam::string Foam::scratchCase::launcher
(
    const dictionary& dict,
    const label nProcs,
    const fileName& casePath,
    const wordList& tools
)
{
    const string mpirun
    (
        dict.getOrDefault<string>
        (
            "mpirun",
            ::geteuid() == 0
          ? "mpirun --allow-run-as-root --oversubscribe"
          : "mpirun --oversubscribe"
        )
    );
    const bool given = dict.found("launcher");
    const string launcher
    (
        given ? dict.get<string>("launcher")
      : nProcs > 1
      ? string(mpirun + " -np {nProcs} {solver} -parallel -case {case}")
      : string("{solver} -case {case}")
    );
    const word key(given ? "launcher" : "mpirun");
    auto bad = [&](const std::string& why)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword '" << key << "' = '" << launcher.c_str() << "': "
            << why.c_str() << ". Expected a shell command with the"
            << " placeholders {solver} and {case} (and optionally {nProcs},"
            << " {log}), e.g. \"srun -n {nProcs} {solver} -parallel -case"
            << " {case}\"" << nl << exit(FatalIOError);
    };

    // The placeholders: {solver} and {case} needed, no unknown {name}
    // (a shell's ${VAR} is not one)
    for (const char* need : {"{solver}", "{case}"})
    {
        if (launcher.find(need) == std::string::npos)
        {
            bad(std::string("no ") + need);
        }
    }
    for
    (
        std::string::size_type b = launcher.find('{');
        b != std::string::npos;
        b = launcher.find('{', b + 1)
    )
    {
        if (b > 0 && launcher[b - 1] == '$') continue;
        const std::string::size_type e = launcher.find('}', b);
        const std::string name
        (
            e == std::string::npos ? launcher.substr(b)
          : launcher.substr(b + 1, e - b - 1)
        );
        bool known = false;
        for (const char* p : placeholders) known = known || name == p;
        if (!known)
        {
            bad
            (
                "unknown placeholder {" + name + "} (valid: {solver},"
                " {nProcs}, {case}, {log})"
            );
        }
    }
    if (nProcs > 1 && launcher.find("-parallel") == std::string::npos)
    {
        bad
        (
            "nProcs " + std::to_string(nProcs) + " > 1 but no -parallel"
            " for the solver"
        );
    }
    // -parallel on 1 rank: OpenFOAM aborts each run ('attempt to run
    // parallel on 1 processor'); a command ending in & returns before the
    // solver ends (doc/hostileTesting-2026-12-05b.md, finding 6)
    {
        const std::string flag(" -parallel");
        const std::string::size_type p = launcher.find(flag);
        const std::string::size_type q = p + flag.size();
        if
        (
            nProcs <= 1 && p != std::string::npos
         && (q == launcher.size() || std::isspace(launcher[q]))
        )
        {
            bad
            (
                "-parallel with nProcs " + std::to_string(nProcs)
              + " (OpenFOAM aborts a -parallel run on 1 processor): give"
                " nProcs > 1 with a decomposeParDict, or no -parallel"
            );
        }
        const std::string::size_type last =
            launcher.find_last_not_of(" \t");
        if
        (
            last != std::string::npos && launcher[last] == '&'
         && (last == 0 || launcher[last - 1] != '&')
        )
        {
            bad
            (
                "it ends in '&': the run would go to the background and"
                " hearthFit would read its output before the solver ends"
            );
        }
    }

    // Its shell syntax, as /bin/sh reads it (an unbalanced quote: every
    // run failed, 'Unterminated quoted string'; finding 6)
    {
        const std::string err(shellSyntaxError(launcher));
        if (!err.empty())
        {
            bad("not a valid shell command: " + err);
        }
    }

    // Its command (not the solver, not an environment assignment VAR=x)
    wordList exes(1, word(launcher.substr(0, launcher.find(' ')), false));
    if
    (
        exes[0] == "{solver}"
     || exes[0].find('=') != std::string::npos
     || (exes[0].find('/') != std::string::npos && isFile(exes[0]))
    )
    {
        exes.clear();
    }
    if (nProcs > 1)
    {
        exes.append(tools);
    }
    for (const word& exe : exes)
    {
        if (exe.empty() || !onPath(exe))
        {
            FatalIOErrorInFunction(dict)
                << "Keyword '" << key << "' = '" << launcher.c_str()
                << "' (nProcs " << nProcs << ") needs '" << exe
                << "', not found on the PATH" << nl << exit(FatalIOError);
        }
    }

    if (nProcs <= 1)
    {
        return launcher;
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
        FatalIOErrorInFunction(dict)
            << "Keyword 'nProcs': nProcs " << nProcs << " but " << decFile
            << " has numberOfSubdomains " << nDomains << " (0: no such"
            << " file or keyword): valid are 1 (serial) or"
            << " numberOfSubdomains" << nl << exit(FatalIOError);
    }
    return launcher;
}


Foam::scalar Foam::scratchCase::readTimeLimit(const dictionary& dict)
{
    const scalar limit =
        checkedRead::getOrDefault
        (
            dict, "timeLimit", dimTime, 0, checkedRead::nonNegative()
        ).value();
    // A limit shorter than a solver's start-up kills every run
    // (minTimeLimit)
    if (limit > 0 && limit < minTimeLimit)
    {
        FatalIOErrorInFunction(dict)
            << "Keyword 'timeLimit' = " << limit << " s in " << dict.name()
            << " is shorter than a solver's start-up: valid 0 (no limit) or"
            << " [" << minTimeLimit << ", inf) s" << nl << exit(FatalIOError);
    }
    return limit;
}


void Foam::scratchCase::catchInterrupts()
{
    struct sigaction sa;
    sa.sa_handler = killRunningGroups;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    ::sigaction(SIGINT, &sa, nullptr);
    ::sigaction(SIGTERM, &sa, nullptr);
}


int Foam::scratchCase::interrupted()
{
    return caught;
}


// ************************************************************************* //
