// `drape plan` on the 20-element strip fold
// (resources/scenes/strip-convergence-20.json, a fifth of a second a run): a plan file refused
// naming its key; one search whose table, best scene and best result are checked against the fold's
// kinematics; a run that fails is a penalised row, not the end; Ctrl-C
// keeps what finished and a rerun resumes without running it again. The
// whole recovery of the shipped plan and the flat term on the diagonal
// fold are in plan_cli_slow_test.cc.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::Column;
using test::ReadCsv;
using test::ReadText;

// Where the fold lands its gripped end: x₀ = (−10 cm, 0, 0) turned by 180°
// about the axis through (0, 0, c), c = 0.036675 cm, is (10 cm, 0, 2c).
constexpr double kCentre = 0.036675e-2;
constexpr double kLandingX = 0.10, kLandingZ = 2 * kCentre;

class PlanCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drape-plan-cli-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // A plan of the arc's angle alone, in [lo, hi] from `start`.
  fs::path WritePlan(double lo, double hi, double start, int evaluations) {
    const fs::path file = dir_ / "plan.json";
    std::ofstream(file) << R"({"drape_plan": 1, "scene": ")"
                        << (test::ScenesDir() / "strip-convergence-20.json").string() << R"(",
      "parameters": [{"key": "stages[1].moves[0].path.arc.angle_deg", "min": )"
                        << lo << ", \"max\": " << hi << ", \"start\": " << start << R"(}],
      "objective": {"probes": [{"probe": "end", "target": ["10 cm", 0, "0.07335 cm"]}]},
      "optimizer": {"max_evaluations": )"
                        << evaluations << "}}";
    return file;
  }

  fs::path dir_;
};

TEST_F(PlanCli, APlanFileErrorNamesTheKeyAndRunsNothing) {
  const fs::path file = dir_ / "bad.json";
  std::ofstream(file) << R"({"drape_plan": 1, "scene": ")"
                      << (test::ScenesDir() / "strip-fold.json").string() << R"(",
      "parameters": [{"key": "stages[1].moves[0].path.arc.angle_deg", "min": 170, "max": 190}],
      "objective": {"probes": [{"probe": "tip", "target": [0, 0, 0]}]}})";
  const test::CommandResult r =
      test::RunDrape("plan '" + file.string() + "' -o '" + (dir_ / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.output,
            "drape plan: " + file.string() +
                ": objective.probes[0].probe: the scene has no probe 'tip' (it has end, "
                "fold)\n");
  EXPECT_FALSE(fs::exists(dir_ / "out" / "evals"));
}

// The first evaluation is the shipped fold itself; the search's second step
// (a fifth of the range up, 186°) drives the end into the table and fails.
TEST_F(PlanCli, ATableOfEveryEvaluationTheBestKeptAndAFailurePenalised) {
  const fs::path out = dir_ / "out";
  const test::CommandResult r = test::RunDrape("plan '" + WritePlan(170, 200, 180, 5).string() +
                                               "' -o '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = ReadCsv(out / "plan.csv");
  ASSERT_GE(rows.size(), 3u);
  const auto& header = rows[0];
  const size_t status = Column(header, "status"), distance = Column(header, "end_distance_m"),
               length = Column(header, "path_length_m"), value = Column(header, "search_value_m"),
               angle = Column(header, "stages[1].moves[0].path.arc.angle_deg");
  EXPECT_EQ(rows[1][angle], "180");
  EXPECT_EQ(rows[1][status], "converged");
  EXPECT_LT(std::stod(rows[1][distance]), 1e-9);
  // The end's path: a half circle of radius √(0.1² + c²), measured as
  // chords between steps: short of the arc, by under 2e-3 (steps of < 13°).
  const double arc = M_PI * std::hypot(0.1, kCentre);
  EXPECT_LE(std::stod(rows[1][length]), arc);
  EXPECT_GT(std::stod(rows[1][length]), arc * (1 - 2e-3));
  int failed = 0;
  for (size_t i = 1; i < rows.size(); ++i) {
    for (const std::string& cell : rows[i]) EXPECT_EQ(cell.find("nan"), std::string::npos);
    if (rows[i][status] != "failed") continue;
    ++failed;
    EXPECT_EQ(rows[i][Column(header, "feasible")], "no");
    EXPECT_EQ(rows[i][Column(header, "objective_m")], "");
    // Above the worst feasible objective before it by 0.1 × the diagonal (20 × 1 cm) ×
    // (1 + 2 × the share of the stages it did not get through).
    double worst = 0;
    for (size_t j = 1; j < i; ++j)
      if (rows[j][Column(header, "feasible")] == "yes")
        worst = std::max(worst, std::stod(rows[j][distance]));
    const json run =
        json::parse(ReadText(out / "evals" / ("s1-e000" + rows[i][1]) / "result" / "result.json"));
    double reached = 0;
    for (const json& stage : run["stages"]) reached += stage["final_lambda"].get<double>();
    const double progress = reached / 2;  // SW, R
    EXPECT_NEAR(std::stod(rows[i][Column(header, "progress")]), progress, 1e-8);
    EXPECT_NEAR(std::stod(rows[i][value]),
                worst + 0.1 * std::hypot(0.2, 0.01) * (1 + 2 * (1 - progress)),
                1e-8);
  }
  EXPECT_GE(failed, 1) << ReadText(out / "plan.csv");
  // The best: its scene and result, the end where the fold puts it.
  const json best = json::parse(ReadText(out / "best" / "result" / "result.json"));
  EXPECT_EQ(best["status"], "converged");
  const auto end = best["final"]["probes"]["end"];
  EXPECT_NEAR(end[0].get<double>(), kLandingX, 1e-9);
  EXPECT_NEAR(end[2].get<double>(), kLandingZ, 1e-9);
  for (const json& step : best["steps"]) EXPECT_EQ(step["negative_pivots"], 0);
  EXPECT_TRUE(fs::is_regular_file(out / "best" / "scene.json"));
  EXPECT_NE(r.output.find("best: objective "), std::string::npos) << r.output;
  // The pictures are drawn by drape-vtk where there is a display
  // (tests/render/plan_chart_test.cc); else the plan says why not.
  for (const std::string name : {"plan.png", "best.png"}) {
    const std::string line = (name == "plan.png" ? "chart: " : "best path: ");
    ASSERT_NE(r.output.find(line), std::string::npos) << r.output;
    if (r.output.find(line + "not drawn: ") == std::string::npos)
      EXPECT_TRUE(fs::is_regular_file(out / name)) << r.output;
  }
}

// Ctrl-C after the second evaluation: exit 130, the table holds what
// finished; the rerun takes those from their folders and completes.
TEST_F(PlanCli, CtrlCKeepsTheBestAndARerunResumes) {
  const fs::path out = dir_ / "out";
  const std::string command = std::string(test::DrapeCli()) + " plan '" +
                              WritePlan(170, 180, 172, 6).string() + "' -o '" + out.string() + "'";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", ("exec " + command + " > /dev/null 2>&1").c_str(), nullptr);
    _exit(127);
  }
  const fs::path second = out / "evals" / "s1-e0002" / "result" / "result.json";
  // Minutes: under the sanitizers a run takes seconds.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(600);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(second) && ReadText(second).find("\"status\": \"running\"") == std::string::npos)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // Wait for the table to hold it, then interrupt the whole group.
  while (std::chrono::steady_clock::now() < deadline && ReadCsv(out / "plan.csv").size() < 3)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(-pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto first = ReadCsv(out / "plan.csv");
  ASSERT_GE(first.size(), 3u);
  EXPECT_TRUE(fs::is_regular_file(out / "best" / "scene.json"));
  const auto kept = fs::last_write_time(out / "evals" / "s1-e0001" / "result" / "result.json");

  const test::CommandResult rerun =
      test::RunDrape("plan '" + (out / "plan.json").string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_EQ(fs::last_write_time(out / "evals" / "s1-e0001" / "result" / "result.json"), kept);
  const auto second_table = ReadCsv(out / "plan.csv");
  ASSERT_GE(second_table.size(), first.size());
  // The evaluations that ended (converged or failed) are replayed: the same
  // points with the same answers. One the interrupt cut off (cancelled, or
  // missing when it stopped before its result was written) is made again.
  int replayed = 0;
  for (size_t i = 1; i < first.size(); ++i) {
    const std::string status = first[i][Column(first[0], "status")];
    if (status != "converged" && status != "failed") continue;
    EXPECT_EQ(second_table[i], first[i]);
    ++replayed;
  }
  EXPECT_GE(replayed, 2);
}

}  // namespace
}  // namespace drape
