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
#include "support/fuzz_files.h"
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

// Two BACK panels side by side, each its own part, each hanging from its
// clamped hem: the DXF export has a piece per part, both flat at step 0.
TEST(PatternCli, ExportsAPiecePerPart) {
  TempDir dir("pattern-cli-parts");
  MakePattern(dir / "p.dxf");
  nlohmann::json scene = BackPanel("p.dxf");
  const nlohmann::json back = scene["fabric"];
  scene["fabric"] = nlohmann::json::array({back, back});
  scene["fabric"][0]["name"] = "left";
  scene["fabric"][1]["name"] = "right";
  scene["fabric"][1]["outline"]["pattern"]["at"] = {"50 cm", 0};
  const auto file = WriteJson(scene, dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(file) + " -o " + Quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json result = ReadJson(dir / "out" / "result.json");
  ASSERT_EQ(result["mesh"]["parts"].size(), 2u);
  EXPECT_EQ(result["mesh"]["parts"][1]["name"], "right");
  EXPECT_EQ(result["mesh"]["parts"][1]["first_node"], result["mesh"]["parts"][0]["nodes"]);
  ASSERT_EQ(RunCommand("export " + Quote(dir / "out") + " -o " + Quote(dir / "dxf") +
                       " --format dxf --step 0")
                .exit_code,
            0);
  const nlohmann::json d = test::DescribedByEzdxf(dir / "dxf" / "outline-step-0.dxf");
  ASSERT_EQ(d["pieces"].size(), 2u);
  // BACK as the script draws it: a trapezoid 36 and 28 cm wide, 28 cm high.
  for (const char* name : {"BACK", "BACK-right"})
    EXPECT_NEAR(d["pieces"][name]["cut_area"].get<double>(), 0.5 * (360 + 280) * 280, 1e-3) << name;
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

// The shoelace area of a JSON cut line in "x cm" strings [mm²].
double CutAreaMm2(const nlohmann::json& cut) {
  double twice = 0;
  for (std::size_t i = 0; i < cut.size(); ++i) {
    const auto& a = cut[i];
    const auto& b = cut[(i + 1) % cut.size()];
    auto mm = [](const nlohmann::json& v) { return 10 * std::stod(v.get<std::string>()); };
    twice += mm(a[0]) * mm(b[1]) - mm(b[0]) * mm(a[1]);
  }
  return std::abs(twice) / 2;
}

TEST(PatternCli, WritesTheShippedGarmentsByteForByte) {
  TempDir dir("pattern-cli-write");
  const std::filesystem::path shipped = test::SourceDir() / "resources" / "patterns";
  const CommandResult r = RunCommand("pattern write " + Quote(shipped / "garments.json") + " -o " +
                                     Quote(dir / "garments.dxf"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The shipped DXF is this writer's output, and stays so.
  EXPECT_EQ(test::ReadBytes(dir / "garments.dxf"), test::ReadBytes(shipped / "garments.dxf"))
      << "resources/patterns/garments.dxf differs from what `drape pattern write` makes of "
         "garments.json; write it again";
  // Read by ezdxf: the pieces the JSON draws.
  const nlohmann::json spec = ReadJson(shipped / "garments.json");
  const nlohmann::json d = test::DescribedByEzdxf(dir / "garments.dxf");
  EXPECT_EQ(d["insunits"], 4);
  for (const auto& piece : spec["pieces"]) {
    const nlohmann::json& read = d["pieces"][piece["name"].get<std::string>()];
    EXPECT_EQ(read["cut_points"], piece["cut"].size());
    EXPECT_NEAR(read["cut_area"].get<double>(), CutAreaMm2(piece["cut"]), 1e-6);
    EXPECT_EQ(read["notches"].size(), piece["notches"].size());
    EXPECT_NEAR(read["grain_deg"].get<double>(), 90.0, 1e-9);
  }
  // A bad description: one line, exit 1.
  std::ofstream(dir / "bad.json") << R"({"drape_pattern": 1, "pieces": [{"name": "X",
      "cut": [[0, 0], ["1 cm", "1 cm"], ["1 cm", 0], [0, "1 cm"]]}]})";
  const CommandResult bad = RunCommand(
      "pattern write " + Quote(dir / "bad.json") + " -o " + Quote(dir / "bad.dxf"), true);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("pieces[0].cut: crosses itself"), std::string::npos) << bad.output;
  EXPECT_EQ(std::count(bad.output.begin(), bad.output.end(), '\n'), 1) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.dxf"));
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
