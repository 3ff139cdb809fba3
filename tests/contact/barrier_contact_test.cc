// Verification of barrier contact with obstacles (contact.law "barrier",
// node_contact.h): the force and tangent against central differences of the
// barrier energy written here from its formula; the step bound against
// closed forms (a node heading straight for a plane) and against the
// distance at the step's end on every shape, the dress form's mesh
// included; and whole runs: a sheet resting on a table under its weight at
// the gap where the barrier carries it (solved here by bisection), and the
// errors of a fabric that starts touching and of a barrier distance larger
// than the part.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/contact/contact_setup.h"
#include "core/contact/node_contact.h"
#include "core/fe/shell_model.h"
#include "core/model/obstacle_geometry.h"
#include "core/model/scene_error.h"
#include "core/solve/shell_solver.h"
#include "support/contact_scenes.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// b(g) = −(g − d̂)² ln(g/d̂) for 0 < g < d̂ and its first derivative, from
// the formula (C-IPC's clamped log barrier on the gap).
double Barrier(double g, double d_hat) {
  return g >= d_hat ? 0.0 : -(g - d_hat) * (g - d_hat) * std::log(g / d_hat);
}
double BarrierSlope(double g, double d_hat) {
  return g >= d_hat ? 0.0 : -2 * (g - d_hat) * std::log(g / d_hat) - (g - d_hat) * (g - d_hat) / g;
}

constexpr double kThickness = 1e-3;  // h [m]
constexpr double kHalf = kThickness / 2;
constexpr double kDistance = 4e-4;  // d̂ [m]
constexpr double kStiffness = 1e5;  // κ per area [N/m³]

ShellModel SmallModel() {
  test::SheetSpec spec;
  spec.thickness = kThickness;
  spec.size = 0.03;
  spec.elements = 3;
  return BuildShellModel(test::FreeSheet(spec));
}

NodeContact BarrierAgainst(const ShellModel& model, const Obstacle& obstacle) {
  std::vector<NamedObstacle> obstacles;
  obstacles.push_back({obstacle.name, MakeObstacleGeometry(obstacle, ".")});
  return NodeContact(model, std::move(obstacles), NormalLaw{0, kDistance, kStiffness}, 0.0);
}

std::vector<Obstacle> Shapes() {
  return {{"plane", PlaneShape{{0, 0, -0.002}, {0.2, -0.3, 0.93}}},
          {"ball", SphereShape{{0.0, 0.0, -0.012}, 0.01}},
          {"box", BoxShape{{-0.03, -0.02, -0.02}, {0.01, 0.01, -0.002}, 0.004}},
          {"rod", CylinderShape{{0, 0, -0.006}, {1, 1, 0}, 0.005, {}}}};
}

// Each node of `state` put at a gap drawn from (0.05 d̂, 1.5 d̂) from the
// obstacle, pulled along the normal (exact for a signed distance).
ShellState NearTheSurface(ShellState state, const ObstacleGeometry& geometry, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < state.NodeCount(); ++i) {
    Eigen::Vector3d x = state.positions.row(i).transpose();
    for (int pull = 0; pull < 3; ++pull) {
      const DistanceQuery q = geometry.Query(x);
      const double target = kHalf + (0.05 + 1.45 * unit(rng)) * kDistance;
      x -= (q.distance - target) * q.normal;
    }
    state.positions.row(i) = x.transpose();
  }
  return state;
}

TEST(BarrierContact, ForceAndTangentAreTheBarriersDerivatives) {
  const ShellModel model = SmallModel();
  std::mt19937 rng(7);
  for (const Obstacle& obstacle : Shapes()) {
    const NodeContact contact = BarrierAgainst(model, obstacle);
    const auto geometry = MakeObstacleGeometry(obstacle, ".");
    const std::vector<double>& area = contact.nodal_area();
    auto energy = [&](const ShellState& s) {
      double e = 0;
      for (int i = 0; i < s.NodeCount(); ++i)
        e += kStiffness * area[i] *
             Barrier(geometry->Query(s.positions.row(i).transpose()).distance - kHalf, kDistance);
      return e;
    };
    auto internal = [&](const ShellState& s) {
      Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
      contact.Add(s, f, nullptr, nullptr, nullptr);
      return f;
    };
    for (int round = 0; round < 4; ++round) {
      const ShellState state = NearTheSurface(model.reference, *geometry, rng);
      EXPECT_NEAR(contact.Energy(state), energy(state), 1e-12 * energy(state)) << obstacle.name;
      Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
      std::vector<Eigen::Matrix3d> blocks;
      contact.Add(state, f, &blocks, nullptr, nullptr);
      int inside_band = 0;
      for (int i = 0; i < model.NodeCount(); ++i) {
        const double g = geometry->Query(state.positions.row(i).transpose()).distance - kHalf;
        if (g < kDistance) ++inside_band;
        // A step far below the gap (≥ 0.05 d̂ = 20 µm): truncation ~ (h/g)².
        const double step = 1e-9;
        Eigen::Matrix3d fd;
        Eigen::Vector3d fd_force;
        for (int k = 0; k < 3; ++k) {
          ShellState plus = state, minus = state;
          plus.positions(i, k) += step;
          minus.positions(i, k) -= step;
          fd_force[k] = (energy(plus) - energy(minus)) / (2 * step);
          fd.col(k) = (internal(plus) - internal(minus)).segment<3>(kDofsPerNode * i) / (2 * step);
        }
        const Eigen::Vector3d force = f.segment<3>(kDofsPerNode * i);
        const double scale = std::max(fd_force.norm(), 1e-12);
        EXPECT_LT((force - fd_force).norm(), 1e-5 * scale)
            << obstacle.name << " node " << i << " g/d̂ = " << g / kDistance;
        const double block_scale = std::max(fd.norm(), 1e-9);
        EXPECT_LT((blocks[i] - fd).norm(), 1e-5 * block_scale)
            << obstacle.name << " node " << i << " g/d̂ = " << g / kDistance << "\n"
            << blocks[i] << "\nfd\n"
            << fd;
        // Its normal force, −κ A b'(g), from the formula.
        EXPECT_NEAR(force.norm(),
                    -kStiffness * area[i] * BarrierSlope(g, kDistance),
                    1e-10 * std::max(force.norm(), 1e-12));
      }
      EXPECT_GT(inside_band, 0) << obstacle.name;
      EXPECT_LT(inside_band, model.NodeCount()) << obstacle.name;
    }
  }
}

TEST(BarrierContact, AStepStopsWhereANodeWouldCloseNineTenthsOfItsGap) {
  const ShellModel model = SmallModel();
  const Obstacle table{"table", PlaneShape{{0, 0, -kHalf - 2e-4}, {0, 0, 1}}};
  const NodeContact contact = BarrierAgainst(model, table);
  // Every node 0.2 mm above the table's surface (gap g); one heads straight
  // down by 2g: it may go 0.9 g of it, t = 0.45.
  Eigen::MatrixX3d dx = Eigen::MatrixX3d::Zero(model.NodeCount(), 3);
  dx(5, 2) = -4e-4;
  EXPECT_NEAR(contact.StepBound(model.reference, dx), 0.45, 1e-12);
  // Slanted by 45°, the same closing speed: the same bound.
  dx(5, 0) = 4e-4;
  EXPECT_NEAR(contact.StepBound(model.reference, dx), 0.45, 1e-12);
  // Along the table or away from it, and down by less than 0.9 g: whole.
  dx.setZero();
  dx(3, 0) = 0.05;
  dx(4, 2) = 0.01;
  dx(6, 2) = -1.7e-4;
  EXPECT_EQ(contact.StepBound(model.reference, dx), 1.0);
  // The penalty law never cuts a step.
  std::vector<NamedObstacle> obstacles;
  obstacles.push_back({"table", MakeObstacleGeometry(table, ".")});
  const NodeContact penalty(model, std::move(obstacles), NormalLaw{1e7}, 0.0);
  dx(5, 2) = -1.0;
  EXPECT_EQ(penalty.StepBound(model.reference, dx), 1.0);
}

// Random moves of up to 5 mm from gaps of (0.05, 1.5) d̂: every node keeps
// at least a tenth of its gap at the bounded step's end (checked by the
// distance there), on the convex shapes and on the dress form's mesh.
TEST(BarrierContact, NoBoundedStepEndsInsideAnyShape) {
  const ShellModel model = SmallModel();
  std::vector<Obstacle> shapes = Shapes();
  shapes.push_back(
      {"form", MeshShape{(test::SourceDir() / "resources/forms/dress-form.obj").string(), {}}});
  std::get<MeshShape>(shapes.back().shape).resolved_path =
      std::get<MeshShape>(shapes.back().shape).file;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const Obstacle& obstacle : shapes) {
    const auto geometry = MakeObstacleGeometry(obstacle, ".");
    const NodeContact contact = BarrierAgainst(model, obstacle);
    int cut = 0;
    for (int round = 0; round < 20; ++round) {
      ShellState state = model.reference;
      if (obstacle.name == "form")  // about its shoulders and chest
        for (int i = 0; i < model.NodeCount(); ++i)
          state.positions.row(i) =
              Eigen::RowVector3d(0.15 * unit(rng), 0.12 * unit(rng), 0.45 + 0.1 * unit(rng));
      state = NearTheSurface(state, *geometry, rng);
      Eigen::MatrixX3d dx(model.NodeCount(), 3);
      for (int i = 0; i < model.NodeCount(); ++i)
        dx.row(i) = 5e-3 * Eigen::RowVector3d(unit(rng), unit(rng), unit(rng));
      const double t = contact.StepBound(state, dx);
      ASSERT_GE(t, 0.0);
      ASSERT_LE(t, 1.0);
      if (t < 1) ++cut;
      for (int i = 0; i < model.NodeCount(); ++i) {
        const Eigen::Vector3d x = state.positions.row(i).transpose();
        const double before = geometry->Query(x).distance - kHalf;
        const double after = geometry->Query(x + t * dx.row(i).transpose()).distance - kHalf;
        EXPECT_GE(after, 0.1 * before - 1e-15) << obstacle.name << " node " << i << " t " << t;
      }
    }
    EXPECT_GT(cut, 0) << obstacle.name;
  }
}

Scene SheetOnTableWithBarrier(const test::SheetSpec& spec, double start_gap) {
  Scene scene = test::FreeSheet(spec);
  scene.contact->law = ContactLaw::kBarrier;
  scene.obstacles.push_back(
      {"table", PlaneShape{{0.0, 0.0, -spec.thickness / 2 - start_gap}, {0.0, 0.0, 1.0}}});
  return scene;
}

// A flat sheet on a flat table carries its weight as a uniform pressure w
// (the weight and the contact both share ∫ N_I dA), so every node rests at
// the gap g where −κ b'(g) = w, edges and corners included.
TEST(BarrierContact, ASheetOnATableRestsAtTheGapWhereTheBarrierCarriesItsWeight) {
  const test::SheetSpec spec;  // 10 × 10 cm, 10 × 10 elements, h = 0.5 mm, w = 2 N/m²
  const double d_hat = spec.thickness / 2;  // the default barrier distance
  const Scene scene = SheetOnTableWithBarrier(spec, 0.5 * d_hat);
  const ShellModel model = BuildShellModel(scene);
  const auto contact = MakeNodeContact(scene, model);
  ASSERT_TRUE(contact->HasBarrier());
  EXPECT_DOUBLE_EQ(contact->law().barrier_distance, d_hat);
  // The stiffness as documented: halfway into the band, ten times w.
  const double kappa = contact->law().barrier_stiffness;
  EXPECT_NEAR(
      -kappa * BarrierSlope(0.5 * d_hat, d_hat), 10 * spec.areal_weight, 1e-12 * spec.areal_weight);
  // The gap that carries w, by bisection on the formula's slope.
  double lo = 1e-9 * d_hat, hi = d_hat;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (-kappa * BarrierSlope(mid, d_hat) > spec.areal_weight ? lo : hi) = mid;
  }
  const double gap = 0.5 * (lo + hi);
  ASSERT_GT(gap, 0.5 * d_hat);  // light: it rests in the band's outer half

  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  StepState last;
  int steps = 0;
  double closest = INFINITY;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    last = s;
    ++steps;
    // Every accepted step: no node's surface at or past the table's.
    closest = std::min(closest, s.state.positions.col(2).minCoeff() + 0.5 * d_hat);
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  EXPECT_GT(closest, 0.0);
  const auto z = last.state.positions.col(2);
  // z = gap − d̂/2 (the table's surface is d̂/2 below the start).
  EXPECT_NEAR(z.maxCoeff(), gap - 0.5 * d_hat, 1e-6 * d_hat);
  EXPECT_NEAR(z.minCoeff(), gap - 0.5 * d_hat, 1e-6 * d_hat);
  ASSERT_TRUE(last.contact);
  const double weight = spec.areal_weight * spec.size * spec.size;
  EXPECT_LT((last.contact->force + model.total_weight).norm(), 1e-6 * weight);
  EXPECT_EQ(last.contact->max_penetration, 0.0);
  std::printf("sheet on a table, barrier: rests at g = %.6g d̂ (closed form %.6g d̂), %d steps\n",
              (z.mean() + 0.5 * d_hat) / d_hat,
              gap / d_hat,
              steps);
}

TEST(BarrierContact, AFabricThatStartsTouchingOrABarrierWiderThanThePartIsOneError) {
  const test::SheetSpec spec;
  Scene touching = SheetOnTableWithBarrier(spec, 0.0);
  try {
    MakeNodeContact(touching, BuildShellModel(touching));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("the fabric starts touching obstacle 'table'"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("contact.law \"penalty\""), std::string::npos) << e.what();
  }
  Scene wide = SheetOnTableWithBarrier(spec, 1e-4);
  wide.contact->barrier_distance = 0.2;  // the part's diagonal is 0.141 m
  try {
    MakeNodeContact(wide, BuildShellModel(wide));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.barrier_distance"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("(200 mm) must be smaller than the part (its diagonal is "
                                         "141.4 mm)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace drape
