#include "core/mechanics/moment_curvature_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drape {

PolynomialFit FitOddPolynomial(const std::vector<double>& curvature,
                               const std::vector<double>& moment,
                               int degree) {
  if (degree < 1 || degree > 9)
    throw std::invalid_argument("the degree must be 1 to 9, got " + std::to_string(degree));
  if (curvature.size() != moment.size())
    throw std::invalid_argument("curvature and moment have different lengths");
  const int n = static_cast<int>(curvature.size());
  if (n < degree)
    throw std::invalid_argument("a degree-" + std::to_string(degree) + " fit needs at least " +
                                std::to_string(degree) + " points, got " + std::to_string(n));
  PolynomialFit fit;
  fit.range = {curvature.front(), curvature.front()};
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(curvature[i]) || !std::isfinite(moment[i]))
      throw std::invalid_argument("point " + std::to_string(i + 1) + " is not finite");
    fit.range[0] = std::min(fit.range[0], curvature[i]);
    fit.range[1] = std::max(fit.range[1], curvature[i]);
  }
  fit.valid_to = std::max(std::abs(fit.range[0]), std::abs(fit.range[1]));
  if (!(fit.valid_to > 0)) throw std::invalid_argument("every curvature is zero");

  // Columns |K|ᵏ of t = |K|/K_max in [0, 1], so the normal equations' scale
  // does not grow like K_max^(2n); cₖ = aₖ / K_maxᵏ.
  Eigen::MatrixXd a(n, degree);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    const double t = std::abs(curvature[i]) / fit.valid_to;
    const double sign = curvature[i] < 0 ? -1.0 : 1.0;
    double power = 1;
    for (int k = 0; k < degree; ++k) a(i, k) = (power *= t);
    b(i) = sign * moment[i];
  }
  const Eigen::VectorXd scaled = a.colPivHouseholderQr().solve(b);
  const Eigen::VectorXd residual = a * scaled - b;
  fit.rms_error = std::sqrt(residual.squaredNorm() / n);
  fit.coefficients.resize(degree);
  for (int k = 0; k < degree; ++k) fit.coefficients[k] = scaled(k) / std::pow(fit.valid_to, k + 1);
  return fit;
}

}  // namespace drape
