#include "core/mechanics/shell_element.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "core/mechanics/director.h"
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
