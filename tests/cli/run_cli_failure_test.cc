// `drape run SCENE -o DIR` when it does not converge: invalid input (exit 1,
// one message naming the key, no result), a failed run (exit 2) and a
// cancelled one (exit 130), each keeping the steps it made.
//
// The failed runs use block-drape.json on a 10 × 10 mesh; the cancelled runs
// use it on 40 × 40 without acceleration, which would take minutes, and
// interrupt it after two steps.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <system_error>
#include <thread>
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
using test::CommandResult;
using test::TempDir;
using test::run_cli::BlockDrape;
using test::run_cli::Quote;
using test::run_cli::ReadJson;
using test::run_cli::RunCommand;
using test::run_cli::SceneJson;
using test::run_cli::StateFileBytes;
using test::run_cli::WriteJson;

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
// and every branch from there slides off. Under `stable` branching the part
// snaps, and with the springs off while it jumps nothing holds it: no rest
// state, a clear failure that says why, with every step kept, the last one
// the stable state just before the bifurcation; under `fundamental` the run
// converges on the primary path and warns that it ends unstable.
TEST(RunCliFailure, ASnapWithNoRestStateFailsSaysWhyAndKeepsItsSteps) {
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
  EXPECT_NE(message.find("past a bifurcation point"), std::string::npos) << message;
  EXPECT_NE(message.find("no rest state"), std::string::npos) << message;
  EXPECT_NE(message.find("can slide off the obstacle"), std::string::npos) << message;
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
    const char* argv[] = {
        test::DrapeCli(), "run", scene_arg.c_str(), "-o", out_arg.c_str(), nullptr};
    execv(test::DrapeCli(), const_cast<char* const*>(argv));
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
