/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "firstEstimate.H"
#include "laloyMassard.H"
#include "checkedRead.H"

#include <cmath>
#include <iomanip>
#include <sstream>

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
    checkedRead::checkKeywords
    (
        fd,
        wordList
        ({
            "surfaceTemperature", "initialTemperature", "sensors",
            "surfaceZ", "timeOrigin"
        })
    );
    // Temperatures in degrees Celsius, above absolute zero; z and t finite
    const validRange celsius{-273.15, GREAT, true, true};
    const validRange finite{-GREAT, GREAT, true, true};
    const scalar T0 =
        checkedRead::get
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
    if (T0 == Ti)
    {
        FatalIOErrorInFunction(fd) << "firstEstimate: surfaceTemperature"
            << " equals initialTemperature" << exit(FatalIOError);
    }
    std::vector<double> tAll, zs, aPer;
    std::vector<std::vector<double>> Ts;
    for (size_t k : obs.rows) tAll.push_back(obs.measured.times[k] - tOrigin);
    Info<< nl << "first estimate (Laloy-Massard, Mansour 5.2.2.1: 1-D"
        << " semi-infinite dry soil, surface at " << T0 << " C from t = "
        << tOrigin << " s, initially " << Ti << " C; erfc history fit):"
        << endl;
    for (const word& sn : feSensors)
    {
        label col = -1;
        for (size_t c = 0; c < obs.measured.names.size(); ++c)
        {
            if (obs.measured.names[c] == sn) col = c;
        }
        label li = -1;
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
        const double z = std::abs(params.sensorFile.xyz[li][2] - zSurf);
        std::vector<double> T;
        for (size_t k : obs.rows) T.push_back(obs.measured.values[col][k]);
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


// ************************************************************************* //
