// The shipped recovery plan (resources/plans/strip-fold-recovery.json,
// docs/plan.md): the strip fold's arc started 3 cm off centre and 20° short
// is brought back until the end lands within 0.5 mm of where the shipped
// fold lands it, every step of the best run stable, in at most 60 runs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

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

}  // namespace
}  // namespace drape
