// `drape run --error-estimate` (and solver.error_estimate): the run, then
// the same scene on meshes 2 and 4 times coarser; result.json's
// error_estimate and the summary line say how far each probe is from the
// converged answer, or why that cannot be told.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/scene_writer.h"
#include "support/drape_command.h"
#include "support/heavy_elastica.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class ErrorEstimateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drape-estimate-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  json Result(const fs::path& out) {
    std::ifstream in(out / "result.json");
    return json::parse(in);
  }
  fs::path dir_;
};

// Peirce's strip (α = 8) on 16 elements: the estimate is the tip's distance
// from the heavy elastica (solved here) within a factor 2, and every number
// is finite.
TEST_F(ErrorEstimateCli, AHeavyStripGetsItsProbesErrors) {
  test::StripSpec spec;
  spec.elements = 16;
  WriteScene(test::HeavyStrip(spec, 8), dir_ / "strip.json");
  const fs::path out = dir_ / "out";
  const test::CommandResult r = test::RunDrape("run '" + (dir_ / "strip.json").string() + "' -o '" +
                                               out.string() + "' --error-estimate");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("error estimate (16 x 1, 8 x 1, 4 x 1): order 2.0"), std::string::npos)
      << r.output;
  const json e = Result(out)["error_estimate"];
  EXPECT_TRUE(e["in_asymptotic_range"].get<bool>());
  EXPECT_NEAR(e["order"].get<double>(), 2, 0.25);
  const json tip = e["probes"]["tip"];
  const test::ElasticaEnd exact = test::SolveHeavyElastica(8);
  const json final_tip = Result(out)["final"]["probes"]["tip"];
  const double truth = std::hypot(final_tip[0].get<double>() - exact.x * spec.length,
                                  final_tip[2].get<double>() - exact.z * spec.length);
  EXPECT_GT(tip["error"].get<double>(), truth / 2);
  EXPECT_LT(tip["error"].get<double>(), truth * 2);
  for (const json& x : tip["extrapolated"]) EXPECT_TRUE(std::isfinite(x.get<double>()));
  EXPECT_TRUE(std::isfinite(tip["gci"].get<double>()));
  EXPECT_FALSE(e.contains("reason"));

  // With --units imperial the line gives the same error in inches.
  const test::CommandResult in =
      test::RunDrape("run '" + (dir_ / "strip.json").string() + "' -o '" + (dir_ / "in").string() +
                     "' --error-estimate --units imperial");
  ASSERT_EQ(in.exit_code, 0) << in.output;
  char expected[64];
  std::snprintf(expected, sizeof expected, "; tip ±%.3g in", tip["error"].get<double>() / 0.0254);
  EXPECT_NE(in.output.find(expected), std::string::npos) << expected << "\n" << in.output;
}

// The block drape (four pinned corners), asked for by the scene's own
// solver.error_estimate: no number, the reason instead.
TEST_F(ErrorEstimateCli, ADrapeOnPointSupportsSaysWhyItHasNone) {
  std::ifstream in(test::ScenesDir() / "block-drape.json");
  json scene = json::parse(in);
  scene["solver"]["error_estimate"] = true;
  scene["fabric"]["mesh"]["elements"] = {16, 16};
  std::ofstream(dir_ / "block.json") << scene.dump();
  const fs::path out = dir_ / "out";
  const test::CommandResult r =
      test::RunDrape("run '" + (dir_ / "block.json").string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("error estimate (16 x 16, 8 x 8, 4 x 4): none, probe"), std::string::npos)
      << r.output;
  const json e = Result(out)["error_estimate"];
  EXPECT_FALSE(e["in_asymptotic_range"].get<bool>());
  EXPECT_TRUE(e["probes"].empty());
  EXPECT_NE(e["reason"].get<std::string>().find("not in the asymptotic range"), std::string::npos);
}

}  // namespace
}  // namespace drape
