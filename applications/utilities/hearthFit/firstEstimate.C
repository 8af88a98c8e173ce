/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "firstEstimate.H"
#include "laloyMassard.H"
#include "laplaceDiffusivity.H"
#include "checkedRead.H"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// The column of sensor sn in the measurements and its line in the
// thermocouples file (FatalIOError if either is missing)
void findSensor
(
    const dictionary& fd,
    const Time& runTime,
    const fitObservations& obs,
    const fitParameters& params,
    const word& sn,
    label& col,
    label& li
)
{
    col = -1;
    for (size_t c = 0; c < obs.measured.names.size(); ++c)
    {
        if (obs.measured.names[c] == sn) col = c;
    }
    li = -1;
    for (size_t i = 0; i < params.sensorFile.names.size(); ++i)
    {
        if (params.sensorFile.names[i] == std::string(sn)) li = i;
    }
    if (col < 0 || li < 0)
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: sensor " << sn
        << " is not " << (col < 0 ? "a column of " : "in ")
        << (col < 0 ? obs.path : runTime.path()/params.sensorFile.rel)
        << exit(FatalIOError);
    }
}


// The measured history of column col inside the time window
std::vector<double> sensorHistory(const fitObservations& obs, const label col)
{
    std::vector<double> T;
    for (size_t k : obs.rows) T.push_back(obs.measured.values[col][k]);
    return T;
}


// The Laplace-transform estimate (Mansour 2015 5.2.2.2,
// src/numerics/identifiability/laplaceDiffusivity.H) of each pair of
// sensors consecutive in depth, printed; returns their median
double laplaceEstimate
(
    const dictionary& fd,
    const Time& runTime,
    const fitObservations& obs,
    const fitParameters& params,
    const wordList& sensors,
    const std::vector<double>& t,
    const scalar Ti,
    const scalar zSurf,
    const scalar pMin,
    const scalar pMax
)
{
    // (depth, sensor, column), sorted by depth
    std::vector<std::tuple<double, word, label>> s;
    for (const word& sn : sensors)
    {
        label col = -1, li = -1;
        findSensor(fd, runTime, obs, params, sn, col, li);
        s.emplace_back
        (
            std::abs(params.sensorFile.xyz[li][2] - zSurf), sn, col
        );
    }
    std::sort(s.begin(), s.end());
    if (s.size() < 2)
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: method"
            << " laplaceTransform needs at least 2 sensors, got "
            << s.size() << exit(FatalIOError);
    }
    Info<< nl << "first estimate (Laplace transform, Mansour 5.2.2.2: 1-D"
        << " dry soil initially at " << Ti << " C, any surface history;"
        << " pairs of sensors consecutive in depth):" << endl;
    std::vector<double> aPair;
    for (size_t i = 0; i + 1 < s.size(); ++i)
    {
        std::vector<double> T1(sensorHistory(obs, std::get<2>(s[i])));
        std::vector<double> T2(sensorHistory(obs, std::get<2>(s[i + 1])));
        for (double& v : T1) v -= Ti;
        for (double& v : T2) v -= Ti;
        std::ostringstream os;
        os << std::setprecision(8) << "    " << std::get<1>(s[i]).c_str()
            << "-" << std::get<1>(s[i + 1]).c_str() << ": depths "
            << std::get<0>(s[i]) << ", " << std::get<0>(s[i + 1]) << " m, ";
        if (!(std::get<0>(s[i + 1]) > std::get<0>(s[i])))
        {
            os << "same depth: no estimate";
            Info<< os.str().c_str() << endl;
            continue;
        }
        hearthFit::laplaceDiffusivity::Result r;
        try
        {
            r = hearthFit::laplaceDiffusivity::estimate
            (
                t, T1, T2, std::get<0>(s[i]), std::get<0>(s[i + 1]),
                pMin, pMax
            );
        }
        catch (const std::exception& e)
        {
            FatalIOErrorInFunction(fd) << "firstEstimate: " << e.what()
                << exit(FatalIOError);
        }
        if (r.a > 0)
        {
            os << "diffusivity a = " << r.a << " m2/s (" << r.p.size()
                << " values of p in [" << r.p.front() << ", " << r.p.back()
                << "] 1/s; rms departure from the line " << r.misfit << ")";
            aPair.push_back(r.a);
        }
        else
        {
            os << "no estimate (transforms not positive or the ratio below"
                << " 1e-6 at every p)";
        }
        Info<< os.str().c_str() << endl;
    }
    if (aPair.empty())
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: no sensor pair gives"
            << " an estimate" << exit(FatalIOError);
    }
    const double a = hearthFit::laloyMassard::median(aPair);
    std::ostringstream os;
    os << std::setprecision(8) << "first estimate: diffusivity a = " << a
        << " m2/s (median of " << aPair.size() << " pairs)";
    Info<< os.str().c_str() << endl;
    return a;
}


// Parameters with initialFrom: initialFactor x a (clipped to their bounds)
void setInitial
(
    fitParameters& params,
    const double aMed,
    const bool resume
)
{
    if (!resume)
    {
        for (label j = 0; j < params.size(); ++j)
        {
            if (!(params.initialFactor[j] > 0)) continue;
            hearthFit::FitParameter& p = params.pars[j];
            double v = params.initialFactor[j]*aMed;
            if (v < p.lower || v > p.upper)
            {
                const double c = std::min(std::max(v, p.lower), p.upper);
                Info<< "    parameter " << params.specs[j].name << ": "
                    << params.initialFactor[j] << " x a = " << v
                    << " outside [" << p.lower << ", " << p.upper
                    << "], clipped to " << c << endl;
                v = c;
            }
            if (p.typical == 0) p.typical = std::abs(p.initial)/100;
            Info<< "    initial " << params.specs[j].name << " = "
                << params.initialFactor[j] << " x a = " << v
                << " (instead of " << p.initial << ")" << endl;
            p.initial = v;
        }
    }
    Info<< endl;
}



} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

void Foam::firstEstimate
(
    const dictionary& fd,
    const Time& runTime,
    const fitObservations& obs,
    fitParameters& params,
    const bool resume
)
{
    // method: laloyMassard (default, Mansour 2015 5.2.2.1) or
    // laplaceTransform (5.2.2.2: consecutive sensor pairs by depth; no
    // surfaceTemperature needed, the surface history is free)
    const word method(fd.getOrDefault<word>("method", "laloyMassard"));
    if (method != "laloyMassard" && method != "laplaceTransform")
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: method " << method
            << " unknown; valid choices: laloyMassard laplaceTransform"
            << exit(FatalIOError);
    }
    const bool laplace = method == "laplaceTransform";
    checkedRead::checkKeywords
    (
        fd,
        laplace
      ? wordList
        ({
            "method", "initialTemperature", "sensors", "surfaceZ",
            "timeOrigin", "pMin", "pMax"
        })
      : wordList
        ({
            "method", "surfaceTemperature", "initialTemperature", "sensors",
            "surfaceZ", "timeOrigin"
        })
    );
    // Temperatures in degrees Celsius, above absolute zero; z and t finite
    const validRange celsius{-273.15, GREAT, true, true};
    const validRange finite{-GREAT, GREAT, true, true};
    const scalar T0 =
        laplace
      ? 0
      : checkedRead::get
        (
            fd, "surfaceTemperature", dimTemperature, celsius
        ).value();
    const scalar Ti =
        checkedRead::get
        (
            fd, "initialTemperature", dimTemperature, celsius
        ).value();
    const scalar zSurf =
        checkedRead::getOrDefault(fd, "surfaceZ", dimLength, 0, finite).value();
    const scalar tOrigin =
        checkedRead::getOrDefault
        (
            fd, "timeOrigin", dimTime, runTime.startTime().value(), finite
        ).value();
    const wordList feSensors
    (
        fd.found("sensors") ? fd.get<wordList>("sensors") : obs.sensors
    );
    if (!laplace && T0 == Ti)
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: surfaceTemperature"
            << " equals initialTemperature" << exit(FatalIOError);
    }
    std::vector<double> tAll, zs, aPer;
    std::vector<std::vector<double>> Ts;
    for (size_t k : obs.rows) tAll.push_back(obs.measured.times[k] - tOrigin);
    if (laplace)
    {
        const validRange positive{0, GREAT, false, true};
        const scalar pMin =
            checkedRead::getOrDefault(fd, "pMin", dimless/dimTime, 0, positive)
           .value();
        const scalar pMax =
            checkedRead::getOrDefault(fd, "pMax", dimless/dimTime, 0, positive)
           .value();
        const double aL = laplaceEstimate
        (
            fd, runTime, obs, params, feSensors, tAll, Ti, zSurf, pMin, pMax
        );
        setInitial(params, aL, resume);
        return;
    }
    Info<< nl << "first estimate (Laloy-Massard, Mansour 5.2.2.1: 1-D"
        << " semi-infinite dry soil, surface at " << T0 << " C from t = "
        << tOrigin << " s, initially " << Ti << " C; erfc history fit):"
        << endl;
    for (const word& sn : feSensors)
    {
        label col = -1, li = -1;
        findSensor(fd, runTime, obs, params, sn, col, li);
        const double z = std::abs(params.sensorFile.xyz[li][2] - zSurf);
        std::vector<double> T(sensorHistory(obs, col));
        int nUsed = 0;
        const double a = hearthFit::laloyMassard::exactEstimate
        (
            z, tAll, T, T0, Ti, nUsed
        );
        std::ostringstream os;
        os << std::setprecision(8);
        os << "    " << std::string(sn) << ": depth " << z << " m, ";
        if (a > 0)
        {
            os << "diffusivity a = " << a << " m2/s (" << nUsed
                << " readings)";
            aPer.push_back(a);
            zs.push_back(z);
            Ts.push_back(T);
        }
        else
        {
            os << "no usable reading (depth 0 or temperatures outside"
                << " (Ti, T0))";
        }
        Info<< os.str().c_str() << endl;
    }
    if (aPer.empty())
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: no sensor gives"
            << " an estimate" << exit(FatalIOError);
    }
    const double aMed = hearthFit::laloyMassard::median(aPer);
    const double aPrinted = hearthFit::laloyMassard::printedRecipe
    (
        zs, tAll, Ts, T0, Ti
    );
    {
        std::ostringstream os;
        os << std::setprecision(8)
            << "first estimate: diffusivity a = " << aMed
            << " m2/s (median of " << aPer.size() << " sensors)";
        if (aPrinted > 0)
        {
            os << "; printed recipe (5.6, geometric-mean approximation)"
                << " a = " << aPrinted << " m2/s";
        }
        Info<< os.str().c_str() << endl;
    }
    setInitial(params, aMed, resume);
}


// ************************************************************************* //
