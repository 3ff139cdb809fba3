// The plate bending laws: derivatives against finite differences (inside,
// across and beyond the valid range, and near κ = 0 where M/K is a limit),
// the strip they reduce to, the linear plate they contain, and objectivity.
#include "core/mechanics/plate_bending_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/mechanics/moment_curvature.h"

namespace drape {
namespace {

constexpr double kGfCmPerCm = 9.80665e-3;  // N·m/m per gf·cm/cm
constexpr double kPerCm = 100.0;           // 1/m per 1/cm
constexpr double kCottonValidTo = 2.5 * kPerCm;

// The paper's cotton twill law (Eischen, Deng & Clapp 1996), SI.
std::shared_ptr<const MomentCurvatureLaw> Cotton() {
  const double paper[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  std::vector<double> c;
  for (int k = 0; k < 5; ++k) c.push_back(paper[k] * kGfCmPerCm * std::pow(kPerCm, -(k + 1.0)));
  return MakePolynomialLaw(c, kCottonValidTo);
}

// A saturating measured curve (M = M∞ tanh(K/K₀)), sampled at 8 points.
std::shared_ptr<const MomentCurvatureLaw> SaturatingCurve() {
  std::vector<std::array<double, 2>> points;
  for (int i = 1; i <= 8; ++i) {
    const double k = 40.0 * i;
    points.push_back({k, 2e-2 * std::tanh(k / 150.0)});
  }
  return MakeCurveLaw(points);
}

PlateBendingResponse Evaluate(const PlateBendingLaw& law, const Eigen::Vector3d& k) {
  PlateBendingResponse r;
  law.Evaluate(k, /*want_tangent=*/true, r);
  return r;
}

// Central differences of W for m and of m for the tangent, fourth order.
void ExpectDerivativesMatchFiniteDifferences(const PlateBendingLaw& law,
                                             const Eigen::Vector3d& k,
                                             double step,
                                             double tolerance) {
  const PlateBendingResponse r = Evaluate(law, k);
  Eigen::Vector3d m_fd;
  Eigen::Matrix3d t_fd;
  for (int i = 0; i < 3; ++i) {
    auto at = [&](double s) {
      Eigen::Vector3d q = k;
      q(i) += s * step;
      return Evaluate(law, q);
    };
    const auto p2 = at(2), p1 = at(1), m1 = at(-1), m2 = at(-2);
    m_fd(i) = (-p2.energy + 8 * p1.energy - 8 * m1.energy + m2.energy) / (12 * step);
    t_fd.col(i) = (-p2.moment + 8 * p1.moment - 8 * m1.moment + m2.moment) / (12 * step);
  }
  EXPECT_LT((m_fd - r.moment).norm(), tolerance * r.moment.norm())
      << "κ = " << k.transpose() << "\n m = " << r.moment.transpose()
      << "\n fd = " << m_fd.transpose();
  EXPECT_LT((t_fd - r.tangent).norm(), tolerance * r.tangent.norm())
      << "κ = " << k.transpose() << "\n tangent =\n"
      << r.tangent << "\n fd =\n"
      << t_fd;
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-15 * r.tangent.norm());
}

// Curvatures whose equivalent K lies at `k_norm` in a random direction.
std::vector<Eigen::Vector3d> Directions() {
  return {Eigen::Vector3d(1, 0, 0),
          Eigen::Vector3d(0, 1, 0),
          Eigen::Vector3d(0, 0, 1),
          Eigen::Vector3d(0.6, -0.3, 0.5),
          Eigen::Vector3d(-0.2, 0.9, -0.7),
          Eigen::Vector3d(1, 1, 0)};
}

TEST(PlateBendingLaw, IsotropicCottonDerivativesMatchFiniteDifferences) {
  const auto plate = MakeIsotropicPlateLaw(Cotton(), 0.3);
  // Inside the range, just below and above its end (the law changes from
  // polynomial to end tangent there: C² only at the moment, C¹ at the
  // tangent), and far beyond.
  for (double size : {0.3, 1.0, 2.0, 2.45, 2.55, 4.0, 10.0})
    for (const Eigen::Vector3d& d : Directions()) {
      const Eigen::Vector3d k = size * kPerCm * d.normalized();
      ExpectDerivativesMatchFiniteDifferences(*plate, k, 1e-3, 1e-7);
    }
}

TEST(PlateBendingLaw, WarpWeftDerivativesMatchFiniteDifferences) {
  const auto plate = MakeWarpWeftPlateLaw(Cotton(), SaturatingCurve());
  for (double size : {0.3, 1.5, 2.55, 4.0})
    for (const Eigen::Vector3d& d : Directions()) {
      const Eigen::Vector3d k = size * kPerCm * d.normalized();
      // A small step: along a pure weft bend K₁ = 0, where the cotton's
      // c₂K|K| term makes the moment's second derivative jump, and a
      // difference across that kink errs by ~c₂ × step.
      ExpectDerivativesMatchFiniteDifferences(*plate, k, 1e-5, 1e-6);
    }
}

TEST(PlateBendingLaw, TangentIsContinuousThroughTheFlatState) {
  // M/K is a limit at K = 0: the law must not jump there.
  const auto plate = MakeIsotropicPlateLaw(Cotton(), 0.3);
  const Eigen::Matrix3d t0 = plate->InitialTangent();
  for (double size : {1e-14, 1e-9, 1e-6})
    for (const Eigen::Vector3d& d : Directions()) {
      const PlateBendingResponse r = Evaluate(*plate, size * d.normalized());
      // The cotton tangent changes as 2 c₂/c₁ |K| ≈ 3.3e-2 m × K.
      EXPECT_LT((r.tangent - t0).norm(), 0.05 * size * t0.norm() + 1e-12 * t0.norm())
          << "K = " << size;
      EXPECT_NEAR(r.energy,
                  0.5 * d.normalized().dot(t0 * d.normalized()) * size * size,
                  1e-6 * r.energy + 1e-300);
    }
}

TEST(PlateBendingLaw, LinearLawIsTheLinearPlate) {
  const double b = 1.3e-4, nu = 0.3;
  const auto plate = MakeIsotropicPlateLaw(MakeLinearLaw(b), nu);
  Eigen::Matrix3d c;
  c << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  c *= b / (1 - nu * nu);
  for (const Eigen::Vector3d& d : Directions()) {
    const Eigen::Vector3d k = 123.0 * d;
    const PlateBendingResponse r = Evaluate(*plate, k);
    EXPECT_LT((r.moment - c * k).norm(), 1e-14 * (c * k).norm());
    EXPECT_LT((r.tangent - c).norm(), 1e-14 * c.norm());
    EXPECT_NEAR(r.energy, 0.5 * k.dot(c * k), 1e-14 * r.energy);
  }
}

TEST(PlateBendingLaw, StripFreeOfTransverseMomentFollowsTheMeasuredLaw) {
  // A narrow strip bent by m₁₁ alone takes κ₂₂ = −νκ₁₁ (anticlastic) and
  // must carry the moment the strip tester measured: m₁₁ = M(κ₁₁), m₂₂ = 0.
  const auto cotton = Cotton();
  for (double nu : {0.0, 0.3, 0.45}) {
    const auto plate = MakeIsotropicPlateLaw(cotton, nu);
    for (double k_cm : {0.2, 1.0, 2.5, 5.0}) {
      const double k = k_cm * kPerCm;
      const PlateBendingResponse r = Evaluate(*plate, Eigen::Vector3d(k, -nu * k, 0));
      EXPECT_NEAR(r.moment(0), cotton->Moment(k), 1e-13 * cotton->Moment(k));
      EXPECT_NEAR(r.moment(1), 0, 1e-13 * cotton->Moment(k));
      EXPECT_NEAR(r.energy, cotton->Energy(k), 1e-13 * cotton->Energy(k));
    }
  }
}

TEST(PlateBendingLaw, WarpWeftBendsEachYarnByItsOwnLaw) {
  const auto warp = Cotton();
  const auto weft = SaturatingCurve();
  const auto plate = MakeWarpWeftPlateLaw(warp, weft);
  const double k = 1.7 * kPerCm;
  const PlateBendingResponse along_warp = Evaluate(*plate, Eigen::Vector3d(k, 0, 0));
  EXPECT_NEAR(along_warp.moment(0), warp->Moment(k), 1e-14 * warp->Moment(k));
  EXPECT_EQ(along_warp.moment(1), 0.0);
  const PlateBendingResponse along_weft = Evaluate(*plate, Eigen::Vector3d(0, k, 0));
  EXPECT_NEAR(along_weft.moment(1), weft->Moment(k), 1e-14 * weft->Moment(k));
  // Twist at small curvature: (B_warp + B_weft)/4 per engineering twist 2κ₁₂.
  const Eigen::Matrix3d t0 = plate->InitialTangent();
  EXPECT_NEAR(t0(2, 2), (warp->Stiffness(0) + weft->Stiffness(0)) / 4, 1e-14 * t0(2, 2));
}

// Rotation of a Voigt curvature (κ₁₁, κ₂₂, 2κ₁₂) as a tensor by angle a.
Eigen::Vector3d Rotated(const Eigen::Vector3d& k, double a) {
  Eigen::Matrix2d t;
  t << k(0), k(2) / 2, k(2) / 2, k(1);
  Eigen::Matrix2d r;
  r << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  const Eigen::Matrix2d t_r = r * t * r.transpose();
  return {t_r(0, 0), t_r(1, 1), 2 * t_r(0, 1)};
}

TEST(PlateBendingLaw, IsotropicLawIsObjective) {
  // The energy of a curvature tensor does not depend on the axes it is
  // written in, so neither does any response: W(Rκ) = W(κ), m rotates as a
  // tensor (m·δκ is invariant).
  const auto plate = MakeIsotropicPlateLaw(Cotton(), 0.3);
  for (const Eigen::Vector3d& d : Directions())
    for (double a : {0.3, 1.0, 2.2}) {
      const Eigen::Vector3d k = 2.2 * kPerCm * d.normalized();
      const PlateBendingResponse r = Evaluate(*plate, k);
      const PlateBendingResponse r_rot = Evaluate(*plate, Rotated(k, a));
      EXPECT_NEAR(r_rot.energy, r.energy, 1e-13 * r.energy);
      const Eigen::Vector3d dk(0.3, -0.7, 0.4);
      EXPECT_NEAR(r_rot.moment.dot(Rotated(dk, a)), r.moment.dot(dk), 1e-12 * r.moment.norm());
    }
}

TEST(PlateBendingLaw, WarpWeftLawDependsOnTheDirectionOfBending) {
  // Not isotropic: bending across the stiffer warp costs more than across
  // the weft, and the difference is what the two laws say.
  std::shared_ptr<const MomentCurvatureLaw> warp = MakeLinearLaw(2e-4);
  std::shared_ptr<const MomentCurvatureLaw> weft = MakeLinearLaw(1e-4);
  const auto plate = MakeWarpWeftPlateLaw(warp, weft);
  const Eigen::Vector3d k(100, 0, 0);
  EXPECT_NEAR(Evaluate(*plate, k).energy, 0.5 * 2e-4 * 1e4, 1e-18);
  EXPECT_NEAR(Evaluate(*plate, Rotated(k, M_PI / 2)).energy, 0.5 * 1e-4 * 1e4, 1e-18);
}

TEST(PlateBendingLaw, RejectsMissingLawsAndImpossiblePoissonRatios) {
  EXPECT_THROW(MakeIsotropicPlateLaw(nullptr, 0.3), std::invalid_argument);
  EXPECT_THROW(MakeIsotropicPlateLaw(Cotton(), 1.0), std::invalid_argument);
  EXPECT_THROW(MakeWarpWeftPlateLaw(Cotton(), nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace drape
