/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "adaptiveTimeStepControls.H"
#include "checkedRead.H"
#include "OStringStream.H"
#include "IFstream.H"
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    // (lower, inf): checkedRead::positive() stops at GREAT (1e15), and
    // maxDeltaT's default is GREAT
    Foam::validRange above(const Foam::scalar lower)
    {
        return Foam::validRange
        {
            lower, std::numeric_limits<Foam::scalar>::infinity(), true, true
        };
    }
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::adaptiveTimeStepControls::adaptiveTimeStepControls
(
    const fvMesh& mesh,
    const scalar defaultMaxDeltaTemperature,
    const scalar defaultMaxDeltaTGrowth,
    const label defaultMaxIter
)
:
    mesh_(mesh),
    defaultMaxDeltaTemperature_(defaultMaxDeltaTemperature),
    defaultMaxDeltaTGrowth_(defaultMaxDeltaTGrowth),
    defaultMaxIter_(defaultMaxIter),
    adjustTimeStep_(true),
    maxDeltaT_(GREAT),
    minDeltaT_(1e-6),
    maxDeltaTemperature_(defaultMaxDeltaTemperature),
    maxDeltaTGrowth_(defaultMaxDeltaTGrowth),
    maxIter_(defaultMaxIter)
{
    read();
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

void Foam::adaptiveTimeStepControls::checkTimeEntries(const argList& args)
{
    const fileName file
    (
        args.rootPath()/args.globalCaseName()/"system"/"controlDict"
    );
    IFstream is(file);
    if (!is.good())
    {
        return;     // Time reports a missing controlDict
    }
    const dictionary controlDict(is);

    const validRange finite
    {
        -std::numeric_limits<scalar>::infinity(),
        std::numeric_limits<scalar>::infinity(), true, true
    };
    checkedRead::get(controlDict, "deltaT", dimTime, above(0));
    checkedRead::get(controlDict, "endTime", dimTime, finite);
    if (controlDict.found("startTime"))
    {
        checkedRead::get(controlDict, "startTime", dimTime, finite);
    }
}


Foam::wordList Foam::adaptiveTimeStepControls::keywords()
{
    return wordList
    ({
        "adjustTimeStep", "maxDeltaT", "minDeltaT", "maxDeltaTemperature",
        "maxDeltaTGrowth"
    });
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::adaptiveTimeStepControls::read()
{
    const Time& runTime = mesh_.time();
    const dictionary& controlDict = runTime.controlDict();

    // A misspelt keyword of ours ('maxDeltaTemprature', 'adjustTimestep')
    // would be ignored by OpenFOAM and its default used silently
    checkedRead::checkNearMisses
    (
        controlDict, keywords(), checkedRead::controlDictKeywords()
    );

    adjustTimeStep_ = controlDict.getOrDefault<bool>("adjustTimeStep", true);

    // Every number finite (nan, inf or a word: FatalIOError naming the
    // keyword and its range) and in its range

    // The first step: the controlDict's entry, and the step the run starts
    // with (a restart takes it from its time directory)
    checkedRead::get(controlDict, "deltaT", dimTime, above(0));
    checkedRead::check
    (
        controlDict, "deltaT", runTime.deltaTValue(), above(0)
    );

    maxDeltaT_ =
        checkedRead::getOrDefault
        (
            controlDict, "maxDeltaT", dimTime, GREAT, above(0)
        ).value();

    // (its range depends on maxDeltaT: a finite number first)
    if (controlDict.found("minDeltaT"))
    {
        OStringStream expected;
        expected
            << "a time step [s] in the range (0, maxDeltaT = " << maxDeltaT_
            << "]";
        checkedRead::checkNumbers(controlDict, "minDeltaT", expected.str());
    }
    minDeltaT_ = controlDict.getOrDefault<scalar>("minDeltaT", 1e-6);
    if (!(minDeltaT_ > 0 && minDeltaT_ <= maxDeltaT_))
    {
        FatalIOErrorInFunction(controlDict)
            << "Keyword 'minDeltaT' = " << minDeltaT_
            << " is outside its valid range (0, maxDeltaT = " << maxDeltaT_
            << "] in dictionary " << controlDict.name() << nl
            << exit(FatalIOError);
    }

    maxDeltaTemperature_ =
        checkedRead::getOrDefault
        (
            controlDict, "maxDeltaTemperature", dimTemperature,
            defaultMaxDeltaTemperature_, above(0)
        ).value();

    maxDeltaTGrowth_ =
        checkedRead::getOrDefault
        (
            controlDict, "maxDeltaTGrowth", dimless,
            defaultMaxDeltaTGrowth_, above(1)
        ).value();

    // endTime after the start. A run restarted at its end (startFrom
    // latestTime, the last time directory at endTime) has nothing to do
    const scalar startTime = runTime.startTime().value();
    const scalar endTime = runTime.endTime().value();
    const bool finishedRestart =
        endTime == startTime
     && controlDict.getOrDefault<word>("startFrom", "latestTime")
     == "latestTime";
    if (!(endTime > startTime) && !finishedRestart)
    {
        FatalIOErrorInFunction(controlDict)
            << "Keyword 'endTime' = " << endTime
            << " is outside its valid range (startTime = " << startTime
            << ", inf) in dictionary " << controlDict.name()
            << ": nothing to run" << nl
            << exit(FatalIOError);
    }

    // Nonlinear iterations (system/fvSolution)
    const dictionary& nonlinearDict =
        mesh_.solutionDict().optionalSubDict("nonlinear");
    maxIter_ =
        checkedRead::getLabelOrDefault
        (
            nonlinearDict, "maxIter", defaultMaxIter_, 2
        );
}


Foam::scalar Foam::adaptiveTimeStepControls::stepFactor
(
    const scalar lastMaxChange,
    const label lastIterations
) const
{
    scalar factor =
        min
        (
            maxDeltaTGrowth_,
            maxDeltaTemperature_/max(lastMaxChange, SMALL)
        );

    if (lastIterations > shrinkIterations())
    {
        factor = min(factor, 0.7);
    }

    return factor;
}


Foam::scalar Foam::adaptiveTimeStepControls::nextDeltaT
(
    const scalar lastDeltaT,
    const scalar lastMaxChange,
    const label lastIterations
) const
{
    return
        min(stepFactor(lastMaxChange, lastIterations)*lastDeltaT, maxDeltaT_);
}


// ************************************************************************* //
