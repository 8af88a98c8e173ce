/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "sensorDisplacements.H"

#include <cmath>
#include <string>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

double hearthFit::sensorDisplacements::normalAngle
(
    const double dTdr,
    const double dTdz
)
{
    if (!(dTdr != 0 || dTdz != 0) || !std::isfinite(dTdr) || !std::isfinite(dTdz))
    {
        throw std::invalid_argument
        (
            "sensorDisplacements: zero or non-finite temperature gradient:"
            " no isotherm normal"
        );
    }
    return std::atan2(dTdz, dTdr);
}


double hearthFit::sensorDisplacements::confocalNormalAngle
(
    const double r,
    const double z,
    const double R
)
{
    if (!(R > 0) || !std::isfinite(R) || !std::isfinite(r) || !std::isfinite(z))
    {
        throw std::invalid_argument
        (
            "sensorDisplacements: confocal normals need a fire radius > 0"
            " and finite positions"
        );
    }
    const double d1 = std::hypot(r - R, z);
    const double d2 = std::hypot(r + R, z);
    if (z == 0 && std::abs(r) <= R)
    {
        throw std::invalid_argument
        (
            "sensorDisplacements: a point on the fire's disc (or its edge):"
            " no confocal ellipse through it"
        );
    }
    return std::atan2(z/d1 + z/d2, (r - R)/d1 + (r + R)/d2);
}


hearthFit::sensorDisplacements::Substitution
hearthFit::sensorDisplacements::substitution(const std::vector<double>& phi)
{
    const int n = phi.size();
    if (n < 3)
    {
        throw std::invalid_argument
        (
            "sensorDisplacements: at least 3 sensors needed (two zero-mean"
            " constraints), got " + std::to_string(n)
        );
    }
    Substitution sub;
    sub.phi = phi;
    sub.A.resize(2, n);
    for (int i = 0; i < n; ++i)
    {
        sub.A(0, i) = std::cos(phi[i]);
        sub.A(1, i) = std::sin(phi[i]);
    }
    // Null space from the full SVD: the right singular vectors beyond the
    // rank (singular values below 1e-10 of sqrt(n), the largest possible)
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(sub.A, Eigen::ComputeFullV);
    int rank = 0;
    for (int k = 0; k < svd.singularValues().size(); ++k)
    {
        if (svd.singularValues()(k) > 1e-10*std::sqrt(double(n))) ++rank;
    }
    sub.Z = svd.matrixV().rightCols(n - rank);
    return sub;
}


void hearthFit::sensorDisplacements::displace
(
    const Substitution& sub,
    const Eigen::VectorXd& q,
    const double shiftR,
    const double shiftZ,
    const std::vector<double>& r0,
    const std::vector<double>& z0,
    std::vector<double>& r,
    std::vector<double>& z
)
{
    const int n = sub.phi.size();
    if (q.size() != sub.Z.cols() || int(r0.size()) != n || int(z0.size()) != n)
    {
        throw std::invalid_argument
        (
            "sensorDisplacements: sizes differ (q " + std::to_string(q.size())
          + ", expected " + std::to_string(sub.Z.cols()) + "; positions "
          + std::to_string(r0.size()) + ", " + std::to_string(z0.size())
          + ", sensors " + std::to_string(n) + ")"
        );
    }
    const Eigen::VectorXd s = sub.Z*q;
    r.resize(n);
    z.resize(n);
    for (int i = 0; i < n; ++i)
    {
        r[i] = r0[i] + s(i)*sub.A(0, i) + shiftR;
        z[i] = z0[i] + s(i)*sub.A(1, i) + shiftZ;
    }
}


// ************************************************************************* //
