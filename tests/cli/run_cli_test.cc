// `drape run SCENE -o DIR`: the result folder (result.json and states.bin) of
// a converged, a failed and a cancelled run; exit codes 0, 1, 2 and 130; what
// the command prints with --quiet, --verbose and on a terminal.
//
// The converged and failed runs use block-drape.json on a 10 × 10 mesh
// (121 nodes, under half a second); the cancelled runs use it on 40 × 40
// without acceleration, which would take minutes, and interrupt it after two
// steps.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/io/state_file.h"
#include "support/drape_command.h"
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

// `drape ARGUMENTS`; with `stderr_only` stdout is discarded.
CommandResult RunCommand(const std::string& arguments, bool stderr_only = false) {
  return test::RunDrape(arguments, stderr_only ? test::Captured::kStderr : test::Captured::kBoth);
}

// A fresh directory under the system's temporary directory, removed with
// everything in it at the end of its scope.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() /
              ("drape-run-cli-" + std::to_string(getpid()) + "-" + name)) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

json ReadJson(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

fs::path WriteJson(const json& doc, const fs::path& file) {
  std::ofstream(file) << doc.dump(2);
  return file;
}

// For the shell: the temporary paths hold no quote.
std::string Quote(const fs::path& p) {
  std::string quoted(1, '\'');
  quoted += p.string();
  quoted += '\'';
  return quoted;
}

json SceneJson(const std::string& name) {
  return ReadJson(test::ScenesDir() / name);
}

// block-drape.json on an n × n mesh.
json BlockDrape(int n) {
  json doc = SceneJson("block-drape.json");
  doc["fabric"]["mesh"] = {{"elements", {n, n}}};
  return doc;
}

// Bytes of states.bin (state_file.h) up to and including `records` step
// records, for a mesh of `nodes` nodes and `elements` quads.
std::uintmax_t StateFileBytes(std::uintmax_t nodes,
                              std::uintmax_t elements,
                              std::uintmax_t records) {
  const std::uintmax_t header = 8 + 16;
  const std::uintmax_t mesh = 8 * 3 * nodes + 4 * 4 * elements + (elements % 2 ? 4 : 0);
  return header + mesh + records * (16 + 48 * nodes);
}

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
    const char* argv[] = {DRAPE_CLI, "run", scene_arg.c_str(), "-o", out.c_str(), nullptr};
    execv(DRAPE_CLI, const_cast<char* const*>(argv));
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

// ---- invalid input: exit 1, one message naming the key, no result ---------------

struct InvalidCase {
  const char* name;
  std::function<json()> scene;  // null: a file that does not exist
  const char* expected;         // in the message
};

const std::vector<InvalidCase>& InvalidCases() {
  static const std::vector<InvalidCase> cases = {
      {"fabric inside an obstacle",
       [] {
         json doc = SceneJson("strip-fold.json");
         doc["obstacles"][0]["plane"]["point"] = {0, 0, "1 cm"};
         return doc;
       },
       "obstacles: the fabric starts inside an obstacle: node"},
      {"bending law flat at zero curvature",
       [] {
         json doc = BlockDrape(10);
         doc["material"]["bending"] = {{"model", "curve"},
                                       {"points", {{0.5, 0.0}, {1.0, 0.2}, {2.0, 0.6}}},
                                       {"moment_unit", "gf*cm/cm"},
                                       {"curvature_unit", "1/cm"}};
         return doc;
       },
       "material.bending: the bending law's stiffness dM/dK at K = 0 is not positive"},
      {"Poisson ratio 0.5",
       [] {
         json doc = BlockDrape(10);
         doc["material"]["poisson_ratio"] = 0.5;
         return doc;
       },
       "material.poisson_ratio: must lie in [0, 0.5)"},
      {"misspelt key",
       [] {
         json doc = BlockDrape(10);
         doc["solver"]["max_iteration"] = 3;
         return doc;
       },
       "solver.max_iteration: unknown key; did you mean 'max_iterations'?"},
      {"zero elements",
       [] {
         json doc = BlockDrape(10);
         doc["fabric"]["mesh"]["elements"][1] = 0;
         return doc;
       },
       "fabric.mesh.elements[1]: must be at least 1"},
      {"missing file", nullptr, "no-such-scene.json"},
  };
  return cases;
}

class RunCliInvalid : public ::testing::TestWithParam<size_t> {};

TEST_P(RunCliInvalid, ExitsOneNamingTheKeyAndWritesNothing) {
  const InvalidCase& c = InvalidCases()[GetParam()];
  TempDir dir("invalid-" + std::to_string(GetParam()));
  const fs::path scene =
      c.scene ? WriteJson(c.scene(), dir / "scene.json") : dir / "no-such-scene.json";
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 1) << c.name << "\n" << r.output;
  EXPECT_NE(r.output.find(c.expected), std::string::npos)
      << c.name << ": expected \"" << c.expected << "\" in\n"
      << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "result.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "states.bin"));
}

INSTANTIATE_TEST_SUITE_P(RunCliInvalidInput,
                         RunCliInvalid,
                         ::testing::Range<size_t>(0, InvalidCases().size()),
                         [](const auto& info) {
                           std::string name = InvalidCases()[info.param].name;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(RunCliArguments, BadArgumentsExitOne) {
  TempDir dir("arguments");
  const fs::path scene = WriteJson(BlockDrape(10), dir / "scene.json");

  const CommandResult no_output = RunCommand("run " + Quote(scene));
  EXPECT_EQ(no_output.exit_code, 1) << no_output.output;
  EXPECT_NE(no_output.output.find("--output"), std::string::npos) << no_output.output;

  const CommandResult no_scene = RunCommand("run -o " + Quote(dir / "out"));
  EXPECT_EQ(no_scene.exit_code, 1) << no_scene.output;

  const CommandResult negative_threads =
      RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out") + " --threads -1");
  EXPECT_EQ(negative_threads.exit_code, 1) << negative_threads.output;
  EXPECT_FALSE(fs::exists(dir / "out"));

  // A result folder that cannot be created (its parent is a file).
  std::ofstream(dir / "file") << "x";
  const CommandResult bad_folder =
      RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "file" / "out"));
  EXPECT_EQ(bad_folder.exit_code, 1) << bad_folder.output;
  EXPECT_NE(bad_folder.output.find((dir / "file" / "out").string()), std::string::npos)
      << bad_folder.output;
}

// ---- solver failure: exit 2, partial result ------------------------------------

TEST(RunCliFailure, TooFewIterationsFailsWithAPartialResult) {
  TempDir dir("failed");
  json doc = BlockDrape(10);
  doc["solver"]["max_iterations"] = 1;
  doc["solver"]["max_step_cuts"] = 1;
  const fs::path scene = WriteJson(doc, dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;

  ASSERT_TRUE(fs::exists(dir / "out" / "result.json")) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  EXPECT_EQ(result["status"], "failed");
  const std::string message = result["message"];
  EXPECT_NE(message.find("stage 'SW'"), std::string::npos) << message;
  EXPECT_NE(message.find("cut-backs"), std::string::npos) << message;
  EXPECT_NE(message.find("no convergence in 1 iterations"), std::string::npos) << message;
  EXPECT_NE(r.output.find(message), std::string::npos) << r.output;  // the brief report says why
  ASSERT_TRUE(result["steps"].is_array());
  ASSERT_EQ(result["stages"].size(), 1u);
  EXPECT_LT(result["stages"][0]["final_lambda"].get<double>(), 1.0);
  EXPECT_GE(result["stages"][0]["step_cuts"].get<int>(), 1);
  EXPECT_EQ(result["mesh"]["nodes"], 121);

  const StateFile states = ReadStateFile(dir / "out" / "states.bin");
  EXPECT_EQ(states.mesh.NodeCount(), 121);
  EXPECT_EQ(states.mesh.ElementCount(), 100);
  EXPECT_EQ(states.steps.size(), result["steps"].size());
}

// --time-limit: the diagonal fold (seconds long) stopped after a tenth of a
// second fails with the reason and keeps every step it converged, in
// result.json and states.bin alike.
TEST(RunCliFailure, ATimeLimitStopsTheRunAndKeepsItsSteps) {
  TempDir dir("time-limit");
  const CommandResult r = RunCommand("run " + Quote(test::ScenesDir() / "diagonal-fold.json") +
                                     " -o " + Quote(dir / "out") + " --time-limit 0.1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  EXPECT_EQ(result["status"], "failed");
  const std::string message = result["message"];
  EXPECT_NE(message.find("time limit of 0.1 s"), std::string::npos) << message;
  const StateFile states = ReadStateFile(dir / "out" / "states.bin");
  EXPECT_EQ(states.steps.size(), result["steps"].size());
  EXPECT_NE(RunCommand("run " + Quote(test::ScenesDir() / "diagonal-fold.json") + " -o " +
                       Quote(dir / "bad") + " --time-limit -1")
                .exit_code,
            0);
}

// A strip balanced on a frictionless rod is a chain over a pulley: once its
// weight outgrows the stabilisation springs, its symmetric hang bifurcates
// and every branch from there slides off (the part would snap). Under
// `stable` branching that is a clear failure with every step kept, the last
// one the stable state just before the bifurcation; under `fundamental` the
// run converges on the primary path and warns that it ends unstable.
TEST(RunCliFailure, ABifurcationWithNoStableBranchFailsAndKeepsItsSteps) {
  TempDir dir("no-stable-branch");
  json doc = {
      {"drape_scene", 1},
      {"name", "strip balanced on a frictionless rod"},
      {"fabric",
       {{"outline", {{"rectangle", {{"size", {"40 cm", "1 cm"}}, {"center", {0, 0}}}}}},
        {"mesh", {{"elements", {80, 1}}}}}},
      {"material",
       {{"thickness", "0.5 mm"},
        {"areal_weight", 2.0},
        {"youngs_modulus", "2 MPa"},
        {"poisson_ratio", 0.0}}},
      {"obstacles",
       {{{"name", "rod"},
         {"cylinder", {{"point", {0, 0, "-2.025 cm"}}, {"axis", {0, 1, 0}}, {"radius", "2 cm"}}}}}},
      {"contact", {{"penalty", "auto"}, {"friction", 0.0}}},
      {"stages", {{{"name", "SW"}, {"kind", "gravity"}, {"initial_increment", 0.01}}}}};
  const fs::path scene = WriteJson(doc, dir / "scene.json");
  const CommandResult r = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  const json result = ReadJson(dir / "out" / "result.json");
  EXPECT_EQ(result["status"], "failed");
  const std::string message = result["message"];
  EXPECT_NE(message.find("bifurcates"), std::string::npos) << message;
  EXPECT_NE(message.find("no stable branch"), std::string::npos) << message;
  ASSERT_GE(result["steps"].size(), 1u);
  EXPECT_EQ(result["steps"].back()["negative_pivots"], 0);
  EXPECT_LT(result["steps"].back()["lambda"].get<double>(), 0.01);
  const StateFile states = ReadStateFile(dir / "out" / "states.bin");
  EXPECT_EQ(states.steps.size(), result["steps"].size());

  doc["solver"]["branching"] = "fundamental";
  WriteJson(doc, dir / "scene.json");
  const CommandResult f = RunCommand("run " + Quote(scene) + " -o " + Quote(dir / "fundamental"));
  EXPECT_EQ(f.exit_code, 0) << f.output;
  const json primary = ReadJson(dir / "fundamental" / "result.json");
  EXPECT_GT(primary["steps"].back()["negative_pivots"].get<int>(), 0);
  ASSERT_FALSE(primary["warnings"].empty());
  EXPECT_NE(primary["warnings"].back().get<std::string>().find("unstable equilibrium"),
            std::string::npos);
  // The summary's first line does not let it pass as "converged".
  const int pivots = primary["steps"].back()["negative_pivots"];
  EXPECT_NE(f.output.find("converged to an unstable equilibrium (" + std::to_string(pivots) +
                          " negative pivot"),
            std::string::npos)
      << f.output;
  for (const auto& e : primary["stability_events"]) {
    EXPECT_EQ(e["kind"], "bifurcation");
    EXPECT_EQ(e["branch"], "fundamental");
  }
}

// ---- cancellation: exit 130, partial result -----------------------------------

// Block drape 40 × 40 (1681 nodes) under load control with fixed steps of
// 0.001: a thousand steps, minutes of work. Started with fork/exec, sent `signal` once
// states.bin holds two step records.
void InterruptLongRun(int signal_number, const std::string& name) {
  TempDir dir(name);
  json doc = BlockDrape(40);
  doc["solver"]["acceleration"] = false;
  doc["stages"][0]["control"] = "load";
  doc["stages"][0]["initial_increment"] = 0.001;
  const fs::path scene = WriteJson(doc, dir / "scene.json");
  const fs::path out = dir / "out";
  const fs::path log = dir / "stderr.txt";
  constexpr int kNodes = 41 * 41, kElements = 40 * 40;

  pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    int err = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int null = open("/dev/null", O_WRONLY);
    if (err < 0 || null < 0) _exit(126);
    dup2(err, STDERR_FILENO);
    dup2(null, STDOUT_FILENO);
    const std::string scene_arg = scene.string(), out_arg = out.string();
    const char* argv[] = {DRAPE_CLI, "run", scene_arg.c_str(), "-o", out_arg.c_str(), nullptr};
    execv(DRAPE_CLI, const_cast<char* const*>(argv));
    _exit(127);
  }

  const auto two_records = StateFileBytes(kNodes, kElements, 2);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  bool ready = false, exited = false;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    const auto size = fs::file_size(out / "states.bin", ec);
    if (!ec && size >= two_records) {
      ready = true;
      break;
    }
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!ready) {
    if (!exited) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
    }
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    FAIL() << (exited ? "drape exited before two steps" : "no two steps within 30 s") << "\n"
           << text;
  }
  ASSERT_EQ(kill(pid, signal_number), 0);
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_TRUE(WIFEXITED(status)) << "terminated by signal "
                                 << (WIFSIGNALED(status) ? WTERMSIG(status) : 0) << "\n"
                                 << text;
  EXPECT_EQ(WEXITSTATUS(status), 130) << text;

  ASSERT_TRUE(fs::exists(out / "result.json")) << text;
  const json result = ReadJson(out / "result.json");
  EXPECT_EQ(result["status"], "cancelled");
  EXPECT_NE(result["message"].get<std::string>().find("cancelled"), std::string::npos)
      << result["message"];
  const json& steps = result["steps"];
  ASSERT_GE(steps.size(), 2u);
  EXPECT_LT(steps.back()["lambda"].get<double>(), 1.0);
  EXPECT_EQ(result["final"]["step"], steps.back()["step"]);
  EXPECT_EQ(result["final"]["positions"].size(), static_cast<size_t>(kNodes));

  const StateFile states = ReadStateFile(out / "states.bin");
  ASSERT_EQ(states.steps.size(), steps.size());
  for (size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(states.steps[i].step, steps[i]["step"].get<int>());
    EXPECT_EQ(states.steps[i].lambda, steps[i]["lambda"].get<double>());
  }
  EXPECT_EQ(fs::file_size(out / "states.bin"), StateFileBytes(kNodes, kElements, steps.size()));
}

TEST(RunCliCancel, SigintCancelsWithAPartialResult) {
  InterruptLongRun(SIGINT, "sigint");
}

TEST(RunCliCancel, SigtermCancelsWithAPartialResult) {
  InterruptLongRun(SIGTERM, "sigterm");
}

}  // namespace
}  // namespace drape
