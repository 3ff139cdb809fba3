// Nothing lost when a run dies (issue 18): `drape run` killed with SIGKILL
// at random moments of a strip fold and of a 50 × 50 drape, 20 times each.
// Every time the result folder reads (as `drape render/animate/export` read
// it), holds every step states.bin recorded, and no file is half-written:
// result.json parses, steps.csv ends with a whole line and lists no step
// states.bin lacks. The moments are spread over a whole run's time.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <thread>

#include "core/io/result_reader.h"
#include "core/io/state_file.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Starts `drape run SCENE -o OUT --quiet` and kills it after `delay`, or
// (no delay) lets it finish; returns how long it ran [ms].
int RunAndKill(const fs::path& scene,
               const fs::path& out,
               std::optional<std::chrono::milliseconds> delay) {
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    const std::string scene_arg = scene.string(), out_arg = out.string();
    const char* argv[] = {
        DRAPE_CLI, "run", scene_arg.c_str(), "-o", out_arg.c_str(), "--quiet", nullptr};
    execv(DRAPE_CLI, const_cast<char* const*>(argv));
    _exit(127);
  }
  if (delay) {
    std::this_thread::sleep_for(*delay);
    kill(pid, SIGKILL);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(
                              std::chrono::steady_clock::now() - start)
                              .count());
}

// The folder as a reader finds it, checked; returns the steps it holds.
size_t ExpectWholeFolder(const fs::path& out, const std::string& what) {
  if (!fs::exists(out / "states.bin")) {
    // Killed before the writer started: nothing was promised yet.
    EXPECT_FALSE(fs::exists(out / "result.json")) << what;
    return 0;
  }
  const StateFile states = ReadStateFile(out / "states.bin");
  RunRecord record;
  try {
    record = ReadRunRecord(out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": " << e.what();
    return 0;
  }
  EXPECT_EQ(record.states.size(), states.steps.size()) << what;
  EXPECT_EQ(record.steps.size(), states.steps.size()) << what;
  for (size_t i = 0; i < record.steps.size() && i < states.steps.size(); ++i)
    EXPECT_EQ(record.steps[i].step, states.steps[i].step) << what;
  EXPECT_TRUE(record.status == "running" || record.status == "converged") << record.status;

  std::ifstream csv(out / "steps.csv", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(csv)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(text.empty()) << what;
  if (!text.empty()) {
    EXPECT_EQ(text.back(), '\n') << what << ": a half line";
  }
  const size_t rows = std::count(text.begin(), text.end(), '\n') - 1;  // less the header
  // A step goes to states.bin first, then to steps.csv.
  EXPECT_TRUE(rows == states.steps.size() || rows + 1 == states.steps.size())
      << what << ": " << rows << " rows, " << states.steps.size() << " states";
  return states.steps.size();
}

// Kills at 20 moments drawn from a seeded generator over the time a whole
// run takes on this machine (measured first: sanitizers slow it down).
void KillTwentyTimes(const fs::path& scene, const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("drape-kill-" + name + "-" + std::to_string(getpid()));
  const int whole_ms = RunAndKill(scene, dir / "whole", std::nullopt);
  ASSERT_GT(whole_ms, 0);
  EXPECT_GT(ExpectWholeFolder(dir / "whole", name + " run to its end"), 2u);
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> delay(0, whole_ms);
  size_t most = 0;
  for (int k = 0; k < 20; ++k) {
    const fs::path out = dir / std::to_string(k);
    const int ms = delay(rng);
    RunAndKill(scene, out, std::chrono::milliseconds(ms));
    most =
        std::max(most, ExpectWholeFolder(out, name + " killed at " + std::to_string(ms) + " ms"));
  }
  EXPECT_GT(most, 0u);  // some kills came after steps had converged
  fs::remove_all(dir);
}

TEST(KillRun, StripFoldKilledAtRandomMomentsLeavesAWholeFolder) {
  KillTwentyTimes(test::ScenesDir() / "strip-fold.json", "strip-fold");
}

TEST(KillRun, FiftyByFiftyDrapeKilledAtRandomMomentsLeavesAWholeFolder) {
  std::ifstream in(test::ScenesDir() / "block-drape.json");
  json doc = json::parse(in);
  doc["fabric"]["mesh"]["elements"] = {50, 50};
  const fs::path scene =
      fs::temp_directory_path() / ("drape-kill-drape-" + std::to_string(getpid()) + ".json");
  std::ofstream(scene) << doc.dump(1);
  KillTwentyTimes(scene, "drape-50");
  fs::remove(scene);
}

}  // namespace
}  // namespace drape
