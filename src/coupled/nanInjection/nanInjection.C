/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "nanInjection.H"
#include "debug.H"
#include "registerSwitch.H"
#include "dictionary.H"
#include "IOstreams.H"

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


const Foam::wordList Foam::nanInjection::names
({
    "pendularNewtonNaN", "pendularNewtonLocalWaterNaN", "richardsNewtonNaN"
});


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

void Foam::nanInjection::checkSwitchNames(const dictionary& controlDict)
{
    const dictionary* optPtr =
        controlDict.findDict("OptimisationSwitches", keyType::LITERAL);
    if (!optPtr)
    {
        return;
    }
    for (const entry& e : *optPtr)
    {
        const word& key = e.keyword();
        if (key.endsWith("NaN") && !names.found(key))
        {
            FatalIOErrorInFunction(*optPtr)
                << "Unknown OptimisationSwitch '" << key << "' in "
                << controlDict.name() << " (OpenFOAM would ignore it): the"
                << " NaN injection switches are " << names
                << exit(FatalIOError);
        }
    }
}


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
