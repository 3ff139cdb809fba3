// Reading a study (docs/format.md §6): the grid or list expanded into runs,
// each run's scene made from the study's scene, and a bad study refused with
// one message naming its key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/io/scene_reader.h"
#include "core/io/study_file.h"
#include "core/io/study_table.h"
#include "core/model/scene_error.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class StudyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drape-study-file-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Writes `body` (the members after drape_study and scene) as a study of
  // the shipped scene `scene`.
  fs::path Write(const std::string& body, const std::string& scene = "strip-fold.json") {
    const fs::path file = dir_ / "study.json";
    std::ofstream(file) << "{\"drape_study\": 1, \"scene\": \""
                        << (test::ScenesDir() / scene).string() << "\", " << body << "}";
    return file;
  }

  std::string ErrorOf(const std::string& body, const std::string& scene = "strip-fold.json") {
    try {
      ReadStudy(Write(body, scene));
    } catch (const SceneError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted: " << body;
    return "";
  }

  fs::path dir_;
};

TEST_F(StudyFile, AGridIsEveryCombinationWithTheLastKeyFastest) {
  const Study study = ReadStudy(Write(
      R"("grid": {"solver.tolerance": [1e-3, 1e-5, 1e-7],
                  "fabric.mesh.elements": [[20, 2], [40, 4]]},
         "reference": {"fabric.mesh.elements": [80, 8], "solver.tolerance": 1e-9})"));
  ASSERT_EQ(study.runs.size(), 6u);
  // In the order written (not alphabetical).
  EXPECT_EQ(study.keys, (std::vector<std::string>{"solver.tolerance", "fabric.mesh.elements"}));
  EXPECT_EQ(study.runs[0].name, "run_001");
  EXPECT_EQ(study.runs[5].name, "run_006");
  EXPECT_EQ(Describe(study.runs[1]),
            "run_002 (solver.tolerance = 0.001, fabric.mesh.elements = [40,4])");
  EXPECT_EQ(Describe(study.runs[4]),
            "run_005 (solver.tolerance = 1e-07, fabric.mesh.elements = [20,2])");
  ASSERT_TRUE(study.reference.has_value());
  EXPECT_EQ(study.reference->name, "reference");
  EXPECT_FALSE(study.time_limit_s.has_value());
}

TEST_F(StudyFile, AListIsItsRunsInOrderWithTheUnionOfTheirKeys) {
  const Study study = ReadStudy(Write(
      R"("list": [{"solver.tolerance": 1e-3},
                  {"stages[1].initial_increment": 0.05, "solver.tolerance": 1e-5}],
         "time_limit_s": 30)"));
  ASSERT_EQ(study.runs.size(), 2u);
  EXPECT_EQ(study.keys,
            (std::vector<std::string>{"solver.tolerance", "stages[1].initial_increment"}));
  EXPECT_EQ(study.runs[1].settings.size(), 2u);
  EXPECT_EQ(study.time_limit_s, 30.0);
  EXPECT_FALSE(study.reference.has_value());
}

// Each run's scene is the study's with its settings, and reads the same as
// a scene written by hand with them.
TEST_F(StudyFile, ARunsSceneHasItsSettingsAndReadsFromAnywhere) {
  const Study study = ReadStudy(
      Write(R"("list": [{"stages[0].initial_increment": 0.05, "solver.tolerance": 1e-7}])",
            "dress-form-drape.json"));
  const std::string text = SceneTextOf(study, study.runs[0]);
  // The form's mesh, "../forms/dress-form.obj" in the scene, is made
  // absolute: the scene reads from a folder that is not the scenes'.
  const json document = json::parse(text);
  const fs::path form = document["obstacles"][0]["mesh"]["file"].get<std::string>();
  EXPECT_TRUE(form.is_absolute());
  EXPECT_TRUE(fs::equivalent(form, test::SourceDir() / "resources" / "forms" / "dress-form.obj"));
  // The scene has one stage: stages[1] does not exist...
  EXPECT_NE(ErrorOf(R"("list": [{"stages[1].initial_increment": 0.05}])", "dress-form-drape.json")
                .find("the scene has no stages[1] (it has 1)"),
            std::string::npos);
  const Study one = ReadStudy(
      Write(R"("list": [{"stages[0].initial_increment": 0.05, "solver.tolerance": 1e-7}])",
            "dress-form-drape.json"));
  const Scene scene = ParseScene(SceneTextOf(one, one.runs[0]), dir_);
  EXPECT_EQ(scene.stages[0].initial_increment, 0.05);
  EXPECT_EQ(scene.solver.tolerance, 1e-7);
  // ...and what the study does not set stays as the scene has it.
  const Scene original = ReadScene(test::ScenesDir() / "dress-form-drape.json");
  ASSERT_EQ(original.supports.size(), 1u);  // the scarf's pin
  EXPECT_EQ(scene.supports, original.supports);
  EXPECT_EQ(scene.material, original.material);
}

// A key the scene has no object for yet is made (the strip fold has no
// `imperfection`).
TEST_F(StudyFile, MissingObjectsAlongAKeyAreMade) {
  const Study study = ReadStudy(Write(
      R"("list": [{"fabric.imperfection.amplitude": "0.1 mm", "fabric.imperfection.seed": 3}])"));
  const Scene scene = ParseScene(SceneTextOf(study, study.runs[0]), dir_);
  ASSERT_TRUE(scene.fabric.imperfection.has_value());
  EXPECT_DOUBLE_EQ(scene.fabric.imperfection->amplitude, 1e-4);
  EXPECT_EQ(scene.fabric.imperfection->seed, 3u);
}

TEST_F(StudyFile, ABadStudyIsOneMessageNamingItsKey) {
  EXPECT_EQ(ErrorOf(R"("grid": {"solver.tolerance": [1e-3]}, "list": [])"),
            "give only one of 'grid', 'list'");
  EXPECT_NE(ErrorOf(R"("grid": {"solver.tolerance": [1e-3]}, "referense": {})").find("referense"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"("grid": {"solver.tolerance": []})").find("grid.solver.tolerance"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"("grid": {"stages[x].initial_increment": [0.1]})")
                .find("'stages[x].initial_increment' is not a scene key path"),
            std::string::npos);
  EXPECT_NE(ErrorOf(R"("grid": {"material.thickness.value": [1]})")
                .find("the scene's material.thickness is not an object"),
            std::string::npos);
  // A value the scene reader refuses: the run, its settings and the
  // reader's own key and message.
  const std::string refused = ErrorOf(R"("grid": {"solver.tolerance": [1e-3, 2]})");
  EXPECT_NE(refused.find("run_002 (solver.tolerance = 2): solver.tolerance"), std::string::npos)
      << refused;
  EXPECT_NE(
      ErrorOf(R"("grid": {"solver.tolerance": [1e-3]}, "reference": {"solver.tolerance": -1})")
          .find("reference (solver.tolerance = -1): solver.tolerance"),
      std::string::npos);
  EXPECT_NE(ErrorOf(R"("grid": {"solver.tolerance": [1e-3]})", "no-such-scene.json")
                .find("scene: cannot open scene file"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf(R"("grid": {"solver.tolerance": [1e-3]}, "time_limit_s": 0)").find("time_limit_s"),
      std::string::npos);
}

// The studies shipped in resources/studies read, with every run's scene:
// the fronts (12 runs or more, against a reference), in presets/ each preset
// on a scene, and the lab's specimens of a drape test (3 or more, no
// reference: they are measured, not compared).
TEST(ShippedStudies, EveryOneReads) {
  int fronts = 0, presets = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(test::SourceDir() / "resources" / "studies")) {
    if (entry.path().extension() != ".json") continue;
    const bool of_presets = entry.path().parent_path().filename() == "presets";
    const bool specimens = entry.path().stem().string().ends_with("-specimens");
    EXPECT_NO_THROW({
      const Study study = ReadStudy(entry.path());
      EXPECT_GE(study.runs.size(), specimens ? 3u : of_presets ? 4u : 12u) << entry.path();
      EXPECT_EQ(study.reference.has_value(), !specimens) << entry.path();
    }) << entry.path();
    if (!specimens) ++(of_presets ? presets : fronts);
  }
  EXPECT_GE(fronts, 3);
  EXPECT_GE(presets, 3);
}

// The Pareto front: a run is on it unless another is faster and as
// accurate, or as fast and more accurate (errors within 1 % equal); runs
// without both numbers never are.
TEST(StudyTable, TheFrontIsTheRunsNoOtherBeatsOnBoth) {
  auto row = [](double time, std::optional<double> error, std::string status = "converged") {
    StudyRow r;
    r.status = std::move(status);
    r.solve_s = time;
    r.max_node_error = error;
    return r;
  };
  const std::vector<StudyRow> rows = {row(1, 1e-2),
                                      row(2, 1e-3),
                                      row(3, 1e-3),  // as accurate as the second, slower
                                      row(2, 1e-3),  // the second's twin: neither beats the other
                                      row(10, 1e-5),
                                      row(12, 0.995e-5),  // 0.5 % better, slower: the same answer
                                      row(0.5, 1e-1, "failed"),
                                      row(20, std::nullopt)};  // the reference
  EXPECT_EQ(ParetoFront(rows),
            (std::vector<bool>{true, true, false, true, true, false, false, false}));
}

}  // namespace
}  // namespace drape
