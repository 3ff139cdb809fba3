// Reading a plan (docs/plan.md): parameters in SI from their units, the
// start from the scene where the plan gives none, the scene of a point, and
// a bad plan refused with one message naming its key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "core/io/scene_reader.h"
#include "core/model/scene_error.h"
#include "core/plan/plan_file.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr const char* kArc = "stages[1].moves[0].path.arc";

class PlanFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drape-plan-file-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A plan of the shipped scene `scene` whose members after drape_plan and
  // scene are `body`.
  fs::path Write(const std::string& body, const std::string& scene = "strip-fold.json") {
    const fs::path file = dir_ / "plan.json";
    std::ofstream(file) << "{\"drape_plan\": 1, \"scene\": \""
                        << (test::ScenesDir() / scene).string() << "\", " << body << "}";
    return file;
  }

  // The parameters and objective of a valid plan, with `extra` members.
  std::string Body(const std::string& parameter, const std::string& extra = "") {
    return R"("parameters": [)" + parameter +
           R"(], "objective": {"probes": [{"probe": "end", "target": ["11 cm", 0, 0]}]})" + extra;
  }
  std::string Centre(const std::string& more = "") {
    return std::string(R"({"key": ")") + kArc + R"(.center[0]", "min": "-5 cm", "max": "5 cm")" +
           more + "}";
  }

  std::string ErrorOf(const std::string& body, const std::string& scene = "strip-fold.json") {
    try {
      ReadPlan(Write(body, scene));
    } catch (const SceneError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted: " << body;
    return "";
  }

  fs::path dir_;
};

TEST_F(PlanFile, TheShippedPlanReadsInSiUnits) {
  const Plan plan = ReadPlan(test::SourceDir() / "resources/plans/strip-fold-recovery.json");
  ASSERT_EQ(plan.parameters.size(), 2u);
  EXPECT_EQ(plan.parameters[0].key, std::string(kArc) + ".center[0]");
  EXPECT_DOUBLE_EQ(plan.parameters[0].min, -0.05);
  EXPECT_DOUBLE_EQ(plan.parameters[0].max, 0.05);
  EXPECT_DOUBLE_EQ(plan.parameters[0].start, 0.03);
  EXPECT_EQ(plan.parameters[0].unit, "cm");
  EXPECT_DOUBLE_EQ(plan.parameters[1].start, 160);  // angle_deg: a plain number
  EXPECT_EQ(plan.parameters[1].unit, "");
  EXPECT_EQ(plan.search.algorithm, PlanAlgorithm::kCobyla);
  EXPECT_EQ(plan.search.max_evaluations, 60);
  EXPECT_DOUBLE_EQ(plan.search.tolerance, 1e-5);
  ASSERT_EQ(plan.objective.probes.size(), 1u);
  EXPECT_DOUBLE_EQ(plan.objective.probes[0].target[0], 0.11);
  EXPECT_DOUBLE_EQ(plan.objective.probes[0].target[2], 0.07035e-2);
  EXPECT_TRUE(plan.constraints.stable);
  EXPECT_TRUE(plan.constraints.layers);
}

TEST_F(PlanFile, WithoutAStartTheSceneValueIsTheStart) {
  // The shipped arc's centre is 0.035175 cm above the table.
  const Plan plan = ReadPlan(
      Write(Body(std::string(R"({"key": ")") + kArc + R"(.center[2]", "min": 0, "max": "1 cm"})")));
  EXPECT_DOUBLE_EQ(plan.parameters[0].start, 0.035175e-2);
  EXPECT_DOUBLE_EQ(StartOf(plan)[0], 0.035175e-2);
}

TEST_F(PlanFile, APointsSceneHoldsItsValuesInThePlansUnit) {
  const Plan plan = ReadPlan(Write(Body(Centre(R"(, "start": "1 cm")"))));
  const std::string text = PlanSceneText(plan, {0.025});
  const auto document = nlohmann::json::parse(text);
  const std::string written = document["stages"][1]["moves"][0]["path"]["arc"]["center"][0];
  EXPECT_EQ(written.substr(written.size() - 3), " cm") << written;
  const Scene scene = ParseScene(text);
  const auto& arc = std::get<ArcPath>(scene.stages[1].moves[0].path);
  EXPECT_NEAR(arc.center[0], 0.025, 1e-17);
  EXPECT_EQ(DescribePoint(plan, {0.025}), std::string(kArc) + ".center[0] = 2.5 cm");
}

TEST_F(PlanFile, ErrorsNameTheKey) {
  const std::string centre = std::string(kArc) + ".center[0]";
  struct Case {
    std::string body, message;
  };
  const Case cases[] = {
      {R"("parameters": [])", "parameters: expected at least one parameter"},
      {Body(R"({"key": "stages[9].name", "min": 0, "max": 1})"),
       "parameters[0].key: 'stages[9].name': the scene has no stages[9] (it has 3)"},
      {Body(R"({"key": "stages[1.name", "min": 0, "max": 1})"),
       "parameters[0].key: 'stages[1.name' is not a scene key path (an index without its "
       "number); write it as in fabric.mesh.elements or stages[1].initial_increment"},
      {Body(R"({"key": ")" + centre + R"(", "min": "5 cm", "max": "5 cm"})"),
       "parameters[0].max: must be greater than min"},
      {Body(R"({"key": ")" + centre + R"(", "min": "0 cm", "max": "3 N"})"),
       "parameters[0].max: has dimension force (N, gf, oz, lbf), but min has length (m, cm, "
       "mm, in, ft)"},
      {Body(Centre(R"(, "start": "9 cm")")),
       "parameters[0]: the start 9 cm lies outside [-5 cm, 5 cm]"},
      {Body(R"({"key": "solver.nothing", "min": 0, "max": 1})"),
       "parameters[0].key: the scene has no value at 'solver.nothing'; give the parameter a "
       "\"start\""},
      {Body(Centre() + "," + Centre()),
       "parameters[1].key: '" + centre + "' is already parameter 1"},
      {R"("parameters": [)" + Centre() +
           R"(], "objective": {"probes": [{"probe": "tip", "target": [0, 0, 0]}]})",
       "objective.probes[0].probe: the scene has no probe 'tip' (it has end, fold)"},
      {R"("parameters": [)" + Centre() + R"(], "objective": {})",
       "objective: nothing to optimise: give probes with targets, a flat region or a "
       "path_length weight"},
      {R"("parameters": [)" + Centre() +
           R"(], "objective": {"flat": {"select": {"edge": "left"}, "on": "floor"}})",
       "objective.flat.on: the scene has no obstacle 'floor' (it has table)"},
      {R"("parameters": [)" + Centre() +
           R"(], "objective": {"flat": {"select": {"edge": "middle"}, "on": "table"}})",
       "objective.flat.select.edge: "},
      {R"("parameters": [)" + Centre() +
           R"(], "objective": {"flat": {"side": {"line": [[0, 0], ["1 cm", 0]],
                                                 "toward": ["5 cm", 0]}, "on": "table"}})",
       "objective.flat.side.toward: lies on the line: it must name a side of it"},
      {R"("parameters": [)" + Centre() +
           R"(], "objective": {"flat": {"on": "table"}})",
       "objective.flat: "},
      {Body(Centre(), R"(, "constraints": {"no_slip": "table"})"),
       "constraints.no_slip: the scene's contact has no friction (contact.friction = 0): nothing "
       "holds the fabric, so it cannot be told not to slip"},
      {Body(Centre(), R"(, "constraints": {"max_gripper_force": "-1 N"})"),
       "constraints.max_gripper_force: must be greater than zero"},
      {Body(Centre(), R"(, "optimizer": {"max_evaluations": 3})"),
       "optimizer.max_evaluations: expected at least 4 (2 × 1 parameters + 2: the search's first "
       "model)"},
      {Body(Centre(), R"(, "optimizer": {"algorithm": "newton"})"), "optimizer.algorithm: "},
      {Body(Centre(), R"(, "budget": 5)"), "budget: unknown key"},
      // The scene refuses a bound: an arc turned by nothing.
      {Body(std::string(R"({"key": ")") + kArc + R"(.angle_deg", "min": 0, "max": 180})"),
       "parameters[0] at its bound (" + std::string(kArc) + ".angle_deg = 0): " + kArc +
           ".angle_deg: "},
  };
  for (const Case& c : cases) {
    const std::string error = ErrorOf(c.body);
    EXPECT_EQ(error.substr(0, c.message.size()), c.message) << c.body;
  }
}

}  // namespace
}  // namespace drape
