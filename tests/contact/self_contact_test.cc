// Self-contact's potential over a whole folded sheet (core/contact/self_contact.h):
// its gradient and Hessian against differences of its energy along random
// directions, forces that balance (the fabric pushes on itself), and a step
// bound that keeps the layers apart.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/contact/self_contact.h"

namespace drape {
namespace {

// A 20 × 10 cm sheet of 20 × 10 elements folded at x = 10 cm: the upper
// layer `gap` above the lower one, with small waves of its own, shifted by
// `shift` along y and 0.62 `shift` along x. (Unshifted, its nodes lie above the lower layer's mesh
// lines: on the borders of the distance's regions, where its Hessian jumps.)
struct FoldedSheet {
  Mesh mesh;
  Positions x;
};

FoldedSheet Fold(double gap, double wave, double shift = 0) {
  FoldedSheet s;
  const int nx = 20, ny = 10;
  s.mesh.positions.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) s.mesh.positions.row(j * (nx + 1) + i) << 0.01 * i, 0.01 * j, 0;
  s.mesh.quads.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n = j * (nx + 1) + i;
      s.mesh.quads.row(j * nx + i) << n, n + 1, n + nx + 2, n + nx + 1;
    }
  s.x = s.mesh.positions;
  for (int i = 0; i < s.x.rows(); ++i) {
    const double X = s.mesh.positions(i, 0), Y = s.mesh.positions(i, 1);
    if (X > 0.1 + 1e-12)
      s.x.row(i) << 0.2 - X + shift * 0.62 + 1e-3 * std::sin(40 * Y), Y + shift,
          gap + wave * std::sin(60 * X + 30 * Y);
  }
  return s;
}

SelfContactSettings Settings() {
  SelfContactSettings s;
  s.offset = 5e-4;      // h = 0.5 mm
  s.activation = 3e-4;  // acting below 0.8 mm
  s.stiffness = 1e-2;
  s.exclusion = 0.015;
  return s;
}

Positions Reshape(const Eigen::VectorXd& v) {
  Positions p(v.size() / 3, 3);
  for (int i = 0; i < p.rows(); ++i) p.row(i) = v.segment<3>(3 * i).transpose();
  return p;
}

Eigen::VectorXd HessianTimes(const SelfContactEvaluation& e, const Eigen::VectorXd& v) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(v.size());
  for (size_t b = 0; b < e.blocks.size(); ++b) {
    Eigen::Matrix<double, 12, 1> local;
    for (int k = 0; k < 4; ++k) local.segment<3>(3 * k) = v.segment<3>(3 * e.block_nodes[b][k]);
    const Eigen::Matrix<double, 12, 1> product = e.blocks[b] * local;
    for (int k = 0; k < 4; ++k)
      out.segment<3>(3 * e.block_nodes[b][k]) += product.segment<3>(3 * k);
  }
  return out;
}

TEST(SelfContact, GradientAndHessianAgainstDifferencesAlongRandomDirections) {
  const FoldedSheet sheet = Fold(6.5e-4, 5e-5, 3.7e-3);
  SelfContact contact(sheet.mesh, Settings());
  const SelfContactEvaluation e = contact.Evaluate(sheet.x, true);
  ASSERT_GT(e.active_pairs, 100);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd v(3 * sheet.x.rows());
    for (int k = 0; k < v.size(); ++k) v(k) = n(rng);
    v.normalize();
    const double h = 1e-9;  // m: small against the 0.15 mm band left
    const Positions plus = sheet.x + h * Reshape(v), minus = sheet.x - h * Reshape(v);
    const SelfContactEvaluation p = contact.Evaluate(plus, false),
                                m = contact.Evaluate(minus, false);
    const double slope = (p.energy - m.energy) / (2 * h);
    EXPECT_NEAR(e.gradient.dot(v), slope, 1e-5 * std::abs(slope) + 1e-12) << trial;
    const Eigen::VectorXd curvature = (p.gradient - m.gradient) / (2 * h);
    const Eigen::VectorXd hv = HessianTimes(e, v);
    EXPECT_LT((hv - curvature).norm(), 1e-4 * hv.norm()) << trial;
  }
}

TEST(SelfContact, TheFabricPushesOnItselfInBalance) {
  const FoldedSheet sheet = Fold(6e-4, 0);
  const SelfContactEvaluation e = SelfContact(sheet.mesh, Settings()).Evaluate(sheet.x, false);
  ASSERT_GT(e.active_pairs, 100);
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), on_upper = Eigen::Vector3d::Zero();
  for (int i = 0; i < sheet.x.rows(); ++i) {
    total += e.gradient.segment<3>(3 * i);
    if (sheet.mesh.positions(i, 0) > 0.1 + 1e-12) on_upper -= e.gradient.segment<3>(3 * i);
  }
  EXPECT_LT(total.norm(), 1e-12 * on_upper.norm());
  EXPECT_GT(on_upper.z(), 0);  // the upper layer is pushed up
  EXPECT_NEAR(e.smallest_distance, 6e-4, 1e-12);
}

TEST(SelfContact, StepBoundKeepsTheLayersApart) {
  const FoldedSheet sheet = Fold(1e-3, 0);
  SelfContact contact(sheet.mesh, Settings());
  // The upper layer moving down 2 mm would pass through the lower one; the
  // offset (0.5 mm) is reached after a quarter of the step.
  Positions dx = Positions::Zero(sheet.x.rows(), 3);
  for (int i = 0; i < dx.rows(); ++i)
    if (sheet.mesh.positions(i, 0) > 0.1 + 1e-12) dx(i, 2) = -2e-3;
  const double t = contact.StepBound(sheet.x, dx);
  EXPECT_GT(t, 0.1);
  EXPECT_LT(t, 0.25);
  const SelfContactEvaluation after = contact.Evaluate(sheet.x + t * dx, false);
  EXPECT_GT(after.smallest_distance, Settings().offset);
  // Moving it up: the whole step.
  EXPECT_EQ(contact.StepBound(sheet.x, -dx), 1);
}

}  // namespace
}  // namespace drape
