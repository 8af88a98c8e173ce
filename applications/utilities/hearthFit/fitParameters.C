/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitParameters.H"
#include "fitFire.H"
#include "fitDisplacements.H"
#include "thermocouples.H"
#include "checkedRead.H"
#include "scratchCase.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <algorithm>
#include <fstream>
#include <iomanip>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitParameters::fitParameters
(
    const dictionary* parsDictPtr,
    const fileName& casePath,
    const dictionary* fireDict,
    const word& startName
)
{
    const dictionary& parsDict =
        parsDictPtr ? *parsDictPtr : dictionary::null;
    for (const entry& e : parsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(parsDict)
                << "parameters: '" << e.keyword() << "' is not a dictionary"
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        if (fitDisplacements::isGroup(d))
        {
            // Sensors displaced along their isotherm normals (§5.2.4)
            displacements.emplace_back
            (
                new fitDisplacements
                (
                    e.keyword(), d, displacements.size(), *this
                )
            );
            continue;
        }
        ParameterSpec s;
        s.name = e.keyword();
        checkedRead::checkKeywords
        (
            d,
            wordList
            ({
                "file", "entry", "scale", "sensor", "component", "initial",
                "min", "max", "typical", "transform", "initialFrom",
                "initialFactor"
            }),
            "parameter " + s.name
        );
        if (d.found("sensor"))
        {
            // An offset [m] of a sensor's position along x, y or z
            if (d.found("file") || d.found("entry") || d.found("scale"))
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": a sensor offset takes"
                    << " no file, entry or scale" << exit(FatalIOError);
            }
            s.sensor = d.get<word>("sensor");
            const word comp(d.get<word>("component"));
            if (comp == "x") s.component = 0;
            else if (comp == "y") s.component = 1;
            else if (comp == "z") s.component = 2;
            else
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": component " << comp
                    << ": valid are x, y, z" << exit(FatalIOError);
            }
        }
        else
        {
            s.file = d.get<fileName>("file");
            s.entry = d.get<fileName>("entry");
            s.scale =
                checkedRead::getOrDefault
                (
                    d, "scale", dimless, 1, checkedRead::positive()
                ).value();
        }

        double factor = 0;
        if (d.found("initialFrom"))
        {
            const word from(d.get<word>("initialFrom"));
            if (from != "laloyMassard" && from != "firstEstimate")
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": initialFrom " << from
                    << ": valid choices: laloyMassard firstEstimate (the same: the"
                    << " firstEstimate method's diffusivity)" << exit(FatalIOError);
            }
            factor =
                checkedRead::getOrDefault
                (
                    d, "initialFactor", dimless, 1, checkedRead::positive()
                ).value();
        }
        initialFactor.push_back(factor);

        hearthFit::FitParameter p;
        p.name = s.name;
        // Finite numbers (the parameter's own units, no dimensions)
        const validRange finite{-GREAT, GREAT, true, true};
        p.initial = checkedRead::get(d, "initial", dimless, finite).value();
        p.lower = checkedRead::get(d, "min", dimless, finite).value();
        p.upper = checkedRead::get(d, "max", dimless, finite).value();
        p.typical =
            checkedRead::getOrDefault
            (
                d, "typical", dimless, 0, checkedRead::nonNegative()
            ).value();
        const word tr(d.lookupOrDefault<word>("transform", "linear"));
        if (tr == "log") p.transform = hearthFit::Transform::log;
        else if (tr != "linear")
        {
            FatalIOErrorInFunction(d)
                << "transform " << tr << ": valid are linear, log"
                << exit(FatalIOError);
        }
        if (!(p.lower < p.upper) || p.initial < p.lower || p.initial > p.upper)
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": need min < max and initial"
                << " within [min, max] (min " << p.lower << ", max "
                << p.upper << ", initial " << p.initial << ")"
                << exit(FatalIOError);
        }
        if (p.initial == 0 && !(p.typical > 0))
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": initial 0 needs a typical"
                << " > 0 (the finite-difference step floor and scale, e.g."
                << " 1e-3 for a sensor offset in m)" << exit(FatalIOError);
        }
        if (p.typical < 0)
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": typical " << p.typical
                << " < 0" << exit(FatalIOError);
        }
        if (s.component >= 0)
        {
            specs.push_back(s);
            pars.push_back(p);
            continue;
        }

        if (!caseDicts.found(s.file))
        {
            IFstream is(casePath/s.file);
            if (!is.good())
            {
                FatalIOErrorInFunction(d)
                    << "parameter " << s.name << ": cannot read "
                    << casePath/s.file << exit(FatalIOError);
            }
            dictionary cd(is);
            cd.remove("FoamFile");
            caseDicts.insert(s.file, cd);
        }
        word key;
        if (!scratchCase::parentDict(caseDicts[s.file], s.entry, key))
        {
            FatalIOErrorInFunction(d)
                << "parameter " << s.name << ": no keyword path '" << s.entry.c_str()
                << "' (a non-dictionary entry) in " << casePath/s.file
                << exit(FatalIOError);
        }
        specs.push_back(s);
        pars.push_back(p);
    }
    // A sensor moves by one group or one set of offsets
    HashTable<word> mover;
    auto claim = [&](const word& sensor, const word& by)
    {
        if (mover.found(sensor) && mover[sensor] != by)
        {
            FatalIOErrorInFunction(parsDict)
                << "parameters: sensor " << sensor << " is moved by "
                << mover[sensor] << " and by " << by << " (a sensor"
                << " belongs to one displacement group at most, and a"
                << " grouped sensor takes no offset)" << exit(FatalIOError);
        }
        mover.set(sensor, by);
    };
    for (const ParameterSpec& s : specs)
    {
        if (s.component >= 0) claim(s.sensor, "an offset parameter");
    }
    for (const auto& g : displacements)
    {
        for (const word& sensor : g->sensors())
        {
            claim(sensor, "the displacement group " + g->name());
        }
    }
    if (fireDict)
    {
        fire.reset(new fitFire(*fireDict, casePath, startName, *this));
    }
    if (specs.empty())
    {
        FatalIOErrorInFunction(parsDict) << "no parameters"
            << exit(FatalIOError);
    }
    priors.assign(specs.size(), hearthFit::Prior());
}


Foam::fitParameters::fitParameters
(
    const dictionary& fitDict,
    const fileName& casePath,
    const word& startName
)
:
    fitParameters
    (
        &parametersDict(fitDict), casePath, fitDict.findDict("fire"),
        startName
    )
{}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

const Foam::dictionary& Foam::fitParameters::parametersDict
(
    const dictionary& fitDict
)
{
    const dictionary* fireDict = fitDict.findDict("fire");
    if (fitDict.found("fire") && !fireDict)
    {
        FatalIOErrorInFunction(fitDict) << "fire: a sub-dictionary"
            << exit(FatalIOError);
    }
    // Without parameters, the fire's are the only ones
    return
        fireDict && !fitDict.found("parameters")
      ? dictionary::null
      : fitDict.subDict("parameters");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitParameters::readPriors
(
    const dictionary& fitDict,
    const bool sigmaGiven
)
{
    const dictionary* priorsDict = fitDict.findDict("priors");
    if (fitDict.found("priors") && !priorsDict)
    {
        FatalIOErrorInFunction(fitDict)
            << "priors: a sub-dictionary of parameter { value v; sd s; }"
            << exit(FatalIOError);
    }
    if (!priorsDict) return;
    wordList names;
    for (const ParameterSpec& s : specs) names.append(s.name);
    checkedRead::checkKeywords(*priorsDict, names, "priors (parameters)");
    if (priorsDict->size() && !sigmaGiven)
    {
        FatalIOErrorInFunction(*priorsDict)
            << "priors: a prior's sd is absolute, so must be the data's"
            << " noise: give observations/sigma (or sigmas, or a sigma"
            << " per group)" << exit(FatalIOError);
    }
    forAll(specs, j)
    {
        const dictionary* d = priorsDict->findDict(specs[j].name);
        if (!d)
        {
            if (priorsDict->found(specs[j].name))
            {
                FatalIOErrorInFunction(*priorsDict)
                    << "priors: " << specs[j].name << " must be a"
                    << " sub-dictionary { value v; sd s; }"
                    << exit(FatalIOError);
            }
            continue;
        }
        checkedRead::checkKeywords
        (
            *d, wordList({"value", "sd"}), "prior of " + specs[j].name
        );
        // In the parameter's own units (no dimensions): finite, sd > 0
        priors[j].mean =
            checkedRead::get
            (
                *d, "value", dimless, validRange{-GREAT, GREAT, true, true}
            ).value();
        priors[j].sd =
            checkedRead::get(*d, "sd", dimless, checkedRead::positive())
           .value();
    }
}


std::unique_ptr<hearthFit::tikhonov> Foam::fitParameters::regularisation
(
    const bool sigmaGiven
) const
{
    return fire ? fire->regularisation(size(), sigmaGiven) : nullptr;
}


bool Foam::fitParameters::anyOffset() const
{
    for (const ParameterSpec& s : specs)
    {
        if (s.component >= 0) return true;
    }
    return !displacements.empty();
}


bool Foam::fitParameters::inDirectory(const word& dirName) const
{
    for (const ParameterSpec& s : specs)
    {
        if
        (
            s.component < 0 && s.fireIndex < 0 && s.group < 0
         && s.file.components()[0] == dirName
        )
        {
            return true;
        }
    }
    return fire && fire->file().components()[0] == dirName;
}


void Foam::fitParameters::readSensorFile
(
    const dictionary& foDict,
    const word& foName,
    const fileName& casePath,
    const word& startName,
    const dictionary& parsDict
)
{
    const std::string raw(foDict.get<string>("file"));
    std::string rel;
    auto starts = [&](const std::string& pre)
    {
        return raw.compare(0, pre.size(), pre) == 0;
    };
    if (starts("<system>/")) rel = "system/" + raw.substr(9);
    else if (starts("<constant>/")) rel = "constant/" + raw.substr(11);
    else if (starts("<case>/")) rel = raw.substr(7);
    else if (raw.find_first_of("<$~") == std::string::npos && !starts("/"))
    {
        rel = raw;
    }
    fileName relName(rel);
    relName.clean();
    const wordList parts(relName.components());
    if
    (
        rel.empty() || relName.find("..") != string::npos
     || parts.size() < 2
     || (
            parts[0] != "system" && parts[0] != "constant"
         && parts[0] != startName
        )
    )
    {
        FatalIOErrorInFunction(foDict)
            << "sensor offsets and first estimate: the sensor file '" << raw.c_str() << "' of the "
            << foName << " function object must lie in the case's"
            << " system, constant or " << startName << " directory"
            << " (given as <system>/..., <constant>/... or relative to"
            << " the case), the directories copied for each run"
            << exit(FatalIOError);
    }
    sensorFile.rel = relName;

    // The sensors as the thermocouples function object reads them
    pointField positions;
    wordList names;
    labelList sensorLines;
    labelList errorLines;
    List<string> errors;
    functionObjects::thermocouples::readSensorFile
    (
        casePath/relName, positions, names, sensorLines, errorLines,
        errors
    );
    if (!errors.empty())
    {
        FatalIOErrorInFunction(foDict)
            << "sensor file " << casePath/relName
            << (errorLines[0] > 0 ? " line " : "")
            << (errorLines[0] > 0 ? Foam::name(errorLines[0]) : word())
            << ": " << errors[0].c_str() << exit(FatalIOError);
    }

    // Its lines as they are (comments, header), the sensor lines
    // marked with their sensor, to be rewritten in the copies
    std::ifstream in(casePath/relName);
    std::string line;
    while (std::getline(in, line))
    {
        sensorFile.lines.push_back(line);
        sensorFile.names.push_back(std::string());
        sensorFile.xyz.push_back(std::array<double, 3>{{0, 0, 0}});
    }
    forAll(names, i)
    {
        const size_t li = sensorLines[i] - 1;
        sensorFile.names[li] = names[i];
        sensorFile.xyz[li] =
            {{positions[i].x(), positions[i].y(), positions[i].z()}};
    }
    for (const ParameterSpec& s : specs)
    {
        if (s.component < 0) continue;
        if
        (
            std::find
            (
                sensorFile.names.begin(), sensorFile.names.end(),
                std::string(s.sensor)
            ) == sensorFile.names.end()
        )
        {
            FatalIOErrorInFunction(parsDict)
                << "parameter " << s.name << ": sensor " << s.sensor
                << " is not in the sensors file " << casePath/relName
                << exit(FatalIOError);
        }
    }
    for (const auto& g : displacements)
    {
        g->setSensors(sensorFile);
    }
}


void Foam::fitParameters::write
(
    const fileName& dir,
    const hearthFit::Vector& p
) const
{
    HashTable<dictionary> dicts(caseDicts);
    std::vector<std::array<double, 3>> xyz(sensorFile.xyz);
    for (label j = 0; j < size(); ++j)
    {
        if (specs[j].component >= 0)
        {
            for (size_t i = 0; i < xyz.size(); ++i)
            {
                if (sensorFile.names[i] == std::string(specs[j].sensor))
                {
                    xyz[i][specs[j].component] += p(j);
                }
            }
            continue;
        }
        if (specs[j].fireIndex >= 0 || specs[j].group >= 0)
        {
            continue;
        }
        word key;
        dictionary* d =
            scratchCase::parentDict(dicts[specs[j].file], specs[j].entry, key);
        d->set(key, specs[j].scale*p(j));
    }
    for (const auto& g : displacements)
    {
        g->move(p, xyz);
    }
    if (fire)
    {
        fire->write(dir, p);
    }
    forAllConstIters(dicts, iter)
    {
        scratchCase::writeDictionary
        (
            dir/iter.key(), iter.val(), "Written by hearthFit (parameters set)"
        );
    }
    if (!sensorFile.rel.empty())
    {
        std::ofstream out(dir/sensorFile.rel);
        out << std::setprecision(17);
        for (size_t i = 0; i < sensorFile.lines.size(); ++i)
        {
            if (sensorFile.names[i].empty())
            {
                out << sensorFile.lines[i] << '\n';
            }
            else
            {
                out << sensorFile.names[i] << ", " << xyz[i][0] << ", "
                    << xyz[i][1] << ", " << xyz[i][2] << '\n';
            }
        }
    }
}


void Foam::fitParameters::writeCase
(
    const fileName& out,
    const fileName& casePath,
    const word& startName,
    const hearthFit::Vector& p
) const
{
    if
    (
        !mkDir(out)
     || !cp(casePath/"system", out)
     || !cp(casePath/"constant", out)
     || !cp(casePath/startName, out)
    )
    {
        FatalErrorInFunction << "Cannot write the case copy " << out
            << exit(FatalError);
    }
    write(out, p);
    Info<< "Best parameters written into the case copy " << out << endl;
}


// ************************************************************************* //
