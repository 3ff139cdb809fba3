// OrientedAreaRatios (shell_element.h) on one element against closed forms:
// (φ,₁ × φ,₂)·t over its reference value is the area ratio of an in-plane
// stretch, 1 after a rigid rotation, −1 for the mirror image, whose strains
// are those of the reference.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>

#include "core/mechanics/shell_element.h"

namespace drape {
namespace {

// A 2 × 1 m rectangle in the xy plane, nodes counter-clockwise, directors +z.
NodeColumns Rectangle() {
  NodeColumns x;
  x << 0, 2, 2, 0,  //
      0, 0, 1, 1,   //
      0, 0, 0, 0;
  return x;
}

NodeColumns Up() {
  NodeColumns t;
  t.setZero();
  t.row(2).setOnes();
  return t;
}

ShellElementReference Reference() {
  return MakeShellElementReference(Rectangle(), Up(), Eigen::Vector3d::UnitX());
}

// 2⁻⁵²-relative sums of a few products of numbers of order 1.
constexpr double kRoundOff = 1e-14;

TEST(OrientedArea, IsOneAtTheReference) {
  for (double r : OrientedAreaRatios(Reference(), Rectangle(), Up())) EXPECT_NEAR(r, 1, kRoundOff);
}

TEST(OrientedArea, IsTheAreaRatioOfAnInPlaneStretch) {
  // x ↦ (1.5 x, 0.8 y): every Gauss point's area grows by 1.5 × 0.8.
  const NodeColumns x = Eigen::Vector3d(1.5, 0.8, 1).asDiagonal() * Rectangle();
  for (double r : OrientedAreaRatios(Reference(), x, Up())) EXPECT_NEAR(r, 1.2, kRoundOff);
}

TEST(OrientedArea, IsOneAfterARigidRotation) {
  const Eigen::Matrix3d q =
      Eigen::AngleAxisd(2.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const NodeColumns x = q * Rectangle(), t = q * Up();
  for (double r : OrientedAreaRatios(Reference(), x, t)) EXPECT_NEAR(r, 1, kRoundOff);
}

TEST(OrientedArea, IsMinusOneForTheMirrorImageWhoseStrainsAreZero) {
  // x ↦ −x with the directors kept: every length and angle as before, so no
  // strain tells the mirror image from the reference; only the orientation.
  const NodeColumns x = Eigen::Vector3d(-1, 1, 1).asDiagonal() * Rectangle();
  const ShellElementReference ref = Reference();
  for (double r : OrientedAreaRatios(ref, x, Up())) EXPECT_NEAR(r, -1, kRoundOff);
  for (const Eigen::Vector3d& e : MembraneStrains(ref, x)) EXPECT_LT(e.norm(), kRoundOff);
  for (const Eigen::Vector3d& k : BendingStrains(ref, x, Up())) EXPECT_LT(k.norm(), kRoundOff);
}

// Node 2 at (2, 1) moved to (−1, −0.5), past the diagonal from node 0. A
// flat bilinear quad's det J(ξ, η) = (∂φ/∂ξ × ∂φ/∂η)·z is linear in ξ and η,
// so it is the bilinear interpolation of its corner values
// (x_{I+1} − x_I) × (x_{I−1} − x_I)/4, here 0.5, −0.25, −1, −0.25; the
// reference's is 0.5 at every point.
TEST(OrientedArea, TurnsNegativeWhereANodePushedPastTheDiagonalFoldsTheElement) {
  NodeColumns x = Rectangle();
  x.col(2) << -1, -0.5, 0;
  const std::array<double, 4> ratios = OrientedAreaRatios(Reference(), x, Up());
  const double corner[4] = {0.5, -0.25, -1, -0.25};
  const double g = 1 / std::sqrt(3.0);
  const double xi[4] = {-g, g, g, -g}, eta[4] = {-g, -g, g, g};
  for (int p = 0; p < 4; ++p) {
    const double n[4] = {(1 - xi[p]) * (1 - eta[p]) / 4,
                         (1 + xi[p]) * (1 - eta[p]) / 4,
                         (1 + xi[p]) * (1 + eta[p]) / 4,
                         (1 - xi[p]) * (1 + eta[p]) / 4};
    double det = 0;
    for (int i = 0; i < 4; ++i) det += n[i] * corner[i];
    EXPECT_NEAR(ratios[p], det / 0.5, kRoundOff) << "Gauss point " << p;
  }
  EXPECT_GT(ratios[0], 0);  // near node 0 the element is still the right way up
  EXPECT_LT(ratios[2], 0);  // near the pushed node it is inside out
}

}  // namespace
}  // namespace drape
