// The graph a polygon is meshed from, with lines and points to follow:
// where lines meet the boundary and each other, worked out by hand on a
// 40 × 30 square, and the errors for lines that leave the part.
#include "core/model/planar_graph.h"

#include <gtest/gtest.h>

#include <string>

#include "core/model/mesh.h"

namespace drape {
namespace {

const std::vector<Eigen::Vector2d> kSquare{{0, 0}, {0.4, 0}, {0.4, 0.3}, {0, 0.3}};
constexpr double kSnap = 0.005;

std::string ErrorOf(const MeshFeatures& features) {
  try {
    BuildPlanarGraph(kSquare, features, kSnap);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// The vertex of `graph` at p (−1: none).
int VertexAt(const PlanarGraph& graph, const Eigen::Vector2d& p) {
  for (std::size_t v = 0; v < graph.vertices.size(); ++v)
    if ((graph.vertices[v] - p).norm() < 1e-15) return static_cast<int>(v);
  return -1;
}

TEST(PlanarGraph, ALineAcrossThePartSplitsTheEdgesItEndsOn) {
  MeshFeatures features;
  features.lines.push_back({{{0.2, 0}, {0.2, 0.3}}, "fold"});
  const PlanarGraph graph = BuildPlanarGraph(kSquare, features, kSnap);
  ASSERT_EQ(graph.loops.size(), 1u);
  // Counter-clockwise: the bottom edge's split after vertex 0, the top
  // edge's after vertex 2.
  const int bottom = VertexAt(graph, {0.2, 0}), top = VertexAt(graph, {0.2, 0.3});
  ASSERT_GE(bottom, 0);
  ASSERT_GE(top, 0);
  EXPECT_EQ(graph.loops[0], (std::vector<int>{0, bottom, 1, 2, top, 3}));
  ASSERT_EQ(graph.segments.size(), 1u);
  EXPECT_EQ(graph.segments[0], (std::array<int, 2>{bottom, top}));
  EXPECT_TRUE(graph.points.empty());
}

TEST(PlanarGraph, CrossingLinesAreSplitWhereTheyCross) {
  MeshFeatures features;
  features.lines.push_back({{{0.1, 0.1}, {0.3, 0.2}}, "a"});
  features.lines.push_back({{{0.1, 0.2}, {0.3, 0.1}}, "b"});
  const PlanarGraph graph = BuildPlanarGraph(kSquare, features, kSnap);
  // The diagonals of the box [0.1, 0.3] × [0.1, 0.2] cross at its centre.
  const int centre = VertexAt(graph, {0.2, 0.15});
  ASSERT_GE(centre, 0);
  ASSERT_EQ(graph.segments.size(), 4u);
  for (const auto& s : graph.segments) EXPECT_TRUE(s[0] == centre || s[1] == centre);
  EXPECT_EQ(graph.loops[0].size(), 4u);
}

TEST(PlanarGraph, APointNearTheBoundaryIsMovedOntoIt) {
  MeshFeatures features;
  features.points.push_back({{0.15, 0.3 - 0.2 * kSnap}, "notch"});  // just inside the top
  features.points.push_back({{0.25, 0.15}, "drill"});
  features.points.push_back({{0.4 - 0.5 * kSnap, 0.3 - 0.5 * kSnap}, "corner"});
  const PlanarGraph graph = BuildPlanarGraph(kSquare, features, kSnap);
  const int notch = VertexAt(graph, {0.15, 0.3});
  ASSERT_GE(notch, 0);
  EXPECT_EQ(graph.loops[0], (std::vector<int>{0, 1, 2, notch, 3}));
  // The drill hole is embedded on its own; the third point is the corner.
  ASSERT_EQ(graph.points.size(), 1u);
  EXPECT_EQ(graph.vertices[graph.points[0]], Eigen::Vector2d(0.25, 0.15));
  EXPECT_EQ(graph.vertices.size(), 6u);
}

TEST(PlanarGraph, ALineEndingOnAnotherSplitsIt) {
  MeshFeatures features;
  features.lines.push_back({{{0.1, 0.15}, {0.3, 0.15}}, "a"});
  features.lines.push_back({{{0.2, 0.05}, {0.2, 0.15}}, "b"});  // a T
  const PlanarGraph graph = BuildPlanarGraph(kSquare, features, kSnap);
  const int joint = VertexAt(graph, {0.2, 0.15});
  ASSERT_GE(joint, 0);
  EXPECT_EQ(graph.segments.size(), 3u);
}

TEST(PlanarGraph, LinesThatLeaveThePartOrCrossAHoleAreNamed) {
  MeshFeatures outside;
  outside.lines.push_back({{{0.2, 0.1}, {0.6, 0.1}}, "internal line 2 (layer 8)"});
  EXPECT_NE(ErrorOf(outside).find("internal line 2 (layer 8) leaves the part at (0.6, 0.1) m"),
            std::string::npos)
      << ErrorOf(outside);

  MeshFeatures through_hole;
  through_hole.holes.push_back({{0.15, 0.1}, {0.25, 0.1}, {0.25, 0.2}, {0.15, 0.2}});
  through_hole.lines.push_back({{{0.05, 0.15}, {0.35, 0.15}}, "fold"});
  EXPECT_NE(ErrorOf(through_hole).find("fold leaves the part"), std::string::npos)
      << ErrorOf(through_hole);

  // Both ends inside, the middle outside a concave part: it crosses.
  const std::vector<Eigen::Vector2d> u_shape{
      {0, 0}, {0.4, 0}, {0.4, 0.3}, {0.3, 0.3}, {0.3, 0.1}, {0.1, 0.1}, {0.1, 0.3}, {0, 0.3}};
  MeshFeatures across;
  across.lines.push_back({{{0.05, 0.2}, {0.35, 0.2}}, "fold"});
  try {
    BuildPlanarGraph(u_shape, across, kSnap);
    ADD_FAILURE() << "a line across the U's gap was taken";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("fold"), std::string::npos) << e.what();
  }

  MeshFeatures stray;
  stray.points.push_back({{0.5, 0.1}, "drill hole 3"});
  EXPECT_NE(ErrorOf(stray).find("drill hole 3 lies outside the part"), std::string::npos)
      << ErrorOf(stray);

  MeshFeatures overlapping;
  overlapping.lines.push_back({{{0.1, 0.1}, {0.3, 0.1}}, "a"});
  overlapping.lines.push_back({{{0.2, 0.1}, {0.35, 0.1}}, "b"});
  EXPECT_NE(ErrorOf(overlapping).find("b runs along a"), std::string::npos) << ErrorOf(overlapping);
}

}  // namespace
}  // namespace drape
