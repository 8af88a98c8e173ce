/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "petscSession.H"
#include "Pstream.H"
#include "error.H"

#include <petscsys.h>

// * * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * //

namespace
{
    bool sessionAlive = false;
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
        check
        (
            PetscInitializeNoArguments(),
            "PetscInitializeNoArguments"
        );
        initialised_ = true;
    }
    sessionAlive = true;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::petscSession::~petscSession()
{
    sessionAlive = false;
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


void Foam::petscSession::check(const int ierr, const char* call)
{
    if (ierr)
    {
        const char* text = nullptr;
        PetscErrorMessage(PetscErrorCode(ierr), &text, nullptr);
        FatalErrorInFunction
            << "PETSc call " << call << " failed with error " << ierr
            << ": " << (text ? text : "(no message)")
            << exit(FatalError);
    }
}


// ************************************************************************* //
