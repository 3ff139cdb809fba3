// `drape measure --drape-coefficient` on the shipped Cusick test: its
// numbers against a raster of the final state's triangles and against the
// outline it writes, all of them finite; and each bad request one message,
// exit 1.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/result_reader.h"
#include "support/csv_file.h"
#include "support/run_cli.h"
#include "support/shadow_raster.h"
#include "support/temp_dir.h"

namespace drape {
namespace {

using nlohmann::json;
using test::TempDir;
using test::run_cli::Quote;
using test::run_cli::RunCommand;
using test::run_cli::SceneJson;
using test::run_cli::WriteJson;

class MeasureCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("measure_cli");
    // The shipped test on a 2 cm mesh: each test's process solves it (CTest
    // runs them apart), in seconds under the sanitizers.
    json scene = SceneJson("cusick-drape.json");
    scene["fabric"]["mesh"] = {{"size", "2 cm"}};
    const auto file = WriteJson(scene, dir_->path() / "cusick.json");
    const auto r = RunCommand("run " + Quote(file) + " -o " + Quote(Result()) + " --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::filesystem::path Result() { return dir_->path() / "cusick"; }
  static TempDir* dir_;
};
TempDir* MeasureCli::dir_ = nullptr;

TEST_F(MeasureCli, TheDrapeCoefficientAgreesWithARasterOfTheShadowAndItsOutline) {
  const auto profile = dir_->path() / "profile.csv";
  const auto r = RunCommand(
      "measure " + Quote(Result()) + " --drape-coefficient --json --profile " + Quote(profile),
      /*stderr_only=*/false);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json m = json::parse(r.output);
  for (const char* key :
       {"drape_coefficient", "shadow_area_m2", "disc_area_m2", "specimen_area_m2"})
    ASSERT_TRUE(m.at(key).is_number() && std::isfinite(m.at(key).get<double>())) << key;
  const double dc = m["drape_coefficient"], shadow = m["shadow_area_m2"];
  const double disc = M_PI * 0.09 * 0.09;
  EXPECT_NEAR(m["disc_area_m2"].get<double>(), disc, 1e-15);
  // The flat mesh's area: a polygon inside the 15 cm circle, 2 cm edges on
  // its rim (a regular 47-gon's area is 0.3 % short of the circle's).
  const double specimen = m["specimen_area_m2"];
  EXPECT_LT(specimen, M_PI * 0.15 * 0.15);
  EXPECT_GT(specimen, 0.995 * M_PI * 0.15 * 0.15);
  EXPECT_NEAR(dc, (shadow - disc) / (specimen - disc), 1e-12);
  // The reference state is the flat specimen: DC 1 exactly.
  const auto flat =
      RunCommand("measure " + Quote(Result()) + " --drape-coefficient --json --step 0");
  ASSERT_EQ(flat.exit_code, 0) << flat.output;
  EXPECT_NEAR(json::parse(flat.output)["drape_coefficient"].get<double>(), 1, 1e-7);
  EXPECT_GT(dc, 0);
  EXPECT_LT(dc, 1);

  // Independently: the last state's triangles on a 0.1 mm raster.
  const RunRecord record = ReadRunRecord(Result());
  const double raster =
      test::RasterShadowArea(record.states.back().positions, record.mesh.quads, 1e-4);
  EXPECT_NEAR(shadow / raster, 1, 2e-3) << "shadow " << shadow << " m², raster " << raster;

  // The outline: 1440 rays, each at a radius between the disc's and the
  // specimen's; the area it bounds, Σ ½ r² Δθ, is the shadow's (the shadow
  // is star-shaped about the centre where it hangs without folding under).
  const auto rows = test::ReadCsv(profile);
  ASSERT_EQ(rows.size(), 1441u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"angle_deg", "radius_m"}));
  double bounded = 0;
  for (size_t k = 1; k < rows.size(); ++k) {
    const double radius = std::stod(rows[k].at(1));
    ASSERT_TRUE(std::isfinite(radius));
    EXPECT_GE(radius, 0.09);
    EXPECT_LE(radius, 0.15 + 1e-9);
    bounded += 0.5 * radius * radius * 2 * M_PI / 1440;
  }
  EXPECT_NEAR(bounded / shadow, 1, 5e-3);

  ASSERT_EQ(m["node_angles_deg"].size(), m["nodes"].get<size_t>());
  ASSERT_EQ(m["node_amplitudes_m"].size(), m["nodes"].get<size_t>());
  EXPECT_GE(m["nodes"].get<int>(), 3);
  for (const auto& a : m["node_amplitudes_m"]) {
    EXPECT_GT(a.get<double>(), 0.025 * 0.06);  // the prominence rule's floor, at least
    EXPECT_LT(a.get<double>(), 0.06);          // no more than the hanging length
  }
}

TEST_F(MeasureCli, EachBadRequestIsOneMessageAndExitOne) {
  const std::string result = Quote(Result());
  const std::pair<std::string, std::string> cases[] = {
      {"measure " + result, "say what to measure: --drape-coefficient"},
      {"measure " + result + " --drape-coefficient --support-radius '20 cm'",
       "reaches 5 cm outside the part"},
      {"measure " + result + " --drape-coefficient --support-radius 3gf", "is not a length"},
      {"measure " + result + " --drape-coefficient --step 999", "'999' is not a step"},
      {"measure " + Quote(test::ScenesDir() / "cusick-drape.json") + " --drape-coefficient",
       "is a scene: measure the result"},
  };
  for (const auto& [arguments, message] : cases) {
    const auto r = RunCommand(arguments);
    EXPECT_EQ(r.exit_code, 1) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << arguments << "\n" << r.output;
  }
}

// A part pressed by a load, with no gravity stage: no drape to measure.
TEST_F(MeasureCli, AResultWithNoGravityStageHasNoDrape) {
  json scene = SceneJson("cusick-drape.json");
  scene["fabric"]["mesh"] = {{"size", "3 cm"}};
  scene["loads"] = {
      {{"name", "press"}, {"select", {{"point", {"12 cm", 0}}}}, {"force", {0, 0, "-1 gf"}}}};
  scene["stages"] = {{{"name", "press"}, {"kind", "load"}}};
  const auto file = WriteJson(scene, dir_->path() / "pressed.json");
  const auto out = dir_->path() / "pressed";
  ASSERT_EQ(RunCommand("run " + Quote(file) + " -o " + Quote(out) + " --quiet").exit_code, 0);
  const auto r = RunCommand("measure " + Quote(out) + " --drape-coefficient");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("no gravity stage"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace drape
