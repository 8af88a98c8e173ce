/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitReport.H"
#include "fitDisplacements.H"
#include "fitPredictions.H"
#include "fitFire.H"
#include "casePaths.H"
#include "scratchCase.H"
#include "OSspecific.H"
#include "subsetSelection.H"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitReport::fitReport
(
    const fitParameters& params,
    const fitObservations& obs,
    const fitForwardRuns& fwd,
    const fitState& state
)
:
    params_(params),
    obs_(obs),
    fwd_(fwd),
    state_(state),
    initial0_(),
    progressCsv_
    (
        fwd.workDir/"progress.csv",
        state.resume ? std::ios::app : std::ios::trunc
    ),
    clock0_(std::chrono::steady_clock::now())
{
    for (const auto& p : params_.pars) initial0_.push_back(p.initial);

    // An earlier fit's posterior must not outlive this fit (hearthDuration
    // reads it): an interrupted fit leaves none
    rm(fwd_.workDir/"posterior.dict");

    progressCsv_ << std::setprecision(8);
    if (!state_.resume)
    {
        progressCsv_ << "iteration,cost";
        for (const auto& s : params_.specs) progressCsv_ << ',' << s.name;
        progressCsv_ << ",damping,elapsed_s,runs,event" << std::endl;
    }
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

// Identifiable parameters and their ranking (Mansour 2015 §4.8 subset
// selection, src/numerics/identifiability) from the final scaled Jacobian
// J diag(s) (s_j = |p_j|, or the parameter's fixed sensitivityScale: the
// fire's temperatures, in Celsius, have 100 K), of the data and prior rows:
// the regularisation rows (nReg, the last ones) are left out, they make
// any knot "identifiable"; numerical rank: singular values above 1e-3 of
// the largest (her bound: the Jacobian's error ~ sqrt of the solver's 1e-6)
void identifiabilityLines
(
    std::ostringstream& rep,
    const hearthFit::FitResult& res,
    const Foam::fitParameters& params,
    const long nReg
)
{
    if (res.jacobian.rows() <= nReg || !res.jacobian.allFinite()) return;
    if (res.sensitivityScale.size() != res.jacobian.cols()) return;
    const double threshold = 1e-3;
    const hearthFit::SubsetSelection s = hearthFit::subsetSelection
    (
        res.jacobian.topRows(res.jacobian.rows() - nReg)
       *res.sensitivityScale.asDiagonal(),
        threshold, true
    );
    rep << "\nidentifiability (subset selection, Mansour 2015 4.8): rank "
        << s.rank << " of " << params.size() << " (singular values above "
        << threshold << " x the largest); ranking:";
    for (size_t k = 0; k < s.order.size(); ++k)
    {
        rep << (k ? (int(k) < s.rank ? " > " : " | ") : " ")
            << params.specs[s.order[k]].name.c_str();
        if (int(k) >= s.rank) rep << " (not identifiable)";
    }
    rep << "\n";
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fileName Foam::fitReport::writeCasePath
(
    const argList& args,
    const fileName& casePath,
    const word& startName
)
{
    fileName writeCasePath;
    if (args.found("writeCase"))
    {
        writeCasePath = casePaths::canonical(args.get<fileName>("writeCase"));
        const fileName holder
        (
            casePaths::copiedDirHolding(casePath, startName, writeCasePath)
        );
        if (casePaths::inside(casePath, writeCasePath))
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << " (" << writeCasePath << ") is the case " << casePath
                << " or contains it: its system, constant and "
                << startName << " would be overwritten. Give a new"
                << " directory outside the case" << exit(FatalError);
        }
        if (!holder.empty())
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << " (" << writeCasePath << ") lies inside " << holder
                << ", which is itself copied into it: the copy would"
                << " contain itself. Give a directory outside the case's"
                << " system, constant and " << startName << exit(FatalError);
        }
        if (exists(writeCasePath) && !args.found("overwrite"))
        {
            FatalErrorInFunction
                << "-writeCase " << args.get<fileName>("writeCase")
                << ": " << writeCasePath << " exists; its system, constant"
                << " and " << startName << " would be replaced and its"
                << " parameter dictionaries rewritten without their"
                << " comments. Give a new directory, or add -overwrite"
                << exit(FatalError);
        }
    }
    return writeCasePath;
}


double Foam::fitReport::elapsed() const
{
    return state_.elapsedOffset + std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - clock0_
    ).count();
}


void Foam::fitReport::header(const hearthFit::FitOptions& opts) const
{
    Info<< "hearthFit: " << params_.size() << " parameters, " << obs_.sensors.size()
        << " sensors x " << obs_.times.size() << " times = "
        << obs_.sensors.size()*obs_.times.size() << " residuals" << nl
        << "    solver " << fwd_.solver;
    if (fwd_.nProcs > 1) Info<< " on " << fwd_.nProcs << " ranks (" << fwd_.launcher << ")";
    Info<< ", up to " << fwd_.maxConcurrent
        << " concurrent runs, relative step " << opts.hRel << ", "
        << (opts.difference == hearthFit::Difference::forward
            ? "forward" : "central")
        << " differences" << nl
        << "    work directory " << fwd_.workDir << nl << nl
        << "iter  cost          ";
    {
        std::ostringstream os;
        for (const auto& s : params_.specs) os << std::setw(14) << s.name << ' ';
        Info<< os.str().c_str();
    }
    Info<< "damping     elapsed_s  runs  event" << endl;
}


void Foam::fitReport::progress(const hearthFit::FitProgress& pr)
{
    const double el = elapsed();
    const int iteration = pr.iteration + state_.iterOffset;
    const bool resumedLine = state_.resume && pr.iteration == 0;
    std::ostringstream os;
    os  << std::setw(4) << iteration << "  "
        << std::setw(12) << std::setprecision(6) << pr.cost << "  ";
    for (label j = 0; j < params_.size(); ++j)
    {
        os << std::setw(14) << std::setprecision(8)
           << pr.parameters(j) << ' ';
    }
    os  << std::setw(10) << std::setprecision(3) << pr.damping << "  "
        << std::setw(9) << std::fixed << std::setprecision(1) << el
        << "  " << std::setw(4) << fwd_.runs << "  "
        << (resumedLine ? std::string("resumed") : pr.event);
    if (pr.rejected)
    {
        os << " (" << pr.rejected << " trial step"
           << (pr.rejected > 1 ? "s" : "") << " rejected)";
    }
    Info<< os.str().c_str() << endl;

    if (resumedLine) return;    // its line is already written
    progressCsv_ << iteration << ',' << pr.cost;
    for (label j = 0; j < params_.size(); ++j) progressCsv_ << ',' << pr.parameters(j);
    progressCsv_ << ',' << pr.damping << ',' << el << ',' << fwd_.runs
        << ",\"" << pr.event << '"' << std::endl;
}


void Foam::fitReport::writePosteriorDict
(
    const hearthFit::FitResult& res
) const
{
    const fileName file(fwd_.workDir/"posterior.dict");
    rm(file);

    // The parameters of a case dictionary (not the sensor offsets,
    // displacements and the fire's)
    std::vector<label> js;
    std::string left;
    for (label j = 0; j < params_.size(); ++j)
    {
        const ParameterSpec& s = params_.specs[j];
        if (s.component >= 0 || s.fireIndex >= 0 || s.group >= 0)
        {
            left += ' ' + s.name;
        }
        else
        {
            js.push_back(j);
        }
    }
    if (js.empty())
    {
        return;
    }
    for (const label j : js)
    {
        const bool ok =
            res.standardErrors.size() > j
         && std::isfinite(res.standardErrors(j))
         && res.standardErrors(j) > 0
         && res.correlation.rows() > j;
        if (!ok)
        {
            Info<< "No " << file << ": parameter " << params_.specs[j].name
                << " has no finite, positive standard error" << endl;
            return;
        }
    }

    std::ofstream os(file);
    os  << std::setprecision(17)
        << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
        << "    class       dictionary;\n    object      posterior;\n}\n"
        << "// hearthFit's posterior (first order): the fitted parameters as"
        << " written into the\n// case (value = scale x estimate, sd = |scale|"
        << " x standard error) and their\n// correlation; status "
        << hearthFit::statusName(res.status)
        << (res.converged ? " (converged)" : " (NOT converged)") << ", "
        << (res.knownSigma ? "sigma given" : "scaled by s^2") << ", s^2 "
        << res.sigma2 << ", dof " << res.dof << ".\n"
        << "// For hearthDuration: uncertainty { fitPosterior \"<this file>\"; }"
        << "\n";
    if (!left.empty())
    {
        os << "// Left out (not an entry of a case file):" << left
           << "; their uncertainty is not propagated\n";
    }
    // hearthDuration refuses the posterior of a fit that did not converge
    os << "\nconverged   " << (res.converged ? "true" : "false") << ";\n";
    os << "\nparameters\n{\n";
    for (const label j : js)
    {
        const ParameterSpec& s = params_.specs[j];
        os  << "    " << s.name << "\n    {\n"
            << "        file    \"" << s.file.c_str() << "\";\n"
            << "        entry   \"" << s.entry.c_str() << "\";\n"
            << "        value   " << s.scale*res.parameters(j) << ";\n"
            << "        sd      " << mag(s.scale)*res.standardErrors(j)
            << ";\n    }\n";
    }
    os << "}\n\n// In the order of the parameters: symmetric, unit diagonal"
       << "\ncorrelation\n(\n";
    for (const label i : js)
    {
        os << "    (";
        for (const label j : js)
        {
            // A scale < 0 flips the sign of its rows and columns
            const scalar flip =
                sign(params_.specs[i].scale)*sign(params_.specs[j].scale);
            os  << (j == js[0] ? "" : " ")
                << (
                       i == j ? 1
                     : flip*min
                       (
                           max
                           (
                               0.5*(res.correlation(i, j) + res.correlation(j, i)),
                               scalar(-1)
                           ),
                           scalar(1)
                       )
                   );
        }
        os << ")\n";
    }
    os << ");\n";
}


void Foam::fitReport::write
(
    const hearthFit::FitResult& res,
    const hearthFit::FitOptions& opts
) const
{
    // ---- Report
    std::ostringstream rep;
    rep << std::setprecision(8);
    rep << "hearthFit report" << "\n"
        << "status: " << hearthFit::statusName(res.status)
        << (res.converged ? " (converged)" : " (NOT converged)") << ": "
        << res.message << "\n"
        << "iterations " << res.iterations + state_.iterOffset
        << (state_.resume ? " (resumed)" : "") << ", forward runs " << fwd_.runs
        << " (" << fwd_.failedRuns << " failed), elapsed "
        << std::fixed << std::setprecision(1) << elapsed() << " s\n"
        << "wall time in forward runs" << (state_.resume ? " (since resumed)" : "")
        << ": " << fwd_.batchWall[0] << " s for " << fwd_.batchRuns[0]
        << " runs in batches (Jacobians, up to " << fwd_.maxConcurrent
        << " at once), " << fwd_.batchWall[1] << " s for " << fwd_.batchRuns[1]
        << " single runs (trial steps)\n";
    rep << "Jacobians " << res.finiteDifferenceJacobians << " by finite"
        << " differences and " << res.broydenJacobians << " Broyden-updated"
        << " (jacobianUpdates " << opts.jacobianUpdates << "), forward runs"
        << " reused " << fwd_.reusedRuns << ", timed out "
        << fwd_.timedOutRuns << "\n";
    rep.unsetf(std::ios::floatfield);
    rep << std::setprecision(8)
        << "cost (weighted residual sum of squares) " << res.cost
        << ", residuals " << res.residuals.size() << ", dof " << res.dof
        << ", s^2 " << res.sigma2 << "\n";
    if (res.knownSigma && res.dof > 0)
    {
        const int pc = int(std::round(100*opts.confidence));
        rep << "sigma given: intervals from it (normal quantile "
            << res.tQuantile << "), not scaled by s^2; with the right sigma"
            << " s^2 lies in [" << res.sigma2Lower << ", " << res.sigma2Upper
            << "] (" << pc << " % chi-square band, dof " << res.dof << ")\n";
        bool inside = true;
        const std::string verdict
        (
            hearthFit::chiSquareBandVerdict(res, opts.confidence, &inside)
        );
        if (!inside)
        {
            std::ostringstream w;
            w << std::setprecision(4) << "WARNING: " << verdict
              << "; the residuals say a noise of " << std::sqrt(res.sigma2)
              << " x the given sigma. The intervals assume the given"
              << " sigma\n";
            rep << w.str();
            WarningInFunction << w.str().c_str() << endl;
        }
    }
    else if (res.dof > 0)
    {
        rep << "sigma not given: intervals scaled by s^2 (t quantile "
            << res.tQuantile << ")\n";
    }
    if (res.dof > 0 && res.sigma2 == 0 && !res.knownSigma)
    {
        rep << "s^2 = 0: the model reproduces every observation exactly"
            << " (noise-free data made by the model itself?): the standard"
            << " errors are 0 and the intervals have zero width (they"
            << " measure the noise, and there is none); the correlation"
            << " matrix is that of (J^T J)^-1\n";
    }
    rep << "\n";
    const int pct = int(std::round(100*opts.confidence));
    rep << std::setprecision(10) << std::left << std::setw(12) << "parameter" << std::right
        << std::setw(18) << "estimate" << std::setw(18) << "std error"
        << std::setw(18) << ("lower " + std::to_string(pct) + "%")
        << std::setw(18) << ("upper " + std::to_string(pct) + "%")
        << std::setw(18) << "initial" << "\n";
    for (label j = 0; j < params_.size(); ++j)
    {
        auto val = [](const hearthFit::Vector& v, label j)
        {
            return v.size() > j ? v(j) : std::nan("");
        };
        rep << std::left << std::setw(12) << params_.specs[j].name.c_str()
            << std::right
            << std::setw(18) << res.parameters(j)
            << std::setw(18) << val(res.standardErrors, j)
            << std::setw(18) << val(res.lowerConfidence, j)
            << std::setw(18) << val(res.upperConfidence, j)
            << std::setw(18) << initial0_[j]
            << ((res.atBound.size() > size_t(j) && res.atBound[j])
                ? "  at bound" : "")
            << "\n";
    }
    rep << "\ncorrelation matrix\n";
    for (label i = 0; i < params_.size(); ++i)
    {
        rep << std::left << std::setw(12) << params_.specs[i].name.c_str() << std::right;
        for (label j = 0; j < params_.size(); ++j)
        {
            rep << std::setw(12) << std::setprecision(4)
                << (res.correlation.rows() > i ? res.correlation(i, j)
                                                : std::nan(""));
        }
        rep << "\n";
    }
    // (fixed scales: the fire's temperatures; the rows of the covariance,
    // regularisation rows included)
    bool fixedScale = false;
    for (const auto& q : params_.pars) fixedScale |= q.sensitivityScale > 0;
    rep << std::setprecision(6)
        << "\nsingular values of the scaled Jacobian J diag("
        << (fixedScale ? "s), s = |p| or the fixed scale of the fire's"
            " temperatures (100 K), regularisation rows included" : "|p|)")
        << ':';
    for (label j = 0; j < res.singularValues.size(); ++j)
    {
        rep << ' ' << res.singularValues(j);
    }
    identifiabilityLines
    (
        rep, res, params_,
        params_.fire ? params_.fire->regularisationRows() : 0
    );
    rep << "\n\nRMS residual per sensor [C]\n";

    // Fitted histories from the residuals at the best parameters
    std::vector<std::vector<double>> fitted
    (
        obs_.sensors.size(), std::vector<double>(obs_.times.size(), std::nan(""))
    );
    // (the prior rows, if any, follow the data rows)
    const bool haveRes =
        res.residuals.size() >= label(obs_.times.size()*obs_.sensors.size());
    forAll(obs_.sensors, si)
    {
        double ss = 0;
        for (size_t k = 0; k < obs_.times.size(); ++k)
        {
            const double m = obs_.measured.values[obs_.measCol[si]][obs_.rows[k]];
            if (haveRes)
            {
                const double r =
                    res.residuals(si*obs_.times.size() + k)
                   *obs_.sigma[si]/std::sqrt(obs_.weight[si]);
                fitted[si][k] = m + r;
                ss += r*r;
            }
        }
        rep << "    " << std::left << std::setw(12) << obs_.sensors[si].c_str()
            << std::right << std::setw(14)
            << (haveRes ? std::sqrt(ss/obs_.times.size()) : std::nan(""))
            << "\n";
    }

    Info<< nl << rep.str().c_str() << endl;
    {
        std::ofstream os(fwd_.workDir/"report.txt");
        os << rep.str();
    }
    {
        std::ofstream os(fwd_.workDir/"fitted.csv");
        os << std::setprecision(10) << "time_s";
        for (const word& s : obs_.sensors) os << ',' << s << "_measured," << s << "_fitted";
        os << "\n";
        for (size_t k = 0; k < obs_.times.size(); ++k)
        {
            os << obs_.times[k];
            forAll(obs_.sensors, si)
            {
                os << ',' << obs_.measured.values[obs_.measCol[si]][obs_.rows[k]]
                   << ',' << fitted[si][k];
            }
            os << "\n";
        }
    }
    {
        std::ofstream os(fwd_.workDir/"parameters.csv");
        os << std::setprecision(12)
           << "name,estimate,std_error,lower,upper\n";
        for (label j = 0; j < params_.size(); ++j)
        {
            os << params_.specs[j].name << ',' << res.parameters(j) << ','
               << (res.standardErrors.size() > j ? res.standardErrors(j) : std::nan("")) << ','
               << (res.lowerConfidence.size() > j ? res.lowerConfidence(j) : std::nan("")) << ','
               << (res.upperConfidence.size() > j ? res.upperConfidence(j) : std::nan(""))
               << "\n";
        }
    }
    for (const auto& g : params_.displacements)
    {
        g->write(res, fwd_.workDir, &g == &params_.displacements[0]);
    }
    writePosteriorDict(res);
    Info<< "Written " << fwd_.workDir/"report.txt" << ", "
        << fwd_.workDir/"fitted.csv" << ", " << fwd_.workDir/"parameters.csv" << ", "
        << fwd_.workDir/"progress.csv" << endl;
    if (isFile(fwd_.workDir/"posterior.dict"))
    {
        Info<< "Written " << fwd_.workDir/"posterior.dict"
            << " (for hearthDuration's uncertainty { fitPosterior ...; })"
            << endl;
    }

    // Scaled sensitivities p_j dT/dp_j [C] from the final Jacobian
    // (dr/dp with r = sqrt(w)(T - m)/sigma: dT/dp = J sigma/sqrt(w))
    const bool haveJac =
        res.jacobian.rows() >= label(obs_.times.size()*obs_.sensors.size())
     && res.jacobian.cols() == params_.size()
     && res.parameters.size() == params_.size();
    if (haveJac)
    {
        std::ofstream os(fwd_.workDir/"sensitivities.csv");
        os << std::setprecision(10) << "time_s";
        for (const word& s : obs_.sensors)
        {
            for (const auto& sp : params_.specs) os << ',' << s << '_' << sp.name;
        }
        os << "\n";
        for (size_t k = 0; k < obs_.times.size(); ++k)
        {
            os << obs_.times[k];
            forAll(obs_.sensors, si)
            {
                for (label j = 0; j < params_.size(); ++j)
                {
                    os << ','
                       << res.jacobian(si*obs_.times.size() + k, j)
                         *obs_.sigma[si]/std::sqrt(obs_.weight[si])
                         *res.parameters(j);
                }
            }
            os << "\n";
        }
        Info<< "Written " << fwd_.workDir/"sensitivities.csv" << endl;
    }
    else
    {
        WarningInFunction
            << "No final Jacobian: sensitivities.csv/png not written" << endl;
    }

    // Plots with gnuplot (fitted.png, sensitivities.png); a missing
    // gnuplot or a failing plot is a warning only
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        WarningInFunction
            << "gnuplot not found: fitted.png and sensitivities.png not"
            << " written" << endl;
    }
    else
    {
        std::ofstream gp(fwd_.workDir/"plots.gp");
        gp  << "set datafile separator ','\n"
            << "set key outside right\n"
            << "set grid\n"
            << "set xlabel 'time [h]'\n"
            << "set terminal pngcairo noenhanced size 1000,650\n"
            << "set output 'fitted.png'\n"
            << "set title 'hearthFit: measured (points) and fitted (lines)'\n"
            << "set ylabel 'T [C]'\n"
            << "plot ";
        forAll(obs_.sensors, si)
        {
            gp  << (si ? ", \\\n     " : "")
                << "'fitted.csv' every ::1 using ($1/3600):" << 2 + 2*si
                << " with points pt 7 ps 0.5 lc " << si + 1
                << " title '" << obs_.sensors[si] << " measured', "
                << "'' every ::1 using ($1/3600):" << 3 + 2*si
                << " with lines lw 2 lc " << si + 1
                << " title '" << obs_.sensors[si] << " fitted'";
        }
        gp  << "\nunset output\n";
        if (haveJac)
        {
            gp  << "set output 'sensitivities.png'\n"
                << "set title 'scaled sensitivities p_j dT/dp_j'\n"
                << "set ylabel 'p dT/dp [C]'\n"
                << "plot ";
            label col = 2;
            const char* dts[] = {"1", "2", "3", "4", "5"};
            bool first = true;
            forAll(obs_.sensors, si)
            {
                for (label j = 0; j < params_.size(); ++j, ++col)
                {
                    // Curves identically zero (the offset of another
                    // sensor) are left out of the plot (not of the CSV)
                    bool zero = true;
                    for (size_t k = 0; zero && k < obs_.times.size(); ++k)
                    {
                        zero = res.jacobian(si*obs_.times.size() + k, j) == 0;
                    }
                    if (zero) continue;
                    gp  << (!first ? ", \\\n     " : "")
                        << (!first ? "''" : "'sensitivities.csv'")
                        << " every ::1 using ($1/3600):" << col
                        << " with lines lw 2 lc " << j + 1
                        << " dt " << dts[si % 5]
                        << " title '" << obs_.sensors[si] << " "
                        << params_.specs[j].name << "'";
                    first = false;
                }
            }
            gp  << "\nunset output\n";
        }
        gp.close();
        const std::string cmd
        (
            "cd " + scratchCase::quoted(fwd_.workDir) + " && gnuplot plots.gp > plots.log 2>&1"
        );
        if (std::system(cmd.c_str()) != 0)
        {
            WarningInFunction
                << "gnuplot failed (see " << fwd_.workDir/"plots.log" << ")"
                << endl;
        }
        else
        {
            Info<< "Written " << fwd_.workDir/"fitted.png";
            if (haveJac) Info<< ", " << fwd_.workDir/"sensitivities.png";
            Info<< endl;
        }
    }
}


void Foam::fitReport::writePosterior
(
    const hearthFit::FitResult& res,
    const hearthFit::fitPosterior& post,
    const fitPredictions& preds
) const
{
    std::ostringstream rep;
    rep << std::setprecision(6);
    const label nData = obs_.size();
    const bool haveRes = res.residuals.size() >= nData;

    // Observation groups: their share of the cost and their s^2
    if (obs_.groupNames.size())
    {
        rep << "\nobservation groups: cost = sum of ((sim - meas)/sigma)^2"
            << " x weight over the group's readings, s^2 = cost/readings"
            << " (~1 if sigma is the noise)\n"
            << std::left << std::setw(14) << "group" << std::right
            << std::setw(10) << "sigma" << std::setw(10) << "readings"
            << std::setw(14) << "cost" << std::setw(12) << "s^2" << "\n";
        for (label g = -1; g < obs_.groupNames.size(); ++g)
        {
            double cost = 0, sig = 0;
            label n = 0;
            forAll(obs_.sensors, si)
            {
                if (obs_.group[si] != g) continue;
                sig = obs_.sigma[si];
                for (size_t k = 0; haveRes && k < obs_.times.size(); ++k)
                {
                    cost += sqr(res.residuals(si*obs_.times.size() + k));
                }
                n += obs_.times.size();
            }
            if (n == 0) continue;
            rep << std::left << std::setw(14)
                << (g < 0 ? word("(no group)") : obs_.groupNames[g]).c_str()
                << std::right << std::setw(10) << sig << std::setw(10) << n
                << std::setw(14) << (haveRes ? cost : std::nan(""))
                << std::setw(12) << (haveRes ? cost/n : std::nan("")) << "\n";
        }
    }

    // Priors against the posterior
    if (post.nPriors())
    {
        const hearthFit::Vector t = post.taught(res);
        rep << "\npriors (rows (p - value)/sd of the cost) and the first-order"
            << " posterior: posterior sd / prior sd = 1 the data taught"
            << " nothing, -> 0 much\n"
            << std::left << std::setw(12) << "parameter" << std::right
            << std::setw(16) << "prior value" << std::setw(16) << "prior sd"
            << std::setw(16) << "estimate" << std::setw(16) << "posterior sd"
            << std::setw(12) << "post/prior" << "\n";
        for (label j = 0; j < params_.size(); ++j)
        {
            const hearthFit::Prior& q = post.priors()[j];
            if (!q.given()) continue;
            rep << std::left << std::setw(12) << params_.specs[j].name.c_str()
                << std::right << std::setw(16) << q.mean << std::setw(16)
                << q.sd << std::setw(16) << res.parameters(j)
                << std::setw(16)
                << (res.standardErrors.size() > j
                    ? res.standardErrors(j) : std::nan(""))
                << std::setw(12) << t(j) << "\n";
        }
    }

    // Predictions with their intervals
    if (preds.size())
    {
        const hearthFit::PredictionResult pr = post.predict(res);
        rep << "\npredictions at the estimates, intervals by linear"
            << " propagation of the parameter covariance at the parameters'"
            << " confidence (method/confidence; sensitivities from the final"
            << " Jacobian's runs)\n";
        if (!pr.ok)
        {
            rep << "    not available: " << pr.message << "\n";
        }
        std::ofstream os(fwd_.workDir/"predictions.csv");
        os << std::setprecision(12) << "name,unit,value,std_error,lower,upper";
        for (const auto& s : params_.specs) os << ",d_" << s.name;
        os << "\n";
        for (label k = 0; k < preds.size(); ++k)
        {
            const fitPredictions::Spec& s = preds.specs()[k];
            auto v = [&](const hearthFit::Vector& x)
            {
                return pr.ok && x.size() > k ? x(k) : std::nan("");
            };
            rep << "    " << std::left << std::setw(14) << s.name.c_str()
                << std::right << std::setw(4) << s.unit.c_str()
                << std::setw(14) << v(pr.value) << "  std error "
                << std::setw(12) << v(pr.standardError) << "  interval ["
                << v(pr.lower) << ", " << v(pr.upper) << "]\n";
            os << s.name << ',' << s.unit << ',' << v(pr.value) << ','
               << v(pr.standardError) << ',' << v(pr.lower) << ','
               << v(pr.upper);
            for (label j = 0; j < params_.size(); ++j)
            {
                os << ',' << (pr.ok ? pr.sensitivity(k, j) : std::nan(""));
            }
            os << "\n";
        }
    }

    if (rep.str().size())
    {
        Info<< rep.str().c_str() << endl;
        std::ofstream os(fwd_.workDir/"report.txt", std::ios::app);
        os << rep.str();
    }
}


// ************************************************************************* //
