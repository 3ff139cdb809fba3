// Bending hysteresis at one Gauss point: the frictional moment is the
// gradient of its incremental potential (finite differences, stick and slip,
// isotropic and yarn norms), the committed slip is the potential's minimiser
// over the slip (a brute-force search), and a KES-FB2 cycle driven in
// curvature opens a loop 2HB wide that reverses over 2HB/k.
#include "core/mechanics/bending_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace drape {
namespace {

constexpr double kPerCm = 100.0;           // 1/m per 1/cm
constexpr double kGfCmPerCm = 9.80665e-3;  // N·m/m per gf·cm/cm

PlateBendingResponse Evaluate(const BendingFriction& friction,
                              const Eigen::Vector3d& k,
                              const ElementSlip& slip,
                              int gauss) {
  PlateBendingResponse r;
  AddBendingFriction(friction, k, slip, gauss, /*want_tangent=*/true, r);
  return r;
}

BendingFriction IsotropicFriction(double width, double nu) {
  return {{MakeFrictionFamily(IsotropicCurvatureMetric(nu), width)}};
}

BendingFriction WarpWeftFriction(double warp, double weft) {
  return {{MakeFrictionFamily(YarnCurvatureMetric(0), warp),
           MakeFrictionFamily(YarnCurvatureMetric(1), weft)}};
}

void ExpectGradientsOfThePotential(const BendingFriction& friction,
                                   const Eigen::Vector3d& k,
                                   const ElementSlip& slip,
                                   int gauss) {
  const PlateBendingResponse r = Evaluate(friction, k, slip, gauss);
  const double step = 1e-4;  // [1/m], far below the stick range's 5 1/m
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d up = k, down = k;
    up(i) += step;
    down(i) -= step;
    const PlateBendingResponse p = Evaluate(friction, up, slip, gauss);
    const PlateBendingResponse m = Evaluate(friction, down, slip, gauss);
    EXPECT_NEAR(r.moment(i), (p.energy - m.energy) / (2 * step), 1e-6 * r.moment.norm() + 1e-15)
        << "moment " << i;
    const Eigen::Vector3d column = (p.moment - m.moment) / (2 * step);
    EXPECT_LT((r.tangent.col(i) - column).norm(), 1e-5 * r.tangent.norm() + 1e-15)
        << "tangent column " << i;
  }
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-12 * r.tangent.norm());
}

TEST(BendingFriction, MomentAndTangentAreTheIncrementalPotentialsDerivatives) {
  const double width = 0.1 * kGfCmPerCm;
  ElementSlip slip = ElementSlip::Zero();
  slip.col(2) << 30, -10, 8;  // Gauss point 1, first family
  slip.col(3) << -5, 20, -4;  // Gauss point 1, second family
  for (const auto& [name, friction] :
       {std::pair{"isotropic", IsotropicFriction(width, 0.3)},
        std::pair{"warp-weft", WarpWeftFriction(width, 0.25 * width)}}) {
    SCOPED_TRACE(name);
    // Slip in every family, then stick (within 5 1/m of the slip) in all.
    ExpectGradientsOfThePotential(friction, {120, -40, 60}, slip, 1);
    ExpectGradientsOfThePotential(friction, {31, -9, 7}, slip, 1);
    ExpectGradientsOfThePotential(friction, {-80, 25, 0}, slip, 0);
  }
}

TEST(BendingFriction, TheCommittedSlipMinimisesThePotentialOverTheSlip) {
  // min over s of ½k|κ − s|² + HB|s − sₙ| (one family, warp norm, κ₁₂ = 0):
  // a brute-force search on a grid of s₁₁ against UpdateSlip.
  const double width = 0.05 * kGfCmPerCm;
  const BendingFriction friction = WarpWeftFriction(width, width);
  const FrictionFamily& f = friction.families[0];
  for (double kappa : {3.0, 4.99, 5.01, 40.0, -120.0}) {
    ElementSlip slip = ElementSlip::Zero();
    slip(0, 0) = 1.0;  // sₙ
    const Eigen::Vector3d k(kappa + 1.0, 0, 0);
    UpdateSlip(friction, k, 0, slip);
    double best = INFINITY, best_s = 0;
    for (int i = -200000; i <= 200000; ++i) {
      const double s = 1.0 + i * 1e-3;
      const double value =
          0.5 * f.stick_stiffness * std::pow(k(0) - s, 2) + f.slip_moment * std::abs(s - 1.0);
      if (value < best) best = value, best_s = s;
    }
    EXPECT_NEAR(slip(0, 0), best_s, 1e-3) << "κ − sₙ = " << kappa;
  }
}

TEST(BendingFriction, ACurvatureCycleOpensAKawabataLoopTwoHbWide) {
  // A KES-FB2 sweep 0 → 2.5 → −2.5 → 0 1/cm in 0.01 1/cm steps, each
  // accepted (slip committed), on the warp norm. Beyond the reversal range
  // the loading branch carries +HB and the unloading branch −HB.
  const double two_hb = 0.124 * kGfCmPerCm;  // Matsudaira et al.'s cotton broadcloth
  const BendingFriction friction = WarpWeftFriction(two_hb, two_hb);
  ElementSlip slip = ElementSlip::Zero();
  std::vector<double> path;
  for (int i = 0; i <= 250; ++i) path.push_back(i);
  for (int i = 249; i >= -250; --i) path.push_back(i);
  for (int i = -249; i <= 0; ++i) path.push_back(i);
  double loading_at_1 = NAN, unloading_at_1 = NAN, loading_at_minus_1 = NAN;
  double reversal_end = NAN;  // the curvature where the moment reaches −HB after the turn
  for (size_t step = 0; step < path.size(); ++step) {
    const Eigen::Vector3d k(path[step] * 0.01 * kPerCm, 0, 0);
    const double m = Evaluate(friction, k, slip, 0).moment(0);
    UpdateSlip(friction, k, 0, slip);
    // The moment at the accepted state does not move when its slip is committed.
    EXPECT_NEAR(Evaluate(friction, k, slip, 0).moment(0), m, 1e-12 * two_hb);
    const bool rising = step < 251;
    if (path[step] == 100) (rising ? loading_at_1 : unloading_at_1) = m;
    if (path[step] == -100 && std::isnan(loading_at_minus_1)) loading_at_minus_1 = m;
    if (!rising && std::isnan(reversal_end) && m <= -0.5 * two_hb * (1 - 1e-12))
      reversal_end = path[step] * 0.01 * kPerCm;
  }
  EXPECT_NEAR(loading_at_1 - unloading_at_1, two_hb, 1e-12 * two_hb);
  EXPECT_NEAR(loading_at_minus_1, -0.5 * two_hb, 1e-12 * two_hb);
  // From +HB at 2.5 1/cm to −HB takes ΔK = 2HB/k = 0.1 1/cm.
  EXPECT_NEAR(2.5 * kPerCm - reversal_end, kHysteresisReversalCurvature, 1e-9);
}

TEST(BendingFriction, ANonPositiveWidthIsRefused) {
  EXPECT_THROW(MakeFrictionFamily(YarnCurvatureMetric(0), 0.0), std::invalid_argument);
  EXPECT_THROW(MakeFrictionFamily(YarnCurvatureMetric(0), NAN), std::invalid_argument);
}

}  // namespace
}  // namespace drape
