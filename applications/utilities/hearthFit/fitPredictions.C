/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitPredictions.H"
#include "checkedRead.H"

#include <algorithm>
#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- A point added to the sensors file of the copies
void addSensor
(
    Foam::SensorFile& f,
    const std::string& name,
    const Foam::vector& x
)
{
    f.lines.push_back(std::string());
    f.names.push_back(name);
    f.xyz.push_back(std::array<double, 3>{{x.x(), x.y(), x.z()}});
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitPredictions::fitPredictions
(
    const dictionary* dict,
    fitParameters& params
)
{
    if (!dict) return;
    SensorFile& sf = params.sensorFile;
    const validRange finite{-GREAT, GREAT, true, true};
    for (const entry& e : *dict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(*dict)
                << "predictions: '" << e.keyword() << "' is not a"
                << " dictionary" << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        Spec s;
        s.name = e.keyword();
        s.type = d.get<word>("type");
        auto readPoint = [&]()
        {
            checkedRead::checkNumbers(d, "point", "(x y z) [m]");
            return d.get<vector>("point");
        };
        if (s.type == "TMax")
        {
            checkedRead::checkKeywords
            (
                d, wordList({"type", "sensor", "point"}),
                "prediction " + s.name + " (type TMax)"
            );
            s.unit = "C";
            if (d.found("sensor") == d.found("point"))
            {
                FatalIOErrorInFunction(d)
                    << "prediction " << s.name << ": give either 'sensor'"
                    << " (a name of the thermocouples file) or 'point'"
                    << " (x y z)" << exit(FatalIOError);
            }
            if (d.found("sensor"))
            {
                const word sn(d.get<word>("sensor"));
                if
                (
                    std::find(sf.names.begin(), sf.names.end(), sn)
                 == sf.names.end()
                )
                {
                    FatalIOErrorInFunction(d)
                        << "prediction " << s.name << ": sensor " << sn
                        << " is not in the sensors file "
                        << sf.rel << exit(FatalIOError);
                }
                s.sensors.push_back(sn);
            }
            else
            {
                s.sensors.push_back(s.name + "_TMax");
                addSensor(sf, s.sensors[0], readPoint());
            }
        }
        else if (s.type == "isothermDepth")
        {
            checkedRead::checkKeywords
            (
                d, wordList({"type", "point", "value", "depth", "nPoints"}),
                "prediction " + s.name + " (type isothermDepth)"
            );
            s.unit = "m";
            const vector x0(readPoint());
            s.value = checkedRead::get(d, "value", dimless, finite).value();
            const scalar depth =
                checkedRead::get(d, "depth", dimLength, checkedRead::positive())
               .value();
            const label n = checkedRead::getLabelOrDefault(d, "nPoints", 201, 2);
            for (label i = 0; i < n; ++i)
            {
                const scalar z = depth*i/(n - 1);
                s.depths.push_back(z);
                s.sensors.push_back(s.name + "_" + Foam::name(i));
                addSensor(sf, s.sensors.back(), x0 - vector(0, 0, z));
            }
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "prediction " << s.name << ": type " << s.type
                << ": valid are TMax, isothermDepth" << exit(FatalIOError);
        }
        specs_.push_back(s);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitPredictions::evaluate
(
    const sensorHistories& sim,
    double* out
) const
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    auto tMax = [&](const std::string& name)
    {
        for (size_t c = 0; c < sim.names.size(); ++c)
        {
            if (sim.names[c] == name && sim.values[c].size())
            {
                return *std::max_element
                (
                    sim.values[c].begin(), sim.values[c].end()
                );
            }
        }
        return nan;
    };
    for (size_t k = 0; k < specs_.size(); ++k)
    {
        const Spec& s = specs_[k];
        out[k] = nan;
        if (s.type == "TMax")
        {
            out[k] = tMax(s.sensors[0]);
            continue;
        }
        // isothermDepth: the first crossing of value going down
        double above = tMax(s.sensors[0]);
        if (!(above >= s.value)) continue;
        for (size_t i = 1; i < s.sensors.size(); ++i)
        {
            const double t = tMax(s.sensors[i]);
            if (std::isnan(t)) break;
            if (t < s.value)
            {
                out[k] =
                    s.depths[i - 1]
                  + (above - s.value)/(above - t)
                   *(s.depths[i] - s.depths[i - 1]);
                break;
            }
            above = t;
        }
    }
}


// ************************************************************************* //
