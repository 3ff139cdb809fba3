// Nothing lost when a run dies (issue 18): `drape run` killed with SIGKILL
// at random moments of a strip fold and of a 50 × 50 drape, 20 times each.
// Every time the result folder reads (as `drape render/animate/export` read
// it), holds every step states.bin recorded, and no file is half-written:
// result.json parses, steps.csv ends with a whole line and lists no step
// states.bin lacks. The moments are spread over a whole run's time. And what
// a killed run kept is what the run to its end computed: each kept step,
// its λ, every node's position and director, agrees with the same step of
// the whole run (the same computation, the same threads).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
        test::DrapeCli(), "run", scene_arg.c_str(), "-o", out_arg.c_str(), "--quiet", nullptr};
    execv(test::DrapeCli(), const_cast<char* const*>(argv));
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
  if (!fs::exists(out / "result.json")) {
    // Killed before the result was first written: nothing was promised yet,
    // but a state file already there is whole (it takes its name only then).
    if (fs::exists(out / "states.bin")) {
      EXPECT_NO_THROW(ReadStateFile(out / "states.bin")) << what;
    }
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

// The largest difference between the steps `kept` holds and the same steps
// of `whole`, relative to the largest coordinate of the whole run's step
// (positions) or to 1 (directors, λ); the steps must be the same ones.
double LargestDifference(const StateFile& kept, const StateFile& whole, const std::string& what) {
  double largest = 0;
  EXPECT_LE(kept.steps.size(), whole.steps.size()) << what;
  for (size_t i = 0; i < kept.steps.size() && i < whole.steps.size(); ++i) {
    const StoredStep &a = kept.steps[i], &b = whole.steps[i];
    EXPECT_EQ(a.stage, b.stage) << what << ", record " << i;
    EXPECT_EQ(a.step, b.step) << what << ", record " << i;
    if (a.positions.rows() != b.positions.rows()) {
      ADD_FAILURE() << what << ", record " << i << ": " << a.positions.rows() << " nodes, not "
                    << b.positions.rows();
      continue;
    }
    const double size = b.positions.cwiseAbs().maxCoeff();
    largest = std::max({largest,
                        std::abs(a.lambda - b.lambda),
                        (a.positions - b.positions).cwiseAbs().maxCoeff() / size,
                        (a.directors - b.directors).cwiseAbs().maxCoeff()});
  }
  return largest;
}

// Kills at 20 moments drawn from a seeded generator over the time a whole
// run takes on this machine (measured first: sanitizers slow it down).
// `same_to`: how far a kept step may be from the whole run's (relative).
void KillTwentyTimes(const fs::path& scene, const std::string& name, double same_to) {
  const fs::path dir =
      fs::temp_directory_path() / ("drape-kill-" + name + "-" + std::to_string(getpid()));
  const int whole_ms = RunAndKill(scene, dir / "whole", std::nullopt);
  ASSERT_GT(whole_ms, 0);
  EXPECT_GT(ExpectWholeFolder(dir / "whole", name + " run to its end"), 2u);
  const StateFile whole = ReadStateFile(dir / "whole" / "states.bin");
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> delay(0, whole_ms);
  size_t most = 0, compared = 0;
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    const fs::path out = dir / std::to_string(k);
    const int ms = delay(rng);
    RunAndKill(scene, out, std::chrono::milliseconds(ms));
    const std::string what = name + " killed at " + std::to_string(ms) + " ms";
    const size_t kept = ExpectWholeFolder(out, what);
    most = std::max(most, kept);
    if (kept == 0) continue;
    const double difference = LargestDifference(ReadStateFile(out / "states.bin"), whole, what);
    EXPECT_LE(difference, same_to) << what << ": " << kept << " steps kept";
    worst = std::max(worst, difference);
    compared += kept;
  }
  std::printf("%s: %zu kept steps compared with the whole run's, largest difference %.3g\n",
              name.c_str(),
              compared,
              worst);
  EXPECT_GT(most, 0u);  // some kills came after steps had converged
  fs::remove_all(dir);
}

// A killed run and the run to its end are the same computation: measured
// bit for bit the same (a difference of 0 at every kept step of both scenes,
// and between runs on one and on two threads), so 1e-12 is round-off's room.
constexpr double kSameTo = 1e-12;

TEST(KillRun, StripFoldKilledAtRandomMomentsLeavesAWholeFolder) {
  KillTwentyTimes(test::ScenesDir() / "strip-fold.json", "strip-fold", kSameTo);
}

TEST(KillRun, FiftyByFiftyDrapeKilledAtRandomMomentsLeavesAWholeFolder) {
  std::ifstream in(test::ScenesDir() / "block-drape.json");
  json doc = json::parse(in);
  doc["fabric"]["mesh"]["elements"] = {50, 50};
  // The path on this mesh, step by step (auto would sequence it: one step).
  doc["solver"]["sequencing"] = 1;
  const fs::path scene =
      fs::temp_directory_path() / ("drape-kill-drape-" + std::to_string(getpid()) + ".json");
  std::ofstream(scene) << doc.dump(1);
  KillTwentyTimes(scene, "drape-50", kSameTo);
  fs::remove(scene);
}

}  // namespace
}  // namespace drape
