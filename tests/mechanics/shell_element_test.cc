#include "core/mechanics/shell_element.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <memory>
#include <vector>

#include "core/mechanics/director.h"
#include "core/mechanics/moment_curvature.h"
#include "core/mechanics/plate_bending_law.h"
#include "support/random_element.h"

namespace drape {
namespace {

using test::NodalState;

// A non-dimensional section: E = 1, ν = 0.3, h = 0.05 on elements of size 1,
// so membrane, bending and shear terms all matter in the sums.
ShellSection TestSection() {
  return IsotropicSection(1.0, 0.3, 0.05);
}

double Energy(const ShellElementReference& ref, const ShellSection& sec, const NodalState& s) {
  ElementEnergy e;
  EvaluateShellElement(ref, sec, s.Element(), ElementOutput::kEnergy, e);
  return e.value;
}

ElementEnergy Full(const ShellElementReference& ref, const ShellSection& sec, const NodalState& s) {
  ElementEnergy e;
  EvaluateShellElement(ref, sec, s.Element(), ElementOutput::kHessian, e);
  return e;
}

ElementVector Unit(int i, double h) {
  ElementVector q = ElementVector::Zero();
  q(i) = h;
  return q;
}

// Central differences of the energy along the exact update (Δu, exp(ŵ)Λ).
ElementVector FiniteDifferenceGradient(const ShellElementReference& ref,
                                       const ShellSection& sec,
                                       const NodalState& s,
                                       double h) {
  ElementVector g;
  for (int i = 0; i < 20; ++i) {
    // Fourth-order stencil so the truncation error is far below 1e-6.
    g(i) = (-Energy(ref, sec, s.Incremented(Unit(i, 2 * h))) +
            8 * Energy(ref, sec, s.Incremented(Unit(i, h))) -
            8 * Energy(ref, sec, s.Incremented(Unit(i, -h))) +
            Energy(ref, sec, s.Incremented(Unit(i, -2 * h)))) /
           (12 * h);
  }
  return g;
}

ElementMatrix SecondDifference(const ShellElementReference& ref,
                               const ShellSection& sec,
                               const NodalState& s,
                               double h) {
  ElementMatrix hess;
  for (int i = 0; i < 20; ++i)
    for (int j = i; j < 20; ++j) {
      auto e = [&](double si, double sj) {
        return Energy(ref, sec, s.Incremented(Unit(i, si * h) + Unit(j, sj * h)));
      };
      hess(i, j) = hess(j, i) = (e(1, 1) - e(1, -1) - e(-1, 1) + e(-1, -1)) / (4 * h * h);
    }
  return hess;
}

// Richardson extrapolation of the O(h²) second difference to O(h⁴).
ElementMatrix FiniteDifferenceHessian(const ShellElementReference& ref,
                                      const ShellSection& sec,
                                      const NodalState& s,
                                      double h) {
  return (4 * SecondDifference(ref, sec, s, h / 2) - SecondDifference(ref, sec, s, h)) / 3;
}

TEST(ShellElement, GradientAndHessianMatchFiniteDifferencesAtLargeRotations) {
  SplitMix64 rng(42);
  const ShellSection sec = TestSection();
  for (int trial = 0; trial < 20; ++trial) {
    const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.2);
    NodeColumns t0;
    t0.colwise() = Eigen::Vector3d::UnitZ();
    const auto ref = MakeShellElementReference(x0, t0, Eigen::Vector3d::UnitX());
    // Nodal rotations up to π away from the rigid rotation: well past 180° folds.
    const NodalState s = test::RandomDeformedState(rng, x0, 1.0, M_PI);
    const ElementEnergy e = Full(ref, sec, s);
    const ElementVector g_fd = FiniteDifferenceGradient(ref, sec, s, 1e-4);
    const ElementMatrix h_fd = FiniteDifferenceHessian(ref, sec, s, 2e-3);
    const double g_error = (g_fd - e.gradient).norm() / e.gradient.norm();
    const double h_error = (h_fd - e.hessian).norm() / e.hessian.norm();
    EXPECT_LT(g_error, 1e-6) << "trial " << trial;
    EXPECT_LT(h_error, 1e-6) << "trial " << trial;
    EXPECT_LT((e.hessian - e.hessian.transpose()).norm(), 1e-14 * e.hessian.norm());
  }
}

// Sections with a nonlinear bending law on the same scale: a softening then
// stiffening strip law M = B₀(K − 0.8K² + 0.6K³) fitted "up to" K = 0.8,
// continued linearly beyond (random states reach K ≈ 3, so Gauss points
// fall on both sides), isotropic or warp against a stiffer linear weft, on
// an orthotropic membrane with a low in-plane shear modulus.
std::vector<ShellSection> NonlinearSections() {
  const double b0 = 0.05 * 0.05 * 0.05 / 12;
  std::shared_ptr<const MomentCurvatureLaw> warp =
      MakePolynomialLaw({b0, -0.8 * b0, 0.6 * b0}, 0.8);
  std::shared_ptr<const MomentCurvatureLaw> weft = MakeLinearLaw(2 * b0);
  ShellSection isotropic = TestSection();
  isotropic.bending_law = MakeIsotropicPlateLaw(warp, 0.3);
  isotropic.bending = isotropic.bending_law->InitialTangent();
  ShellSection woven = OrthotropicSection(1.0, 0.6, 0.2, 0.05, 0.05);
  woven.bending_law = MakeWarpWeftPlateLaw(warp, weft);
  woven.bending = woven.bending_law->InitialTangent();
  return {isotropic, woven};
}

TEST(ShellElement, NonlinearLawsMatchFiniteDifferencesAtLargeRotations) {
  SplitMix64 rng(7);
  for (const ShellSection& sec : NonlinearSections())
    for (int trial = 0; trial < 10; ++trial) {
      const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.2);
      NodeColumns t0;
      t0.colwise() = Eigen::Vector3d::UnitZ();
      const auto ref = MakeShellElementReference(x0, t0, Eigen::Vector3d(1, 1, 0));
      const NodalState s = test::RandomDeformedState(rng, x0, 1.0, M_PI);
      const ElementEnergy e = Full(ref, sec, s);
      const double g_error =
          (FiniteDifferenceGradient(ref, sec, s, 1e-4) - e.gradient).norm() / e.gradient.norm();
      const double h_error =
          (FiniteDifferenceHessian(ref, sec, s, 2e-3) - e.hessian).norm() / e.hessian.norm();
      EXPECT_LT(g_error, 1e-6) << "trial " << trial;
      EXPECT_LT(h_error, 1e-6) << "trial " << trial;
      EXPECT_LT((e.hessian - e.hessian.transpose()).norm(), 1e-14 * e.hessian.norm());
    }
}

TEST(ShellElement, TurningThePartAndItsMaterialAxesTogetherChangesNothing) {
  // Objectivity of the direction-dependent laws: an element turned in its
  // plane by a, with its warp axis turned by a as well, deformed by the same
  // turned motion, stores the same energy; its forces turn with it.
  SplitMix64 rng(23);
  const std::vector<ShellSection> sections = NonlinearSections();
  for (size_t k = 0; k < sections.size(); ++k) {
    const ShellSection& sec = sections[k];
    const bool isotropic = k == 0;
    const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.2);
    NodeColumns t0;
    t0.colwise() = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d warp(std::cos(0.4), std::sin(0.4), 0);
    const auto ref = MakeShellElementReference(x0, t0, warp);
    const NodalState s = test::RandomDeformedState(rng, x0, 1.0, 1.5);
    const ElementEnergy e = Full(ref, sec, s);
    for (double a : {0.5, 1.3, 2.2}) {
      const Eigen::Matrix3d r = ExpRotation(Eigen::Vector3d(0, 0, a));
      const auto ref_turned = MakeShellElementReference(r * x0, t0, r * warp);
      NodalState turned = s;
      for (int i = 0; i < 4; ++i) {
        turned.positions.col(i) = r * s.positions.col(i);
        turned.rotations[i] = r * s.rotations[i];
      }
      const ElementEnergy m = Full(ref_turned, sec, turned);
      EXPECT_NEAR(m.value, e.value, 1e-12 * e.value);
      for (int i = 0; i < 4; ++i)
        EXPECT_LT((m.gradient.segment<3>(5 * i) - r * e.gradient.segment<3>(5 * i)).norm(),
                  1e-11 * e.gradient.norm());
      // Turning the warp axis alone changes a direction-dependent law only.
      const auto ref_axes_only = MakeShellElementReference(x0, t0, r * warp);
      const double change = std::abs(Full(ref_axes_only, sec, s).value - e.value);
      if (isotropic)
        EXPECT_LT(change, 1e-12 * e.value);
      else
        EXPECT_GT(change, 1e-3 * e.value);
    }
  }
}

TEST(ShellElement, RigidMotionOfTheReferenceStoresNoEnergy) {
  SplitMix64 rng(3);
  const ShellSection sec = TestSection();
  const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.25);
  NodeColumns t0;
  t0.colwise() = Eigen::Vector3d::UnitZ();
  const auto ref = MakeShellElementReference(x0, t0, Eigen::Vector3d::UnitX());
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Matrix3d r = ExpRotation(test::RandomVector(rng, 3.0));
    const Eigen::Vector3d c = test::RandomVector(rng, 5.0);
    NodalState s;
    for (int i = 0; i < 4; ++i) {
      s.positions.col(i) = r * x0.col(i) + c;
      s.rotations[i] = r;
    }
    const ElementEnergy e = Full(ref, sec, s);
    EXPECT_NEAR(e.value, 0.0, 1e-14);
    EXPECT_LT(e.gradient.norm(), 1e-13);
  }
}

TEST(ShellElement, RigidMotionOfADeformedStateLeavesEnergyAndForcesInvariant) {
  SplitMix64 rng(11);
  const ShellSection sec = TestSection();
  const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.2);
  NodeColumns t0;
  t0.colwise() = Eigen::Vector3d::UnitZ();
  const auto ref = MakeShellElementReference(x0, t0, Eigen::Vector3d::UnitX());
  const NodalState s = test::RandomDeformedState(rng, x0, 1.0, 1.0);
  const ElementEnergy e = Full(ref, sec, s);
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Matrix3d r = ExpRotation(test::RandomVector(rng, 3.0));
    NodalState moved = s;
    for (int i = 0; i < 4; ++i) {
      moved.positions.col(i) = r * s.positions.col(i) + Eigen::Vector3d(1, -2, 3);
      moved.rotations[i] = r * s.rotations[i];
    }
    const ElementEnergy m = Full(ref, sec, moved);
    EXPECT_NEAR(m.value, e.value, 1e-12 * e.value);
    // Forces rotate with the body; moments in the nodal bases are unchanged.
    for (int i = 0; i < 4; ++i) {
      EXPECT_LT((m.gradient.segment<3>(5 * i) - r * e.gradient.segment<3>(5 * i)).norm(),
                1e-12 * e.gradient.norm());
      EXPECT_LT((m.gradient.segment<2>(5 * i + 3) - e.gradient.segment<2>(5 * i + 3)).norm(),
                1e-12 * e.gradient.norm());
    }
  }
}

TEST(ShellElement, UndeformedTangentHasExactlyTheRigidBodyKernel) {
  // At the reference state the stiffness must be positive semi-definite with
  // exactly 6 zero eigenvalues: 3 translations and 3 rotations (in-plane
  // rotation about the normal moves positions; the 5th-DOF-free rotations
  // about tangent axes turn directors with the positions).
  SplitMix64 rng(5);
  const ShellSection sec = TestSection();
  const NodeColumns x0 = test::RandomFlatQuad(rng, 1.0, 0.2);
  NodeColumns t0;
  t0.colwise() = Eigen::Vector3d::UnitZ();
  const auto ref = MakeShellElementReference(x0, t0, Eigen::Vector3d::UnitX());
  NodalState s;
  s.positions = x0;
  s.rotations.fill(Eigen::Matrix3d::Identity());
  const ElementEnergy e = Full(ref, sec, s);
  Eigen::SelfAdjointEigenSolver<ElementMatrix> eig(e.hessian);
  const auto& lambda = eig.eigenvalues();
  const double largest = lambda.maxCoeff();
  int zero = 0;
  for (int i = 0; i < 20; ++i) {
    EXPECT_GT(lambda(i), -1e-12 * largest);
    if (std::abs(lambda(i)) < 1e-10 * largest) ++zero;
  }
  EXPECT_EQ(zero, 6) << lambda.transpose();
}

}  // namespace
}  // namespace drape
