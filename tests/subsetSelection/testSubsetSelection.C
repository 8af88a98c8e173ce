// Unit checks of src/numerics/identifiability (plain C++ + Eigen): see run.
#include "subsetSelection.H"
#include "laplaceDiffusivity.H"
#include "sensorDisplacements.H"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <functional>

namespace
{

int failures = 0;

void check(const char* what, const bool ok, const double value, const double ref)
{
    std::printf("%-66s %s (%.10g, expected %.10g)\n", what, ok ? "ok" : "FAILED", value, ref);
    if (!ok) ++failures;
}

void checkRel(const char* what, const double v, const double ref, const double tol)
{
    check(what, std::abs(v - ref) <= tol*std::abs(ref), v, ref);
}

void checkThrows(const char* what, const std::function<void()>& f)
{
    bool thrown = false;
    try { f(); } catch (const std::invalid_argument& e)
    {
        thrown = true;
        std::printf("    (%s)\n", e.what());
    }
    check(what, thrown, thrown, 1);
}

// A deterministic m x n matrix with orthonormal columns
Eigen::MatrixXd orthonormal(const int m, const int n)
{
    Eigen::MatrixXd A(m, n);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < n; ++j)
            A(i, j) = std::sin(1.3*(i + 1)*(j + 1) + 0.7*j) + 0.1*i/m;
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
    return qr.householderQ()*Eigen::MatrixXd::Identity(m, n);
}

// 1-D semi-infinite medium, T = 0 initially, surface temperature
// dT min(t/tr, 1) (Carslaw & Jaeger 1959 §2.5: surface T = t gives
// t[(1 + 2 e^2) erfc e - 2 e exp(-e^2)/sqrt(pi)], e = z/(2 sqrt(a t)))
double ramp(const double z, const double t, const double a)
{
    if (t <= 0) return 0;
    const double e = z/(2*std::sqrt(a*t));
    return t*((1 + 2*e*e)*std::erfc(e) - 2*e*std::exp(-e*e)/std::sqrt(M_PI));
}

double rampHold(const double z, const double t, const double a, const double tr)
{
    return 600*(ramp(z, t, a) - ramp(z, t - tr, a))/tr;
}

} // End anonymous namespace


int main()
{
    using namespace hearthFit;

    // ---- 1. Mansour 2015 §4.8: columns ((rho C)_s, phi, k_s) orthogonal
    // with norms 26.79, 4.86e3, 4.24e2 (her singular values attributed to
    // her parameters, Fig. 4.13): the SVD returns them, rank 3 above her
    // 1e-3, and P = [0 0 1; 1 0 0; 0 1 0] (phi > k_s > (rho C)_s)
    {
        const Eigen::MatrixXd U = orthonormal(60, 3);
        Eigen::MatrixXd J(60, 3);
        J.col(0) = 26.79*U.col(0);
        J.col(1) = 4.86e3*U.col(1);
        J.col(2) = 4.24e2*U.col(2);
        const SubsetSelection s = subsetSelection(J, 1e-3, false);
        checkRel("Mansour columns: s1 = 4.86e3", s.singularValues(0), 4.86e3, 1e-12);
        checkRel("Mansour columns: s2 = 4.24e2", s.singularValues(1), 4.24e2, 1e-12);
        checkRel("Mansour columns: s3 = 26.79", s.singularValues(2), 26.79, 1e-12);
        check("Mansour columns: rank 3 (threshold 1e-3)", s.rank == 3, s.rank, 3);
        const Eigen::MatrixXd P = permutationMatrix(s.order);
        Eigen::MatrixXd Pm(3, 3);
        Pm << 0, 0, 1,  1, 0, 0,  0, 1, 0;
        check("Mansour columns: P = [0 0 1; 1 0 0; 0 1 0] (her P)", P == Pm, (P - Pm).norm(), 0);
        checkRel("Mansour columns: |R_11| = s1 (phi alone)", s.pivotNorms(0), 4.86e3, 1e-12);
        const SubsetSelection s2 = subsetSelection(J, 100, false);
        check("Mansour columns: rank 2 above 100", s2.rank == 2, s2.rank, 2);
        check
        (
            "Mansour columns: printed algorithm (V_2^T) keeps phi, k_s",
            s2.printedOrder.size() == 2 && s2.printedOrder[0] == 1
         && s2.printedOrder[1] == 2, s2.printedOrder.size(), 2
        );
        const SubsetSelection s3 = subsetSelection(J, 0.01, true);
        check("Mansour columns: rank 2 above 1e-2 s1 (26.79/4860 = 5.5e-3)", s3.rank == 2, s3.rank, 2);
    }

    // ---- 2. A general J = U S V^T with a known rotation V: singular values
    // and singular vectors recovered to rounding
    {
        const Eigen::MatrixXd U = orthonormal(40, 3);
        const Eigen::MatrixXd V = orthonormal(3, 3);
        const Eigen::Vector3d S(100, 10, 1e-4);
        const Eigen::MatrixXd J = U*S.asDiagonal()*V.transpose();
        const SubsetSelection s = subsetSelection(J, 1e-3, false);
        for (int k = 0; k < 3; ++k)
        {
            char msg[80];
            std::snprintf(msg, sizeof msg, "rotated J: singular value %d", k + 1);
            checkRel(msg, s.singularValues(k), S(k), 1e-9);
        }
        check("rotated J: rank 2 (s3 = 1e-4 below 1e-3)", s.rank == 2, s.rank, 2);
        const double align = std::abs(s.V.col(0).dot(V.col(0)));
        checkRel("rotated J: first right singular vector", align, 1, 1e-12);
        // rank 2: the parameter left out is the one that the two kept
        // columns' span explains best: check with the printed algorithm's
        // own definition, the pivoted QR of V_2^T
        const Eigen::MatrixXd Vt = V.leftCols(2).transpose();
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Vt);
        const int last = qr.colsPermutation().indices()(2);
        check
        (
            "rotated J: printed algorithm leaves out the same parameter",
            s.printedOrder.size() == 2 && s.printedOrder[0] != last
         && s.printedOrder[1] != last, last, last
        );
    }

    // ---- 3. Exactly collinear columns: rank 2 whatever the scaling
    {
        const Eigen::MatrixXd U = orthonormal(30, 2);
        Eigen::MatrixXd J(30, 3);
        J.col(0) = 3*U.col(0);
        J.col(1) = 2*U.col(1);
        J.col(2) = J.col(0) + J.col(1);
        const SubsetSelection s = subsetSelection(J, 1e-8, true);
        check("collinear columns: rank 2", s.rank == 2, s.rank, 2);
        check("collinear columns: s3 below 1e-12 s1", s.singularValues(2) < 1e-12*s.singularValues(0), s.singularValues(2), 0);
    }

    // ---- 4. Relative sensitivities (4.46) and bad input
    {
        Eigen::MatrixXd D(2, 2);
        D << 1, 2, 3, 4;
        const Eigen::MatrixXd R =
            relativeSensitivity(D, Eigen::Vector2d(10, 100), Eigen::Vector2d(2, 5));
        checkRel("relative sensitivity J_12 = 2 x 100/2", R(0, 1), 100, 1e-15);
        checkRel("relative sensitivity J_21 = 3 x 10/5", R(1, 0), 6, 1e-15);
        checkThrows("empty J throws", [](){ subsetSelection(Eigen::MatrixXd(0, 3), 1e-3, false); });
        Eigen::MatrixXd N = Eigen::MatrixXd::Ones(3, 2);
        N(1, 1) = std::nan("");
        checkThrows("non-finite J throws", [&](){ subsetSelection(N, 1e-3, false); });
        checkThrows("threshold 0 throws", [](){ subsetSelection(Eigen::MatrixXd::Ones(3, 2), 0, false); });
        checkThrows("size mismatch throws", [&](){ relativeSensitivity(D, Eigen::Vector3d(1, 2, 3), Eigen::Vector2d(1, 1)); });
    }

    // ---- 5. Laplace-transform diffusivity (Mansour 2015 §5.2.2.2) on
    // exact 1-D histories: a fire ramping to 600 C over 10 min then held,
    // a = 1e-7 m2/s, sensors at 1 and 3 cm, readings every 10 s for 200 h
    // (p from 10/t_end = 1.4e-5 to 100/t_end: tail weight <= e^-10).
    // Exact in 1-D whatever the surface history (A(p) cancels): the error
    // is that of the linear interpolation of the readings (h^2 p^2/12 at
    // most 1e-8 here) and of the tail (exp(-10) T(t_end)/T-bar: <= 1e-4
    // for the ratio): 1e-4 allowed
    {
        const double a = 1e-7, tr = 600;
        std::vector<double> t, T1, T2;
        for (int k = 0; k <= 72000; ++k)
        {
            t.push_back(10.0*k);
            T1.push_back(rampHold(0.01, t.back(), a, tr));
            T2.push_back(rampHold(0.03, t.back(), a, tr));
        }
        const laplaceDiffusivity::Result r =
            laplaceDiffusivity::estimate(t, T1, T2, 0.01, 0.03);
        checkRel("Laplace 1-D exact: a = 1e-7", r.a, a, 1e-4);
        check("Laplace 1-D exact: 40 values of p used", r.p.size() == 40, r.p.size(), 40);
        check("Laplace 1-D exact: points on a line (misfit < 1e-4)", r.misfit < 1e-4, r.misfit, 0);
        // A transform of a constant: int_0^T e^-pt = (1 - e^-pT)/p
        const std::vector<double> tc{0, 1, 3, 7}, Tc{2, 2, 2, 2};
        checkRel("Laplace transform of a constant", laplaceDiffusivity::transform(tc, Tc, 0.3), 2*(1 - std::exp(-2.1))/0.3, 1e-13);
        // Of a linear history T = t over [0, 10], p = 1e-5 (series branch):
        // int t e^-pt = 50 - 1e3 p/3 + 1e4 p^2/8 - 1e5 p^3/30 (Taylor; the
        // closed form (1 - e^-10p (1 + 10p))/p^2 loses 8 digits here)
        const std::vector<double> tl{0, 5, 10}, Tl{0, 5, 10};
        const double p = 1e-5;
        checkRel("Laplace transform of T = t (series branch)", laplaceDiffusivity::transform(tl, Tl, p), 50 - 1e3*p/3 + 1e4*p*p/8 - 1e5*p*p*p/30, 1e-14);
        // Short record: a shallow pair at large p only
        checkThrows("Laplace: z2 <= z1 throws", [&](){ laplaceDiffusivity::estimate(t, T1, T2, 0.03, 0.01); });
        checkThrows("Laplace: times not increasing throws", [&](){ auto t2 = tc; t2[2] = 1; laplaceDiffusivity::estimate(t2, Tc, Tc, 0.01, 0.02); });
        checkThrows("Laplace: lengths differ throws", [&](){ laplaceDiffusivity::estimate(tc, Tl, Tc, 0.01, 0.02); });
    }

    // ---- 6. Constrained sensor displacements (Mansour 2015 §5.2.4):
    // 10 sensors on a layout like her experiment 13 (0.18 <= r/R <= 0.54,
    // 0.18 <= z/R <= 1.96, R = 5 cm) with the normals of the isotherms of
    // a point source at the fire's centre (grad T along (r, z)): the
    // substitution leaves n - 2 = 8 unknowns, every displacement along its
    // normal (5.19), zero mean (5.20), the shifts added (5.21); all normals
    // parallel (1-D): n - 1 unknowns
    {
        namespace sd = sensorDisplacements;
        std::vector<double> r0, z0, phi;
        for (int i = 0; i < 10; ++i)
        {
            r0.push_back(0.05*(0.18 + 0.04*i));
            z0.push_back(0.05*(0.18 + 0.1978*i));
            phi.push_back(sd::normalAngle(-r0.back(), -z0.back()) + M_PI);
        }
        const sd::Substitution sub = sd::substitution(phi);
        check("displacements: 8 free unknowns for 10 sensors", sub.Z.cols() == 8, sub.Z.cols(), 8);
        const double orth = (sub.Z.transpose()*sub.Z - Eigen::MatrixXd::Identity(8, 8)).norm();
        check("displacements: Z orthonormal", orth < 1e-13, orth, 0);
        Eigen::VectorXd q(8);
        for (int k = 0; k < 8; ++k) q(k) = 1e-3*std::cos(1.7*k + 0.3);
        std::vector<double> r, z;
        sd::displace(sub, q, 1.4e-3, 9.8e-3, r0, z0, r, z);
        double sr = 0, sz = 0, cross = 0, moved = 0;
        for (int i = 0; i < 10; ++i)
        {
            const double dr = r[i] - r0[i] - 1.4e-3, dz = z[i] - z0[i] - 9.8e-3;
            sr += dr;
            sz += dz;
            cross = std::max(cross, std::abs(dr*std::sin(phi[i]) - dz*std::cos(phi[i])));
            moved = std::max(moved, std::hypot(dr, dz));
        }
        // rounding: positions ~0.1 m carry 1.4e-17 m each, 10 of them
        check("displacements: sum dr = 0 (5.20), to rounding 1e-15", std::abs(sr) < 1e-15, sr, 0);
        check("displacements: sum dz = 0 (5.20), to rounding 1e-15", std::abs(sz) < 1e-15, sz, 0);
        check("displacements: along the normals, sin phi dr = cos phi dz (5.19)", cross < 1e-16, cross, 0);
        check("displacements: the sensors did move", moved > 1e-4, moved, 1e-3);
        checkRel("normal angle of grad T = (0, -1): -pi/2", sd::normalAngle(0, -1), -M_PI/2, 1e-15);
        const sd::Substitution sub1 = sd::substitution(std::vector<double>(6, M_PI/2));
        check("displacements: parallel normals (1-D): n - 1 = 5 unknowns", sub1.Z.cols() == 5, sub1.Z.cols(), 5);
        checkThrows("displacements: 2 sensors throw", [](){ sd::substitution({0, 1}); });
        checkThrows("displacements: zero gradient throws", [](){ sd::normalAngle(0, 0); });
        // Confocal normals (Mansour 2015 §5.2.4 (i)): the isotherms of the
        // steady temperature under a disc held at T_c on an insulated
        // half-space, T/T_c = (2/pi) asin(2R/(d1 + d2)) (the potential of
        // a charged disc), are the confocal ellipses: -grad T, by central
        // differences (h = 1e-7 m: error ~h^2 T''' ~ 1e-10 rad), has the
        // angle of confocalNormalAngle
        {
            const double R = 0.05;
            auto T = [R](const double r, const double z)
            {
                return 2/M_PI*std::asin(2*R/(std::hypot(r - R, z) + std::hypot(r + R, z)));
            };
            double worst = 0;
            const double pts[6][2] = {{0.009, -0.009}, {0.027, -0.098}, {0.07, -0.01}, {0.2, -0.25}, {0.0, -0.03}, {0.049, -0.001}};
            for (const auto& rz : pts)
            {
                const double h = 1e-7, r = rz[0], z = rz[1];
                const double gr = (T(r + h, z) - T(r - h, z))/(2*h);
                const double gz = (T(r, z + h) - T(r, z - h))/(2*h);
                const double d = std::remainder(sd::confocalNormalAngle(r, z, R) - std::atan2(-gz, -gr), 2*M_PI);
                worst = std::max(worst, std::abs(d));
            }
            check("confocal normal = -grad of the disc's steady T, 6 points, 1e-6 rad", worst < 1e-6, worst, 0);
            checkRel("confocal normal on the axis below the fire: -pi/2", sd::confocalNormalAngle(0, -0.02, R), -M_PI/2, 1e-15);
            checkThrows("confocal normal on the fire's disc throws", [R](){ sd::confocalNormalAngle(0.01, 0, R); });
            checkThrows("confocal normal with R = 0 throws", [](){ sd::confocalNormalAngle(0.01, -0.01, 0); });
        }
        checkThrows("displacements: wrong q size throws", [&](){ std::vector<double> a, b; sd::displace(sub, Eigen::VectorXd(3), 0, 0, r0, z0, a, b); });
    }

    std::printf("%d failed\n", failures);
    return failures ? 1 : 0;
}
