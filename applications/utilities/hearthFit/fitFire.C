/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitFire.H"
#include "fitParameters.H"
#include "fitForwardRuns.H"
#include "fitObservations.H"
#include "fireHistory.H"
#include "fireRecord.H"
#include "checkedRead.H"
#include "IFstream.H"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The keywords of hearthFit::tikhonov::Rule, in its order
const char* const ruleNames[] = {"fixed", "discrepancy", "lCurve"};

//- A fire parameter { initial; min; max; } (C or h)
hearthFit::FitParameter readBounded
(
    const dictionary& d,
    const word& name,
    const scalar lowest
)
{
    checkedRead::checkKeywords
    (
        d, wordList({"initial", "min", "max"}), "fire " + name
    );
    const validRange range{lowest, GREAT, false, true};
    hearthFit::FitParameter p;
    p.name = name;
    p.initial = checkedRead::get(d, "initial", dimless, range).value();
    p.lower = checkedRead::get(d, "min", dimless, range).value();
    p.upper = checkedRead::get(d, "max", dimless, range).value();
    if (!(p.lower < p.upper) || p.initial < p.lower || p.initial > p.upper)
    {
        FatalIOErrorInFunction(d)
            << "fire " << name << ": need min < max and initial within"
            << " [min, max] (min " << p.lower << ", max " << p.upper
            << ", initial " << p.initial << ")" << exit(FatalIOError);
    }
    return p;
}

//- FatalIOError unless a patch of the case's temperature field (start
//  time) has the boundary condition fireTemperature reading the fire CSV
//  file (relative to the case): a CSV no patch reads would leave the fire
//  parameters without effect, one that is another case file would
//  overwrite it in every copy
void checkFireFileRead
(
    const dictionary& dict,
    const fileName& casePath,
    const word& startName,
    const fileName& file
)
{
    const fileName TPath(casePath/startName/"T");
    fileName target(casePath/file);
    target.clean();
    wordList readers;
    if (isFile(TPath))
    {
        IFstream is(TPath);
        const dictionary T(is);
        const dictionary* bf = T.findDict("boundaryField");
        if (bf)
        {
            for (const entry& e : *bf)
            {
                if
                (
                    !e.isDict()
                 || e.dict().getOrDefault<word>("type", word::null)
                    != "fireTemperature"
                 || !e.dict().found("file")
                )
                {
                    continue;
                }
                ITstream& its = e.dict().lookup("file");
                token tok;
                its.read(tok);
                if (!tok.isStringType()) continue;
                const fileName f
                (
                    fireRecord::resolveFile
                    (
                        tok.stringToken(), casePath
                    )
                );
                if (f == target) return;
                readers.append(e.keyword() + ": " + f);
            }
        }
    }
    FatalIOErrorInFunction(dict)
        << "fire: file " << file << ": no patch of " << TPath
        << " reads it: expected a patch with the boundary condition"
        << " fireTemperature whose file is this one (e.g. file"
        << " \"<constant>/fire.csv\"); fireTemperature patches and their"
        << " files: " << readers << exit(FatalIOError);
}


//- FatalIOError if a fire parameter (from first on) has the name of an
//  earlier parameter (priors and reports name parameters)
void checkNamesUnique
(
    const dictionary& dict,
    const fitParameters& params,
    const label first
)
{
    for (size_t j = first; j < params.specs.size(); ++j)
    {
        for (size_t i = 0; i < size_t(first); ++i)
        {
            if (params.specs[i].name == params.specs[j].name)
            {
                FatalIOErrorInFunction(dict)
                    << "fire: parameter " << params.specs[j].name.c_str()
                    << " has the name of a parameter of 'parameters':"
                    << " rename that one" << exit(FatalIOError);
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitFire::fitFire
(
    const dictionary& dict,
    const fileName& casePath,
    const word& startName,
    fitParameters& params
)
:
    type_(Type::knots),
    dict_(dict),
    first_(params.size()),
    order_(0),
    rule_(hearthFit::tikhonov::Rule::fixed),
    weight_(0)
{
    const word type(dict.get<word>("type"));
    if (type == "knots")
    {
        checkedRead::checkKeywords
        (
            dict,
            wordList
            ({"type", "file", "knots", "initial", "min", "max",
              "regularisation"}),
            "fire (type knots)"
        );
    }
    else if (type == "law")
    {
        type_ = Type::law;
        checkedRead::checkKeywords
        (
            dict,
            wordList
            ({"type", "file", "fire", "cooling", "duration", "temperature"}),
            "fire (type law)"
        );
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "fire: type " << type << ": valid choices: knots (the"
            << " surface temperature on knots), law (duration and plateau"
            << " temperature of the fire law)" << exit(FatalIOError);
    }

    // The fire CSV: in a directory copied for each run
    file_ = dict.get<fileName>("file");
    file_.clean();
    const wordList parts(file_.components());
    if
    (
        file_.isAbsolute() || file_.find("..") != string::npos
     || parts.size() < 2
     || (parts[0] != "system" && parts[0] != "constant" && parts[0] != startName)
    )
    {
        FatalIOErrorInFunction(dict)
            << "fire: file '" << file_ << "' must lie in the case's system,"
            << " constant or " << startName << " directory (relative to the"
            << " case), the directories copied for each run"
            << exit(FatalIOError);
    }
    if (!isDir(casePath/file_.path()))
    {
        FatalIOErrorInFunction(dict)
            << "fire: file " << file_ << ": no directory "
            << casePath/file_.path() << exit(FatalIOError);
    }
    checkFireFileRead(dict, casePath, startName, file_);

    if (type_ == Type::law)
    {
        lawFire_ = dict.subDict("fire");
        lawCooling_ = dict.subDict("cooling");
        if (lawFire_.found("temperature"))
        {
            FatalIOErrorInFunction(lawFire_)
                << "fire/fire: temperature is the parameter fireTemperature"
                << " (fire/temperature { initial; min; max; }): remove it"
                << exit(FatalIOError);
        }
        hearthFit::FitParameter d =
            readBounded(dict.subDict("duration"), "fireDuration", 0);
        hearthFit::FitParameter T =
            readBounded(dict.subDict("temperature"), "fireTemperature", -273.15);
        T.sensitivityScale = 100;   // K, as the knots' (Celsius: no scale)
        // The law checked (keywords, ranges) with the initial values, and
        // the duration bounds against its ramp
        dictionary fd(lawFire_);
        fd.set("temperature", T.initial);
        fireHistory law(fd, lawCooling_, wordList());
        if (d.lower*fireHistory::hour < law.rampTime())
        {
            FatalIOErrorInFunction(dict.subDict("duration"))
                << "fire duration: min " << d.lower << " h is shorter than"
                << " the ramp (rampTime " << law.rampTime()/fireHistory::hour
                << " h)" << exit(FatalIOError);
        }
        for (hearthFit::FitParameter& p : {std::ref(d), std::ref(T)})
        {
            ParameterSpec s;
            s.name = p.name;
            s.fireIndex = params.size() - first_;
            params.specs.push_back(s);
            params.pars.push_back(p);
            params.initialFactor.push_back(0);
        }
        checkNamesUnique(dict, params, first_);
        return;
    }

    // Knots [s], strictly increasing, at least 2
    knots_ = dict.get<scalarList>("knots");
    if (knots_.size() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "fire: knots: need at least 2 times [s], strictly increasing"
            << exit(FatalIOError);
    }
    forAll(knots_, k)
    {
        if (!std::isfinite(knots_[k]))
        {
            FatalIOErrorInFunction(dict)
                << "fire: knots: time " << k + 1 << " is not finite"
                << exit(FatalIOError);
        }
        if (k > 0 && !(knots_[k] > knots_[k - 1]))
        {
            FatalIOErrorInFunction(dict)
                << "fire: knots must be strictly increasing: knot " << k + 1
                << " (" << knots_[k] << " s) is not after knot " << k
                << " (" << knots_[k - 1] << " s)" << exit(FatalIOError);
        }
    }
    const validRange celsius{-273.15, GREAT, false, true};
    const scalar T0 = checkedRead::get(dict, "initial", dimless, celsius).value();
    const scalar Tmin = checkedRead::get(dict, "min", dimless, celsius).value();
    const scalar Tmax = checkedRead::get(dict, "max", dimless, celsius).value();
    if (!(Tmin < Tmax) || T0 < Tmin || T0 > Tmax)
    {
        FatalIOErrorInFunction(dict)
            << "fire: need min < max and initial within [min, max] (min "
            << Tmin << ", max " << Tmax << ", initial " << T0 << ") [C]"
            << exit(FatalIOError);
    }
    forAll(knots_, k)
    {
        hearthFit::FitParameter p;
        p.name = "Tfire_" + std::to_string(k + 1);
        p.initial = T0;
        p.lower = Tmin;
        p.upper = Tmax;
        p.typical = 100;        // K: the finite-difference step's scale
        // and the scale of the identifiability SVD (a Celsius value is no
        // scale: a knot at 10 C would look 10 times less identifiable
        // than the same knot at 100 C)
        p.sensitivityScale = p.typical;
        ParameterSpec s;
        s.name = p.name;
        s.fireIndex = k;
        params.specs.push_back(s);
        params.pars.push_back(p);
        params.initialFactor.push_back(0);
    }
    checkNamesUnique(dict, params, first_);

    const dictionary* reg = dict.findDict("regularisation");
    if (dict.found("regularisation") && !reg)
    {
        FatalIOErrorInFunction(dict)
            << "fire: regularisation must be a sub-dictionary { order 1|2;"
            << " rule discrepancy|lCurve|fixed|none; weight w; }"
            << exit(FatalIOError);
    }
    if (!reg) return;
    checkedRead::checkKeywords
    (
        *reg, wordList({"order", "rule", "weight"}), "fire regularisation"
    );
    const word rule(reg->get<word>("rule"));
    // rule none: order still checked (switching the rule back is one
    // word), a weight refused (it is for rule fixed only)
    const bool noRule = (rule == "none");
    if (noRule && reg->found("weight"))
    {
        FatalIOErrorInFunction(*reg)
            << "fire regularisation: the weight is for rule fixed only, not"
            << " rule none (remove it)" << exit(FatalIOError);
    }
    if (noRule && !reg->found("order")) return;
    bool known = false;
    for (int k = 0; k < 3; ++k)
    {
        if (rule == ruleNames[k])
        {
            rule_ = static_cast<hearthFit::tikhonov::Rule>(k);
            known = true;
        }
    }
    if (!known && !noRule)
    {
        FatalIOErrorInFunction(*reg)
            << "fire regularisation: rule " << rule << ": valid choices:"
            << " discrepancy (chi^2 = number of data), lCurve (its corner),"
            << " fixed (weight), none" << exit(FatalIOError);
    }
    order_ = reg->get<label>("order");
    if (order_ != 1 && order_ != 2)
    {
        FatalIOErrorInFunction(*reg)
            << "fire regularisation: order " << order_ << ": valid are 1"
            << " (first differences), 2 (second differences)"
            << exit(FatalIOError);
    }
    if (knots_.size() < order_ + 1)
    {
        FatalIOErrorInFunction(*reg)
            << "fire regularisation: order " << order_ << " needs at least "
            << order_ + 1 << " knots" << exit(FatalIOError);
    }
    if (noRule)
    {
        order_ = 0;
        return;
    }
    if (rule_ == hearthFit::tikhonov::Rule::fixed)
    {
        // In s/K^2 (order 1) or s^3/K^2 (order 2): the rows weigh divided
        // differences (integrals of T'^2 or T''^2 dt); dimensions written
        // with the value (weight [0 0 3 -2 0 0 0] 2e4;) are checked
        weight_ =
            checkedRead::get
            (
                *reg, "weight",
                pow(dimTime, scalar(2*order_ - 1))/sqr(dimTemperature),
                checkedRead::nonNegative()
            ).value();
    }
    else if (reg->found("weight"))
    {
        FatalIOErrorInFunction(*reg)
            << "fire regularisation: weight is for rule fixed only (rule "
            << rule << " chooses it)" << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitFire::history
(
    const hearthFit::Vector& p,
    scalarList& t,
    scalarList& T
) const
{
    if (type_ == Type::knots)
    {
        t = knots_;
        T.setSize(knots_.size());
        forAll(T, k) T[k] = p(first_ + k);
        return;
    }
    dictionary fd(lawFire_);
    fd.set("temperature", p(first_ + 1));
    const fireHistory law(fd, lawCooling_, wordList());
    const temperatureHistory h(law.table(p(first_)*fireHistory::hour));
    t = h.times();
    T = h.temperatures() - 273.15;
}


void Foam::fitFire::write
(
    const fileName& dir,
    const hearthFit::Vector& p
) const
{
    scalarList t, T;
    history(p, t, T);
    std::ofstream out(dir/file_);
    out << std::setprecision(17)
        << "# fire history written by hearthFit (fire, type "
        << (type_ == Type::knots ? "knots" : "law") << ")\n"
        << "time_s,T_C\n";
    forAll(t, k)
    {
        out << t[k] << ',' << T[k] << '\n';
    }
}


std::unique_ptr<hearthFit::tikhonov> Foam::fitFire::regularisation
(
    const label nPar,
    const bool sigmaGiven
) const
{
    if (type_ != Type::knots || order_ == 0)
    {
        return nullptr;
    }
    if (!sigmaGiven)
    {
        FatalIOErrorInFunction(dict_)
            << "fire regularisation: the weight is absolute (chi^2 against"
            << " the number of data): give the data's noise,"
            << " observations/sigma (or sigmas, or a sigma per group)"
            << exit(FatalIOError);
    }
    return std::unique_ptr<hearthFit::tikhonov>
    (
        new hearthFit::tikhonov
        (
            nPar, first_,
            std::vector<double>(knots_.begin(), knots_.end()),
            order_, weight_
        )
    );
}


Foam::word Foam::fitFire::weightUnit() const
{
    return order_ == 1 ? "s/K^2" : "s^3/K^2";
}


void Foam::fitFire::chooseWeight
(
    hearthFit::tikhonov& reg,
    hearthFit::levenbergMarquardt& lm,
    const label nData
) const
{
    const char* ruleName = ruleNames[int(rule_)];
    Info<< "Fire regularisation: " << (order_ == 1 ? "first" : "second")
        << " divided differences of the " << knots_.size() << " knot"
        << " temperatures (|L T|^2 ~ integral of "
        << (order_ == 1 ? "T'^2" : "T''^2") << " dt), rule " << ruleName
        << endl;
    if (rule_ == hearthFit::tikhonov::Rule::fixed)
    {
        Info<< "    weight w = " << reg.weight() << ' ' << weightUnit().c_str()
            << " (given)" << endl;
        return;
    }

    // The linearisation at the initial (or resumed) values p0: the fit's
    // own first Jacobian (levenbergMarquardt::initialLinearisation: its
    // steps, bounds handling and retries), whose runs the fit then finds
    // made (fitForwardRuns caches runs by parameters)
    hearthFit::Vector p0, r;
    hearthFit::Matrix J;
    if (!lm.initialLinearisation(p0, r, J))
    {
        FatalErrorInFunction
            << "fire regularisation: a forward run of the"
            << " linearisation at the initial values failed: cannot"
            << " choose the weight (rule " << ruleName << ")"
            << exit(FatalError);
    }
    // The data rows only (the prior and regularisation rows follow them)
    const hearthFit::Vector r0 = r.head(nData);
    const hearthFit::Matrix Jd = J.topRows(nData);
    const hearthFit::tikhonov::Choice c = reg.choose(rule_, Jd, r0, p0);
    Info<< "    weight w = " << c.weight << ' ' << weightUnit().c_str()
        << ": chi^2 = " << c.chi2
        << " (N = " << nData << " data; unregularised " << c.chi2Unregularised
        << "), roughness |L T| = " << c.roughness << " K/s^"
        << (order_ == 1 ? "0.5" : "1.5")
        << " (linearisation at the initial values: the fit's first Jacobian,"
        << " " << p0.size() + 1 << " runs)" << endl;
    if (c.message.size())
    {
        WarningInFunction << "fire regularisation: " << c.message.c_str()
            << endl;
    }

    // The intervals of the knots hold the noise's variance only, not the
    // regularisation's bias: honest when the weight leaves chi^2 within
    // the noise's band (the discrepancy rule: chi^2 = N), not when it
    // smooths more (chi^2 above N + 2 sqrt(2N), two standard deviations
    // of a chi-square of N degrees of freedom)
    const scalar chi2Band =
        nData + hearthFit::tikhonov::dataMisfitBand(nData);
    if (c.chi2 > chi2Band)
    {
        WarningInFunction
            << "fire regularisation: the weight (rule " << ruleName
            << ") leaves chi^2 = " << c.chi2 << " above the noise's band"
            << " N + 2 sqrt(2N) = " << chi2Band << ": the regularisation"
            << " biases the history by more than the noise, and the knots'"
            << " intervals (the noise's variance only) do not cover that"
            << " bias. Rule discrepancy keeps chi^2 = N" << endl;
    }
}


void Foam::fitFire::checkAtEstimate
(
    const hearthFit::tikhonov& reg,
    const hearthFit::FitResult& res,
    const label nData
) const
{
    if (res.residuals.size() < nData) return;
    const char* ruleName = ruleNames[int(rule_)];
    const scalar chi2 = res.residuals.head(nData).squaredNorm();
    const scalar band = hearthFit::tikhonov::dataMisfitBand(nData);
    Info<< "Fire regularisation at the estimate: data-only chi^2 = " << chi2
        << " (N = " << nData << ", band N -/+ 2 sqrt(2N) = [" << nData - band
        << ", " << nData + band << "]; the final cost " << res.cost
        << " includes the penalty w |L T|^2 = "
        << res.residuals.tail(reg.rows()).squaredNorm()
        << ")" << endl;
    if (hearthFit::tikhonov::dataMisfitInBand(chi2, nData)) return;

    // The weight the discrepancy principle gives on the linearisation at
    // the estimate (the final Jacobian: no run)
    std::ostringstream alt;
    if
    (
        res.jacobian.rows() == res.residuals.size()
     && res.jacobian.allFinite()
    )
    {
        hearthFit::tikhonov probe(reg);
        const hearthFit::tikhonov::Choice c = probe.choose
        (
            hearthFit::tikhonov::Rule::discrepancy,
            res.jacobian.topRows(nData),
            res.residuals.head(nData),
            res.parameters
        );
        alt << "; the discrepancy principle on the linearisation at the"
            << " estimate gives w = " << c.weight << ' '
            << weightUnit().c_str() << " (chi^2 " << c.chi2 << " there):"
            << " rerun with rule fixed; weight " << c.weight
            << "; (or start from the estimate)";
    }
    WarningInFunction
        << "fire regularisation: the data-only chi^2 at the estimate, "
        << chi2 << ", is outside the noise's band N -/+ 2 sqrt(2N) = "
        << nData << " -/+ " << band << " (rule " << ruleName << ", weight "
        << reg.weight() << ' ' << weightUnit().c_str()
        << (rule_ == hearthFit::tikhonov::Rule::fixed ? "" : ", chosen on"
            " the linearisation at the initial values: the forward model is"
            " not linear in the knots")
        << "): the history is "
        << (chi2 > nData ? "smoothed beyond the noise (biased, the knots'"
            " intervals do not cover the bias)" : "fitted into the noise")
        << alt.str().c_str() << endl;
}


// ************************************************************************* //
