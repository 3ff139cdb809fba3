#include "core/model/obstacle_anchor.h"

#include <gtest/gtest.h>

#include "core/model/obstacle_geometry.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// A rigid translation by b moves the distance field with it:
// d_moved(x + b) = d(x) at every x.
void ExpectMovedRigidly(const Obstacle& o, const Eigen::Vector3d& by) {
  const auto before = MakeObstacleGeometry(o, ".");
  const auto after = MakeObstacleGeometry(Translated(o, by), ".");
  for (const Eigen::Vector3d& x : {Eigen::Vector3d(0.3, -0.2, 0.1),
                                   Eigen::Vector3d(0.0, 0.0, 0.0),
                                   Eigen::Vector3d(-0.05, 0.12, -0.4)})
    EXPECT_NEAR(after->Query(x + by).distance, before->Query(x).distance, 1e-14) << o.name;
  EXPECT_LT((*ObstacleAnchor(Translated(o, by)) - *ObstacleAnchor(o) - by).norm(), 1e-15);
}

TEST(ObstacleAnchor, IsWhereEachShapeIsPlaced) {
  EXPECT_EQ(*ObstacleAnchor({"table", PlaneShape{{0, 0, -0.1}, {0, 0, 1}}}),
            Eigen::Vector3d(0, 0, -0.1));
  EXPECT_LT((*ObstacleAnchor({"block", BoxShape{{-0.1, -0.2, -0.3}, {0.1, 0.2, 0.1}, 0.01}}) -
             Eigen::Vector3d(0, 0, -0.1))
                .norm(),
            1e-15);
  EXPECT_EQ(*ObstacleAnchor({"rod", CylinderShape{{0.1, 0, 0}, {0, 1, 0}, 0.01, std::nullopt}}),
            Eigen::Vector3d(0.1, 0, 0));
  EXPECT_EQ(*ObstacleAnchor({"ball", SphereShape{{0, 0.2, 0}, 0.05}}), Eigen::Vector3d(0, 0.2, 0));
  MeshShape form{"form.obj", ""};
  form.at = {0.1, -0.2, 0.3};
  EXPECT_EQ(*ObstacleAnchor({"form", form}), Eigen::Vector3d(0.1, -0.2, 0.3));
}

TEST(ObstacleAnchor, TranslatedShapesKeepTheirDistanceFields) {
  const Eigen::Vector3d by(0.02, -0.03, 0.05);
  ExpectMovedRigidly({"table", PlaneShape{{0, 0, -0.1}, {0, 0.6, 0.8}}}, by);
  ExpectMovedRigidly({"block", BoxShape{{-0.1, -0.2, -0.3}, {0.1, 0.2, 0.1}, 0.01}}, by);
  ExpectMovedRigidly({"rod", CylinderShape{{0.1, 0, 0}, {0, 0.6, 0.8}, 0.01, 0.3}}, by);
  ExpectMovedRigidly({"ball", SphereShape{{0, 0.2, 0}, 0.05}}, by);
  const std::string cube = (test::SourceDir() / "resources/forms/unit-cube.stl").string();
  MeshShape turned{cube, cube};
  turned.scale = {0.2, 0.3, 0.4};
  turned.rotation_deg = 30;
  turned.at = {0.1, 0, -0.2};
  ExpectMovedRigidly({"form", turned}, by);
}

}  // namespace
}  // namespace drape
