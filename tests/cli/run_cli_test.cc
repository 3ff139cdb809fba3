// `drape run SCENE -o DIR`: the result folder (result.json and states.bin) of
// a converged run, exit code 0, and what the command prints with --quiet,
// --verbose and on a terminal. Invalid input, failed and cancelled runs:
// run_cli_failure_test.cc.
//
// The converged run uses block-drape.json on a 10 × 10 mesh (121 nodes,
// under half a second).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/state_file.h"
#include "support/drape_command.h"
#include "support/run_cli.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The sheet of block-drape.json: 10 × 10 in at 5.425e-3 oz/in², 0.5425 oz,
// weighs 0.5425 ozf [N].
constexpr double kSheetWeight = 0.5425 * 0.028349523125 * 9.80665;
constexpr double kSceneTolerance = 1e-6;  // block-drape.json's solver.tolerance

using test::CommandResult;
using test::TempDir;
using test::run_cli::BlockDrape;
using test::run_cli::Quote;
using test::run_cli::ReadJson;
using test::run_cli::RunCommand;
using test::run_cli::SceneJson;
using test::run_cli::StateFileBytes;
using test::run_cli::WriteJson;

// ---- converged run ------------------------------------------------------------

// One converged run of block drape 10 × 10 that the tests of the suite inspect.
class RunCliConverged : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir("converged");
    const fs::path scene = WriteJson(BlockDrape(10), *dir_ / "scene.json");
    run_ = new CommandResult(RunCommand("run " + Quote(scene) + " -o " + Quote(*dir_ / "out")));
  }
  static void TearDownTestSuite() {
    delete run_;
    delete dir_;
    run_ = nullptr;
    dir_ = nullptr;
  }
  void SetUp() override {
    ASSERT_EQ(run_->exit_code, 0) << run_->output;
    ASSERT_TRUE(fs::exists(Out() / "result.json")) << run_->output;
  }

  static fs::path Out() { return *dir_ / "out"; }
  static json Result() { return ReadJson(Out() / "result.json"); }

  static TempDir* dir_;
  static CommandResult* run_;
};

TempDir* RunCliConverged::dir_ = nullptr;
CommandResult* RunCliConverged::run_ = nullptr;

TEST_F(RunCliConverged, ResultHeaderMeshAndStages) {
  const json r = Result();
  EXPECT_EQ(r["drape_result"], 1);
  EXPECT_EQ(r["status"], "converged");
  EXPECT_EQ(r["scene"], SceneJson("block-drape.json")["name"]);
  EXPECT_TRUE(r["message"].is_string());
  EXPECT_EQ(r["mesh"]["nodes"], 121);
  EXPECT_EQ(r["mesh"]["elements"], 100);
  EXPECT_EQ(r["mesh"]["dofs"], 605);
  ASSERT_EQ(r["stages"].size(), 1u);
  EXPECT_EQ(r["stages"][0]["name"], "SW");
  EXPECT_EQ(r["stages"][0]["final_lambda"].get<double>(), 1.0);
  EXPECT_EQ(r["stages"][0]["steps"], r["steps"].size());
  EXPECT_EQ(r["states_file"], "states.bin");
  ASSERT_TRUE(r["scene_resolved"].is_object());
  EXPECT_EQ(r["scene_resolved"]["drape_scene"], 1);
  EXPECT_EQ(r["scene_resolved"]["fabric"]["mesh"]["elements"], json({10, 10}));
  EXPECT_TRUE(r["timing"]["total_s"].is_number());
}

// The scene asks for arc-length control (the default); under load control
// each step's arc length is its Δλ and the first step is the initial increment.
TEST_F(RunCliConverged, StepsAreNumberedWithLambdaRisingToOne) {
  const json r = Result();
  const json& steps = r["steps"];
  ASSERT_FALSE(steps.empty());
  const bool load_control = r["stages"][0]["control"] == "load";
  double previous_lambda = 0;
  for (size_t i = 0; i < steps.size(); ++i) {
    const json& s = steps[i];
    SCOPED_TRACE("step " + std::to_string(i + 1));
    EXPECT_EQ(s["stage"], 0);
    EXPECT_EQ(s["step"], i + 1);
    const double lambda = s["lambda"].get<double>();
    EXPECT_GT(lambda, previous_lambda);
    EXPECT_GT(s["arc_length"].get<double>(), 0.0);
    if (load_control) {
      EXPECT_NEAR(s["arc_length"].get<double>(), lambda - previous_lambda, 1e-15);
    }
    previous_lambda = lambda;
    EXPECT_GE(s["iterations"].get<int>(), 1);
    EXPECT_TRUE(s["negative_pivots"].is_number_integer());
    EXPECT_GE(s["negative_pivots"].get<int>(), 0);
    ASSERT_TRUE(s["reactions"].contains("corners")) << s["reactions"];
    EXPECT_EQ(s["reactions"]["corners"].size(), 3u);
    EXPECT_TRUE(s["probes"].contains("centre")) << s["probes"];
    EXPECT_TRUE(s["probes"].contains("edge_mid")) << s["probes"];
  }
  if (load_control) {  // the scene's initial increment
    EXPECT_EQ(steps.front()["lambda"].get<double>(), 0.00025);
  }
  EXPECT_EQ(steps.back()["lambda"].get<double>(), 1.0);
}

// residuals[k] = ‖R‖/R₀ after each assembly, R₀ = Δλ‖F_ref‖ the load the
// step adds (docs/format.md §5.1). The history does not start at 1: each
// step starts from a predictor (load control: secant, or the tangent solve
// on the first step; arc length: tangent), and the first entry is where the
// predictor landed, relative to the step's load. Newton stops at the first
// residual at or below the tolerance, or at a round-off floor (‖R‖ ≤ 1e-11 of
// the loads, or a correction ≤ 1e-8 of the part's size). On this scene every
// step ends by the tolerance test (the residual floor lies below 1e-6 of any
// step's load), so every entry but the last is above the tolerance and the
// last at or below it. `iterations` counts linear solves, the predictor's
// included, hence at least as many as the residuals after it.
TEST_F(RunCliConverged, ResidualHistoriesEndAtTheTolerance) {
  const json steps = Result()["steps"];
  ASSERT_FALSE(steps.empty());
  for (const json& s : steps) {
    SCOPED_TRACE("step " + s["step"].dump());
    const std::vector<double> residuals = s["residuals"];
    ASSERT_FALSE(residuals.empty());
    EXPECT_GE(s["iterations"].get<size_t>() + 1, residuals.size());
    for (size_t k = 0; k + 1 < residuals.size(); ++k) EXPECT_GT(residuals[k], kSceneTolerance);
    EXPECT_LE(residuals.back(), kSceneTolerance);
  }
}

// With the corners the only support, their reaction carries the whole sheet.
TEST_F(RunCliConverged, FinalReactionCarriesTheSheetsWeight) {
  const json r = Result();
  const json& last = r["steps"].back();
  const std::vector<double> reaction = last["reactions"]["corners"];
  EXPECT_NEAR(reaction[2], kSheetWeight, 1e-8 * kSheetWeight);
  EXPECT_NEAR(reaction[0], 0.0, 1e-10 * kSheetWeight);
  EXPECT_NEAR(reaction[1], 0.0, 1e-10 * kSheetWeight);
  // Every step carries λ times the weight.
  for (const json& s : r["steps"])
    EXPECT_NEAR(s["reactions"]["corners"][2].get<double>(),
                s["lambda"].get<double>() * kSheetWeight,
                1e-6 * kSheetWeight)
        << "step " << s["step"];
}

TEST_F(RunCliConverged, FinalStateIsTheLastStep) {
  const json r = Result();
  const json& final_state = r["final"];
  EXPECT_EQ(final_state["step"], r["steps"].back()["step"]);
  ASSERT_EQ(final_state["positions"].size(), 121u);
  for (const json& row : final_state["positions"]) EXPECT_EQ(row.size(), 3u);
  EXPECT_EQ(final_state["probes"], r["steps"].back()["probes"]);
  // The centre sags; by symmetry it stays on the z axis.
  const std::vector<double> centre = final_state["probes"]["centre"];
  EXPECT_LT(centre[2], 0.0);
  EXPECT_NEAR(centre[0], 0.0, 1e-12);
  EXPECT_NEAR(centre[1], 0.0, 1e-12);
}

TEST_F(RunCliConverged, StateFileHoldsEveryStep) {
  const json r = Result();
  const StateFile states = ReadStateFile(Out() / r["states_file"].get<std::string>());
  EXPECT_EQ(states.mesh.NodeCount(), 121);
  EXPECT_EQ(states.mesh.ElementCount(), 100);
  // The reference mesh: the 10 × 10 in sheet, flat, centred on the origin.
  EXPECT_NEAR(states.mesh.positions.col(0).minCoeff(), -0.127, 1e-12);
  EXPECT_NEAR(states.mesh.positions.col(0).maxCoeff(), 0.127, 1e-12);
  EXPECT_NEAR(states.mesh.positions.col(2).cwiseAbs().maxCoeff(), 0.0, 1e-15);

  const json& steps = r["steps"];
  ASSERT_EQ(states.steps.size(), steps.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE("record " + std::to_string(i));
    const StoredStep& stored = states.steps[i];
    EXPECT_EQ(stored.stage, steps[i]["stage"].get<int>());
    EXPECT_EQ(stored.step, steps[i]["step"].get<int>());
    EXPECT_EQ(stored.lambda, steps[i]["lambda"].get<double>());
    ASSERT_EQ(stored.positions.rows(), 121);
    ASSERT_EQ(stored.directors.rows(), 121);
    for (int n = 0; n < stored.directors.rows(); ++n)
      EXPECT_NEAR(stored.directors.row(n).norm(), 1.0, 1e-12) << "node " << n;
  }
  // Doubles round-trip through JSON, so the last record is final.positions exactly.
  const StoredStep& last = states.steps.back();
  const json& positions = r["final"]["positions"];
  ASSERT_EQ(positions.size(), 121u);
  for (int n = 0; n < 121; ++n)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(last.positions(n, k), positions[n][k].get<double>()) << "node " << n << ", " << k;
  // And the file is exactly that long: no partial record.
  EXPECT_EQ(fs::file_size(Out() / "states.bin"), StateFileBytes(121, 100, steps.size()));
}

// Without a terminal there is no progress line (no '\r'): the brief report,
// then the results path.
TEST_F(RunCliConverged, NoProgressLineWithoutATerminal) {
  EXPECT_EQ(run_->output.find('\r'), std::string::npos) << run_->output;
  EXPECT_EQ(run_->output.find("\033["), std::string::npos) << run_->output;
  EXPECT_NE(run_->output.find("converged"), std::string::npos) << run_->output;
  EXPECT_NE(run_->output.find("results: " + (Out() / "result.json").string()), std::string::npos)
      << run_->output;
  EXPECT_EQ(run_->output.find("Drape solve report"), std::string::npos) << run_->output;
}

// ---- what the command prints ----------------------------------------------------

TEST(RunCliOutput, QuietPrintsNothing) {
  TempDir dir("quiet");
  const fs::path scene = WriteJson(BlockDrape(10), dir / "scene.json");
  const CommandResult r =
      RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out") + " --quiet", true);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, "");
  EXPECT_EQ(ReadJson(dir / "out" / "result.json")["status"], "converged");
}

TEST(RunCliOutput, VerbosePrintsTheFullReport) {
  TempDir dir("verbose");
  const fs::path scene = WriteJson(BlockDrape(10), dir / "scene.json");
  const CommandResult r =
      RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out") + " --verbose --threads 1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("Drape solve report"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("termination"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("nodes 121, elements 100, DOFs 605"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\r'), std::string::npos) << r.output;
}

// A measured law that softens inside its range runs, with the warning on
// stderr and in result.json; the summary line gives the curvature reached.
TEST(RunCliOutput, SofteningBendingLawIsWarnedOf) {
  TempDir dir("softening");
  json doc = BlockDrape(10);
  // M = K − K³/6.75 (gf·cm/cm, 1/cm): dM/dK < 0 beyond 1.5 1/cm, fit to 2.5.
  doc["material"]["bending"] = {{"model", "polynomial"},
                                {"coefficients", {1.0, 0.0, -1.0 / 6.75}},
                                {"moment_unit", "gf*cm/cm"},
                                {"curvature_unit", "1/cm"},
                                {"valid_to", "2.5 1/cm"}};
  const fs::path scene = WriteJson(doc, dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"), true);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string warning =
      "material.bending: the moment falls with curvature (dM/dK < 0) for K from 1.5 to 2.5 1/cm";
  EXPECT_NE(r.output.find("  warning: " + warning), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("largest curvature"), std::string::npos) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  ASSERT_EQ(result["warnings"].size(), 1u);
  EXPECT_EQ(result["warnings"][0].get<std::string>().rfind(warning, 0), 0u);
  EXPECT_EQ(result["bending"]["valid_to"], 250.0);
  EXPECT_GT(result["bending"]["max_curvature"].get<double>(), 0.0);
}

// The other side of NoProgressLineWithoutATerminal: with stderr on a
// pseudo-terminal the progress line is drawn with '\r' and cleared at the end.
TEST(RunCliOutput, ProgressLineOnATerminal) {
  TempDir dir("tty");
  const fs::path scene = WriteJson(BlockDrape(10), dir / "scene.json");
  const std::string out = (dir / "out").string();
  int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  int slave = open(ptsname(master), O_RDWR | O_NOCTTY);
  ASSERT_GE(slave, 0);
  pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    dup2(slave, STDERR_FILENO);
    int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    close(master);
    const std::string scene_arg = scene.string();
    const char* argv[] = {test::DrapeCli(), "run", scene_arg.c_str(), "-o", out.c_str(), nullptr};
    execv(test::DrapeCli(), const_cast<char* const*>(argv));
    _exit(127);
  }
  close(slave);
  std::string output;
  std::array<char, 4096> buffer;
  for (;;) {
    ssize_t n = read(master, buffer.data(), buffer.size());
    if (n <= 0) break;  // EIO once the child has closed the terminal
    output.append(buffer.data(), n);
  }
  close(master);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << output;
  EXPECT_NE(output.find("\r  stage SW"), std::string::npos) << output;
  EXPECT_NE(output.find("\r\033[K"), std::string::npos) << output;
  EXPECT_NE(output.find("converged"), std::string::npos) << output;
}

}  // namespace
}  // namespace drape
