/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "petscSession.H"
#include "Pstream.H"
#include "error.H"

#include <petscsys.h>
#include <string>
#include <cstdlib>

// * * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * //

namespace
{
    bool sessionAlive = false;

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
            // Open MPI's singleton without its daemon (see Description;
            // overwrite 0: a value in the environment wins)
            ::setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
        }
        // OpenFOAM's signal handlers stay (its stack trace on SIGSEGV,
        // its floating-point traps): PETSc installs none
        check
        (
            PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr),
            "PetscOptionsSetValue"
        );
        check
        (
            PetscInitializeNoArguments(),
            "PetscInitializeNoArguments"
        );
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
