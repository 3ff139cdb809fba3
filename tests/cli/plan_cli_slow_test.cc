// The shipped recovery plan (resources/plans/strip-fold-recovery.json,
// docs/plan.md): the strip fold's arc started 3 cm off centre and 20° short
// is brought back until the end lands within 0.5 mm of where the shipped
// fold lands it, every step of the best run stable, in at most 60 runs;
// and the flat term measured on the paper's diagonal fold.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(PlanCliSlow, TheStripFoldIsRecoveredFromAPathGoneWrong) {
  const fs::path out = fs::temp_directory_path() / ("drape-plan-slow-" + std::to_string(getpid()));
  fs::remove_all(out);
  const test::CommandResult r = test::RunDrape(
      "plan '" + (test::SourceDir() / "resources/plans/strip-fold-recovery.json").string() +
      "' -o '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = test::ReadCsv(out / "plan.csv");
  EXPECT_LE(rows.size() - 1, 60u);
  // (−10 cm, 0, 0) turned 180° about the axis through (0, 0, c), then 1 cm on.
  const double c = 0.035175e-2;
  const json best = json::parse(test::ReadText(out / "best" / "result" / "result.json"));
  ASSERT_EQ(best["status"], "converged");
  const auto end = best["final"]["probes"]["end"];
  const double miss =
      std::hypot(end[0].get<double>() - 0.11, end[1].get<double>(), end[2].get<double>() - 2 * c);
  std::printf("recovered in %zu runs: the end lands %.4f mm from the shipped landing\n",
              rows.size() - 1,
              miss * 1e3);
  EXPECT_LT(miss, 0.5e-3);
  for (const json& step : best["steps"]) EXPECT_EQ(step["negative_pivots"], 0);
  fs::remove_all(out);
}

// The flat term on the paper's diagonal fold: the half on the gripped
// corner's side of the diagonal, on one layer of fabric (layer 2), the gap
// 90 % of its nodes stay within — against the same measure taken here from
// result.json's final positions (the table's top at −h/2, so a node resting
// on the lower layer has z = h).
TEST(PlanCliSlow, TheFlatGapOfAFoldedHalfIsItsNodesHeightAboveOneLayer) {
  const fs::path dir = fs::temp_directory_path() / ("drape-plan-flat-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "diagonal.json", out = dir / "out";
  std::ofstream(file) << R"({"drape_plan": 1, "scene": ")"
                      << (test::ScenesDir() / "diagonal-fold.json").string() << R"(",
      "parameters": [{"key": "stages[1].moves[0].path.arc.angle_deg", "min": 179, "max": 180, "start": 180}],
      "objective": {"flat": {"side": {"line": [["-10 cm", "10 cm"], ["10 cm", "-10 cm"]],
                                      "toward": ["-10 cm", "-10 cm"]},
                             "on": "table", "layer": 2, "share": 0.9}},
      "optimizer": {"max_evaluations": 4}})";
  const test::CommandResult r =
      test::RunDrape("plan '" + file.string() + "' -o '" + out.string() + "' --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = test::ReadCsv(out / "plan.csv");
  ASSERT_GE(rows.size(), 2u);
  const json result =
      json::parse(test::ReadText(out / "evals" / "s1-e0001" / "result" / "result.json"));
  const double h = 0.0489e-2;
  std::vector<double> gaps;
  const json& positions = result["final"]["positions"];
  // The 20 × 20 mesh's node k sits at (−10 + (k % 21), −10 + k / 21) cm.
  for (size_t k = 0; k < positions.size(); ++k)
    if ((k % 21) + (k / 21) <= 20) gaps.push_back(std::max(0.0, positions[k][2].get<double>() - h));
  ASSERT_EQ(gaps.size(), 231u);  // the triangle with its diagonal
  std::sort(gaps.begin(), gaps.end());
  const double expected = gaps[static_cast<size_t>(std::ceil(0.9 * 231)) - 1];
  EXPECT_NEAR(std::stod(rows[1][test::Column(rows[0], "flat_gap_m")]), expected, 1e-9);
  // The paper's path leaves the half on the loop, not on the lower layer
  // (docs/plan.md: 36 mm, 74 h).
  EXPECT_GT(expected, 30 * h);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace drape
