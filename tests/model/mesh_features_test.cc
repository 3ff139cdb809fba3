// Meshes that follow lines and points inside a polygon (a pattern's fold
// lines, notches and drill holes): the lines are chains of element edges,
// the points are nodes, and the area is the polygon's.
#include <gtest/gtest.h>

#include <cmath>

#include "core/model/mesh.h"
#include "core/model/polygon_checks.h"
#include "support/edge_chain.h"

namespace drape {
namespace {

// A concave 40 × 30 cm panel with a cut-out.
const std::vector<Eigen::Vector2d> kPanel{{0, 0}, {0.40, 0}, {0.40, 0.30}, {0.20, 0.32}, {0, 0.30}};
const std::vector<Eigen::Vector2d> kHole{{0.10, 0.10}, {0.15, 0.10}, {0.15, 0.14}, {0.10, 0.14}};

TEST(MeshFeatures, LinesAreEdgesAndPointsAreNodes) {
  MeshFeatures features;
  features.holes = {kHole};
  // A fold line from the bottom edge to the peak, and a placement cross
  // whose arms cross each other inside.
  features.lines.push_back({{{0.20, 0}, {0.20, 0.32}}, "fold"});
  features.lines.push_back({{{0.27, 0.20}, {0.33, 0.20}}, "cross a"});
  features.lines.push_back({{{0.30, 0.17}, {0.30, 0.23}}, "cross b"});
  // A notch on the slanted top edge, a drill hole, and a notch drawn 1 mm
  // inside the right edge (moved onto it).
  features.points.push_back({{0.30, 0.31}, "notch 1"});
  features.points.push_back({{0.25, 0.08}, "drill 1"});
  features.points.push_back({{0.399, 0.15}, "notch 2"});
  const double h = 0.015;
  const Mesh mesh = MeshPolygon(kPanel, h, 0.0, features);

  const double area = std::abs(ShoelaceArea(kPanel)) - std::abs(ShoelaceArea(kHole));
  EXPECT_NEAR(std::abs(ProjectedArea(mesh)) / area, 1.0, 1e-12);

  const double tol = 1e-9;
  const auto fold = test::ExpectEdgeChain(mesh, {0.20, 0}, {0.20, 0.32}, tol);
  // Full-quad meshing halves the segments: no edge longer than about h.
  EXPECT_GE(fold.size(), static_cast<std::size_t>(0.32 / h));
  test::ExpectEdgeChain(mesh, {0.27, 0.20}, {0.33, 0.20}, tol);
  test::ExpectEdgeChain(mesh, {0.30, 0.17}, {0.30, 0.23}, tol);
  EXPECT_LE(test::DistanceToNearestNode(mesh, {0.30, 0.20}), tol);  // where the arms cross
  EXPECT_LE(test::DistanceToNearestNode(mesh, {0.30, 0.31}), tol);
  EXPECT_LE(test::DistanceToNearestNode(mesh, {0.25, 0.08}), tol);
  EXPECT_LE(test::DistanceToNearestNode(mesh, {0.40, 0.15}), tol);
}

TEST(MeshFeatures, TheSameFeaturesGiveTheSameMesh) {
  MeshFeatures features;
  features.lines.push_back({{{0.20, 0}, {0.20, 0.32}}, "fold"});
  features.points.push_back({{0.25, 0.08}, "drill"});
  const Mesh a = MeshPolygon(kPanel, 0.02, 0.0, features);
  const Mesh b = MeshPolygon(kPanel, 0.02, 0.0, features);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.quads, b.quads);
}

TEST(MeshFeatures, ALineLeavingThePartIsAnError) {
  MeshFeatures features;
  features.lines.push_back({{{0.20, 0.10}, {0.50, 0.10}}, "internal line 1 (layer 8)"});
  try {
    MeshPolygon(kPanel, 0.02, 0.0, features);
    ADD_FAILURE() << "meshed a line that leaves the part";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("internal line 1 (layer 8) leaves the part"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace drape
