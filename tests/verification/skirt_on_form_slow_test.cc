// The shipped pattern example (issue 38): resources/scenes/skirt-on-form.json
// drapes the SKIRT-FRONT piece of resources/patterns/garments.dxf over the
// dress form, pinned at its middle drill hole, run as a user runs it (the
// `drape` binary). It must end at rest on a stable state (0 negative
// pivots), its weight carried by the form and the pin (global equilibrium:
// the piece's area from the pattern's coordinates, its weight per area from
// the library), no node's mid-surface within h/2 of the form on any step
// (measured from states.bin), no material line stretched (each probe no
// farther from the pin than on the flat piece), and no number it writes
// NaN. ~90 s: the slow tier, and so left out of the shipped scenes' fast
// run (tests/render/shipped_scenes_test.cc).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/io/scene_reader.h"
#include "core/io/state_file.h"
#include "core/model/obstacle_geometry.h"
#include "support/drape_command.h"
#include "support/finite_outputs.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// SKIRT-FRONT's cut line as resources/patterns/garments.json draws it [cm].
const double kCut[][2] = {{-30, 0},
                          {30, 0},
                          {24.5, 35},
                          {22, 45},
                          {19, 55},
                          {10.5, 54.7},
                          {8.5, 54.6},
                          {0, 54.4},
                          {-8.5, 54.6},
                          {-10.5, 54.7},
                          {-19, 55},
                          {-22, 45},
                          {-24.5, 35}};

double CutAreaM2() {
  double twice = 0;
  const int n = sizeof kCut / sizeof kCut[0];
  for (int i = 0; i < n; ++i)
    twice += kCut[i][0] * kCut[(i + 1) % n][1] - kCut[(i + 1) % n][0] * kCut[i][1];
  return std::abs(twice) / 2 * 1e-4;
}

Eigen::Vector3d Vector(const nlohmann::json& j) {
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

TEST(SkirtOnForm, ThePatternPieceRestsStablyOnTheForm) {
  const std::filesystem::path file = test::ScenesDir() / "skirt-on-form.json";
  const Scene scene = ReadScene(file);
  const test::TempDir dir("skirt-on-form");
  const test::CommandResult run =
      test::RunDrape("run '" + file.string() + "' -o '" + dir.path().string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(dir / "result.json");
  const nlohmann::json result = nlohmann::json::parse(in);
  EXPECT_EQ(result["status"], "converged") << result["message"];
  std::vector<std::string> nulls;
  test::CollectNulls(result, "", nulls);
  EXPECT_TRUE(nulls.empty()) << "result.json: first non-finite number at " << nulls.front();
  const nlohmann::json& last = result["steps"].back();
  EXPECT_EQ(last["negative_pivots"], 0);
  EXPECT_EQ(last["lambda"], 1.0);

  // The weight: the piece's area at the library's weight per area, all of
  // it on the form and the pin.
  const double weight = CutAreaM2() * scene.material.areal_weight;
  const Eigen::Vector3d pin_force = Vector(last["reactions"]["pin"]);
  const Eigen::Vector3d held = Vector(last["contact"]["force"]) + pin_force;
  EXPECT_NEAR(held.z(), weight, 1e-3 * weight);
  EXPECT_NEAR(held.head<2>().norm(), 0.0, 1e-3 * weight);
  // The form carries the weight (measured: the pin 1.2 % of it); the pin
  // keeps the piece from sliding off the front (measured: 0.11 of it).
  EXPECT_LT(std::abs(pin_force.z()), 0.05 * weight);
  EXPECT_EQ(last["contact"]["max_penetration"], 0.0);

  // No node's mid-surface within h/2 of the form, on any step.
  const auto form = MakeObstacleGeometry(scene.obstacles.at(0), test::ScenesDir());
  const StateFile states = ReadStateFile(dir / "states.bin");
  double smallest_gap = INFINITY;
  for (const StoredStep& s : states.steps)
    for (int i = 0; i < s.positions.rows(); ++i)
      smallest_gap = std::min(
          smallest_gap,
          form->Query(s.positions.row(i).transpose()).distance - 0.5 * scene.material.thickness);
  EXPECT_GT(smallest_gap, 0.0);

  // The pin holds the piece's middle (0, 27.5) cm at the top of the neck.
  const Eigen::Vector3d pin(0, 0, scene.fabric.elevation);
  const std::pair<const char*, double> flat[] = {
      {"hem_middle", 0.275}, {"hem_corner", std::hypot(0.30, 0.275)}, {"waist_middle", 0.269}};
  for (const auto& [probe, distance] : flat)
    EXPECT_LE((Vector(result["final"]["probes"][probe]) - pin).norm(), distance * 1.001) << probe;
  // It fell: the hem's corner hangs well below the shoulders (z ≈ 0.5 m).
  const Eigen::Vector3d corner = Vector(result["final"]["probes"]["hem_corner"]);
  EXPECT_LT(corner.z(), 0.45);
  std::printf(
      "skirt on the form: %zu steps, %zu stability events; the pin carries %.3f of the weight; "
      "hem corner at (%.3f, %.3f, %.3f) m; closest gap %.3g h\n",
      result["steps"].size(),
      result["stability_events"].size(),
      pin_force.norm() / weight,
      corner.x(),
      corner.y(),
      corner.z(),
      smallest_gap / scene.material.thickness);
}

}  // namespace
}  // namespace drape
