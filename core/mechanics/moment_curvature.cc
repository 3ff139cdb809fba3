#include "core/mechanics/moment_curvature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace drape {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

[[noreturn]] void Fail(const std::string& message) {
  throw std::invalid_argument(message);
}

double Sign(double k) {
  return k < 0 ? -1.0 : 1.0;
}

// ---- linear -------------------------------------------------------------------

class LinearLaw final : public MomentCurvatureLaw {
 public:
  explicit LinearLaw(double rigidity) : b_(rigidity) {}
  double Energy(double k) const override { return 0.5 * b_ * k * k; }
  double Moment(double k) const override { return b_ * k; }
  double Stiffness(double) const override { return b_; }
  double ValidTo() const override { return kInfinity; }

 private:
  double b_;
};

// ---- polynomial ---------------------------------------------------------------

// M = sign(K) P(|K|), P(x) = Σ cₖ xᵏ (k ≥ 1), W = Q(|K|), Q(x) = Σ cₖ xᵏ⁺¹/(k+1);
// linear in |K| beyond valid_to with the tangent P'(valid_to).
class PolynomialLaw final : public MomentCurvatureLaw {
 public:
  PolynomialLaw(std::vector<double> c, double valid_to) : c_(std::move(c)), valid_to_(valid_to) {
    end_w_ = Q(valid_to_);
    end_m_ = P(valid_to_);
    end_s_ = DP(valid_to_);
  }

  double Energy(double k) const override {
    const double x = std::abs(k);
    if (x <= valid_to_) return Q(x);
    const double s = x - valid_to_;
    return end_w_ + s * (end_m_ + 0.5 * end_s_ * s);
  }
  double Moment(double k) const override {
    const double x = std::abs(k);
    if (x <= valid_to_) return Sign(k) * P(x);
    return Sign(k) * (end_m_ + end_s_ * (x - valid_to_));
  }
  double Stiffness(double k) const override {
    const double x = std::abs(k);
    return x <= valid_to_ ? DP(x) : end_s_;
  }
  Point At(double k) const override {
    const double x = std::abs(k);
    if (x > valid_to_) {
      const double s = x - valid_to_;
      return {end_w_ + s * (end_m_ + 0.5 * end_s_ * s), Sign(k) * (end_m_ + end_s_ * s), end_s_};
    }
    return {Q(x), Sign(k) * P(x), DP(x)};
  }
  double ValidTo() const override { return valid_to_; }

 private:
  // Horner forms; c_[i] multiplies x^(i+1) in P.
  double P(double x) const {
    double r = 0;
    for (auto it = c_.rbegin(); it != c_.rend(); ++it) r = r * x + *it;
    return r * x;
  }
  double DP(double x) const {
    double r = 0;
    for (std::size_t i = c_.size(); i-- > 0;) r = r * x + static_cast<double>(i + 1) * c_[i];
    return r;
  }
  double Q(double x) const {
    double r = 0;
    for (std::size_t i = c_.size(); i-- > 0;) r = r * x + c_[i] / static_cast<double>(i + 2);
    return r * x * x;
  }

  std::vector<double> c_;
  double valid_to_;
  double end_w_ = 0, end_m_ = 0, end_s_ = 0;
};

// ---- curve --------------------------------------------------------------------

// One piece of a C¹ piecewise cubic in power form about `anchor`, the end of the
// piece nearer K = 0 (so energies near the origin carry no cancellation):
// M = a + b s + c s² + d s³, s = K − anchor, W = w + ∫_anchor^K M.
struct CubicPiece {
  double anchor = 0, w = 0, a = 0, b = 0, c = 0, d = 0;
  double Moment(double s) const { return a + s * (b + s * (c + s * d)); }
  double Stiffness(double s) const { return b + s * (2 * c + 3 * d * s); }
  double Energy(double s) const { return w + s * (a + s * (b / 2 + s * (c / 3 + s * d / 4))); }
};

// Fritsch–Carlson tangents for strictly increasing x.
std::vector<double> MonotoneTangents(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), delta(n - 1), m(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    h[i] = x[i + 1] - x[i];
    delta[i] = (y[i + 1] - y[i]) / h[i];
  }
  // Ends: the one-sided secant (at K = 0 of an odd law this is also what the
  // mirrored data's three-point formula gives). Interior: the three-point
  // (parabola) derivative, zero at a local extremum of the data.
  m[0] = delta[0];
  m[n - 1] = delta[n - 2];
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (delta[i - 1] * delta[i] <= 0) {
      m[i] = 0;
    } else {
      m[i] = (h[i] * delta[i - 1] + h[i - 1] * delta[i]) / (h[i - 1] + h[i]);
    }
  }
  // Monotonicity limiter: (α, β) = (mᵢ, mᵢ₊₁)/Δᵢ inside the circle of radius 3.
  // Shrinking a tangent never takes an earlier interval out of its region.
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (delta[i] == 0) {
      m[i] = 0;
      m[i + 1] = 0;
      continue;
    }
    const double alpha = m[i] / delta[i];
    const double beta = m[i + 1] / delta[i];
    const double r2 = alpha * alpha + beta * beta;
    if (r2 > 9) {
      const double tau = 3 / std::sqrt(r2);
      m[i] = tau * alpha * delta[i];
      m[i + 1] = tau * beta * delta[i];
    }
  }
  return m;
}

class CurveLaw final : public MomentCurvatureLaw {
 public:
  // x strictly increasing and containing 0 with y = 0 there; odd: x[0] = 0 and
  // the law is evaluated as sign(K) M(|K|).
  CurveLaw(std::vector<double> x, std::vector<double> y, bool odd) : x_(std::move(x)), odd_(odd) {
    const std::size_t n = x_.size();
    const std::vector<double> m = MonotoneTangents(x_, y);
    const std::size_t zero =
        static_cast<std::size_t>(std::find(x_.begin(), x_.end(), 0.0) - x_.begin());

    // Energies at the knots, accumulated outwards from K = 0 with the exact
    // integral of each Hermite cubic: h (yᵢ + yᵢ₊₁)/2 + h² (mᵢ − mᵢ₊₁)/12.
    std::vector<double> w(n, 0.0);
    auto integral = [&](std::size_t i) {
      const double h = x_[i + 1] - x_[i];
      return h * (y[i] + y[i + 1]) / 2 + h * h * (m[i] - m[i + 1]) / 12;
    };
    for (std::size_t i = zero; i + 1 < n; ++i) w[i + 1] = w[i] + integral(i);
    for (std::size_t i = zero; i-- > 0;) w[i] = w[i + 1] - integral(i);

    // pieces_[0]: linear continuation below x₀; pieces_[i + 1]: [xᵢ, xᵢ₊₁];
    // pieces_[n]: linear continuation above xₙ₋₁.
    pieces_.resize(n + 1);
    pieces_[0] = {x_[0], w[0], y[0], m[0], 0, 0};
    pieces_[n] = {x_[n - 1], w[n - 1], y[n - 1], m[n - 1], 0, 0};
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double h = x_[i + 1] - x_[i];
      const double delta = (y[i + 1] - y[i]) / h;
      CubicPiece& p = pieces_[i + 1];
      if (x_[i] >= 0) {  // anchored at the left end
        p = {x_[i],
             w[i],
             y[i],
             m[i],
             (3 * delta - 2 * m[i] - m[i + 1]) / h,
             (m[i] + m[i + 1] - 2 * delta) / (h * h)};
      } else {  // anchored at the right end, which is ≤ 0
        p = {x_[i + 1],
             w[i + 1],
             y[i + 1],
             m[i + 1],
             (2 * m[i + 1] + m[i] - 3 * delta) / h,
             (m[i] + m[i + 1] - 2 * delta) / (h * h)};
      }
    }
    valid_to_ = odd_ ? x_.back() : std::max(-x_.front(), x_.back());
  }

  double Energy(double k) const override {
    const double x = odd_ ? std::abs(k) : k;
    const CubicPiece& p = Piece(x);
    return p.Energy(x - p.anchor);
  }
  double Moment(double k) const override {
    const double x = odd_ ? std::abs(k) : k;
    const CubicPiece& p = Piece(x);
    return (odd_ ? Sign(k) : 1.0) * p.Moment(x - p.anchor);
  }
  double Stiffness(double k) const override {
    const double x = odd_ ? std::abs(k) : k;
    const CubicPiece& p = Piece(x);
    return p.Stiffness(x - p.anchor);
  }
  Point At(double k) const override {
    const double x = odd_ ? std::abs(k) : k;
    const CubicPiece& p = Piece(x);
    const double s = x - p.anchor;
    return {p.Energy(s), (odd_ ? Sign(k) : 1.0) * p.Moment(s), p.Stiffness(s)};
  }
  double ValidTo() const override { return valid_to_; }

 private:
  const CubicPiece& Piece(double x) const {
    if (x <= x_.front()) return pieces_.front();
    if (x >= x_.back()) return pieces_.back();
    // A knot belongs to the piece anchored at it, so the data are reproduced
    // exactly: x_[i] ≤ x < x_[i + 1] for x ≥ 0, x_[i] < x ≤ x_[i + 1] for x < 0.
    const auto i = x >= 0 ? std::upper_bound(x_.begin(), x_.end(), x) - x_.begin() - 1
                          : std::lower_bound(x_.begin(), x_.end(), x) - x_.begin() - 1;
    return pieces_[static_cast<std::size_t>(i) + 1];
  }

  std::vector<double> x_;
  bool odd_;
  std::vector<CubicPiece> pieces_;
  double valid_to_ = 0;
};

// Bisection between a and b where the stiffness changes sign, to rounding.
double SignChange(const MomentCurvatureLaw& law, double a, double b) {
  const bool neg_a = law.Stiffness(a) < 0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (a + b);
    if (mid <= a || mid >= b) break;
    if ((law.Stiffness(mid) < 0) == neg_a) {
      a = mid;
    } else {
      b = mid;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

std::unique_ptr<MomentCurvatureLaw> MakeLinearLaw(double rigidity) {
  if (!std::isfinite(rigidity) || rigidity <= 0) {
    std::ostringstream os;
    os << "linear bending law: rigidity must be finite and > 0 [N·m²/m], got " << rigidity;
    Fail(os.str());
  }
  return std::make_unique<LinearLaw>(rigidity);
}

std::unique_ptr<MomentCurvatureLaw> MakePolynomialLaw(std::vector<double> coefficients,
                                                      double valid_to) {
  if (coefficients.empty()) {
    Fail("polynomial bending law: no coefficients (expected c1..cn of M = sum ck K^k)");
  }
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    if (!std::isfinite(coefficients[i])) {
      std::ostringstream os;
      os << "polynomial bending law: coefficient c" << i + 1 << " is not finite ("
         << coefficients[i] << ")";
      Fail(os.str());
    }
  }
  if (!std::isfinite(valid_to) || valid_to <= 0) {
    std::ostringstream os;
    os << "polynomial bending law: valid_to must be finite and > 0 [1/m], got " << valid_to;
    Fail(os.str());
  }
  return std::make_unique<PolynomialLaw>(std::move(coefficients), valid_to);
}

std::unique_ptr<MomentCurvatureLaw> MakeCurveLaw(std::vector<std::array<double, 2>> points) {
  if (points.size() < 2) {
    std::ostringstream os;
    os << "bending curve: need at least 2 [K, M] points, got " << points.size();
    Fail(os.str());
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i][0]) || !std::isfinite(points[i][1])) {
      std::ostringstream os;
      os << "bending curve: point " << i << " [" << points[i][0] << ", " << points[i][1]
         << "] is not finite";
      Fail(os.str());
    }
    if (i > 0 && !(points[i][0] > points[i - 1][0])) {
      std::ostringstream os;
      os << "bending curve: K must be strictly increasing, but point " << i
         << " has K = " << points[i][0] << " after K = " << points[i - 1][0];
      Fail(os.str());
    }
    if (points[i][0] == 0 && points[i][1] != 0) {
      std::ostringstream os;
      os << "bending curve: the point at K = 0 must have M = 0 (the flat state carries no "
            "moment), got M = "
         << points[i][1];
      Fail(os.str());
    }
  }
  // Data on one side of K = 0 only: an odd law built from K ≥ 0 data.
  const bool all_nonpositive = points.back()[0] <= 0;
  const bool odd = points.front()[0] >= 0 || all_nonpositive;
  if (all_nonpositive) {
    std::reverse(points.begin(), points.end());
    for (auto& p : points) p = {-p[0], -p[1]};
  }
  const auto at_or_above_zero = std::lower_bound(
      points.begin(), points.end(), 0.0, [](const auto& p, double k) { return p[0] < k; });
  if (at_or_above_zero == points.end() || (*at_or_above_zero)[0] != 0) {
    points.insert(at_or_above_zero, {0.0, 0.0});
  }
  std::vector<double> x, y;
  x.reserve(points.size());
  y.reserve(points.size());
  for (const auto& p : points) {
    x.push_back(p[0] == 0 ? 0.0 : p[0]);  // −0 → +0
    y.push_back(p[1]);
  }
  return std::make_unique<CurveLaw>(std::move(x), std::move(y), odd);
}

std::vector<std::array<double, 2>> NegativeStiffnessIntervals(const MomentCurvatureLaw& law,
                                                              int samples) {
  if (samples < 1) {
    std::ostringstream os;
    os << "NegativeStiffnessIntervals: samples must be >= 1, got " << samples;
    Fail(os.str());
  }
  const double v = law.ValidTo();
  if (!std::isfinite(v)) {
    if (law.Stiffness(0) < 0) return {{-kInfinity, kInfinity}};
    return {};
  }
  if (!(v > 0)) return {};
  auto grid = [&](int j) { return j == samples ? v : -v + 2 * v * j / samples; };
  std::vector<std::array<double, 2>> intervals;
  bool inside = false;
  double start = 0, previous = grid(0);
  for (int j = 0; j <= samples; ++j) {
    const double k = grid(j);
    const bool negative = law.Stiffness(k) < 0;
    if (negative && !inside) {
      start = j == 0 ? -v : SignChange(law, previous, k);
      inside = true;
    } else if (!negative && inside) {
      intervals.push_back({start, SignChange(law, previous, k)});
      inside = false;
    }
    previous = k;
  }
  if (inside) intervals.push_back({start, v});
  return intervals;
}

}  // namespace drape
