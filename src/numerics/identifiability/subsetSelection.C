/*---------------------------------------------------------------------------*\
  hearthFoam: heat and water transfer in soil under a fire
\*---------------------------------------------------------------------------*/

#include "subsetSelection.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

std::vector<int> pivots(const Eigen::MatrixXd& A)
{
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    const auto& ind = qr.colsPermutation().indices();
    return std::vector<int>(ind.data(), ind.data() + ind.size());
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * //

hearthFit::SubsetSelection hearthFit::subsetSelection
(
    const Eigen::MatrixXd& J,
    const double threshold,
    const bool relative
)
{
    if (J.rows() == 0 || J.cols() == 0)
    {
        throw std::invalid_argument("subsetSelection: empty sensitivity matrix");
    }
    if (!J.allFinite())
    {
        throw std::invalid_argument
        (
            "subsetSelection: non-finite entry in the sensitivity matrix"
        );
    }
    if (!(threshold > 0) || !std::isfinite(threshold))
    {
        throw std::invalid_argument
        (
            "subsetSelection: threshold must be finite and > 0, got "
          + std::to_string(threshold)
        );
    }

    SubsetSelection s;
    const int n = J.cols();

    // 1. SVD (Mansour 2015 §4.8 step 1)
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
    s.singularValues = svd.singularValues();
    s.V = svd.matrixV();

    // 2. Numerical rank (step 2)
    const double smax = s.singularValues.size() ? s.singularValues(0) : 0;
    s.threshold = relative ? threshold*smax : threshold;
    s.rank = 0;
    for (int k = 0; k < s.singularValues.size(); ++k)
    {
        if (s.singularValues(k) > s.threshold) ++s.rank;
    }
    if (s.rank == 0)
    {
        // Nothing identifiable: no ranking
        s.pivotNorms.resize(0);
        return s;
    }

    // 3.-5. Pivoted QR of the dominant right singular vectors (steps 3-5):
    // as printed (V_rho^T) and weighted (S_rho V_rho^T, see the header)
    const Eigen::MatrixXd Vt = s.V.leftCols(s.rank).transpose();
    s.printedOrder = pivots(Vt);
    s.printedOrder.resize(s.rank);

    const Eigen::MatrixXd SVt = s.singularValues.head(s.rank).asDiagonal()*Vt;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(SVt);
    const auto& ind = qr.colsPermutation().indices();
    s.order.assign(ind.data(), ind.data() + ind.size());
    const Eigen::MatrixXd R =
        qr.matrixQR().triangularView<Eigen::Upper>();
    s.pivotNorms.resize(n);
    for (int k = 0; k < n; ++k)
    {
        s.pivotNorms(k) = k < R.rows() ? std::abs(R(k, k)) : 0;
    }
    return s;
}


Eigen::MatrixXd hearthFit::relativeSensitivity
(
    const Eigen::MatrixXd& dTdp,
    const Eigen::VectorXd& p,
    const Eigen::VectorXd& T
)
{
    if (dTdp.cols() != p.size() || dTdp.rows() != T.size())
    {
        throw std::invalid_argument
        (
            "relativeSensitivity: sizes differ (J " + std::to_string(dTdp.rows())
          + "x" + std::to_string(dTdp.cols()) + ", p "
          + std::to_string(p.size()) + ", T " + std::to_string(T.size()) + ")"
        );
    }
    if ((T.array() == 0).any())
    {
        throw std::invalid_argument("relativeSensitivity: a temperature is 0");
    }
    return T.cwiseInverse().asDiagonal()*dTdp*p.asDiagonal();
}


Eigen::MatrixXd hearthFit::permutationMatrix(const std::vector<int>& order)
{
    const int n = order.size();
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < n; ++k) P(order[k], k) = 1;
    return P;
}


// ************************************************************************* //
