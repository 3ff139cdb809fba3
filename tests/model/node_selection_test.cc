#include "core/model/node_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/model/outline_geometry.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

// A 20 × 2 cm strip (the paper's polyester strip) at two densities.
const RectangleOutline kStrip{{0.2, 0.02}, {0, 0}};

Mesh Strip(int nx, int ny) {
  return MeshRectangle(0.2, 0.02, {0, 0}, nx, ny, 0.0);
}

size_t Count(const SelectionShape& shape, const Mesh& mesh, const Outline& outline = kStrip) {
  return SelectNodes(Selection{shape, std::nullopt}, mesh, outline).size();
}

TEST(NodeSelection, EdgesCountRowsAtTwoDensities) {
  for (auto [nx, ny] : {std::pair{80, 1}, std::pair{40, 4}}) {
    Mesh mesh = Strip(nx, ny);
    EXPECT_EQ(Count(EdgeSelection{Side::kLeft}, mesh), size_t(ny + 1));
    EXPECT_EQ(Count(EdgeSelection{Side::kRight}, mesh), size_t(ny + 1));
    EXPECT_EQ(Count(EdgeSelection{Side::kBottom}, mesh), size_t(nx + 1));
    EXPECT_EQ(Count(EdgeSelection{Side::kTop}, mesh), size_t(nx + 1));
    EXPECT_EQ(Count(EdgeSelection{Side::kBoundary}, mesh), size_t(2 * (nx + ny)));
  }
}

TEST(NodeSelection, CornersAndPointsDoNotDependOnDensity) {
  for (auto [nx, ny] : {std::pair{80, 1}, std::pair{40, 4}}) {
    Mesh mesh = Strip(nx, ny);
    auto corners = SelectNodes(Selection{CornersSelection{}, {}}, mesh, kStrip);
    ASSERT_EQ(corners.size(), 4u);
    const int last = (nx + 1) * (ny + 1) - 1;
    EXPECT_EQ(corners, (std::vector<int>{0, nx, last - nx, last}));
    // The nearest node to a point between nodes.
    auto p = SelectNodes(Selection{PointSelection{{-0.1, 0.0}}, {}}, mesh, kStrip);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NEAR(mesh.positions(p[0], 0), -0.1, 1e-15);
  }
}

TEST(NodeSelection, LineCountsNodesOnTheSegment) {
  const RectangleOutline square{{0.2, 0.2}, {0, 0}};
  for (int n : {20, 40}) {  // multiples of 4, so x = ±0.05 falls on nodes
    Mesh mesh = MeshRectangle(0.2, 0.2, {0, 0}, n, n, 0.0);
    // The diagonal passes through n + 1 nodes; the mid-line y = 0 through n + 1.
    EXPECT_EQ(Count(LineSelection{{-0.1, -0.1}, {0.1, 0.1}}, mesh, square), size_t(n + 1));
    EXPECT_EQ(Count(LineSelection{{-0.1, 0.0}, {0.1, 0.0}}, mesh, square), size_t(n + 1));
    // Half the mid-line: x in [0, 0.1] holds n/2 + 1 nodes.
    EXPECT_EQ(Count(LineSelection{{0.0, 0.0}, {0.1, 0.0}}, mesh, square), size_t(n / 2 + 1));
    // A box around the centre quarter: x, y in [-0.05, 0.05] holds (n/2 + 1)² nodes.
    EXPECT_EQ(Count(BoxSelection{{-0.05, -0.05}, {0.05, 0.05}}, mesh, square),
              size_t((n / 2 + 1) * (n / 2 + 1)));
  }
}

// Lattice points within r of a lattice point: Gauss's circle problem,
// N(r) for r² = 1, 2, 4, 5, 8, 9, 10 is 5, 9, 13, 21, 25, 29, 37 (OEIS A057655).
TEST(NodeSelection, CircleCountsTheLatticePointsOfGausssCircleProblem) {
  const RectangleOutline square{{0.2, 0.2}, {0, 0}};
  Mesh mesh = MeshRectangle(0.2, 0.2, {0, 0}, 20, 20, 0.0);  // 1 cm spacing
  const std::pair<double, size_t> expected[] = {
      {1, 5}, {2, 9}, {4, 13}, {5, 21}, {8, 25}, {9, 29}, {10, 37}};
  for (const auto& [r2, count] : expected) {
    EXPECT_EQ(Count(CircleSelection{{0, 0}, 0.01 * std::sqrt(r2)}, mesh, square), count)
        << "r² = " << r2 << " cm²";
    // Off the centre node: the same count around (3 cm, −2 cm).
    EXPECT_EQ(Count(CircleSelection{{0.03, -0.02}, 0.01 * std::sqrt(r2)}, mesh, square), count);
  }
  // A circle that misses every node selects nothing.
  EXPECT_EQ(Count(CircleSelection{{0.005, 0.005}, 0.002}, mesh, square), 0u);
}

TEST(NodeSelection, ToleranceWidensALine) {
  Mesh mesh = Strip(80, 4);  // rows at y = -0.01, -0.005, 0, 0.005, 0.01
  Selection near_axis{LineSelection{{-0.1, 0.001}, {0.1, 0.001}}, std::nullopt};
  EXPECT_TRUE(SelectNodes(near_axis, mesh, kStrip).empty());
  near_axis.tolerance = 0.002;
  EXPECT_EQ(SelectNodes(near_axis, mesh, kStrip).size(), 81u);
}

TEST(NodeSelection, RulesThatCannotApplyThrow) {
  Mesh mesh = Strip(8, 1);
  EXPECT_THROW(SelectNodes(Selection{PointSelection{{1.0, 1.0}}, {}}, mesh, kStrip),
               SelectionError);
  EXPECT_THROW(SelectNodes(Selection{NodesSelection{{18}}, {}}, mesh, kStrip), SelectionError);
  EXPECT_EQ(SelectNodes(Selection{NodesSelection{{17, 0, 17}}, {}}, mesh, kStrip),
            (std::vector<int>{0, 17}));
  const DiskOutline disk{0.1, {0, 0}};
  EXPECT_THROW(SelectNodes(Selection{CornersSelection{}, {}}, mesh, disk), SelectionError);
}

TEST(NodeSelection, ResolveNamesTheEmptySelection) {
  Scene scene;
  scene.fabric.outline = kStrip;
  scene.supports.push_back({"root", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kClamp});
  scene.grippers.push_back(
      {"lost", Selection{LineSelection{{-0.1, 0.001}, {0.1, 0.001}}, {}}, Fixity::kPosition});
  Mesh mesh = Strip(8, 1);
  try {
    ResolveSelections(scene, mesh);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "grippers[0].select");
    EXPECT_NE(std::string(e.what()).find("'lost' matched no node"), std::string::npos);
  }
  scene.grippers.clear();
  auto resolved = ResolveSelections(scene, mesh);
  ASSERT_EQ(resolved.size(), 1u);
  EXPECT_EQ(resolved[0].path, "supports[0].select");
  EXPECT_EQ(resolved[0].nodes, (std::vector<int>{0, 9}));
}

TEST(OutlineGeometry, AreasDistancesAndCorners) {
  PolygonOutline ell{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  EXPECT_DOUBLE_EQ(OutlineArea(ell), 3.0);
  EXPECT_DOUBLE_EQ(DistanceToOutline(ell, {0.5, 0.5}), 0.0);
  EXPECT_DOUBLE_EQ(DistanceToOutline(ell, {1.5, 1.5}), 0.5);  // in the notch
  EXPECT_DOUBLE_EQ(DistanceToOutline(ell, {3, 0.5}), 1.0);
  EXPECT_EQ(OutlineCorners(ell).size(), 6u);
  EXPECT_NEAR(OutlineArea(DiskOutline{0.1, {0, 0}}), M_PI * 0.01, 1e-15);
  EXPECT_DOUBLE_EQ(DistanceToOutline(DiskOutline{1, {0, 0}}, {3, 4}), 4.0);
  EXPECT_DOUBLE_EQ(DistanceToOutline(kStrip, {0.13, 0.05}), std::hypot(0.03, 0.04));
  EXPECT_DOUBLE_EQ(OutlineSize(kStrip), std::hypot(0.2, 0.02));
}

}  // namespace
}  // namespace drape
