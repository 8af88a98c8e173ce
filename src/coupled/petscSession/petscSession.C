/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "petscSession.H"
#include "Pstream.H"
#include "error.H"

#include <petscsys.h>
#include <string>
#include <cstdlib>
#include <vector>

// * * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * //

namespace
{
    bool sessionAlive = false;

    //- Open MPI's singleton (a serial run: MPI started by PETSc, a world
    //  of one rank that talks only to itself): no daemon (orted), the
    //  only transport it uses (self: no tcp sockets, no shared-memory
    //  segment of vader), and the components it selects anyway (ob1, the
    //  state and error manager of an application process, shmem mmap);
    //  the reachability component by weights, not netlink's (used by the
    //  tcp transport only); hwloc without its GPU, PCI and XML plugins
    //  (libxml2 with ICU, X11's NV-CONTROL, libpciaccess)
    const char* const singletonDefaults[][2] =
    {
        {"OMPI_MCA_ess_singleton_isolated", "1"},
        {"OMPI_MCA_btl", "self"},
        {"OMPI_MCA_pml", "ob1"},
        {"OMPI_MCA_state", "app"},
        {"OMPI_MCA_errmgr", "default_app"},
        {"OMPI_MCA_reachable", "weighted"},
        {"OMPI_MCA_shmem", "mmap"},
        {
            "HWLOC_PLUGINS_BLACKLIST",
            "hwloc_gl,hwloc_opencl,hwloc_pci,hwloc_xml_libxml"
        }
    };

    //- PETSc's message of the last error, with where it was raised
    std::string lastPetscError;

    //- PETSc's error handler: keep the message for petscSession::check
    //  (PETSc's default handler prints a trace and its whole configuration
    //  on every rank), return the error code
    PetscErrorCode keepMessage
    (
        MPI_Comm,
        int line,
        const char* func,
        const char* file,
        PetscErrorCode n,
        PetscErrorType p,
        const char* mess,
        void*
    )
    {
        if (p == PETSC_ERROR_INITIAL)
        {
            lastPetscError =
                std::string(mess ? mess : "")
              + " (in " + (func ? func : "?") + ", " + (file ? file : "?")
              + ":" + std::to_string(line) + ")";
        }
        return n;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::petscSession::petscSession()
:
    initialised_(false)
{
    if (sessionAlive)
    {
        FatalErrorInFunction
            << "A PETSc session is already alive: construct one petscSession"
            << " in main" << exit(FatalError);
    }

    // The variables set here for Open MPI's singleton
    std::vector<const char*> setHere;
    PetscBool already = PETSC_FALSE;
    check(PetscInitialized(&already), "PetscInitialized");
    if (!already)
    {
        // The communicator of the run: all ranks in parallel; this rank
        // alone in a serial run (a serial application started by mpirun
        // must not couple with the others). PETSc accepts a communicator
        // only once MPI runs; without MPI (a serial run) it starts MPI
        // itself on a world of one rank
        int mpiRunning = 0;
        MPI_Initialized(&mpiRunning);
        if (mpiRunning)
        {
            PETSC_COMM_WORLD =
                Pstream::parRun() ? MPI_COMM_WORLD : PETSC_COMM_SELF;
        }
        else
        {
            // A serial run started by a launcher (mpirun -np N without
            // -parallel): PETSc's MPI_Init would join the N copies of the
            // serial run in one world (and the singleton's settings below
            // would not let them talk): refused
            for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
            {
                const char* n = ::getenv(var);
                if (n && std::atoi(n) > 1)
                {
                    FatalErrorInFunction
                        << "Started by mpirun on " << n << " ranks ("
                        << var << ") without -parallel: each rank would"
                        << " run the whole case. Run 'mpirun -np " << n
                        << " <solver> -parallel' on a decomposed case"
                        << " (decomposePar), or the solver without mpirun"
                        << exit(FatalError);
                }
            }
            // Open MPI's singleton without its daemon and without the
            // components a world of one rank does not use (see
            // Description); only where the environment sets none (a value
            // there wins)
            for (const auto& var : singletonDefaults)
            {
                if (!::getenv(var[0]))
                {
                    ::setenv(var[0], var[1], 1);
                    setHere.push_back(var[0]);
                }
            }
        }
        // OpenFOAM's signal handlers stay (its stack trace on SIGSEGV,
        // its floating-point traps): PETSc installs none
        check
        (
            PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr),
            "PetscOptionsSetValue"
        );
        const int ierr = PetscInitializeNoArguments();
        // (read by MPI_Init only: out of the environment again, which a
        // process this one starts, e.g. an mpirun, inherits)
        for (const char* name : setHere)
        {
            ::unsetenv(name);
        }
        check(ierr, "PetscInitializeNoArguments");
        initialised_ = true;
    }
    check
    (
        PetscPushErrorHandler(keepMessage, nullptr),
        "PetscPushErrorHandler"
    );
    sessionAlive = true;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::petscSession::~petscSession()
{
    sessionAlive = false;
    PetscPopErrorHandler();
    if (initialised_)
    {
        PetscFinalize();
    }
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

bool Foam::petscSession::active()
{
    return sessionAlive;
}


void Foam::petscSession::checkActive(const string& who)
{
    if (!sessionAlive)
    {
        FatalErrorInFunction
            << who << " needs PETSc: construct a petscSession in main after"
            << " the argList (#include \"setRootCase.H\")"
            << exit(FatalError);
    }
}


const std::string& Foam::petscSession::lastError()
{
    return lastPetscError;
}


void Foam::petscSession::check(const int ierr, const char* call)
{
    if (ierr)
    {
        const char* text = nullptr;
        PetscErrorMessage(PetscErrorCode(ierr), &text, nullptr);
        FatalErrorInFunction
            << "PETSc call " << call << " failed with error " << ierr
            << ": " << (text ? text : "(no message)") << nl
            << "    " << lastError().c_str()
            << exit(FatalError);
    }
}


// ************************************************************************* //
