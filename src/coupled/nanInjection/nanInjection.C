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

// A test switch: its int, from the OptimisationSwitches (0 by default),
// registered, so that a case's controlDict or -opt-switch sets it (each
// on a line of its own: registerOptSwitch names its object by the line)
#define testSwitch(var, name)                                                 \
    int Foam::nanInjection::var(Foam::debug::optimisationSwitch(name, 0));    \
    registerOptSwitch(name, int, Foam::nanInjection::var)

testSwitch(pendularNewtonResidual, "pendularNewtonNaN");
testSwitch(pendularNewtonLocalWater, "pendularNewtonLocalWaterNaN");
testSwitch(richardsNewtonResidual, "richardsNewtonNaN");
// (not a NaN: pendularNewton's projection onto non-negative air off)
testSwitch(pendularNewtonNoAirProjection, "pendularNewtonNoAirProjection");

#undef testSwitch


const Foam::wordList Foam::nanInjection::names
({
    "pendularNewtonNaN", "pendularNewtonLocalWaterNaN", "richardsNewtonNaN",
    "pendularNewtonNoAirProjection"
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
                << " test switches are " << names
                << " (case-sensitive)" << exit(FatalIOError);
        }
    }
}


void Foam::nanInjection::checkNoAirProjection(const dictionary& controlDict)
{
    const int value = pendularNewtonNoAirProjection;
    if (value >= 0 && value <= 2)
    {
        return;
    }
    const dictionary* optPtr =
        controlDict.findDict("OptimisationSwitches", keyType::LITERAL);
    const word key("pendularNewtonNoAirProjection");
    const char* valid =
        ": valid 0 (the air projection on), 1 (pendularNewton's iterates not"
        " projected onto non-negative air) or 2 (nor refused for a gas"
        " density <= 0; test only)";
    // The value in effect: the case controlDict's when it sets one (read
    // with the Time, after -opt-switch, v1912), -opt-switch's otherwise
    if (optPtr && optPtr->found(key) && optPtr->get<label>(key) == value)
    {
        FatalIOErrorInFunction(*optPtr)
            << "OptimisationSwitch " << key << " = " << value << " in "
            << controlDict.name() << valid << exit(FatalIOError);
    }
    FatalErrorInFunction
        << "OptimisationSwitch " << key << " = " << value << " (from"
        << " -opt-switch or the OptimisationSwitches of etc/controlDict)"
        << valid << exit(FatalError);
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
