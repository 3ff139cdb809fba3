#include "core/mechanics/moment_curvature_fit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/mechanics/moment_curvature.h"

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

CurveFit FitMonotoneCurve(const std::vector<double>& curvature,
                          const std::vector<double>& moment,
                          int knots) {
  if (knots < 2 || knots > 50)
    throw std::invalid_argument("the number of knots must be 2 to 50, got " +
                                std::to_string(knots));
  // The same checks and folding as the polynomial fit; its range is ours.
  const PolynomialFit line = FitOddPolynomial(curvature, moment, 1);
  CurveFit fit;
  fit.range = line.range;
  fit.valid_to = line.valid_to;
  const int n = static_cast<int>(curvature.size());
  std::vector<double> x(n), y(n);
  for (int i = 0; i < n; ++i) {
    x[i] = std::abs(curvature[i]);
    y[i] = curvature[i] < 0 ? -moment[i] : moment[i];
  }
  const double spacing = fit.valid_to / knots;
  // A local quadratic, not a line: a line through a curved law is biased by
  // f''·(spread of the window)/2, which near K = 0 of a stiff-then-softening
  // fabric is a percent of the moment.
  for (int j = 1; j <= knots; ++j) {
    const double at = j * spacing;
    // The last knot sees data on one side only: twice the reach.
    const double window = (j == knots ? 3.0 : 1.5) * spacing;
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    int count = 0;
    for (int i = 0; i < n; ++i) {
      const double d = (x[i] - at) / window;
      const double w = 1 - std::abs(d);
      if (w <= 0) continue;
      ++count;
      const Eigen::Vector3d basis(1, d, d * d);
      normal += w * basis * basis.transpose();
      rhs += w * y[i] * basis;
    }
    const Eigen::LDLT<Eigen::Matrix3d> solve(normal);
    if (count < 3 || solve.info() != Eigen::Success || !(solve.rcond() > 1e-10))
      throw std::invalid_argument("fewer than 3 distinct points within " + std::to_string(window) +
                                  " of K = " + std::to_string(at) + "; use fewer knots");
    fit.points.push_back({at, solve.solve(rhs)(0)});
  }
  const auto law = MakeCurveLaw(fit.points);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = law->Moment(curvature[i]) - moment[i];
    sum += r * r;
  }
  fit.rms_error = std::sqrt(sum / n);
  return fit;
}

}  // namespace drape
