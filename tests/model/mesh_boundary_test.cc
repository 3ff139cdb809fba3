// Boundary loops of meshed parts against the outlines they were meshed
// from: node counts and enclosed areas from the geometry, not the code.
#include "core/model/mesh_boundary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace drape {
namespace {

double SignedArea(const PieceLine& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const PiecePoint& a = loop[i];
    const PiecePoint& b = loop[(i + 1) % loop.size()];
    twice += a[0] * b[1] - b[0] * a[1];
  }
  return twice / 2;
}

TEST(MeshBoundary, ARectangleHasOneCounterClockwiseLoop) {
  const Mesh mesh = MeshRectangle(0.4, 0.3, {0, 0}, 4, 3, 0.0);
  const auto loops = BoundaryLoops(mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 2u * (4 + 3));
  const PatternPiece outline = ProjectedOutline(mesh, mesh.positions, "R");
  EXPECT_NEAR(SignedArea(outline.boundary), 0.4 * 0.3, 1e-15);
}

TEST(MeshBoundary, AHoleIsASecondClockwiseLoop) {
  const std::vector<Eigen::Vector2d> outer{{0, 0}, {0.4, 0}, {0.4, 0.3}, {0, 0.3}};
  const std::vector<Eigen::Vector2d> hole{{0.1, 0.1}, {0.15, 0.1}, {0.15, 0.14}, {0.1, 0.14}};
  const Mesh mesh = MeshPolygon(outer, 0.02, 0.0, {.holes = {hole}});
  const PatternPiece outline = ProjectedOutline(mesh, mesh.positions, "P", {{0.4, 0.15}});
  ASSERT_EQ(outline.holes.size(), 1u);
  EXPECT_NEAR(SignedArea(outline.boundary), 0.4 * 0.3, 1e-12);
  EXPECT_NEAR(SignedArea(outline.holes[0]), -0.05 * 0.04, 1e-12);
  // The mark follows its nearest node: on the right edge, near mid-height.
  ASSERT_EQ(outline.notches.size(), 1u);
  EXPECT_NEAR(outline.notches[0][0], 0.4, 1e-12);
  EXPECT_NEAR(outline.notches[0][1], 0.15, 0.02);
}

TEST(MeshBoundary, TheOutlineFollowsThePositionsGiven) {
  const Mesh mesh = MeshRectangle(0.2, 0.1, {0, 0}, 2, 1, 0.0);
  Eigen::Matrix<double, Eigen::Dynamic, 3> moved = mesh.positions;
  moved.col(0) *= 0.5;  // squeezed to half its width, lifted
  moved.col(2).array() += 0.3;
  const PatternPiece outline = ProjectedOutline(mesh, moved, "S");
  EXPECT_NEAR(SignedArea(outline.boundary), 0.1 * 0.1, 1e-15);
}

}  // namespace
}  // namespace drape
