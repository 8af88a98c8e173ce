// pendularColumn1D: independent 1-D reference ("oracle") for the pendular
// evaporation model of hearthFoam (solver pendularFoam).  Standalone C++17 +
// Eigen; no OpenFOAM.
//
// ---------------------------------------------------------------------------
// Model (z downward, column 0 < z < H, SI units, T in kelvin)
// ---------------------------------------------------------------------------
//   sigma(T)   = 0.2358 tau^1.256 (1 - 0.625 tau),  tau = (647.15 - T)/647.15
//   p_wsat(T)  : Wagner & Pruss (1993)
//   K(alpha)   = -5.06 / (R_0 sqrt(alpha))                  (toroidal meniscus)
//   p_w        = p_wsat(T) exp( (M_w/rho_l) K(alpha) sigma(T) / (R T) )
//   rho_w = p_w M_w/(R T), rho_a = p_a M_a/(R T), p_g = p_a + p_w,
//   rho_g = rho_a + rho_w, omega = rho_w/rho_g
//   K_g(alpha) = C_kc ((1-alpha) phi)^3 / (1 - (1-alpha) phi)^2
//   v_g = -(K_g/mu_g) dp_g/dz,   j = -tau_s D_wa rho_g d(omega)/dz
//   F_w = rho_w v_g + j,  F_a = rho_a v_g - j
//   theta = T - T_L
//   F_E = -lambda dT/dz + F_a Cp_a theta + F_w (Cp_w theta + L)
//
//   water : d/dt[ phi (alpha rho_l + (1-alpha) rho_w) ] + dF_w/dz = 0
//   air   : d/dt[ phi (1-alpha) rho_a ]                + dF_a/dz = 0
//   energy: d/dt[ (1-phi) rho_s C_s theta + phi alpha rho_l C_l theta
//                 + phi (1-alpha) (rho_a Cp_a theta + rho_w (Cp_w theta + L)) ]
//                                                      + dF_E/dz = 0
//   top z = 0    : T = T_0(t), p_g = p_atm, p_w = p_w0(t)   (Dirichlet)
//   bottom z = H : no flux of water, air, energy
//
// ---------------------------------------------------------------------------
// Discretisation (method of lines)
// ---------------------------------------------------------------------------
//   Vertex-centred finite volumes/differences: nodes z_i = i dz, i = 0..N,
//   dz = H/N.  Node i owns the control volume V_i = dz (V_0 = V_N = dz/2, the
//   boundary half cells).  Node 0 carries the Dirichlet gas state
//   (T_0, p_a = p_atm - p_w0, p_w0); its liquid fraction does not enter any
//   flux (the face 1/2 permeability uses alpha_1) and is only used for the
//   storage of the half cell in the reported totals (alpha_0 = Kelvin-Laplace
//   inverse of (p_w0, T_0), 0 when p_w0 = 0).
//   Unknowns at nodes 1..N: T, p_a, s = ln(alpha).
//   Fluxes at half-nodes i+1/2 (central):
//     dp_g/dz, d(omega)/dz, dT/dz = two-point differences,
//     rho_w, rho_a, rho_g, theta at the face = arithmetic means,
//     K_g at the face = K_g(mean alpha)      (face 1/2: K_g(alpha_1)),
//     F_{N+1/2} = 0.
//   Semi-discrete conservation, node i = 1..N:
//     V_i dU_i/dt + F_{i+1/2} - F_{i-1/2} = 0,   U = (E, rho_air, rho_water).
//   Time integration: variable-step BDF2 applied to the conserved quantities
//     a0 V U(y_{n+1}) + a1 V U_n + a2 V U_{n-1} + h (F_{i+1/2} - F_{i-1/2}) = 0,
//     w = h_n/h_{n-1}, a0 = (1+2w)/(1+w), a1 = -(1+w), a2 = w^2/(1+w);
//   the flux through the face 1/2 is integrated by the same BDF2 formula, so
//   the discrete balances close to the Newton tolerance.  The outflow through
//   z = 0 is that through face 1/2 minus the storage change of the half cell 0.
//   Start: the initial state is at rest for t < 0, so the BDF2 history is
//   y(-h0) = y(0) (no backward-Euler start).
//   Local error: Milne device with the quadratic extrapolation predictor,
//     LTE_BDF2 = y''' h^2 (h+h')^2 / (6 (2h+h')),
//     predictor error = y''' h (h+h') (h+h'+h'') / 6,
//   controlled in the max norm with weights rtol (|y| + y_typical) on T and
//   p_a, and on the water content U_w = phi (alpha rho_l + (1-alpha) rho_w)
//   (weight rtol (|U_w| + phi alpha0 rho_l)) rather than on s = ln(alpha):
//   the vanishing of the liquid at a node is a very fast transient of s that
//   carries no mass (option waterErrorNorm=0 controls s instead).
//   Newton iterations with a finite-difference Jacobian (9 coloured residual
//   evaluations: block-tridiagonal structure), equilibrated and solved with
//   Eigen::SparseLU.
//
// Usage:
//   pendularColumn1D N=200 H=0.1 tEnd=43200 times=3600,10800,21600 out=DIR
//                    [rtol=1e-6] [any constant=value]
//   writes DIR/profile_<t>.csv and DIR/history.csv (see writeHistoryHeader).
// ---------------------------------------------------------------------------

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

using Vec = Eigen::VectorXd;

// ---------------------------------------------------------------------------
// Named constants of the closure laws
// ---------------------------------------------------------------------------
namespace law
{
    // Vargaftik surface tension of water
    constexpr double vargaftikB = 0.2358;       // N/m
    constexpr double vargaftikMu = 1.256;
    constexpr double vargaftikb = -0.625;
    constexpr double vargaftikTc = 647.15;      // K

    // Wagner & Pruss (1993) saturation pressure
    constexpr double wagnerTc = 647.096;        // K
    constexpr double wagnerPc = 22.064e6;       // Pa
    constexpr double wagnerA[6] =
        {-7.85951783, 1.84408259, -11.7866497, 22.6807411, -15.9618719,
         1.80122502};
}

// ---------------------------------------------------------------------------
// Parameters (all overridable as key=value)
// ---------------------------------------------------------------------------
struct Parameters
{
    // material / physical constants
    double phi = 0.26;          // porosity
    double rho_l = 1000;        // liquid density
    double tau_s = 0.5;         // tortuosity factor of vapour diffusion
    double D_wa = 2e-5;         // vapour-air diffusivity
    double lambda = 1.0;        // thermal conductivity
    double rho_s = 2600;        // grain density
    double C_s = 800;           // grain heat capacity
    double C_l = 4200;          // liquid heat capacity
    double Cp_a = 1005;         // air heat capacity
    double Cp_w = 1890;         // vapour heat capacity
    double L = 2.2e6;           // latent heat at T_L
    double T_L = 373.15;        // reference temperature of L
    double R = 8.31;            // gas constant
    double M_w = 0.018;         // molar mass of water
    double M_a = 0.029;         // molar mass of air
    double mu_g = 1.22e-5;      // gas viscosity
    double C_kc = 3.11e-11;     // Kozeny-Carman constant
    double R_0 = 1e-4;          // grain radius
    double p_atm = 101325;      // atmospheric pressure
    double meniscusCoeff = 5.06;// K = -meniscusCoeff/(R_0 sqrt(alpha))

    // scenario
    int N = 200;                // number of intervals
    double H = 0.1;             // column height
    double tEnd = 43200;
    double T_init = 293.15;
    double alpha0 = 0.005;      // initial liquid fraction of the pores
    double T_top = 463.15;      // top temperature after the ramp
    double tRamp = 3600;        // duration of the linear ramp of T_0
    double tDry = 3600;         // duration of the linear decay of p_w0
    double pwTopFinal = 0;      // p_w0(t >= tDry) / p_w,init
    std::vector<double> times = {3600, 10800, 21600, 32400, 43200};
    std::string out = "pendularOut";

    // numerics
    double rtol = 1e-6;         // relative local-error tolerance
    double h0 = 1e-3;           // first time step
    double hMax = 20;           // largest time step (slow late phase:
                                // local control alone lets errors pile up)
    double newtonTol = 1e-4;    // Newton: max weighted update (x rtol weights)
    int maxNewton = 12;
    int historyEvery = 1;       // write every n-th accepted step to history
    int verbose = 1;
    int waterErrorNorm = 1;     // 1: water error on U_w, 0: on s = ln(alpha)
};

// typical magnitudes (absolute parts of the error weights): T, p_a, s
constexpr double typicalT = 0.0;
constexpr double typicalPa = 1e3;
constexpr double typicalS = 1.0;

// ---------------------------------------------------------------------------
// Closure laws
// ---------------------------------------------------------------------------
double surfaceTension(double T)
{
    const double tau = (law::vargaftikTc - T)/law::vargaftikTc;
    if (tau <= 0) return 0;
    return law::vargaftikB*std::pow(tau, law::vargaftikMu)
        *(1 + law::vargaftikb*tau);
}

double saturationPressure(double T)
{
    const double th = 1 - T/law::wagnerTc;
    const double* a = law::wagnerA;
    const double sq = std::sqrt(th), th3 = th*th*th;
    const double sum = a[0]*th + a[1]*th*sq + a[2]*th3 + a[3]*th3*sq
        + a[4]*th3*th + a[5]*th3*th3*th*sq;     // th^1, 1.5, 3, 3.5, 4, 7.5
    return law::wagnerPc*std::exp(law::wagnerTc/T*sum);
}

double meniscusCurvature(double alpha, const Parameters& P)
{
    return -P.meniscusCoeff/(P.R_0*std::sqrt(alpha));
}

// Kelvin-Laplace equilibrium vapour pressure over the pendular liquid
double kelvinVapourPressure(double alpha, double T, const Parameters& P)
{
    if (alpha <= 0) return 0;
    const double exponent =
        P.M_w/P.rho_l*meniscusCurvature(alpha, P)*surfaceTension(T)/(P.R*T);
    return saturationPressure(T)*std::exp(exponent);
}

// Inverse of kelvinVapourPressure in alpha (used only for the boundary node)
double kelvinLiquidFraction(double p_w, double T, const Parameters& P)
{
    if (p_w <= 0) return 0;
    const double ratio = p_w/saturationPressure(T);
    if (ratio >= 1) return 1;
    const double x = P.M_w/P.rho_l*P.meniscusCoeff/P.R_0*surfaceTension(T)
        /(P.R*T*std::log(1/ratio));
    return std::min(1.0, x*x);
}

double gasPermeability(double alpha, const Parameters& P)
{
    const double eps = (1 - alpha)*P.phi;
    return P.C_kc*eps*eps*eps/((1 - eps)*(1 - eps));
}

// ---------------------------------------------------------------------------
// Node state and face fluxes
// ---------------------------------------------------------------------------
struct NodeState
{
    double T, p_a, p_w, alpha;
    double rho_w, rho_a, rho_g, omega, p_g, theta;
    double E, Uair, Uwater;     // conserved densities per m3 of soil
};

NodeState makeState(double T, double p_a, double p_w, double alpha,
                    const Parameters& P)
{
    NodeState n;
    n.T = T; n.p_a = p_a; n.p_w = p_w; n.alpha = alpha;
    n.rho_w = p_w*P.M_w/(P.R*T);
    n.rho_a = p_a*P.M_a/(P.R*T);
    n.rho_g = n.rho_w + n.rho_a;
    n.omega = n.rho_w/n.rho_g;
    n.p_g = p_a + p_w;
    n.theta = T - P.T_L;
    const double gas = P.phi*(1 - alpha);
    n.E = (1 - P.phi)*P.rho_s*P.C_s*n.theta
        + P.phi*alpha*P.rho_l*P.C_l*n.theta
        + gas*(n.rho_a*P.Cp_a*n.theta + n.rho_w*(P.Cp_w*n.theta + P.L));
    n.Uair = gas*n.rho_a;
    n.Uwater = P.phi*alpha*P.rho_l + gas*n.rho_w;
    return n;
}

NodeState interiorState(double T, double p_a, double s, const Parameters& P)
{
    const double alpha = std::exp(s);
    return makeState(T, p_a, kelvinVapourPressure(alpha, T, P), alpha, P);
}

double topTemperature(double t, const Parameters& P)
{
    const double f = P.tRamp > 0 ? std::min(std::max(t, 0.0)/P.tRamp, 1.0) : 1;
    return P.T_init + (P.T_top - P.T_init)*f;
}

double initialVapourPressure(const Parameters& P)
{
    return kelvinVapourPressure(P.alpha0, P.T_init, P);
}

double topVapourPressure(double t, const Parameters& P)
{
    const double f = P.tDry > 0 ? std::min(std::max(t, 0.0)/P.tDry, 1.0) : 1;
    return initialVapourPressure(P)*(1 - (1 - P.pwTopFinal)*f);
}

NodeState boundaryState(double t, const Parameters& P)
{
    const double T = topTemperature(t, P);
    const double p_w = topVapourPressure(t, P);
    return makeState(T, P.p_atm - p_w, p_w, kelvinLiquidFraction(p_w, T, P), P);
}

struct FaceFlux
{
    double E, air, water;       // energy, air and vapour mass fluxes (+z)
    double v_g;                 // Darcy velocity
};

FaceFlux faceFlux(const NodeState& a, const NodeState& b, double alphaFace,
                  double dz, const Parameters& P)
{
    FaceFlux F;
    const double Kg = gasPermeability(alphaFace, P);
    F.v_g = -Kg/P.mu_g*(b.p_g - a.p_g)/dz;
    const double rho_g = 0.5*(a.rho_g + b.rho_g);
    const double j = -P.tau_s*P.D_wa*rho_g*(b.omega - a.omega)/dz;
    F.water = 0.5*(a.rho_w + b.rho_w)*F.v_g + j;
    F.air = 0.5*(a.rho_a + b.rho_a)*F.v_g - j;
    const double theta = 0.5*(a.theta + b.theta);
    F.E = -P.lambda*(b.T - a.T)/dz + F.air*P.Cp_a*theta
        + F.water*(P.Cp_w*theta + P.L);
    return F;
}

// ---------------------------------------------------------------------------
// The column: unknown vector y = [T_i, p_a,i, s_i] for i = 1..N, and the
// equations in the same order [energy_i, air_i, water_i].
// ---------------------------------------------------------------------------
class PendularColumn
{
public:
    const Parameters& P;
    const int N;
    const double dz;
    std::vector<double> V;      // control volumes per unit area, nodes 0..N

    explicit PendularColumn(const Parameters& p)
    : P(p), N(p.N), dz(p.H/p.N), V(p.N + 1, p.H/p.N)
    {
        V[0] = V[N] = 0.5*dz;
    }

    int size() const { return 3*N; }

    static int idx(int node, int k) { return 3*(node - 1) + k; }

    std::vector<NodeState> states(const Vec& y, double t) const
    {
        std::vector<NodeState> st(N + 1);
        st[0] = boundaryState(t, P);
        for (int i = 1; i <= N; ++i)
            st[i] = interiorState(y[idx(i, 0)], y[idx(i, 1)], y[idx(i, 2)], P);
        return st;
    }

    // fluxes at faces i+1/2, i = 0..N-1 (the face N+1/2 is the wall)
    std::vector<FaceFlux> fluxes(const std::vector<NodeState>& st) const
    {
        std::vector<FaceFlux> F(N);
        for (int i = 0; i < N; ++i)
        {
            const double alphaFace =
                i == 0 ? st[1].alpha : 0.5*(st[i].alpha + st[i + 1].alpha);
            F[i] = faceFlux(st[i], st[i + 1], alphaFace, dz, P);
        }
        return F;
    }

    // V_i U_i for the unknown nodes, ordered like the equations
    Vec storage(const std::vector<NodeState>& st) const
    {
        Vec U(size());
        for (int i = 1; i <= N; ++i)
        {
            U[idx(i, 0)] = V[i]*st[i].E;
            U[idx(i, 1)] = V[i]*st[i].Uair;
            U[idx(i, 2)] = V[i]*st[i].Uwater;
        }
        return U;
    }

    // BDF2 residual G = a0 V U(y) + hist + h (F_{i+1/2} - F_{i-1/2});
    // also returns the flux through face 1/2
    Vec residual(const Vec& y, double t, double h, double a0, const Vec& hist,
                 FaceFlux* top = nullptr) const
    {
        const auto st = states(y, t);
        const auto F = fluxes(st);
        Vec G = a0*storage(st) + hist;
        for (int i = 1; i <= N; ++i)
        {
            const FaceFlux& in = F[i - 1];
            FaceFlux outF{0, 0, 0, 0};
            if (i < N) outF = F[i];
            G[idx(i, 0)] += h*(outF.E - in.E);
            G[idx(i, 1)] += h*(outF.air - in.air);
            G[idx(i, 2)] += h*(outF.water - in.water);
        }
        if (top) *top = F[0];
        return G;
    }

    // finite-difference perturbation of unknown i
    static double perturbation(const Vec& y, int i)
    {
        const double rel = 1e-7;
        switch (i % 3)
        {
            case 0: return rel*std::max(std::abs(y[i]), 100.0);
            case 1: return rel*std::max(std::abs(y[i]), typicalPa);
            default: return rel*std::max(std::abs(y[i]), 1.0);
        }
    }

    // Jacobian dG/dy by coloured finite differences: equation rows of node i
    // depend on nodes i-1, i, i+1 only, so nodes with equal (i mod 3) and the
    // same variable are perturbed together: 9 residual evaluations.
    Eigen::SparseMatrix<double> jacobian(const Vec& y, const Vec& G0, double t,
                                         double h, double a0,
                                         const Vec& hist) const
    {
        std::vector<Eigen::Triplet<double>> trip;
        trip.reserve(27*N);
        for (int colour = 0; colour < 3; ++colour)
            for (int k = 0; k < 3; ++k)
            {
                Vec yp = y;
                for (int i = 1 + colour; i <= N; i += 3)
                    yp[idx(i, k)] += perturbation(y, idx(i, k));
                const Vec Gp = residual(yp, t, h, a0, hist);
                for (int i = 1 + colour; i <= N; i += 3)
                {
                    const int col = idx(i, k);
                    const double d = yp[col] - y[col];
                    for (int m = std::max(1, i - 1); m <= std::min(N, i + 1); ++m)
                        for (int e = 0; e < 3; ++e)
                        {
                            const int row = idx(m, e);
                            trip.emplace_back(row, col, (Gp[row] - G0[row])/d);
                        }
                }
            }
        Eigen::SparseMatrix<double> J(size(), size());
        J.setFromTriplets(trip.begin(), trip.end());
        return J;
    }
};

// ---------------------------------------------------------------------------
// Diagnostics
// ---------------------------------------------------------------------------
struct Totals { double E, air, water; };

Totals columnTotals(const PendularColumn& c, const std::vector<NodeState>& st)
{
    Totals s{0, 0, 0};
    for (int i = 0; i <= c.N; ++i)
    {
        s.E += c.V[i]*st[i].E;
        s.air += c.V[i]*st[i].Uair;
        s.water += c.V[i]*st[i].Uwater;
    }
    return s;
}

double interpolateAt(const PendularColumn& c, const std::vector<NodeState>& st,
                     double z)
{
    if (z <= 0) return st[0].T;
    if (z >= c.P.H) return st[c.N].T;
    const int i = std::min(static_cast<int>(z/c.dz), c.N - 1);
    const double f = z/c.dz - i;
    return (1 - f)*st[i].T + f*st[i + 1].T;
}

// depth where alpha first (from the top) reaches alpha0/2, linear in alpha
double frontDepth(const PendularColumn& c, const std::vector<NodeState>& st)
{
    const double a = 0.5*c.P.alpha0;
    if (st[0].alpha >= a) return 0;
    for (int i = 1; i <= c.N; ++i)
        if (st[i].alpha >= a)
        {
            const double f = (a - st[i - 1].alpha)/(st[i].alpha - st[i - 1].alpha);
            return (i - 1 + f)*c.dz;
        }
    return c.P.H;
}

std::string timeLabel(double t)
{
    std::ostringstream os;
    if (std::abs(t - std::round(t)) < 1e-9*std::max(1.0, std::abs(t)))
        os << static_cast<long long>(std::llround(t));
    else
        os << std::setprecision(10) << t;
    return os.str();
}

void writeProfile(const std::string& dir, double t, const PendularColumn& c,
                  const std::vector<NodeState>& st)
{
    std::ofstream f(dir + "/profile_" + timeLabel(t) + ".csv");
    f << "z,T,p_g,p_a,p_w,rho_w,alpha,RH\n" << std::setprecision(12);
    for (int i = 0; i <= c.N; ++i)
    {
        const NodeState& n = st[i];
        f << i*c.dz << ',' << n.T << ',' << n.p_g << ',' << n.p_a << ','
          << n.p_w << ',' << n.rho_w << ',' << n.alpha << ','
          << n.p_w/saturationPressure(n.T) << '\n';
    }
}

// ---------------------------------------------------------------------------
// Command line
// ---------------------------------------------------------------------------
Parameters parseArguments(int argc, char** argv)
{
    Parameters P;
    std::map<std::string, double*> reals = {
        {"phi", &P.phi}, {"rho_l", &P.rho_l}, {"tau_s", &P.tau_s},
        {"D_wa", &P.D_wa}, {"lambda", &P.lambda}, {"rho_s", &P.rho_s},
        {"C_s", &P.C_s}, {"C_l", &P.C_l}, {"Cp_a", &P.Cp_a},
        {"Cp_w", &P.Cp_w}, {"L", &P.L}, {"T_L", &P.T_L}, {"R", &P.R},
        {"M_w", &P.M_w}, {"M_a", &P.M_a}, {"mu_g", &P.mu_g},
        {"C_kc", &P.C_kc}, {"R_0", &P.R_0}, {"p_atm", &P.p_atm},
        {"meniscusCoeff", &P.meniscusCoeff}, {"H", &P.H}, {"tEnd", &P.tEnd},
        {"T_init", &P.T_init}, {"alpha0", &P.alpha0}, {"T_top", &P.T_top},
        {"tRamp", &P.tRamp}, {"tDry", &P.tDry}, {"pwTopFinal", &P.pwTopFinal},
        {"rtol", &P.rtol}, {"h0", &P.h0}, {"hMax", &P.hMax},
        {"newtonTol", &P.newtonTol}};
    std::map<std::string, int*> ints = {
        {"N", &P.N}, {"maxNewton", &P.maxNewton},
        {"historyEvery", &P.historyEvery}, {"verbose", &P.verbose},
        {"waterErrorNorm", &P.waterErrorNorm}};
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        const auto eq = arg.find('=');
        if (arg == "-h" || arg == "--help" || eq == std::string::npos)
        {
            std::cerr << "usage: pendularColumn1D [key=value ...]\n"
                "  N H tEnd times=t1,t2,.. out=DIR rtol T_init alpha0 T_top"
                " tRamp tDry pwTopFinal\n  and any constant: phi rho_l tau_s"
                " D_wa lambda rho_s C_s C_l Cp_a Cp_w L T_L R M_w M_a mu_g"
                " C_kc R_0 p_atm meniscusCoeff\n";
            std::exit(arg == "-h" || arg == "--help" ? 0 : 1);
        }
        const std::string key = arg.substr(0, eq), val = arg.substr(eq + 1);
        if (reals.count(key)) *reals[key] = std::stod(val);
        else if (ints.count(key)) *ints[key] = std::stoi(val);
        else if (key == "out") P.out = val;
        else if (key == "times")
        {
            P.times.clear();
            std::stringstream ss(val);
            std::string item;
            while (std::getline(ss, item, ','))
                if (!item.empty()) P.times.push_back(std::stod(item));
        }
        else throw std::runtime_error("unknown parameter " + key);
    }
    std::sort(P.times.begin(), P.times.end());
    P.times.erase(std::remove_if(P.times.begin(), P.times.end(),
        [&](double t) { return t > P.tEnd || t <= 0; }), P.times.end());
    if (P.N < 3) throw std::runtime_error("N must be >= 3");
    return P;
}

// ---------------------------------------------------------------------------
// Time integration
// ---------------------------------------------------------------------------
int main(int argc, char** argv)
{
    const auto wallStart = std::chrono::steady_clock::now();
    Parameters P;
    try { P = parseArguments(argc, argv); }
    catch (const std::exception& e)
    {
        std::cerr << "pendularColumn1D: " << e.what() << '\n';
        return 1;
    }
    mkdir(P.out.c_str(), 0755);

    PendularColumn column(P);
    const int n = column.size();

    // initial state: uniform, at rest
    Vec y(n);
    const double p_wInit = initialVapourPressure(P);
    for (int i = 1; i <= P.N; ++i)
    {
        y[PendularColumn::idx(i, 0)] = P.T_init;
        y[PendularColumn::idx(i, 1)] = P.p_atm - p_wInit;
        y[PendularColumn::idx(i, 2)] = std::log(P.alpha0);
    }

    // error weights
    auto weights = [&](const Vec& a, const Vec& b)
    {
        Vec w(n);
        const double typ[3] = {typicalT, typicalPa, typicalS};
        for (int i = 0; i < n; ++i)
            w[i] = P.rtol*(std::max(std::abs(a[i]), std::abs(b[i])) + typ[i % 3]);
        return w;
    };

    // stop times: outputs, the kinks of the boundary data and tEnd
    std::vector<double> stops = P.times;
    for (double tk : {P.tRamp, P.tDry, P.tEnd})
        if (tk > 0 && tk <= P.tEnd) stops.push_back(tk);
    std::sort(stops.begin(), stops.end());
    stops.erase(std::unique(stops.begin(), stops.end()), stops.end());

    // history (t_{n-2}, t_{n-1}, t_n): at rest before t = 0
    double t = 0;
    Vec yOld = y, yOlder = y;
    double hPrev = P.h0, hPrevPrev = P.h0;
    auto st = column.states(y, t);
    Vec U = column.storage(st), UOld = U, UOlder = U;
    Eigen::Vector3d Q = Eigen::Vector3d::Zero(), QOld = Q;   // through face 1/2
    const Totals total0 = columnTotals(column, st);
    const NodeState top0 = st[0];

    std::ofstream hist(P.out + "/history.csv");
    hist << "t,water,energy,waterOut,energyOut,front,T_1cm,T_2cm,T_5cm,"
            "air,airOut,maxAbsVg,maxPgExcess\n" << std::setprecision(14);
    double maxVg = 0;
    auto topOutflow = [&](const std::vector<NodeState>& s)
    {
        // outflow through z = 0 = outflow through face 1/2 - storage change
        // of the half cell of node 0
        return Eigen::Vector3d(
            Q[0] - column.V[0]*(s[0].E - top0.E),
            Q[1] - column.V[0]*(s[0].Uair - top0.Uair),
            Q[2] - column.V[0]*(s[0].Uwater - top0.Uwater));
    };
    auto maxPgExcess = [&](const std::vector<NodeState>& s)
    {
        double m = 0;
        for (const auto& nd : s) m = std::max(m, nd.p_g - P.p_atm);
        return m;
    };
    auto writeHistory = [&](const std::vector<NodeState>& s)
    {
        const Totals tot = columnTotals(column, s);
        const Eigen::Vector3d out = topOutflow(s);
        hist << t << ',' << tot.water << ',' << tot.E << ',' << out[2] << ','
             << out[0] << ',' << frontDepth(column, s) << ','
             << interpolateAt(column, s, 0.01) << ','
             << interpolateAt(column, s, 0.02) << ','
             << interpolateAt(column, s, 0.05) << ',' << tot.air << ','
             << out[1] << ',' << maxVg << ',' << maxPgExcess(s) << '\n';
    };
    writeHistory(st);

    double h = P.h0;
    size_t nextStop = 0;
    long steps = 0, rejectedError = 0, rejectedNewton = 0, newtonIts = 0;
    double worstBalanceStep = 0;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    bool patternAnalysed = false;
    long jacobians = 0;

    while (nextStop < stops.size())
    {
        // step size: land exactly on the next stop time
        const double tStop = stops[nextStop];
        h = std::min(h, P.hMax);
        bool hitsStop = false;
        if (t + h >= tStop*(1 - 1e-12)) { h = tStop - t; hitsStop = true; }
        else if (t + 2*h > tStop) h = 0.5*(tStop - t);

        const double w = h/hPrev;
        const double a0 = (1 + 2*w)/(1 + w), a1 = -(1 + w), a2 = w*w/(1 + w);
        const Vec histU = a1*U + a2*UOld;
        const double tNew = t + h;

        // predictor: quadratic extrapolation through t_{n-2}, t_{n-1}, t_n
        const double tn = t, tn1 = t - hPrev, tn2 = t - hPrev - hPrevPrev;
        const double l0 = (tNew - tn1)*(tNew - tn2)/((tn - tn1)*(tn - tn2));
        const double l1 = (tNew - tn)*(tNew - tn2)/((tn1 - tn)*(tn1 - tn2));
        const double l2 = (tNew - tn)*(tNew - tn1)/((tn2 - tn)*(tn2 - tn1));
        const Vec yP = l0*y + l1*yOld + l2*yOlder;

        // Newton iterations
        Vec yN = yP;
        bool converged = false;
        const Vec wN = weights(y, y);
        // (the factorised Jacobian is reused while the iterations contract
        // fast: simplified Newton)
        bool haveJacobian = false;
        double dnPrev = 0;
        Vec r(n), c(n);
        for (int it = 0; it < P.maxNewton; ++it)
        {
            const Vec G = column.residual(yN, tNew, h, a0, histU);
            if (!G.allFinite()) break;
            if (!haveJacobian)
            {
                Eigen::SparseMatrix<double> J =
                    column.jacobian(yN, G, tNew, h, a0, histU);
                // equilibrate rows then columns
                r.setZero(); c.setZero();
                for (int k = 0; k < J.outerSize(); ++k)
                    for (Eigen::SparseMatrix<double>::InnerIterator e(J, k); e; ++e)
                        r[e.row()] = std::max(r[e.row()], std::abs(e.value()));
                for (int i = 0; i < n; ++i) r[i] = r[i] > 0 ? 1/r[i] : 1;
                J = r.asDiagonal()*J;
                for (int k = 0; k < J.outerSize(); ++k)
                    for (Eigen::SparseMatrix<double>::InnerIterator e(J, k); e; ++e)
                        c[e.col()] = std::max(c[e.col()], std::abs(e.value()));
                for (int i = 0; i < n; ++i) c[i] = c[i] > 0 ? 1/c[i] : 1;
                J = J*c.asDiagonal();
                if (!patternAnalysed) { lu.analyzePattern(J); patternAnalysed = true; }
                lu.factorize(J);
                if (lu.info() != Eigen::Success) break;
                haveJacobian = true;
                ++jacobians;
            }
            Vec dy = lu.solve(Vec(-r.cwiseProduct(G)));
            dy = c.cwiseProduct(dy);
            if (!dy.allFinite()) break;
            // limit large changes of T and s (robustness far from the root)
            double damp = 1;
            for (int i = 0; i < n; ++i)
            {
                const double lim = (i % 3 == 0) ? 50.0 : (i % 3 == 2 ? 5.0 : 1e30);
                if (std::abs(dy[i]) > lim) damp = std::min(damp, lim/std::abs(dy[i]));
            }
            yN += damp*dy;
            ++newtonIts;
            const double dn = (dy.cwiseQuotient(wN)).cwiseAbs().maxCoeff();
            if (damp == 1 && dn < P.newtonTol) { converged = true; break; }
            // slow contraction: refresh the Jacobian at the next iteration
            if (it > 0 && dn > 0.2*dnPrev) haveJacobian = false;
            if (it > 0 && dn > 2*dnPrev) haveJacobian = false;
            dnPrev = dn;
        }

        if (!converged)
        {
            ++rejectedNewton;
            h *= 0.25;
            if (h < 1e-10) { std::cerr << "time step collapsed at t = " << t << '\n'; return 2; }
            continue;
        }

        // local error estimate (Milne device)
        const double hp = hPrev, hpp = hPrevPrev;
        const double A = h*h*(h + hp)*(h + hp)/(6*(2*h + hp));
        const double B = h*(h + hp)*(h + hp + hpp)/6;
        const Vec wE = weights(y, yN);
        Vec diff = (yN - yP).cwiseQuotient(wE);
        Vec UN;     // V U(y_{n+1}), needed for the water-content error norm
        if (P.waterErrorNorm)
        {
            // the water error is measured on the water content U_w (kg/m3)
            // instead of s = ln(alpha): the disappearance of the liquid at a
            // node is a very fast transient in s that carries negligible mass
            UN = column.storage(column.states(yN, tNew));
            const Vec UP = l0*U + l1*UOld + l2*UOlder;
            const double typ = P.phi*P.alpha0*P.rho_l;
            for (int i = 1; i <= P.N; ++i)
            {
                const int k = PendularColumn::idx(i, 2);
                const double Un = UN[k]/column.V[i], Up = UP[k]/column.V[i];
                diff[k] = (Un - Up)/(P.rtol*(std::max(std::abs(Un),
                    std::abs(U[k]/column.V[i])) + typ));
            }
        }
        const double err = (A/(A + B))*diff.cwiseAbs().maxCoeff();
        double factor = 0.9*std::pow(std::max(err, 1e-10), -1.0/3.0);
        factor = std::min(2.0, std::max(0.2, factor));
        if (err > 1)
        {
            ++rejectedError;
            h *= std::min(factor, 0.7);
            continue;
        }

        // accept: flux through face 1/2 integrated by the same BDF2 formula
        FaceFlux top;
        const Vec G = column.residual(yN, tNew, h, a0, histU, &top);
        const Eigen::Vector3d outRate(-top.E, -top.air, -top.water);
        const Eigen::Vector3d QNew = (h*outRate - a1*Q - a2*QOld)/a0;
        worstBalanceStep = std::max(worstBalanceStep, std::abs(
            [&]{ double s = 0; for (int i = 2; i < n; i += 3) s += G[i]; return s; }()));
        QOld = Q; Q = QNew;
        yOlder = yOld; yOld = y; y = yN;
        hPrevPrev = hPrev; hPrev = h;
        t = hitsStop ? tStop : tNew;
        st = column.states(y, t);
        UOlder = UOld; UOld = U; U = column.storage(st);
        ++steps;
        h *= factor;

        maxVg = 0;
        for (const auto& f : column.fluxes(st)) maxVg = std::max(maxVg, std::abs(f.v_g));

        const bool atStop = hitsStop;
        if (atStop || steps % P.historyEvery == 0) writeHistory(st);
        if (atStop)
        {
            if (std::find(P.times.begin(), P.times.end(), tStop) != P.times.end())
            {
                writeProfile(P.out, t, column, st);
                if (P.verbose)
                    std::cerr << "t = " << t << " s  steps " << steps
                              << "  front " << frontDepth(column, st)
                              << "  T(1,2,5 cm) " << interpolateAt(column, st, 0.01)
                              << ' ' << interpolateAt(column, st, 0.02) << ' '
                              << interpolateAt(column, st, 0.05) << '\n';
            }
            ++nextStop;
        }
    }

    // final balances
    const Totals tot = columnTotals(column, st);
    const Eigen::Vector3d out = topOutflow(st);
    const double dW = tot.water - total0.water, dE = tot.E - total0.E;
    const double dA = tot.air - total0.air;
    const double wall = std::chrono::duration<double>(
        std::chrono::steady_clock::now() - wallStart).count();
    std::cout << std::setprecision(6)
        << "pendularColumn1D: N = " << P.N << ", rtol = " << P.rtol
        << ", t = " << t << " s\n"
        << "  steps " << steps << ", rejected (error) " << rejectedError
        << ", rejected (Newton) " << rejectedNewton << ", Newton iterations "
        << newtonIts << ", Jacobians " << jacobians << '\n'
        << "  water : initial " << total0.water << " kg/m2, change " << dW
        << ", out " << out[2] << ", change+out " << dW + out[2]
        << ", relative to initial " << (dW + out[2])/total0.water << '\n'
        << "  air   : initial " << total0.air << " kg/m2, change " << dA
        << ", out " << out[1] << ", change+out " << dA + out[1]
        << ", relative to initial " << (dA + out[1])/total0.air << '\n'
        << "  energy: change " << dE << " J/m2, out " << out[0]
        << ", change+out " << dE + out[0] << ", relative to |change| "
        << (dE + out[0])/std::max(std::abs(dE), 1e-300) << '\n'
        << "  largest per-step water residual sum " << worstBalanceStep
        << " kg/m2\n"
        << "  wall time " << wall << " s\n";
    return 0;
}
