/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "nanInjection.H"
#include "debug.H"
#include "registerSwitch.H"
#include "dictionary.H"
#include "IOstreams.H"
#include <cctype>

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
    // A key starting with an engine's name (any case: pendularNewtonNan,
    // PendularNewtonNaN) or ending in NaN that is none of the names
    auto startsNoCase = [](const word& key, const std::string& prefix)
    {
        if (key.size() < prefix.size())
        {
            return false;
        }
        for (std::string::size_type i = 0; i < prefix.size(); ++i)
        {
            if (std::tolower(key[i]) != std::tolower(prefix[i]))
            {
                return false;
            }
        }
        return true;
    };
    for (const entry& e : *optPtr)
    {
        const word& key = e.keyword();
        if
        (
            (
                key.endsWith("NaN")
             || startsNoCase(key, "pendularNewton")
             || startsNoCase(key, "richardsNewton")
            )
         && !names.found(key)
        )
        {
            FatalIOErrorInFunction(*optPtr)
                << "Unknown OptimisationSwitch '" << key << "' in "
                << controlDict.name() << " (OpenFOAM would ignore it): the"
                << " NaN injection switches are " << names
                << " (case-sensitive)" << exit(FatalIOError);
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
