#include "core/linalg/critical_modes.h"

#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drape {
namespace {

// y = (S K S)⁻¹ x = S⁻¹ K⁻¹ S⁻¹ x with the tangent's factorisation: Spectra's
// shift-solve operator at σ = 0.
class ScaledTangentInverse {
 public:
  using Scalar = double;

  ScaledTangentInverse(const FactorizedTangent& tangent, const Eigen::VectorXd& scale)
      : tangent_(tangent), scale_(scale) {}

  Eigen::Index rows() const { return scale_.size(); }
  Eigen::Index cols() const { return scale_.size(); }
  void set_shift(double sigma) {
    if (sigma != 0) throw std::logic_error("CriticalModes: only the shift 0 is factorised");
  }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
    Eigen::Map<Eigen::VectorXd> y(y_out, rows());
    y = tangent_.solve(x.cwiseQuotient(scale_)).cwiseQuotient(scale_);
  }

 private:
  const FactorizedTangent& tangent_;
  const Eigen::VectorXd& scale_;
};

}  // namespace

std::vector<CriticalMode> CriticalModes(const FactorizedTangent& tangent, int count) {
  const Eigen::VectorXd& diagonal = tangent.diagonal;
  const int n = static_cast<int>(diagonal.size());
  count = std::clamp(count, 1, std::max(1, n - 2));
  Eigen::VectorXd scale(n);
  for (int i = 0; i < n; ++i) {
    const double d = std::abs(diagonal(i));
    scale(i) = d > 0 ? 1 / std::sqrt(d) : 1.0;
  }
  ScaledTangentInverse op(tangent, scale);
  // Shift-invert at 0 turns each eigenvalue μ into ν = 1/μ: the negative μ
  // nearest zero are the most negative ν, the lower end of the spectrum,
  // whatever crowd of small positive μ (huge ν) there is.
  const int ncv = std::min(n, std::max(2 * count + 1, 20));
  Spectra::SymEigsShiftSolver<ScaledTangentInverse> eigs(op, count, ncv, 0.0);
  eigs.init();
  eigs.compute(Spectra::SortRule::SmallestAlge, 1000, 1e-8);
  if (eigs.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error("CriticalModes: the Lanczos iteration for the " +
                             std::to_string(count) +
                             " negative eigenvalue(s) nearest zero did not converge");
  const Eigen::VectorXd values = eigs.eigenvalues();
  const Eigen::MatrixXd vectors = eigs.eigenvectors();
  std::vector<CriticalMode> modes;
  for (int k = 0; k < values.size(); ++k)
    if (values(k) < 0) modes.push_back({values(k), scale.cwiseProduct(vectors.col(k))});
  std::sort(modes.begin(), modes.end(), [](const CriticalMode& a, const CriticalMode& b) {
    return a.eigenvalue > b.eigenvalue;  // nearest zero first
  });
  return modes;
}

}  // namespace drape
