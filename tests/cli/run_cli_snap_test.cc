// `drape run` on a part that snaps: a 10 × 10 cm sheet picked up by two
// adjacent corners (pinned: free to turn) and loaded by its weight. Flat, it
// is a mechanism — it swings about the line through the corners, which its
// flat tangent cannot carry — so the stage's first step cannot start; under
// `stable` branching the sheet falls, at the first increment's λ, to where
// it hangs, and the path goes on from there.
//
// Independent answers: hanging, the sheet's free edge is a side length below
// the corners (its membrane strain under 1.5 N/m² is ~1e-4 of that); the
// jump lowers its centre of mass by half a side length, so the energy
// released is λ w A L/2 (w the areal weight, A the area, L the side), less
// the strain energy it stores (same order as the strain: 1e-4).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/csv_file.h"
#include "support/finite_outputs.h"
#include "support/run_cli.h"
#include "support/temp_dir.h"

namespace drape {
namespace {

using nlohmann::json;
using test::TempDir;
using test::run_cli::Quote;
using test::run_cli::ReadJson;
using test::run_cli::RunCommand;
using test::run_cli::WriteJson;

constexpr double kSide = 0.1;       // [m]
constexpr double kWeight = 1.5;     // [N/m²]
constexpr double kIncrement = 0.1;  // Δλ₀: where the sheet falls

// A 10 × 10 cm sheet of 10 × 10 elements, 0.5 mm, kWeight, ν = 0.3, of
// Young's modulus `modulus`; the callers hold it and add its stages.
json Sheet(const std::string& name, const std::string& modulus) {
  return {{"drape_scene", 1},
          {"name", name},
          {"fabric",
           {{"outline", {{"rectangle", {{"size", {"10 cm", "10 cm"}}, {"center", {0, 0}}}}}},
            {"mesh", {{"elements", {10, 10}}}}}},
          {"material",
           {{"thickness", "0.5 mm"},
            {"areal_weight", kWeight},
            {"youngs_modulus", modulus},
            {"poisson_ratio", 0.3}}}};
}

json PickedUpSheet() {
  json sheet = Sheet("sheet picked up by two corners", "2 MPa");
  sheet["grippers"] = {
      {{"name", "left"}, {"select", {{"point", {"-5 cm", "5 cm"}}}}, {"hold", "position"}},
      {{"name", "right"}, {"select", {{"point", {"5 cm", "5 cm"}}}}, {"hold", "position"}}};
  sheet["probes"] = {{{"name", "free"}, {"at", {0, "-5 cm"}}}};
  sheet["stages"] = {{{"name", "hang"}, {"kind", "gravity"}, {"initial_increment", kIncrement}}};
  return sheet;
}

TEST(RunCliSnap, ASheetPickedUpByTwoCornersFallsToWhereItHangs) {
  TempDir dir("picked-up");
  const auto scene = WriteJson(PickedUpSheet(), dir / "scene.json");
  const test::CommandResult r =
      test::run_cli::RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  std::vector<std::string> nulls;
  test::CollectNulls(result, "", nulls);
  EXPECT_TRUE(nulls.empty()) << nulls.front();
  EXPECT_EQ(result["status"], "converged");

  // One snap, from the stage's start, at the first increment.
  ASSERT_EQ(result["stability_events"].size(), 1u) << result["stability_events"].dump();
  const json& snap = result["stability_events"][0];
  EXPECT_EQ(snap["kind"], "snap");
  EXPECT_EQ(snap["trigger"], "start");
  EXPECT_EQ(snap["step"], 1);
  EXPECT_DOUBLE_EQ(snap["lambda"].get<double>(), kIncrement);
  EXPECT_EQ(snap["negative_pivots_after"], 0);
  const double released = kIncrement * kWeight * kSide * kSide * kSide / 2;
  EXPECT_NEAR(snap["energy_released"].get<double>(), released, 1e-3 * released);
  // The corner opposite a gripper swings from 0.1 m beside it to 0.1 m below:
  // √2 · 0.1 m.
  EXPECT_NEAR(snap["max_displacement"].get<double>(), std::sqrt(2.0) * kSide, 1e-3 * kSide);
  EXPECT_GT(snap["iterations"].get<int>(), 0);
  EXPECT_GE(snap["time_s"].get<double>(), 0);

  // Every step stable and hanging; the free edge a side length below.
  for (const json& step : result["steps"]) EXPECT_EQ(step["negative_pivots"], 0);
  const auto rows = test::ReadCsv(dir / "out" / "steps.csv");
  ASSERT_GE(rows.size(), 3u);
  const size_t event = test::Column(rows[0], "event");
  const size_t free_z = test::Column(rows[0], "free_z_m");
  EXPECT_EQ(rows[1][event], "snap");
  for (size_t i = 2; i < rows.size(); ++i) EXPECT_EQ(rows[i][event], "") << "row " << i;
  EXPECT_NEAR(std::stod(rows.back()[free_z]), -kSide, 1e-3 * kSide);
}

// Under `fundamental` the path is the paper's: no jumps, and a sheet that
// cannot start fails, saying where it starts it barely resists its load.
TEST(RunCliSnap, UnderFundamentalBranchingTheSameSheetDoesNotSnap) {
  TempDir dir("picked-up-fundamental");
  json doc = PickedUpSheet();
  doc["solver"] = {{"branching", "fundamental"}};
  const auto scene = WriteJson(doc, dir / "scene.json");
  const test::CommandResult r =
      test::run_cli::RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  EXPECT_EQ(result["stability_events"].size(), 0u);
  EXPECT_NE(result["message"].get<std::string>().find("barely resists"), std::string::npos)
      << result["message"];
}

// A sheet resting on a table whose slope (here: gravity tilted by θ) is
// steeper than its friction allows, tan θ > μ, has no rest state: it slides
// away. Flat on the table it carries its load by friction only through the
// contact's regularisation, so the stage cannot start and the sheet snaps;
// the jump must end saying nothing holds it, not land it kilometres away
// where its coordinates' round-off passes for rest (it did: 1.6e6 m,
// "converged"). Below the limit it stays where it lies (tan θ = 0.98 μ).
json SheetOnATiltedTable(double slope) {
  const double angle = std::atan(slope);
  json sheet = Sheet("sheet on a tilted table", "5 MPa");
  sheet["obstacles"] = {
      {{"name", "table"}, {"plane", {{"point", {0, 0, "-0.25 mm"}}, {"normal", {0, 0, 1}}}}}};
  sheet["gravity"] = {{"direction", {std::sin(angle), 0, -std::cos(angle)}}};
  sheet["contact"] = {{"friction", 0.3}};
  sheet["probes"] = {{{"name", "centre"}, {"at", {0, 0}}}};
  sheet["stages"] = {{{"name", "weight"}, {"kind", "gravity"}, {"initial_increment", 0.05}}};
  return sheet;
}

TEST(RunCliSnap, ASheetOnATableSteeperThanItsFrictionSaysNothingHoldsIt) {
  TempDir dir("tilted-table");
  const auto scene = WriteJson(SheetOnATiltedTable(1.02 * 0.3), dir / "scene.json");
  const test::CommandResult r =
      test::run_cli::RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("nothing holds the part"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("it slides off 'table'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("give it more friction (contact.friction is 0.3)"), std::string::npos)
      << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  std::vector<std::string> nulls;
  test::CollectNulls(result, "", nulls);
  EXPECT_TRUE(nulls.empty()) << nulls.front();
  EXPECT_NE(result["status"], "converged");
}

TEST(RunCliSnap, ASheetOnATableLessSteepThanItsFrictionStaysWhereItLies) {
  TempDir dir("tilted-table-holding");
  const auto scene = WriteJson(SheetOnATiltedTable(0.98 * 0.3), dir / "scene.json");
  const test::CommandResult r =
      test::run_cli::RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  EXPECT_EQ(result["status"], "converged");
  // Stuck: every node carries 0.98 of its Coulomb limit, which friction
  // mobilises at the slip y with f₁(y) = 2y/ε − y²/ε² = 0.98, i.e.
  // y = ε (1 − √0.02); ε = 1e-3 of the 1 cm elements (contact.friction_slip's
  // default). The centre moves by that and no more.
  const auto rows = test::ReadCsv(dir / "out" / "steps.csv");
  ASSERT_GE(rows.size(), 2u);
  const double x = std::stod(rows.back()[test::Column(rows[0], "centre_x_m")]);
  const double epsilon = 1e-5;
  EXPECT_NEAR(x, epsilon * (1 - std::sqrt(0.02)), 1e-2 * epsilon);
  // Every node sticks, and friction carries the weight's component along
  // the table, W sin θ (W = w A), to the equilibrium tolerance.
  const json& friction = result["steps"].back()["contact"]["friction"];
  EXPECT_EQ(friction["sliding"], 0);
  EXPECT_EQ(friction["sticking"], 121);  // the 11 × 11 nodes
  // The same per node at the last step, for the workbench's "slip" field.
  const json& states = result["final"]["friction_state"];
  ASSERT_EQ(states.size(), 121u);
  for (const json& s : states) EXPECT_EQ(s, 1);
  const double weight = kWeight * 0.1 * 0.1;
  const double sine = std::sin(std::atan(0.98 * 0.3));
  EXPECT_NEAR(friction["force"][0].get<double>(), -weight * sine, 1e-6 * weight);
  EXPECT_NEAR(friction["force"][1].get<double>(), 0.0, 1e-6 * weight);
}

}  // namespace
}  // namespace drape
