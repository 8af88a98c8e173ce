/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitObservations.H"
#include "fitPredictions.H"
#include "numericTable.H"
#include "checkedRead.H"
#include "HashTable.H"
#include "Pair.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

bool Foam::readSensorCsv
(
    const std::string& path,
    sensorHistories& h,
    std::string& err,
    const bool observations
)
{
    numericTable::settings s;
    s.nColumns = -2;
    s.uniqueNames = true;
    s.roles = {"a time"};
    s.collect = !observations;
    if (observations)
    {
        s.orderedColumn = 0;
        s.what = "the observations file";
        s.context = "observations of system/hearthFitDict";
    }
    else
    {
        s.what = "the sensors CSV of the run";
    }
    const numericTable table(fileName(path), s);

    if (table.errors().size())
    {
        const numericTable::error& e = table.errors()[0];
        err = path + (e.line > 0 ? " line " + std::to_string(e.line) : "")
            + ": " + e.message;
        return false;
    }
    if (table.names().size() < 2)
    {
        err = path + ": the header needs a time and a sensor column";
        if (observations)
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, path)
                << "observations: " << err.c_str() << nl
                << exit(FatalIOError);
        }
        return false;
    }

    h.names.assign(table.names().begin() + 1, table.names().end());
    h.values.assign(h.names.size(), std::vector<double>());
    h.times.clear();
    forAll(table, rowi)
    {
        const double t = table.value(rowi, 0);
        // Restarted run (not for observations: checked increasing)
        while (h.times.size() && h.times.back() >= t)
        {
            h.times.pop_back();
            for (auto& v : h.values) v.pop_back();
        }
        h.times.push_back(t);
        for (size_t i = 0; i < h.names.size(); ++i)
        {
            h.values[i].push_back(table.value(rowi, i + 1));
        }
    }
    return true;
}


bool Foam::interpolateLinear
(
    const std::vector<double>& t,
    const std::vector<double>& y,
    const double x,
    double& v
)
{
    const double tol = 1e-9*std::max(1.0, std::abs(x));
    if (t.empty() || x < t.front() - tol || x > t.back() + tol) return false;
    if (t.size() == 1) { v = y[0]; return true; }
    size_t i = std::upper_bound(t.begin(), t.end(), x) - t.begin();
    if (i == 0) i = 1;
    if (i >= t.size()) i = t.size() - 1;
    const double t0 = t[i - 1], t1 = t[i];
    const double w = (t1 > t0) ? (x - t0)/(t1 - t0) : 0;
    v = y[i - 1] + std::min(1.0, std::max(0.0, w))*(y[i] - y[i - 1]);
    return true;
}



// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitObservations::fitObservations
(
    const dictionary& obsDict,
    const Time& runTime,
    const label nPar
)
:
    sigmaGiven(false),
    predictions(nullptr)
{
    checkedRead::checkKeywords
    (
        obsDict,
        wordList
        ({
            "file", "timeUnit", "timeWindow", "sensors", "sigma", "sigmas",
            "weights", "groups"
        })
    );
    const fileName obsFile(obsDict.get<fileName>("file").expand());
    path = obsFile.isAbsolute() ? obsFile : runTime.path()/obsFile;
    {
        std::string err;
        if (!readSensorCsv(path, measured, err, true))
        {
            FatalIOErrorInFunction(obsDict)
                << "observations: " << err.c_str() << exit(FatalIOError);
        }
    }
    // The file's time unit (s, min or h; default s): the times, and the
    // timeWindow, converted to the case's seconds at once
    const word timeUnit(obsDict.getOrDefault<word>("timeUnit", "s"));
    const HashTable<scalar> secondsPer({{"s", 1}, {"min", 60}, {"h", 3600}});
    if (!secondsPer.found(timeUnit))
    {
        FatalIOErrorInFunction(obsDict)
            << "timeUnit " << timeUnit << ": valid units are s, min and h"
            << exit(FatalIOError);
    }
    for (double& t : measured.times)
    {
        t *= secondsPer[timeUnit];
    }
    // Times in minutes or hours read as seconds would all fall in the first
    // minutes of the run and be fitted there without a word: unless the
    // unit is given, observations that end within the first 1/60 of the
    // run stop the fit
    const scalar simulated =
        runTime.endTime().value() - runTime.startTime().value();
    if
    (
        !obsDict.found("timeUnit") && !measured.times.empty()
     && measured.times.back() - runTime.startTime().value() <= simulated/60
    )
    {
        FatalIOErrorInFunction(obsDict)
            << "the observations in " << path << " end at t = "
            << measured.times.back() << " s, within the first 1/60 of the "
            << simulated << " s simulated: are the file's times in minutes"
            << " or hours? Give timeUnit min or h (or timeUnit s if they"
            << " are seconds)" << exit(FatalIOError);
    }
    scalar t0 = -GREAT, t1 = GREAT;
    if (obsDict.found("timeWindow"))
    {
        const scalarList w
        (
            checkedRead::getList
            (
                obsDict, "timeWindow",
                validRange{-GREAT, GREAT, false, false},
                "(start end): two finite times, start < end"
            )
        );
        if (w.size() != 2 || !(w[0] < w[1]))
        {
            FatalIOErrorInFunction(obsDict)
                << "Keyword 'timeWindow' = " << w << " in dictionary "
                << obsDict.name() << ": expected (start end), two finite"
                << " times with start < end" << exit(FatalIOError);
        }
        t0 = secondsPer[timeUnit]*w[0];
        t1 = secondsPer[timeUnit]*w[1];
    }
    // Observation groups read from their own file (groups name { file
    // "..."; sigma s; }): the file's sensor columns joined to the
    // observations' table; same times (the residuals are times x sensors)
    // and no sensor in two files
    const dictionary* groupsDict = obsDict.findDict("groups");
    std::vector<wordList> fileGroupSensors;
    std::vector<fileName>& colFile = columnFile;
    colFile.assign(measured.names.size(), path);
    if (groupsDict)
    {
        for (const entry& e : *groupsDict)
        {
            fileGroupSensors.push_back(wordList());
            if (!e.isDict() || !e.dict().found("file")) continue;
            const dictionary& g = e.dict();
            const fileName f(g.get<fileName>("file").expand());
            const fileName gPath(f.isAbsolute() ? f : runTime.path()/f);
            sensorHistories h;
            std::string err;
            if (!readSensorCsv(gPath, h, err, true))
            {
                FatalIOErrorInFunction(g)
                    << "observation group " << e.keyword() << ": file: "
                    << err.c_str() << exit(FatalIOError);
            }
            bool sameTimes = h.times.size() == measured.times.size();
            for (size_t k = 0; sameTimes && k < h.times.size(); ++k)
            {
                const double t = h.times[k]*secondsPer[timeUnit];
                sameTimes = std::abs(t - measured.times[k])
                    <= 1e-9*std::max(1.0, std::abs(t));
            }
            if (!sameTimes)
            {
                FatalIOErrorInFunction(g)
                    << "observation group " << e.keyword() << ": file "
                    << gPath << " has other times than " << path << " ("
                    << h.times.size() << " and " << measured.times.size()
                    << " rows): every observations file needs the same"
                    << " time column" << exit(FatalIOError);
            }
            for (size_t c = 0; c < h.names.size(); ++c)
            {
                const word sn(h.names[c]);
                const auto it = std::find
                (
                    measured.names.begin(), measured.names.end(), sn
                );
                if (it != measured.names.end())
                {
                    FatalIOErrorInFunction(g)
                        << "observation group " << e.keyword() << ": file "
                        << gPath << ": sensor " << sn << " is already in "
                        << colFile[it - measured.names.begin()]
                        << " (a sensor belongs to one observations file)"
                        << exit(FatalIOError);
                }
                measured.names.push_back(sn);
                colFile.push_back(gPath);
                measured.values.push_back(h.values[c]);
                fileGroupSensors.back().append(sn);
            }
        }
    }
    if (obsDict.found("sensors"))
    {
        sensors = obsDict.get<wordList>("sensors");
    }
    else
    {
        for (const auto& n : measured.names) sensors.append(word(n));
    }
    measCol.assign(sensors.size(), -1);
    sigma.assign(sensors.size(), 1);
    weight.assign(sensors.size(), 1);
    group.assign(sensors.size(), -1);
    // Measurement standard deviation [K] and weights: finite, > 0
    const scalar sigmaAll =
        checkedRead::getOrDefault
        (
            obsDict, "sigma", dimTemperature, 1, checkedRead::positive()
        ).value();
    // Observation groups: sensors sharing a noise level
    std::vector<scalar> groupSigma;
    if (obsDict.found("groups") && !groupsDict)
    {
        FatalIOErrorInFunction(obsDict)
            << "groups: a sub-dictionary of groups name { sensors (...);"
            << " sigma s; }" << exit(FatalIOError);
    }
    bool groupSigmaGiven = false;
    if (groupsDict)
    {
        for (const entry& e : *groupsDict)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(*groupsDict)
                    << "groups: '" << e.keyword() << "' is not a dictionary"
                    << " { sensors (...); sigma s; }" << exit(FatalIOError);
            }
            const dictionary& g = e.dict();
            const word gName(e.keyword());
            checkedRead::checkKeywords
            (
                g, wordList({"sensors", "sigma", "file"}),
                "observation group " + gName
            );
            groupSigmaGiven = groupSigmaGiven || g.found("sigma");
            groupSigma.push_back
            (
                checkedRead::getOrDefault
                (
                    g, "sigma", dimTemperature, sigmaAll,
                    checkedRead::positive()
                ).value()
            );
            // A group with its own file: its sensors (all of the file's,
            // or those listed, which must be columns of that file)
            const wordList& inFile = fileGroupSensors[groupNames.size()];
            const wordList members
            (
                g.found("file") && !g.found("sensors") ? inFile
              : g.get<wordList>("sensors")
            );
            for (const word& m : members)
            {
                if (g.found("file") && !inFile.found(m))
                {
                    FatalIOErrorInFunction(g)
                        << "observation group " << gName << ": sensors: "
                        << m << " is not a column of its file "
                        << g.get<fileName>("file") << "; its columns: "
                        << inFile << exit(FatalIOError);
                }
                const label si = sensors.find(m);
                if (si < 0)
                {
                    const word near(checkedRead::nearest(m, sensors));
                    FatalIOErrorInFunction(g)
                        << "observation group " << gName << ": sensor " << m
                        << " is not an observed sensor";
                    if (near.size())
                    {
                        FatalIOError << " (did you mean " << near << "?)";
                    }
                    FatalIOError << "; observed: " << sensors
                        << exit(FatalIOError);
                }
                if (group[si] >= 0)
                {
                    FatalIOErrorInFunction(g)
                        << "observation group " << gName << ": sensor " << m
                        << " is already in group " << groupNames[group[si]]
                        << " (a sensor belongs to one group at most)"
                        << exit(FatalIOError);
                }
                group[si] = groupNames.size();
            }
            groupNames.append(gName);
        }
    }
    sigmaGiven =
        obsDict.found("sigma") || obsDict.found("sigmas") || groupSigmaGiven;
    const dictionary* sigmasDict = obsDict.findDict("sigmas");
    const dictionary* weightsDict = obsDict.findDict("weights");
    // Their keywords are the observed sensors or groups (a misspelt name
    // would silently keep the default)
    wordList allowed(sensors);
    allowed.append(groupNames);
    for (const dictionary* sw : {sigmasDict, weightsDict})
    {
        if (sw)
        {
            checkedRead::checkKeywords
            (
                *sw, allowed, "observed sensors and groups"
            );
        }
    }
    forAll(sensors, si)
    {
        for (size_t c = 0; c < measured.names.size(); ++c)
        {
            if (measured.names[c] == sensors[si]) measCol[si] = c;
        }
        if (measCol[si] < 0)
        {
            FatalIOErrorInFunction(obsDict)
                << "sensor " << sensors[si] << " is not a column of "
                << path << (colFile.size() > 0 && groupsDict ?
                    " (nor of a group's file)" : "") << exit(FatalIOError);
        }
        // The sensor's own entry, else its group's, else the default
        const label gi = group[si];
        sigma[si] = gi >= 0 ? groupSigma[gi] : sigmaAll;
        auto perSensor = [&]
        (
            const dictionary* d, const dimensionSet& dims, scalar& v
        )
        {
            if (!d) return;
            if (gi >= 0 && d->found(groupNames[gi]))
            {
                v = checkedRead::get
                    (
                        *d, groupNames[gi], dims, checkedRead::positive()
                    ).value();
            }
            if (d->found(sensors[si]))
            {
                v = checkedRead::get
                    (
                        *d, sensors[si], dims, checkedRead::positive()
                    ).value();
            }
        };
        perSensor(sigmasDict, dimTemperature, sigma[si]);
        perSensor(weightsDict, dimless, weight[si]);
        if (!(sigma[si] > 0) || !(weight[si] > 0))
        {
            FatalIOErrorInFunction(obsDict)
                << "sensor " << sensors[si] << ": sigma and weight must be"
                << " > 0" << exit(FatalIOError);
        }
    }
    for (size_t k = 0; k < measured.times.size(); ++k)
    {
        if (measured.times[k] >= t0 && measured.times[k] <= t1)
        {
            times.push_back(measured.times[k]);
            rows.push_back(k);
        }
    }
    if (times.size()*sensors.size() <= size_t(nPar))
    {
        FatalIOErrorInFunction(obsDict)
            << "fewer observations (" << times.size()*sensors.size()
            << ") inside the time window than parameters + 1"
            << exit(FatalIOError);
    }
    const scalar endTime = runTime.endTime().value();
    if (times.back() > endTime + 1e-9*max(1, mag(endTime))
     || times.front() < runTime.startTime().value())
    {
        FatalIOErrorInFunction(obsDict)
            << "observation times [" << times.front() << ", "
            << times.back() << "] outside the simulated window ["
            << runTime.startTime().value() << ", " << endTime << "]"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitObservations::checkCaseSensors
(
    const dictionary& obsDict,
    const fileName& sensorFile,
    const wordList& caseSensors
) const
{
    // The observed sensors missing from the case, by file
    std::vector<fileName> files;
    std::vector<wordList> missing;
    forAll(sensors, si)
    {
        if (caseSensors.found(sensors[si])) continue;
        const fileName& f = columnFile[measCol[si]];
        const auto it = std::find(files.begin(), files.end(), f);
        if (it == files.end())
        {
            files.push_back(f);
            missing.push_back(wordList(1, sensors[si]));
        }
        else
        {
            missing[it - files.begin()].append(sensors[si]);
        }
    }
    if (files.empty()) return;

    const bool one = files.size() == 1 && missing[0].size() == 1;
    FatalIOErrorInFunction(obsDict) << "observations: ";
    for (size_t i = 0; i < files.size(); ++i)
    {
        FatalIOError << (i ? "; " : "")
            << (missing[i].size() > 1 ? "the columns " : "the column ");
        forAll(missing[i], j)
        {
            const word& m = missing[i][j];
            const word near(checkedRead::nearest(m, caseSensors));
            FatalIOError << (j ? ", " : "") << m;
            if (near.size())
            {
                FatalIOError << " (did you mean " << near << "?)";
            }
        }
        FatalIOError << " of " << files[i];
    }
    FatalIOError
        << (one ? " is not a sensor" : " are not sensors")
        << " of the case; the sensors of " << sensorFile << " (its"
        << " thermocouples function object):";
    for (const word& c : caseSensors)
    {
        FatalIOError << ' ' << c;
    }
    FatalIOError
        << nl << "    (a forward run would not write "
        << (one ? "it" : "them") << ": remove the column, list the"
        << " observed sensors in 'sensors', or add the sensor to the case)"
        << exit(FatalIOError);
}


bool Foam::fitObservations::residuals
(
    const fileName& csv,
    hearthFit::Vector& r,
    std::string& why
) const
{
    sensorHistories sim;
    if (!readSensorCsv(csv, sim, why)) return false;
    r.resize(times.size()*sensors.size());
    label n = 0;
    forAll(sensors, si)
    {
        label col = -1;
        for (size_t c = 0; c < sim.names.size(); ++c)
        {
            if (sim.names[c] == sensors[si]) col = c;
        }
        if (col < 0)
        {
            why = "sensor " + sensors[si] + " not in " + csv;
            return false;
        }
        for (size_t k = 0; k < times.size(); ++k)
        {
            double v;
            if (!interpolateLinear(sim.times, sim.values[col], times[k], v))
            {
                why = "simulated times do not cover the observations";
                return false;
            }
            r(n++) = std::sqrt(weight[si])*(v - value(si, k))/sigma[si];
        }
    }
    if (predictions && predictions->size())
    {
        r.conservativeResize(n + predictions->size());
        predictions->evaluate(sim, r.data() + n);
    }
    return true;
}


// ************************************************************************* //
