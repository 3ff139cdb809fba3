// `drape study`'s longest check: a 24-run sweep interrupted and resumed
// (tens of seconds, minutes under the sanitizers: the slow tier,
// tests/CMakeLists.txt); the others are in study_cli_test.cc.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// The Done-when's sweep: 24 runs of the paper's convergence strip (meshes
// 5 … 40 along × three tolerances × N_p 4 and 10) with progress, stopped by
// Ctrl-C once eight runs are done, then resumed: every run done before the
// interrupt is kept as it was (its result.json byte for byte), and the
// rerun finishes the other sixteen.
TEST(StudyCli, ATwentyFourRunSweepResumesAfterCtrlC) {
  const test::TempDir dir("study-sweep");
  const fs::path file = dir / "sweep.json";
  std::ofstream(file) << R"({"drape_study": 1, "scene": ")"
                      << (test::ScenesDir() / "strip-convergence-20.json").string() << R"(",
      "grid": {"fabric.mesh.elements": [[5, 1], [10, 1], [20, 1], [40, 1]],
               "solver.tolerance": [1e-3, 1e-5, 1e-7],
               "solver.target_iterations": [4, 10]},
      "reference": {"fabric.mesh.elements": [80, 1], "solver.tolerance": 1e-8}})";
  const fs::path out = dir / "sweep";
  const std::string command = std::string(test::DrapeCli()) + " study '" + file.string() +
                              "' -o '" + out.string() + "' --jobs 2";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);
    execl("/bin/sh", "sh", "-c", ("exec " + command + " > /dev/null 2>&1").c_str(), nullptr);
    _exit(127);
  }
  auto done_runs = [&] {
    std::map<std::string, std::string> done;
    std::error_code ec;
    for (const auto& run : fs::directory_iterator(out / "runs", ec)) {
      const std::string text = test::ReadText(run.path() / "result" / "result.json");
      if (text.find("\"status\": \"converged\"") != std::string::npos ||
          text.find("\"status\": \"failed\"") != std::string::npos)
        done[run.path().filename().string()] = text;
    }
    return done;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while (done_runs().size() < 8 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(-pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  const std::map<std::string, std::string> before = done_runs();
  std::printf(
      "interrupted with exit code %d after %zu of 25 runs\n", WEXITSTATUS(status), before.size());
  ASSERT_EQ(WEXITSTATUS(status), 130);
  ASSERT_GE(before.size(), 8u);
  ASSERT_LT(before.size(), 25u);
  const test::CommandResult rerun =
      test::RunDrape("study '" + file.string() + "' -o '" + out.string() + "' --jobs 2");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_NE(rerun.output.find(std::to_string(before.size()) + " of 25 runs already done, kept"),
            std::string::npos)
      << rerun.output;
  const std::map<std::string, std::string> after = done_runs();
  EXPECT_EQ(after.size(), 25u);
  for (const auto& [name, text] : before) EXPECT_EQ(after.at(name), text) << name;
  const auto rows = test::ReadCsv(out / "study.csv");
  EXPECT_EQ(rows.size(), 26u);  // header, 24 runs, the reference
}

// The shipped Cusick study: three specimens, each row with its drape
// coefficient and node count as `drape measure` gives them for that run's
// result, and the line that reports their mean and standard deviation
// computed here from the column (a minute and a half under the sanitizers:
// the slow tier). A study of a scene that is no drape test has no such
// columns (study_cli_test.cc).
TEST(StudyCli, CusickSpecimensReportTheirDrapeCoefficientsAndTheirSpread) {
  const test::TempDir dir_("study-cusick");
  const fs::path study = test::SourceDir() / "resources" / "studies" / "cusick-specimens.json";
  const auto r = test::RunDrape("study '" + study.string() + "' -o '" +
                                (dir_.path() / "out").string() + "' --jobs 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto rows = test::ReadCsv(dir_.path() / "out" / "study.csv");
  ASSERT_EQ(rows.size(), 4u);
  const size_t dc_column = test::Column(rows[0], "drape_coefficient");
  const size_t nodes_column = test::Column(rows[0], "drape_nodes");
  std::vector<double> dc, nodes;
  for (size_t i = 1; i < rows.size(); ++i) {
    const std::string run = rows[i][0];
    const auto m =
        test::RunDrape("measure '" + (dir_.path() / "out" / "runs" / run / "result").string() +
                       "' --drape-coefficient --json");
    ASSERT_EQ(m.exit_code, 0) << m.output;
    const auto measured = nlohmann::json::parse(m.output);
    dc.push_back(std::stod(rows[i][dc_column]));
    nodes.push_back(std::stod(rows[i][nodes_column]));
    EXPECT_NEAR(dc.back(), measured["drape_coefficient"].get<double>(), 1e-8) << run;
    EXPECT_EQ(nodes.back(), measured["nodes"].get<int>()) << run;
  }
  const double mean = (dc[0] + dc[1] + dc[2]) / 3;
  double ss = 0;
  for (double x : dc) ss += (x - mean) * (x - mean);
  char expected[64];
  std::snprintf(
      expected, sizeof expected, "drape coefficient %.3f ± %.3f", mean, std::sqrt(ss / 2));
  EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  EXPECT_NE(r.output.find("3 specimens"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace drape
