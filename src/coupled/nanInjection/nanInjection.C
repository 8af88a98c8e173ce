/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "nanInjection.H"
#include "debug.H"
#include "registerSwitch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

int Foam::nanInjection::pendularNewtonResidual
(
    Foam::debug::optimisationSwitch("pendularNewtonNaN", 0)
);
registerOptSwitch
(
    "pendularNewtonNaN",
    int,
    Foam::nanInjection::pendularNewtonResidual
);

int Foam::nanInjection::pendularNewtonLocalWater
(
    Foam::debug::optimisationSwitch("pendularNewtonLocalWaterNaN", 0)
);
registerOptSwitch
(
    "pendularNewtonLocalWaterNaN",
    int,
    Foam::nanInjection::pendularNewtonLocalWater
);

int Foam::nanInjection::richardsNewtonResidual
(
    Foam::debug::optimisationSwitch("richardsNewtonNaN", 0)
);
registerOptSwitch
(
    "richardsNewtonNaN",
    int,
    Foam::nanInjection::richardsNewtonResidual
);


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::nanInjection::report(const char* target) const
{
    if (at_ != 0)
    {
        Info<< "OptimisationSwitch " << name_ << " = " << at_ << ": "
            << target << " set to NaN at its evaluation " << mag(at_)
            << (at_ < 0 ? " and every later one" : " only")
            << " (test only)" << endl;
    }
}


// ************************************************************************* //
