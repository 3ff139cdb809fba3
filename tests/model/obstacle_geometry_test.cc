// Distance queries of the analytic obstacle shapes (plane, sphere, finite and
// infinite cylinder, rounded box) against closed forms, their normal and
// Hessian against central differences; mesh shapes found through the scene.
#include "core/model/obstacle_geometry.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>

#include "core/model/scene_error.h"
#include "support/obstacle_test_geometry.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using test::CheckDerivatives;
using test::ExpectQuery;
using test::Frame;
using test::InBox;
using test::Make;
using test::Rng;
using test::Uniform;
using test::UnitVector;

TEST(ObstacleGeometry, PlaneDistanceAndDerivatives) {
  const Vector3d point(0.1, -0.2, 0.3), normal = Vector3d(1, 2, 2) / 3;
  const auto g = Make(PlaneShape{{0.1, -0.2, 0.3}, {1.0 / 3, 2.0 / 3, 2.0 / 3}});
  Rng rng(1);
  for (int i = 0; i < 20; ++i) {
    const Vector3d x = InBox(rng, Vector3d::Constant(-1), Vector3d::Constant(1));
    ExpectQuery(g->Query(x), normal.dot(x - point), normal);
    EXPECT_EQ(g->Query(x).hessian, Matrix3d::Zero());
  }
  CheckDerivatives(*g, {{"anywhere", [](Rng& r) -> std::optional<Vector3d> {
                           return InBox(r, Vector3d::Constant(-1), Vector3d::Constant(1));
                         }}});
}

TEST(ObstacleGeometry, SphereDistanceAndDerivatives) {
  const Vector3d center(0.1, 0.2, -0.3);
  const double radius = 0.5;
  const auto g = Make(SphereShape{{0.1, 0.2, -0.3}, radius});
  ExpectQuery(g->Query(center + Vector3d(0, 0.3, 0.4)), 0.0, Vector3d(0, 0.6, 0.8));
  ExpectQuery(g->Query(center + Vector3d(2, 0, 0)), 1.5, Vector3d::UnitX());
  ExpectQuery(g->Query(center + Vector3d(0, -0.1, 0)), -0.4, -Vector3d::UnitY());
  // Away from the centre, where the normal is undefined.
  CheckDerivatives(*g, {{"around", [&](Rng& r) -> std::optional<Vector3d> {
                           return center + Uniform(r, 0.1, 1.5) * UnitVector(r);
                         }}});
}

TEST(ObstacleGeometry, InfiniteCylinderDerivatives) {
  const Vector3d point(0.2, -0.1, 0.4), axis = Vector3d(1, 1, 0).normalized();
  const auto g = Make(CylinderShape{{0.2, -0.1, 0.4}, {axis.x(), axis.y(), axis.z()}, 0.3, {}});
  const auto [u, w] = Frame(axis);
  ExpectQuery(g->Query(point + 5 * axis + 0.7 * u), 0.4, u);
  ExpectQuery(g->Query(point - 3 * axis - 0.1 * w), -0.2, -w);
  CheckDerivatives(*g, {{"around", [&](Rng& r) -> std::optional<Vector3d> {
                           const double angle = Uniform(r, 0, 2 * std::numbers::pi);
                           return point + Uniform(r, -2, 2) * axis +
                                  Uniform(r, 0.05, 1.0) *
                                      (std::cos(angle) * u + std::sin(angle) * w);
                         }}});
}

// A tilted finite cylinder, sampled in (t along the axis, ρ from it).
TEST(ObstacleGeometry, FiniteCylinderDerivativesBySideCapAndRim) {
  const Vector3d point(0.1, 0, 0.2), axis = Vector3d(0.2, -0.3, 1).normalized();
  const double radius = 0.3, half = 0.4, m = 1e-2;
  const auto g =
      Make(CylinderShape{{0.1, 0, 0.2}, {axis.x(), axis.y(), axis.z()}, radius, 2 * half});
  const auto [u, w] = Frame(axis);
  auto at = [&](Rng& r, double t, double rho) -> std::optional<Vector3d> {
    const double angle = Uniform(r, 0, 2 * std::numbers::pi);
    const double sign = Uniform(r, -1, 1) < 0 ? -1 : 1;
    return point + sign * t * axis + rho * (std::cos(angle) * u + std::sin(angle) * w);
  };
  CheckDerivatives(
      *g,
      {{"side outside",
        [&](Rng& r) { return at(r, Uniform(r, 0, half - m), Uniform(r, radius + m, 3 * radius)); }},
       {"cap outside",
        [&](Rng& r) { return at(r, Uniform(r, half + m, 3 * half), Uniform(r, m, radius - m)); }},
       {"rim",
        [&](Rng& r) {
          return at(r, Uniform(r, half + m, 3 * half), Uniform(r, radius + m, 3 * radius));
        }},
       {"side inside",
        [&](Rng& r) -> std::optional<Vector3d> {
          const double t = Uniform(r, 0, half), rho = Uniform(r, 0.05, radius - m);
          if ((rho - radius) - (t - half) < m) return std::nullopt;
          return at(r, t, rho);
        }},
       {"cap inside", [&](Rng& r) -> std::optional<Vector3d> {
          const double t = Uniform(r, 0, half - m), rho = Uniform(r, 0.05, radius);
          if ((t - half) - (rho - radius) < m) return std::nullopt;
          return at(r, t, rho);
        }}});
}

TEST(ObstacleGeometry, FiniteCylinderClosedForm) {
  const auto g = Make(CylinderShape{{0, 0, 0}, {0, 0, 1}, 0.3, 0.8});
  ExpectQuery(g->Query({0, 0.5, 0.1}), 0.2, Vector3d::UnitY());
  ExpectQuery(g->Query({0.1, 0, -0.6}), 0.2, -Vector3d::UnitZ());
  ExpectQuery(g->Query({0.1, 0, 0.3}), -0.1, Vector3d::UnitZ());
  // Rim: 0.2 beyond the side, 0.3 beyond the cap.
  const DistanceQuery rim = g->Query({0.5, 0, 0.7});
  const double d = std::sqrt(0.13);
  ExpectQuery(rim, d, Vector3d(0.2, 0, 0.3) / d);
  // Along the rim circle the normal turns as on a torus of tube radius d
  // about a circle of radius 0.3 seen from ρ = 0.5: (1 − 0.3/0.5)/d.
  EXPECT_NEAR(rim.hessian(1, 1), 0.4 / d, 1e-12);
}

// Box [0,1]×[0,0.8]×[0,0.6] with edges rounded by 0.1, sampled by q, the
// excess over the inner box's half-widths (0.4, 0.3, 0.2) per axis.
TEST(ObstacleGeometry, RoundedBoxDerivativesByFaceEdgeCornerAndInside) {
  const double r = 0.1, m = 1e-2;
  const auto g = Make(BoxShape{{0, 0, 0}, {1, 0.8, 0.6}, r});
  const Vector3d center(0.5, 0.4, 0.3), inner(0.4, 0.3, 0.2);
  // `beyond` random axes get q in [m, 0.3] (inside the rounding when
  // q < r), the others stay m inside the inner box's slab.
  auto region = [&](int beyond) {
    return [=](Rng& rng) -> std::optional<Vector3d> {
      std::array<int, 3> axes{0, 1, 2};
      std::shuffle(axes.begin(), axes.end(), rng);
      Vector3d x;
      for (int i = 0; i < 3; ++i) {
        const int k = axes[i];
        const double a =
            i < beyond ? inner[k] + Uniform(rng, m, 0.3) : Uniform(rng, 0, inner[k] - m);
        x[k] = center[k] + (Uniform(rng, -1, 1) < 0 ? -a : a);
      }
      return x;
    };
  };
  CheckDerivatives(*g,
                   {{"face", region(1)},
                    {"edge", region(2)},
                    {"corner", region(3)},
                    {"inner box", [&](Rng& rng) -> std::optional<Vector3d> {
                       const Vector3d x = InBox(rng, center - inner, center + inner);
                       std::array<double, 3> q;
                       for (int k = 0; k < 3; ++k) q[k] = std::abs(x[k] - center[k]) - inner[k];
                       std::sort(q.begin(), q.end());
                       if (q[2] - q[1] < m) return std::nullopt;  // the medial surface
                       return x;
                     }}});
}

TEST(ObstacleGeometry, RoundedBoxClosedForm) {
  // Inner box [0.1, 0.9]³.
  const auto g = Make(BoxShape{{0, 0, 0}, {1, 1, 1}, 0.1});
  ExpectQuery(g->Query({0.5, 0.5, 1.3}), 0.3, Vector3d::UnitZ());
  ExpectQuery(
      g->Query({1.5, 1.5, 0.5}), 0.6 * std::sqrt(2.0) - 0.1, Vector3d(1, 1, 0).normalized());
  ExpectQuery(
      g->Query({1.2, 1.3, 1.4}), std::sqrt(0.5) - 0.1, Vector3d(0.3, 0.4, 0.5).normalized());
  ExpectQuery(g->Query({0.5, 0.5, 0.8}), -0.2, Vector3d::UnitZ());
  ExpectQuery(g->Query({0.5, 0.05, 0.5}), -0.05, -Vector3d::UnitY());
  // Inside the sharp box but outside the rounded corner.
  ExpectQuery(
      g->Query({0.98, 0.98, 0.98}), 0.08 * std::sqrt(3.0) - 0.1, Vector3d::Ones().normalized());
  const DistanceQuery edge = g->Query({1.5, 1.5, 0.5});
  const double rho = 0.6 * std::sqrt(2.0);
  EXPECT_NEAR(edge.hessian(2, 2), 0.0, 1e-12);
  EXPECT_NEAR(edge.hessian(0, 0), 0.5 / rho, 1e-12);
  EXPECT_NEAR(edge.hessian(0, 1), -0.5 / rho, 1e-12);
}

TEST(ObstacleGeometry, MeshShapeUsesResolvedPath) {
  const fs::path cube = test::SourceDir() / "resources" / "forms" / "unit-cube.stl";
  // The resolved path wins over the scene directory.
  const auto resolved =
      MakeObstacleGeometry(Obstacle{"form", MeshShape{"cube.stl", cube.string()}}, "/no/such/dir");
  ExpectQuery(resolved->Query({0.5, 0.5, 1.25}), 0.25, Vector3d::UnitZ());
  // Without it, the file is relative to the scene.
  const auto relative =
      MakeObstacleGeometry(Obstacle{"form", MeshShape{"unit-cube.stl", ""}}, cube.parent_path());
  ExpectQuery(relative->Query({0.5, 0.5, 0.75}), -0.25, Vector3d::UnitZ());
}

TEST(ObstacleGeometry, MeshShapeErrorNamesObstacle) {
  try {
    MakeObstacleGeometry(
        Obstacle{"mannequin", MeshShape{"gone.obj", ""}}, "/no/such/dir", "obstacles[3]");
    ADD_FAILURE() << "no SceneError";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.where(), "obstacles[3].mesh.file");
    EXPECT_NE(error.message().find("cannot read"), std::string::npos) << error.message();
    EXPECT_NE(error.message().find("/no/such/dir/gone.obj"), std::string::npos) << error.message();
  }
}
}  // namespace
}  // namespace drape
