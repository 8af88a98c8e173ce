/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "fitDisplacements.H"
#include "fitParameters.H"
#include "checkedRead.H"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

hearthFit::sensorDisplacements::Substitution
Foam::fitDisplacements::substitution(const std::vector<double>& phi) const
{
    try
    {
        return hearthFit::sensorDisplacements::substitution(phi);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(dict_)
            << "parameter " << name_ << ": " << e.what()
            << exit(FatalIOError);
    }
    return hearthFit::sensorDisplacements::Substitution();
}


void Foam::fitDisplacements::unknowns
(
    const hearthFit::Vector& p,
    Eigen::VectorXd& q,
    double& shiftR,
    double& shiftZ
) const
{
    q.resize(nFree_);
    for (label k = 0; k < nFree_; ++k) q(k) = p(first_ + k);
    label j = first_ + nFree_;
    shiftR = shiftR_ ? p(j++) : 0;
    shiftZ = shiftZ_ ? p(j) : 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fitDisplacements::fitDisplacements
(
    const word& name,
    const dictionary& dict,
    const label group,
    fitParameters& params
)
:
    dict_(dict),
    name_(name),
    normal_(Normal::confocal),
    fireRadius_(0),
    fireCentre_(Zero),
    shiftR_(false),
    shiftZ_(false),
    first_(params.size()),
    nFree_(0)
{
    checkedRead::checkKeywords
    (
        dict,
        wordList
        ({
            "sensors", "normal", "fireRadius", "fireCentre", "angles",
            "shift", "max", "typical"
        }),
        "parameter " + name + " (sensor displacements)"
    );
    sensors_ = dict.get<wordList>("sensors");
    const label n = sensors_.size();
    if (n < 3)
    {
        FatalIOErrorInFunction(dict)
            << "parameter " << name << ": sensors: " << n << " given, at"
            << " least 3 needed (two zero-mean constraints, Mansour 2015"
            << " §5.2.4 (5.20))" << exit(FatalIOError);
    }
    for (label i = 0; i < n; ++i)
    {
        for (label k = 0; k < i; ++k)
        {
            if (sensors_[i] == sensors_[k])
            {
                FatalIOErrorInFunction(dict)
                    << "parameter " << name << ": sensors: " << sensors_[i]
                    << " listed twice" << exit(FatalIOError);
            }
        }
    }

    const word normal(dict.get<word>("normal"));
    if (normal == "confocal")
    {
        normal_ = Normal::confocal;
        fireRadius_ =
            checkedRead::get
            (
                dict, "fireRadius", dimLength, checkedRead::positive()
            ).value();
        fireCentre_ = dict.getOrDefault<vector>("fireCentre", Zero);
        if (dict.found("angles"))
        {
            FatalIOErrorInFunction(dict)
                << "parameter " << name << ": angles: only with normal"
                << " angles" << exit(FatalIOError);
        }
    }
    else if (normal == "angles")
    {
        normal_ = Normal::angles;
        if (dict.found("fireRadius") || dict.found("fireCentre"))
        {
            FatalIOErrorInFunction(dict)
                << "parameter " << name << ": fireRadius, fireCentre: only"
                << " with normal confocal" << exit(FatalIOError);
        }
        const scalarList deg(dict.get<scalarList>("angles"));
        if (deg.size() != n)
        {
            FatalIOErrorInFunction(dict)
                << "parameter " << name << ": angles: " << deg.size()
                << " given, one per sensor needed (" << n << ")"
                << exit(FatalIOError);
        }
        for (const scalar a : deg)
        {
            if (!std::isfinite(a) || a < -360 || a > 360)
            {
                FatalIOErrorInFunction(dict)
                    << "parameter " << name << ": angles: " << a
                    << ": valid range [-360, 360] degrees"
                    << exit(FatalIOError);
            }
            angles_.push_back(a*M_PI/180);
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "parameter " << name << ": normal " << normal
            << ": valid choices: confocal angles" << exit(FatalIOError);
    }

    for (const word& c : dict.getOrDefault<wordList>("shift", wordList()))
    {
        bool& flag = c == "r" ? shiftR_ : shiftZ_;
        if ((c != "r" && c != "z") || flag)
        {
            FatalIOErrorInFunction(dict)
                << "parameter " << name << ": shift: component " << c
                << (flag ? " twice" : "") << ": valid are r, z (each once)"
                << exit(FatalIOError);
        }
        flag = true;
    }

    const scalar maxD =
        checkedRead::get(dict, "max", dimLength, checkedRead::positive())
       .value();
    const scalar typical =
        checkedRead::getOrDefault
        (
            dict, "typical", dimLength, 1e-3, checkedRead::positive()
        ).value();

    // The number of free unknowns: n - rank(A), A = [cos phi; sin phi];
    // confocal normals are parallel only for sensors all on the axis,
    // refused in setSensors (rank 2 taken here)
    nFree_ =
        normal_ == Normal::angles
      ? label(substitution(angles_).Z.cols())
      : n - 2;

    auto add = [&](const word& pname)
    {
        ParameterSpec s;
        s.name = pname;
        s.group = group;
        hearthFit::FitParameter p;
        p.name = pname;
        p.initial = 0;
        p.lower = -maxD;
        p.upper = maxD;
        p.typical = typical;
        params.specs.push_back(s);
        params.pars.push_back(p);
        params.initialFactor.push_back(0);
    };
    for (label k = 0; k < nFree_; ++k)
    {
        add(name + "_q" + Foam::name(k + 1));
    }
    if (shiftR_) add(name + "_shift_r");
    if (shiftZ_) add(name + "_shift_z");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fitDisplacements::setSensors(const SensorFile& sf)
{
    const label n = sensors_.size();
    lines_.clear();
    r0_.clear();
    z0_.clear();
    er_.clear();
    std::vector<double> phi;
    for (label i = 0; i < n; ++i)
    {
        const auto it =
            std::find
            (
                sf.names.begin(), sf.names.end(), std::string(sensors_[i])
            );
        if (it == sf.names.end())
        {
            FatalIOErrorInFunction(dict_)
                << "parameter " << name_ << ": sensor " << sensors_[i]
                << " is not in the sensors file " << sf.rel
                << exit(FatalIOError);
        }
        const size_t li = it - sf.names.begin();
        const std::array<double, 3>& x = sf.xyz[li];
        const double dx = x[0] - fireCentre_.x();
        const double dy = x[1] - fireCentre_.y();
        const double r = std::hypot(dx, dy);
        const double z = x[2] - fireCentre_.z();
        lines_.push_back(li);
        r0_.push_back(r);
        z0_.push_back(z);
        er_.push_back
        (
            r > 0 ? std::array<double, 2>{{dx/r, dy/r}}
                  : std::array<double, 2>{{1, 0}}
        );
        if (normal_ == Normal::confocal)
        {
            try
            {
                phi.push_back
                (
                    hearthFit::sensorDisplacements::confocalNormalAngle
                    (
                        r, z, fireRadius_
                    )
                );
            }
            catch (const std::exception& e)
            {
                FatalIOErrorInFunction(dict_)
                    << "parameter " << name_ << ": sensor " << sensors_[i]
                    << " at (r, z) = (" << r << ", " << z << ") from"
                    << " fireCentre: " << e.what() << exit(FatalIOError);
            }
        }
        else
        {
            phi.push_back(angles_[i]);
        }
        // On the axis no radial direction: only an axial normal and no
        // shift along r (r = 0 exactly: confocal gives +-pi/2, whose
        // cosine 6e-17 moves it by round-off)
        if (r == 0 && (shiftR_ || std::abs(std::cos(phi.back())) > 1e-12))
        {
            FatalIOErrorInFunction(dict_)
                << "parameter " << name_ << ": sensor " << sensors_[i]
                << " lies on the axis (r = 0): it has no radial direction,"
                << " so its normal must be along z (angle +-90) and the"
                << " group may not shift along r" << exit(FatalIOError);
        }
    }
    sub_ = substitution(phi);
    if (sub_.Z.cols() != nFree_)
    {
        FatalIOErrorInFunction(dict_)
            << "parameter " << name_ << ": the confocal normals of the"
            << " sensors are all parallel (all on the axis): the two"
            << " zero-mean constraints are one; give normal angles"
            << exit(FatalIOError);
    }
}


void Foam::fitDisplacements::move
(
    const hearthFit::Vector& p,
    std::vector<std::array<double, 3>>& xyz
) const
{
    Eigen::VectorXd q;
    double shiftR, shiftZ;
    unknowns(p, q, shiftR, shiftZ);
    std::vector<double> r, z;
    hearthFit::sensorDisplacements::displace
    (
        sub_, q, shiftR, shiftZ, r0_, z0_, r, z
    );
    forAll(sensors_, i)
    {
        std::array<double, 3>& x = xyz[lines_[i]];
        x[0] = fireCentre_.x() + r[i]*er_[i][0];
        x[1] = fireCentre_.y() + r[i]*er_[i][1];
        x[2] = fireCentre_.z() + z[i];
    }
}


void Foam::fitDisplacements::write
(
    const hearthFit::FitResult& res,
    const fileName& workDir,
    const bool first
) const
{
    const label n = sensors_.size();
    Eigen::VectorXd q;
    double shiftR, shiftZ;
    unknowns(res.parameters, q, shiftR, shiftZ);
    const Eigen::VectorXd s = sub_.Z*q;

    // The covariance of s = Z q: Z C_q Z^T (NaN without statistics)
    const bool haveCov =
        res.covariance.rows() == res.parameters.size()
     && res.covariance.cols() == res.parameters.size();
    Eigen::VectorXd sd = Eigen::VectorXd::Constant(n, std::nan(""));
    if (haveCov)
    {
        const Eigen::MatrixXd Cq =
            res.covariance.block(first_, first_, nFree_, nFree_);
        sd = (sub_.Z*Cq*sub_.Z.transpose()).diagonal().cwiseSqrt();
    }
    const double t = haveCov ? res.tQuantile : std::nan("");

    std::ostringstream rep;
    rep << std::setprecision(4)
        << "Sensor displacements " << name_ << " (Mansour 2015 §5.2.4):"
        << " s along the isotherm normal [mm], interval +- "
        << t << " se\n"
        << "    sensor     phi[deg]          s       se      lower"
        << "      upper       dr       dz\n";
    double sumR = 0, sumZ = 0, meanR = 0, meanZ = 0;
    std::vector<double> dr(n), dz(n);
    for (label i = 0; i < n; ++i)
    {
        dr[i] = s(i)*sub_.A(0, i);
        dz[i] = s(i)*sub_.A(1, i);
        sumR += dr[i];
        sumZ += dz[i];
        rep << "    " << std::left << std::setw(10) << sensors_[i].c_str()
            << std::right << std::fixed << std::setprecision(3)
            << std::setw(9) << sub_.phi[i]*180/M_PI
            << std::setw(11) << 1e3*s(i) << std::setw(9) << 1e3*sd(i)
            << std::setw(11) << 1e3*(s(i) - t*sd(i))
            << std::setw(11) << 1e3*(s(i) + t*sd(i))
            << std::setw(9) << 1e3*dr[i] << std::setw(9) << 1e3*dz[i]
            << "\n" << std::defaultfloat;
    }
    meanR = sumR/n;
    meanZ = sumZ/n;
    double varR = 0, varZ = 0;
    for (label i = 0; i < n; ++i)
    {
        varR += (dr[i] - meanR)*(dr[i] - meanR);
        varZ += (dz[i] - meanZ)*(dz[i] - meanZ);
    }
    rep << std::setprecision(4)
        << "    sum dr = " << sumR << " m, sum dz = " << sumZ
        << " m (5.20: zero to round-off)\n"
        << "    std over the sensors: dr " << 1e3*std::sqrt(varR/n)
        << " mm, dz " << 1e3*std::sqrt(varZ/n) << " mm; shift r "
        << 1e3*shiftR << " mm, shift z " << 1e3*shiftZ << " mm"
        << (shiftR_ || shiftZ_ ? "" : " (not fitted)") << "\n";
    Info<< nl << rep.str().c_str() << endl;

    std::ofstream os
    (
        workDir/"displacements.csv",
        first ? std::ios::out : std::ios::app
    );
    os << std::setprecision(17);
    if (first)
    {
        os << "group,sensor,r0,z0,phi_deg,s,s_se,s_lower,s_upper,dr,dz,"
           << "shift_r,shift_z,x,y,z\n";
    }
    std::vector<std::array<double, 3>> xyz(n);
    for (label i = 0; i < n; ++i)
    {
        const double r = r0_[i] + dr[i] + shiftR;
        os << name_ << ',' << sensors_[i] << ',' << r0_[i] << ',' << z0_[i]
           << ',' << sub_.phi[i]*180/M_PI << ',' << s(i) << ',' << sd(i)
           << ',' << s(i) - t*sd(i) << ',' << s(i) + t*sd(i) << ','
           << dr[i] << ',' << dz[i] << ',' << shiftR << ',' << shiftZ << ','
           << fireCentre_.x() + r*er_[i][0] << ','
           << fireCentre_.y() + r*er_[i][1] << ','
           << fireCentre_.z() + z0_[i] + dz[i] + shiftZ << "\n";
    }
    if (first)
    {
        Info<< "Written " << workDir/"displacements.csv" << endl;
    }
}


// ************************************************************************* //
