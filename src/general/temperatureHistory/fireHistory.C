/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fireHistory.H"
#include "checkedRead.H"
#include "OFstream.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- Absolute zero in C
    constexpr scalar zeroCelsius = 273.15;

    //- A temperature in C, above absolute zero, returned in K
    scalar readCelsius(const dictionary& dict, const word& keyword)
    {
        return checkedRead::get
        (
            dict, keyword, dimless,
            validRange{-zeroCelsius, GREAT, true, true}
        ).value() + zeroCelsius;
    }

    //- A time in h, returned in s
    scalar readHours
    (
        const dictionary& dict,
        const word& keyword,
        const validRange& range
    )
    {
        return checkedRead::get(dict, keyword, dimless, range).value()
           *fireHistory::hour;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fireHistory::fireHistory
(
    const dictionary& fireDict,
    const dictionary& coolingDict,
    const wordList& fireKeywords
)
:
    fireTemperature_(readCelsius(fireDict, "temperature")),
    rampTime_
    (
        checkedRead::getOrDefault
        (
            fireDict, "rampTime", dimless, 0, checkedRead::nonNegative()
        ).value()*hour
    ),
    rampStartTemperature_
    (
        rampTime_ > 0
      ? readCelsius(fireDict, "rampStartTemperature")
      : fireTemperature_
    ),
    coolingType_(coolingDict.get<word>("type")),
    Tair_(fireTemperature_),
    tau_(0),
    coolingTable_(),
    coolingTime_
    (
        readHours(coolingDict, "duration", checkedRead::positive())
    ),
    description_()
{
    // Unknown keywords (a misspelt 'rampTime' would silently give none)
    {
        wordList known({"temperature", "rampTime", "rampStartTemperature"});
        known.append(fireKeywords);
        checkedRead::checkKeywords(fireDict, known, "fire history: fire");
    }
    if (coolingType_ == "exponential")
    {
        checkedRead::checkKeywords
        (
            coolingDict, wordList({"type", "duration", "Tair", "tau"}),
            "cooling type exponential"
        );
    }
    else if (coolingType_ == "table")
    {
        checkedRead::checkKeywords
        (
            coolingDict, wordList({"type", "duration", "table"}),
            "cooling type table"
        );
    }

    OStringStream os;
    os  << "fire at " << fireTemperature_ - zeroCelsius << " C";
    if (rampTime_ > 0)
    {
        os  << " (ramp from " << rampStartTemperature_ - zeroCelsius
            << " C over " << rampTime_/hour << " h)";
    }

    if (coolingType_ == "exponential")
    {
        Tair_ = readCelsius(coolingDict, "Tair");
        tau_ = readHours(coolingDict, "tau", checkedRead::positive());

        os  << ", then exponential cooling to " << Tair_ - zeroCelsius
            << " C with a time constant of " << tau_/hour << " h";
    }
    else if (coolingType_ == "table")
    {
        checkedRead::checkNumbers
        (
            coolingDict, "table",
            "(time after extinction [h], T [C]) pairs, times > 0 and"
            " strictly increasing, e.g. ((0.5 300) (2 100) (6 20))"
        );
        coolingTable_ =
            coolingDict.get<List<Tuple2<scalar, scalar>>>("table");

        if (coolingTable_.empty())
        {
            FatalIOErrorInFunction(coolingDict)
                << "Keyword 'table' is an empty list: expected (time after"
                << " extinction [h], T [C]) pairs, times > 0 and strictly"
                << " increasing, e.g. ((0.5 300) (2 100) (6 20))" << nl
                << exit(FatalIOError);
        }

        scalar previous = 0;
        for (Tuple2<scalar, scalar>& point : coolingTable_)
        {
            if (point.first() <= previous)
            {
                FatalIOErrorInFunction(coolingDict)
                    << "Keyword 'table': time " << point.first()
                    << " h is not after " << previous << " h: expected"
                    << " times after extinction in (0, inf) h, strictly"
                    << " increasing" << nl
                    << exit(FatalIOError);
            }
            checkedRead::check
            (
                coolingDict, "table", point.second(),
                validRange{-zeroCelsius, GREAT, true, true}
            );
            previous = point.first();

            point.first() *= hour;
            point.second() += zeroCelsius;
        }

        os  << ", then cooling table of " << coolingTable_.size()
            << " points to " << coolingTable_.last().second() - zeroCelsius
            << " C at " << coolingTable_.last().first()/hour << " h";
    }
    else
    {
        FatalIOErrorInFunction(coolingDict)
            << "Keyword 'type' = " << coolingType_
            << " is not a cooling type; valid choices: (exponential table)"
            << nl << exit(FatalIOError);
    }

    os  << " after extinction, followed for " << coolingTime_/hour << " h";
    description_ = os.str();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::temperatureHistory Foam::fireHistory::table
(
    const scalar duration
) const
{
    if (duration < rampTime_)
    {
        FatalErrorInFunction
            << "Fire duration " << duration << " s is shorter than its ramp "
            << rampTime_ << " s" << exit(FatalError);
    }

    temperatureHistory history;
    auto add = [&history](const scalar t, const scalar T)
    {
        if (history.append(t, T) != temperatureHistory::check::ok)
        {
            FatalErrorInFunction
                << "Invalid point (" << t << " s, " << T << " K) of the"
                << " fire history after " << history.size() << " point(s)"
                << exit(FatalError);
        }
    };

    // Burning
    if (rampTime_ > 0)
    {
        add(0, rampStartTemperature_);
        add(rampTime_, fireTemperature_);
    }
    else
    {
        add(0, fireTemperature_);
    }
    if (duration > history.times().last())
    {
        add(duration, fireTemperature_);
    }

    // Cooling, from (duration, fireTemperature)
    if (coolingType_ == "exponential")
    {
        // Linear interpolation between points tau/50 apart: error
        // <= (tau/50)^2/8 max|T''| = (T_fire - Tair)/20000; after 20 tau
        // the air temperature (exp(-20) = 2e-9)
        const scalar step = tau_/50;
        const scalar end = min(coolingTime_, 20*tau_);
        const label n = ceil(end/step - SMALL);

        for (label i = 1; i <= n; ++i)
        {
            const scalar t = min(i*step, end);
            add
            (
                duration + t,
                Tair_ + (fireTemperature_ - Tair_)*Foam::exp(-t/tau_)
            );
        }
        if (coolingTime_ > end)
        {
            add(duration + coolingTime_, Tair_);
        }
    }
    else
    {
        for (const Tuple2<scalar, scalar>& point : coolingTable_)
        {
            add(duration + point.first(), point.second());
        }
    }

    return history;
}


void Foam::fireHistory::write
(
    const fileName& file,
    const scalar duration,
    const scalar startTime
) const
{
    OStringStream header;
    header.precision(12);
    header
        << "Fire history written by hearthDuration: duration "
        << duration/hour << " h (" << duration << " s), "
        << description_.c_str() << nl
        << "(time [s], fire temperature [K]), linear in between, the"
        << " last value held. Read by the fire patch of 0/T:" << nl
        << "    type uniformFixedValue; uniformValue tableFile;" << nl
        << "    uniformValueCoeffs { file \"<this file>\";"
        << " outOfBounds clamp; interpolationScheme linear; }";

    table(duration).writeTableFile(file, header.str(), startTime, 12);
}


// ************************************************************************* //
