/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "exitWithStatus.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"

#include <mpi.h>
#include <cstdio>
#include <cstdlib>
#include <iostream>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Finalise MPI as UPstream::exit(0) does, without its std::exit(0)
void finaliseMpi()
{
    #if defined(OPENFOAM) && (OPENFOAM >= 2006)
    // v2006 and later (read in ESI's sources of v2006, v2106, v2406; not
    // compiled here): public 'static void shutdown(int errNo = 0)', MPI
    // finalised (MPI_Abort only for errNo != 0); UPstream::exit(errNo) is
    // shutdown(errNo), then std::exit(errNo)
    Foam::UPstream::shutdown(0);
    #else
    // v1912: UPstream::exit(0)'s steps on public MPI calls: the buffer
    // Pstream attached for buffered sends (new char[]) detached, which
    // waits for its messages, then MPI_Finalize (it frees the remaining
    // communicators)
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (finalised)
    {
        return;
    }
    void* buf = nullptr;
    int len = 0;
    if (MPI_Buffer_detach(&buf, &len) == MPI_SUCCESS && buf && len)
    {
        delete[] static_cast<char*>(buf);
    }
    MPI_Finalize();
    #endif
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::exitWithStatus(int status)
{
    // Every rank takes the same path below (no-op in a serial run)
    reduce(status, maxOp<int>());

    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);

    if (!UPstream::parRun() || status == 0)
    {
        UPstream::exit(status);
    }
    else
    {
        finaliseMpi();
    }
    std::exit(status);
}


// ************************************************************************* //
