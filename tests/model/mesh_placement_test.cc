// A mesh obstacle placed in the world (scale, turn, move) against the box it
// must become, and the flat fabric lowered onto an obstacle against the
// heights worked out by hand: a sphere's cap and the dress form's flat neck.
#include "core/model/mesh_placement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/model/elevation_above.h"
#include "core/model/obstacle_geometry.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

Obstacle PlacedCube(const Vec3& scale, double rotation_deg, const Vec3& at) {
  const std::string cube = (test::SourceDir() / "resources/forms/unit-cube.stl").string();
  MeshShape shape{cube, cube};
  shape.scale = scale;
  shape.rotation_deg = rotation_deg;
  shape.at = at;
  return {"cube", shape};
}

// The unit cube [0, 1]³ scaled by (0.2, 0.3, 0.4) and turned a quarter about
// z (x → y, y → −x) occupies x ∈ [−0.3, 0], y ∈ [0, 0.2], z ∈ [0, 0.4],
// then moved by `at`: its distance outside is a sharp box's.
TEST(MeshPlacement, ScalesTurnsAndMovesTheFile) {
  const Vec3 at{1, 2, 3};
  const auto placed = MakeObstacleGeometry(PlacedCube({0.2, 0.3, 0.4}, 90, at), ".");
  const Vector3d lo(0.7, 2.0, 3.0), hi(1.0, 2.2, 3.4);
  const auto box =
      MakeObstacleGeometry({"box", BoxShape{{0.7, 2.0, 3.0}, {1.0, 2.2, 3.4}, 0}}, ".");
  for (const Vector3d& x : {Vector3d(1.5, 2.1, 3.2),
                            Vector3d(0.85, 1.7, 3.1),
                            Vector3d(0.2, 2.5, 2.0),
                            Vector3d(0.9, 2.1, 4.0),
                            Vector3d(1.3, 2.6, 3.9)})
    EXPECT_NEAR(placed->Query(x).distance, box->Query(x).distance, 1e-12) << x.transpose();
  const auto bounds = placed->Bounds();
  ASSERT_TRUE(bounds);
  EXPECT_LT((bounds->min() - lo).norm(), 1e-12);
  EXPECT_LT((bounds->max() - hi).norm(), 1e-12);
}

std::vector<Vector2d> Grid(const Vector2d& center, double half, int n) {
  std::vector<Vector2d> points;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      points.push_back(center + half * Vector2d(2.0 * i / n - 1, 2.0 * j / n - 1));
  return points;
}

// Lowered onto a sphere, the sheet's point nearest the centre (in plan, at
// distance a) is the first within c of it: z = z_c + √((R + c)² − a²).
TEST(ElevationAbove, LowersTheSheetOntoASphere) {
  const auto ball = MakeObstacleGeometry({"ball", SphereShape{{0.01, 0.02, 0.3}, 0.1}}, ".");
  const double c = 0.004;
  // A 20 × 20 cm grid at 2 cm: its nearest point is (0.02, 0.02), 1 cm off in plan.
  const auto elevation = ElevationAbove(Grid({0.0, 0.0}, 0.1, 10), *ball, c);
  ASSERT_TRUE(elevation);
  EXPECT_NEAR(*elevation, 0.3 + std::sqrt(std::pow(0.104, 2) - std::pow(0.01, 2)), 1e-6);
}

// The dress form's neck is a flat cap at the form's height: a small sheet
// centred over it stops c above s·0.60 m + at_z, wherever the form is turned.
TEST(ElevationAbove, StopsAboveTheDressFormsNeck) {
  const std::string file = (test::SourceDir() / "resources/forms/dress-form.obj").string();
  MeshShape form{file, file};
  form.scale = {1.1, 1.1, 1.2};
  form.rotation_deg = 35;
  form.at = {0.2, -0.1, 0.05};
  const auto g = MakeObstacleGeometry({"form", form}, ".");
  const double c = 0.003;
  const auto elevation = ElevationAbove(Grid({0.2, -0.1}, 0.03, 6), *g, c);
  ASSERT_TRUE(elevation);
  EXPECT_NEAR(*elevation, 0.05 + 1.2 * 0.60 + c, 1e-6);
}

TEST(ElevationAbove, NoneBesideTheObstacleOrWithoutATop) {
  const auto ball = MakeObstacleGeometry({"ball", SphereShape{{0, 0, 0}, 0.1}}, ".");
  EXPECT_FALSE(ElevationAbove(Grid({0.5, 0.0}, 0.1, 4), *ball, 0.004));
  const auto table = MakeObstacleGeometry({"table", PlaneShape{{0, 0, 0}, {0, 0, 1}}}, ".");
  EXPECT_FALSE(ElevationAbove(Grid({0.0, 0.0}, 0.1, 4), *table, 0.004));
}

}  // namespace
}  // namespace drape
