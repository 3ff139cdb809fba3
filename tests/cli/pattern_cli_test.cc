// `drape run` on a part cut from a pattern file (DXF-AAMA written by ezdxf,
// tests/data/patterns/make_aama_dxf.py): it runs, its result reads back
// from anywhere, and a bad pattern file is one message and exit 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/aama_patterns.h"
#include "support/finite_outputs.h"
#include "support/run_cli.h"
#include "support/temp_dir.h"

namespace drape {
namespace {

using test::CommandResult;
using test::TempDir;
using test::run_cli::Quote;
using test::run_cli::ReadJson;
using test::run_cli::RunCommand;
using test::run_cli::WriteJson;

void MakePattern(const std::filesystem::path& out) {
  test::MakeAamaPattern(out, "in");
}

// The BACK panel (a trapezoid, 36 cm at the bottom, 28 cm at the top, 28
// cm high) flat on its weight, its bottom edge clamped: a cantilever plate.
nlohmann::json BackPanel(const std::string& file) {
  return {{"drape_scene", 1},
          {"fabric",
           {{"outline", {{"pattern", {{"file", file}, {"piece", "BACK"}}}}},
            {"mesh", {{"size", "4 cm"}}}}},
          {"material",
           {{"thickness", "0.5 mm"},
            {"areal_weight", "1.5 N/m^2"},
            {"youngs_modulus", "20 MPa"},
            {"poisson_ratio", 0.3},
            {"angle_deg", "grain"}}},
          {"supports", {{{"name", "hem"}, {"select", {{"edge", "bottom"}}}, {"fix", "clamp"}}}},
          {"stages", {{{"name", "weight"}, {"kind", "gravity"}}}}};
}

TEST(PatternCli, RunsAPieceAndItsResultReadsBackFromElsewhere) {
  TempDir dir("pattern-cli");
  MakePattern(dir / "p.dxf");
  const auto scene = WriteJson(BackPanel("p.dxf"), dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json result = ReadJson(dir / "out" / "result.json");
  std::vector<std::string> nulls;
  test::CollectNulls(result, "", nulls);
  EXPECT_TRUE(nulls.empty()) << nulls.front();
  EXPECT_EQ(result["scene_resolved"]["material"]["angle_deg"], "grain");
  // The resolved scene names the pattern by its absolute path: it reads
  // from another folder.
  const std::string file =
      result["scene_resolved"]["fabric"]["outline"]["pattern"]["file"].get<std::string>();
  EXPECT_TRUE(std::filesystem::path(file).is_absolute()) << file;
  std::filesystem::create_directories(dir / "elsewhere");
  const auto copy = WriteJson(result["scene_resolved"], dir / "elsewhere" / "scene.json");
  const CommandResult again = RunCommand("validate " + Quote(copy));
  EXPECT_EQ(again.exit_code, 0) << again.output;
}

TEST(PatternCli, ExportsTheOutlineOnTheTableAsDxf) {
  TempDir dir("pattern-cli-dxf");
  MakePattern(dir / "p.dxf");
  const auto scene = WriteJson(BackPanel("p.dxf"), dir / "scene.json");
  ASSERT_EQ(RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out")).exit_code, 0);
  for (const char* step : {"0", "last"}) {
    const CommandResult r = RunCommand("export " + Quote(dir / "out") + " -o " + Quote(dir / step) +
                                       " --format dxf --step " + step);
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  // The reference: the trapezoid as drawn, (36 + 28) / 2 × 28 cm², in mm.
  const nlohmann::json flat = test::DescribedByEzdxf(dir / "0" / "outline-step-0.dxf");
  EXPECT_EQ(flat["insunits"], 4);
  EXPECT_NEAR(flat["pieces"]["BACK"]["cut_area"].get<double>(), 32.0 * 28.0 * 100.0, 1e-6);
  // Hanging over its clamped hem the panel's shadow on the table shrinks.
  std::filesystem::path last;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "last")) last = entry.path();
  const double drooped = test::DescribedByEzdxf(last)["pieces"]["BACK"]["cut_area"].get<double>();
  EXPECT_TRUE(std::isfinite(drooped));
  EXPECT_LT(drooped, 32.0 * 28.0 * 100.0);
  EXPECT_GT(drooped, 0.0);
}

TEST(PatternCli, ListsThePiecesOfAFile) {
  TempDir dir("pattern-cli-list");
  MakePattern(dir / "p.dxf");
  const CommandResult table = RunCommand("pattern list " + Quote(dir / "p.dxf"));
  ASSERT_EQ(table.exit_code, 0) << table.output;
  // FRONT as the script draws it: 40 × 32 cm, 1 240 cm² less a 20 cm² cut-out.
  EXPECT_NE(table.output.find("FRONT"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("1220.0 cm²"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("40.0 x 32.0 cm"), std::string::npos) << table.output;
  EXPECT_NE(table.output.find("30.00 deg"), std::string::npos) << table.output;
  const CommandResult json = RunCommand("pattern list " + Quote(dir / "p.dxf") + " --json", false);
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json doc = nlohmann::json::parse(json.output);
  EXPECT_EQ(doc["unit_m"], 0.0254);
  ASSERT_EQ(doc["pieces"].size(), 2u);
  EXPECT_NEAR(doc["pieces"][0]["area_m2"].get<double>(), 0.122, 1e-12);
  EXPECT_EQ(doc["pieces"][0]["notches_m"].size(), 4u);
  EXPECT_NEAR(doc["pieces"][1]["grain_deg"].get<double>(), 90.0, 1e-6);
  const CommandResult bad = RunCommand("pattern list " + Quote(dir / "none.dxf"), true);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("cannot be opened"), std::string::npos) << bad.output;
}

TEST(PatternCli, ABadPatternFileIsOneMessageAndExitOne) {
  TempDir dir("pattern-cli-bad");
  std::ofstream(dir / "notes.dxf") << "a pattern, but not a DXF\n";
  const auto scene = WriteJson(BackPanel("notes.dxf"), dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"), true);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("fabric.outline.pattern.file: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a DXF file"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
}  // namespace drape
