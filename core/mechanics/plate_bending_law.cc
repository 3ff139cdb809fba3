#include "core/mechanics/plate_bending_law.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace drape {
namespace {

using DiagonalMetric = Eigen::DiagonalMatrix<double, 3>;

void AddScaled(double s, const Eigen::Matrix3d& a, Eigen::Matrix3d& sum) {
  sum += s * a;
}
void AddScaled(double s, const DiagonalMetric& a, Eigen::Matrix3d& sum) {
  sum.diagonal() += s * a.diagonal();
}

// W(K) of a norm K = √(κᵀAκ) of the curvatures (A symmetric, positive
// semi-definite) with its derivatives in κ, added to `response`:
//   ∂W/∂κ = (M/K) Aκ,
//   ∂²W/∂κ² = (M/K) A + (dM/dK − M/K) (Aκ)(Aκ)ᵀ/K².
// M/K → dM/dK(0) as K → 0 (every law has M(0) = 0 and a continuous tangent),
// so below a round-off floor the law's initial tangent stands in for M/K and
// the second term, bounded, vanishes with K.
// `Metric` is a full Eigen::Matrix3d or, for the yarn curvatures, a diagonal
// one (a third of the products in the element's inner loop).
template <typename Metric>
void AddNormLaw(const MomentCurvatureLaw& law,
                const Metric& a,
                const Eigen::Vector3d& curvature,
                bool want_tangent,
                PlateBendingResponse& response) {
  const Eigen::Vector3d a_k = a * curvature;
  const double k = std::sqrt(std::max(0.0, curvature.dot(a_k)));
  constexpr double kRoundOff = 1e-12;  // [1/m]: fabric curvatures are ≥ 1e-3
  if (k < kRoundOff) {
    const double b0 = law.Stiffness(0.0);
    response.energy += 0.5 * b0 * k * k;
    response.moment += b0 * a_k;
    if (want_tangent) AddScaled(b0, a, response.tangent);
    return;
  }
  const MomentCurvatureLaw::Point p = law.At(k);
  const double secant = p.moment / k;
  response.energy += p.energy;
  response.moment += secant * a_k;
  if (want_tangent) {
    AddScaled(secant, a, response.tangent);
    response.tangent.noalias() += ((p.stiffness - secant) / (k * k)) * a_k * a_k.transpose();
  }
}

class IsotropicPlateLaw final : public PlateBendingLaw {
 public:
  IsotropicPlateLaw(std::shared_ptr<const MomentCurvatureLaw> law, double nu)
      : law_(std::move(law)) {
    c_ = IsotropicCurvatureMetric(nu);
  }
  void Evaluate(const Eigen::Vector3d& curvature,
                bool want_tangent,
                PlateBendingResponse& response) const override {
    response = PlateBendingResponse{};
    AddNormLaw(*law_, c_, curvature, want_tangent, response);
  }
  double LawCurvature(const Eigen::Vector3d& curvature) const override {
    return std::sqrt(std::max(0.0, curvature.dot(c_ * curvature)));
  }

 private:
  std::shared_ptr<const MomentCurvatureLaw> law_;
  Eigen::Matrix3d c_;
};

class WarpWeftPlateLaw final : public PlateBendingLaw {
 public:
  WarpWeftPlateLaw(std::shared_ptr<const MomentCurvatureLaw> warp,
                   std::shared_ptr<const MomentCurvatureLaw> weft)
      : warp_(std::move(warp)), weft_(std::move(weft)) {
    // K₁² = κ₁₁² + (2κ₁₂)²/4, K₂² = κ₂₂² + (2κ₁₂)²/4.
    warp_norm_.diagonal() << 1, 0, 0.25;
    weft_norm_.diagonal() << 0, 1, 0.25;
  }
  void Evaluate(const Eigen::Vector3d& curvature,
                bool want_tangent,
                PlateBendingResponse& response) const override {
    response = PlateBendingResponse{};
    AddNormLaw(*warp_, warp_norm_, curvature, want_tangent, response);
    AddNormLaw(*weft_, weft_norm_, curvature, want_tangent, response);
  }
  double LawCurvature(const Eigen::Vector3d& curvature) const override {
    return std::sqrt(
        std::max(curvature.dot(warp_norm_ * curvature), curvature.dot(weft_norm_ * curvature)));
  }

 private:
  std::shared_ptr<const MomentCurvatureLaw> warp_, weft_;
  DiagonalMetric warp_norm_, weft_norm_;
};

void RequireLaw(const std::shared_ptr<const MomentCurvatureLaw>& law, const char* what) {
  if (!law) throw std::invalid_argument(std::string("plate bending law: no ") + what + " law");
}

}  // namespace

Eigen::Matrix3d IsotropicCurvatureMetric(double nu) {
  Eigen::Matrix3d c;
  c << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return c / (1 - nu * nu);
}

Eigen::Matrix3d YarnCurvatureMetric(int family) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  a(family == 0 ? 0 : 1, family == 0 ? 0 : 1) = 1;
  a(2, 2) = 0.25;
  return a;
}

void AddCurvatureNormLaw(const MomentCurvatureLaw& law,
                         const Eigen::Matrix3d& metric,
                         const Eigen::Vector3d& curvature,
                         bool want_tangent,
                         PlateBendingResponse& response) {
  AddNormLaw(law, metric, curvature, want_tangent, response);
}

Eigen::Matrix3d PlateBendingLaw::InitialTangent() const {
  PlateBendingResponse response;
  Evaluate(Eigen::Vector3d::Zero(), /*want_tangent=*/true, response);
  return response.tangent;
}

std::unique_ptr<PlateBendingLaw> MakeIsotropicPlateLaw(
    std::shared_ptr<const MomentCurvatureLaw> law, double poisson_ratio) {
  RequireLaw(law, "moment-curvature");
  if (!(poisson_ratio > -1 && poisson_ratio < 1))
    throw std::invalid_argument("plate bending law: Poisson's ratio must lie in (-1, 1)");
  return std::make_unique<IsotropicPlateLaw>(std::move(law), poisson_ratio);
}

std::unique_ptr<PlateBendingLaw> MakeWarpWeftPlateLaw(
    std::shared_ptr<const MomentCurvatureLaw> warp,
    std::shared_ptr<const MomentCurvatureLaw> weft) {
  RequireLaw(warp, "warp");
  RequireLaw(weft, "weft");
  return std::make_unique<WarpWeftPlateLaw>(std::move(warp), std::move(weft));
}

}  // namespace drape
