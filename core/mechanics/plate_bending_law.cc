#include "core/mechanics/plate_bending_law.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace drape {
namespace {

// W(K) of a norm K = √(κᵀAκ) of the curvatures (A symmetric, positive
// semi-definite) with its derivatives in κ, added to `response`:
//   ∂W/∂κ = (M/K) Aκ,
//   ∂²W/∂κ² = (M/K) A + (dM/dK − M/K) (Aκ)(Aκ)ᵀ/K².
// M/K → dM/dK(0) as K → 0 (every law has M(0) = 0 and a continuous tangent),
// so below a round-off floor the law's initial tangent stands in for M/K and
// the second term, bounded, vanishes with K.
void AddNormLaw(const MomentCurvatureLaw& law,
                const Eigen::Matrix3d& a,
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
    if (want_tangent) response.tangent += b0 * a;
    return;
  }
  const double m = law.Moment(k);
  const double secant = m / k;
  response.energy += law.Energy(k);
  response.moment += secant * a_k;
  if (want_tangent) {
    response.tangent += secant * a;
    response.tangent += ((law.Stiffness(k) - secant) / (k * k)) * a_k * a_k.transpose();
  }
}

class IsotropicPlateLaw final : public PlateBendingLaw {
 public:
  IsotropicPlateLaw(std::shared_ptr<const MomentCurvatureLaw> law, double nu)
      : law_(std::move(law)) {
    c_ << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
    c_ /= (1 - nu * nu);
  }
  void Evaluate(const Eigen::Vector3d& curvature,
                bool want_tangent,
                PlateBendingResponse& response) const override {
    response = PlateBendingResponse{};
    AddNormLaw(*law_, c_, curvature, want_tangent, response);
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
    warp_norm_ = Eigen::Vector3d(1, 0, 0.25).asDiagonal();
    weft_norm_ = Eigen::Vector3d(0, 1, 0.25).asDiagonal();
  }
  void Evaluate(const Eigen::Vector3d& curvature,
                bool want_tangent,
                PlateBendingResponse& response) const override {
    response = PlateBendingResponse{};
    AddNormLaw(*warp_, warp_norm_, curvature, want_tangent, response);
    AddNormLaw(*weft_, weft_norm_, curvature, want_tangent, response);
  }

 private:
  std::shared_ptr<const MomentCurvatureLaw> warp_, weft_;
  Eigen::Matrix3d warp_norm_, weft_norm_;
};

void RequireLaw(const std::shared_ptr<const MomentCurvatureLaw>& law, const char* what) {
  if (!law) throw std::invalid_argument(std::string("plate bending law: no ") + what + " law");
}

}  // namespace

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
