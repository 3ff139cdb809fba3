// Obstacles carried along a stage's path: the contact force follows the
// obstacle, and the continuation sees the motion through ∂F/∂λ.
//
// A cantilever strip (L = 0.2 m, clamped root, weightless) rests with its
// tip on a rod; the rod rises by δ. For δ ≪ L the tip follows it and the rod
// pushes with Euler–Bernoulli's F = 3 E I δ / L³, less the penetration the
// penalty needs (the tip rises δ − g). Shear adds (E I / κGA)·3/L² ≈ 2e-7 of
// the deflection at this slenderness, well inside the tolerance.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/model/scene_error.h"
#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

constexpr double kLift = 1e-3;  // δ [m]

Scene RodUnderTip(const test::StripSpec& spec, const Path& path) {
  Scene scene = test::CantileverStrip(spec);
  const double radius = 0.01;
  // The rod's top touches the tip's underside (h/2 below the midsurface).
  scene.obstacles.push_back(
      {"rod",
       CylinderShape{{spec.length, 0, -radius - spec.thickness / 2}, {0, 1, 0}, radius, {}}});
  Stage lift;
  lift.name = "lift";
  lift.kind = StageKind::kMove;
  lift.initial_increment = 0.1;
  Move move;
  move.obstacle = "rod";
  move.path = path;
  lift.moves.push_back(move);
  scene.stages.push_back(lift);
  return scene;
}

TEST(MovingObstacle, RisingRodPushesTheTipWithTheBeamStiffness) {
  test::StripSpec spec;  // L = 0.2 m, b = 0.01 m, h = 0.5 mm, E = 1 MPa
  Scene scene = RodUnderTip(spec, LinePath{{0, 0, kLift}});
  scene.solver.tolerance = 1e-10;  // positions to ~1e-10 of the lift
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  const double stiffness = 3 * test::StripBendingStiffness(spec) / std::pow(spec.length, 3);
  int steps = 0;
  const SolveSummary summary = solver.Solve({[&](const StepState& step) {
    ++steps;
    const double lift = step.lambda * kLift;
    // The tip sits on the rod: its midsurface node lies on the circle of
    // radius R + h/2 − p about the rod's axis (p the penetration), which has
    // risen by the lift; the tip has moved dx towards the root (the strip
    // shortens in projection).
    const double tip_rise = step.probes[0].value.z();
    const double dx = step.probes[0].value.x() - spec.length;
    const double offset = 0.01 + spec.thickness / 2;
    const double on_circle =
        lift - offset + std::sqrt(std::pow(offset - step.contact->max_penetration, 2) - dx * dx);
    EXPECT_NEAR(tip_rise, on_circle, 1e-9 * lift);
    // Small deflection (δ/L = 0.005): the force is linear in the tip's rise.
    // Geometric nonlinearity enters as (δ/L)², ~3e-5 relative.
    EXPECT_NEAR(step.contact->force.z(), stiffness * tip_rise, 1e-3 * stiffness * tip_rise)
        << "λ = " << step.lambda;
    EXPECT_EQ(step.contact->nodes, 2);  // the tip's two nodes
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  EXPECT_GE(steps, 2);
  // Auto penalty: the penetration is a tiny part of the thickness.
  EXPECT_LT(summary.max_penetration, 1e-3 * spec.thickness);
}

// Rotating the rod about its own axis changes nothing for a frictionless
// contact: the rod's surface stays where it was. Checks that placements turn
// points into the obstacle's frame and back.
TEST(MovingObstacle, RodTurningAboutItsAxisLeavesTheStripAlone) {
  test::StripSpec spec;
  const double radius = 0.01;
  const Vec3 axis_point{spec.length, 0, -radius - spec.thickness / 2};
  Scene scene = RodUnderTip(spec, ArcPath{axis_point, {0, 1, 0}, 90});
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  const SolveSummary summary = solver.Solve({[&](const StepState& step) {
    EXPECT_NEAR(step.probes[0].value.z(), 0.0, 1e-12);
    // Round-off of the gap (1e-18 m) times the nodal penalty (~250 N/m).
    EXPECT_LT(step.contact->force.norm(), 1e-12);
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
}

TEST(MovingObstacle, SceneNamesTheObstacleItMoves) {
  const std::string scene = R"({
    "drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": [0.2, 0.02], "center": [0.1, 0]}},
               "mesh": {"elements": [10, 1]}},
    "material": {"thickness": 0.0005, "areal_weight": 1.0, "youngs_modulus": 1e6,
                 "poisson_ratio": 0},
    "supports": [{"name": "root", "select": {"edge": "left"}, "fix": "clamp"}],
    "obstacles": [{"name": "table", "plane": {"point": [0, 0, -0.1], "normal": [0, 0, 1]}}],
    "stages": [{"name": "up", "kind": "move",
                "moves": [{"obstacle": "tabel", "path": {"line": {"by": [0, 0, 0.05]}}}]}]
  })";
  try {
    ParseScene(scene);
    ADD_FAILURE() << "an unknown obstacle was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "stages[0].moves[0].obstacle");
    EXPECT_NE(e.message().find("no obstacle is named 'tabel'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace drape
