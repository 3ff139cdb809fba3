// `drape study`: a grid of runs of the 20-element strip fold
// (strip-convergence-20.json, a fraction of a second each) run as parallel
// processes and tabulated; a rerun keeps what is done; Ctrl-C keeps what
// finished; the job lists for GNU parallel and Slurm run as they are; and
// --collect makes the same table from the folders. The 24-run sweep is in
// study_cli_slow_test.cc.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

using test::Column;
using test::ReadCsv;
using test::ReadText;

class StudyCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drape-study-cli-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // Meshes 10 × 1 and 20 × 2, tolerances 1e-3 and 1e-5, against 40 × 4 at
  // 1e-8: five runs.
  fs::path WriteStudy(const std::string& extra = "") {
    const fs::path file = dir_ / "study.json";
    std::ofstream(file) << R"({"drape_study": 1, "scene": ")"
                        << (test::ScenesDir() / "strip-convergence-20.json").string() << R"(",
      "grid": {"fabric.mesh.elements": [[10, 1], [20, 2]], "solver.tolerance": [1e-3, 1e-5]},
      "reference": {"fabric.mesh.elements": [40, 4], "solver.tolerance": 1e-8})"
                        << extra << "}";
    return file;
  }

  fs::path dir_;
};

TEST_F(StudyCli, RunsAGridInParallelTabulatesItAndKeepsWhatIsDone) {
  const fs::path out = dir_ / "out";
  const test::CommandResult first =
      test::RunDrape("study '" + WriteStudy().string() + "' -o '" + out.string() + "' --jobs 2");
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("5 runs: 5 converged"), std::string::npos) << first.output;
  // front.png is drawn by drape front (tests/render/front_chart_test.cc)
  // where there is a renderer and a display; else the study says why not.
  if (first.output.find("front: not drawn: ") == std::string::npos) {
    EXPECT_TRUE(fs::is_regular_file(out / "front.png")) << first.output;
  }
  const auto rows = ReadCsv(out / "study.csv");
  ASSERT_EQ(rows.size(), 6u);  // header, four runs, the reference
  const auto& header = rows[0];
  EXPECT_EQ(header[0], "run");
  // No drape test, no drape columns (a Cusick study's: study_cli_slow_test.cc).
  EXPECT_EQ(std::find(header.begin(), header.end(), "drape_coefficient"), header.end());
  EXPECT_EQ(header[1], "fabric.mesh.elements");
  EXPECT_EQ(header[2], "solver.tolerance");
  EXPECT_EQ(rows[1][0], "run_001");
  EXPECT_EQ(rows[1][1], "[10,1]");
  EXPECT_EQ(rows[5][0], "reference");
  const size_t status = Column(header, "status"), error = Column(header, "fold_error_m"),
               node_error = Column(header, "max_node_error_m"), steps = Column(header, "steps"),
               memory = Column(header, "peak_memory_bytes"), wall = Column(header, "wall_s");
  for (size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(rows[r][status], "converged") << rows[r][0];
    EXPECT_GT(std::stoi(rows[r][steps]), 0);
    EXPECT_GT(std::stod(rows[r][memory]), 1e6);
    EXPECT_GT(std::stod(rows[r][wall]), 0);
  }
  // Each row's errors against the reference's own numbers, recomputed here
  // from the probe columns; the largest nodal error is at least the probe's.
  const size_t fx = Column(header, "fold_x_m");
  for (size_t r = 1; r < 5; ++r) {
    const double d = std::hypot(std::stod(rows[r][fx]) - std::stod(rows[5][fx]),
                                std::stod(rows[r][fx + 1]) - std::stod(rows[5][fx + 1]),
                                std::stod(rows[r][fx + 2]) - std::stod(rows[5][fx + 2]));
    EXPECT_NEAR(std::stod(rows[r][error]), d, 1e-8 + 1e-6 * d);
    EXPECT_GE(std::stod(rows[r][node_error]), std::stod(rows[r][error]) - 1e-12);
  }
  // The finer mesh is nearer the reference (the mesh dominates the error).
  EXPECT_LT(std::stod(rows[3][error]), std::stod(rows[1][error]));
  EXPECT_TRUE(rows[5][error].empty());  // the reference against itself: no number

  // A rerun keeps every run and writes the same table.
  const std::string table = ReadText(out / "study.csv");
  std::string lower = table;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  EXPECT_EQ(lower.find("nan"), std::string::npos) << table;
  EXPECT_EQ(lower.find("inf"), std::string::npos) << table;
  const test::CommandResult again =
      test::RunDrape("study '" + (dir_ / "study.json").string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("5 of 5 runs already done, kept"), std::string::npos) << again.output;
  EXPECT_EQ(ReadText(out / "study.csv"), table);

  // --collect makes the same table from the folder alone.
  fs::remove(out / "study.csv");
  const test::CommandResult collected = test::RunDrape("study '" + out.string() + "' --collect");
  ASSERT_EQ(collected.exit_code, 0) << collected.output;
  EXPECT_EQ(ReadText(out / "study.csv"), table);

  // Editing the study makes again only the runs whose scene changed.
  std::ofstream(dir_ / "study.json")
      << R"({"drape_study": 1, "scene": ")"
      << (test::ScenesDir() / "strip-convergence-20.json").string() << R"(",
      "grid": {"fabric.mesh.elements": [[10, 1], [20, 2]], "solver.tolerance": [1e-3, 1e-6]},
      "reference": {"fabric.mesh.elements": [40, 4], "solver.tolerance": 1e-8}})";
  const test::CommandResult edited =
      test::RunDrape("study '" + (dir_ / "study.json").string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(edited.exit_code, 0) << edited.output;
  EXPECT_NE(edited.output.find("3 of 5 runs already done, kept"), std::string::npos)
      << edited.output;
}

// Ctrl-C: the runs going on stop (cancelled, made again next time), what
// finished is tabulated, and the exit code says interrupted.
TEST_F(StudyCli, CtrlCKeepsWhatFinishedAndARerunCompletes) {
  const fs::path out = dir_ / "out";
  const std::string command = std::string(test::DrapeCli()) + " study '" + WriteStudy().string() +
                              "' -o '" + out.string() + "' --jobs 1";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    setpgid(0, 0);  // its own group, as a terminal's foreground job is
    execl("/bin/sh", "sh", "-c", ("exec " + command + " > /dev/null 2>&1").c_str(), nullptr);
    _exit(127);
  }
  // Interrupt once the reference (the first run) is done.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream in(out / "runs" / "reference" / "result" / "result.json");
    if (in && ReadText(out / "runs" / "reference" / "result" / "result.json")
                      .find("\"status\": \"converged\"") != std::string::npos)
      break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(-pid, SIGINT);  // the whole group, as Ctrl-C does
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  const int code = WEXITSTATUS(status);
  const auto rows = ReadCsv(out / "study.csv");
  ASSERT_EQ(rows.size(), 6u);
  int converged = 0;
  for (size_t r = 1; r < rows.size(); ++r)
    converged += rows[r][Column(rows[0], "status")] == "converged";
  EXPECT_GE(converged, 1);
  // The four runs left take tens of milliseconds each (process start
  // included); the signal comes within 5 ms of the reference's end.
  std::printf("interrupted with exit code %d after %d of 5 runs\n", code, converged);
  EXPECT_EQ(code, 130);
  EXPECT_LT(converged, 5);
  const test::CommandResult rerun =
      test::RunDrape("study '" + (dir_ / "study.json").string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_NE(rerun.output.find("5 runs: 5 converged"), std::string::npos) << rerun.output;
}

// The list for GNU parallel, run by parallel, then collected.
TEST_F(StudyCli, TheParallelListRunsAsWrittenAndIsCollected) {
  if (test::RunCommand("command -v parallel").exit_code != 0)
    GTEST_SKIP() << "GNU parallel is not installed (scripts/setup.sh installs it)";
  const fs::path out = dir_ / "out";
  const test::CommandResult emitted = test::RunDrape("study '" + WriteStudy().string() + "' -o '" +
                                                     out.string() + "' --emit parallel");
  ASSERT_EQ(emitted.exit_code, 0) << emitted.output;
  const std::string jobs = ReadText(out / "jobs.txt");
  EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 5);
  EXPECT_FALSE(fs::exists(out / "runs" / "run_001" / "result"));  // nothing run yet
  const test::CommandResult ran =
      test::RunCommand("parallel --will-cite -j 2 < '" + (out / "jobs.txt").string() + "'");
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  const test::CommandResult collected = test::RunDrape("study '" + out.string() + "' --collect");
  ASSERT_EQ(collected.exit_code, 0) << collected.output;
  EXPECT_NE(collected.output.find("5 runs: 5 converged"), std::string::npos) << collected.output;
  // Emitted again, only what is not done is listed.
  ASSERT_EQ(test::RunDrape("study '" + (dir_ / "study.json").string() + "' -o '" + out.string() +
                           "' --emit parallel")
                .exit_code,
            0);
  EXPECT_TRUE(ReadText(out / "jobs.txt").empty());
}

// The Slurm array: its size and runs, and one of its tasks run by bash as
// Slurm would (SLURM_ARRAY_TASK_ID set).
TEST_F(StudyCli, TheSlurmArrayHasOneTaskPerRunAndATaskRuns) {
  const fs::path out = dir_ / "out";
  const test::CommandResult emitted =
      test::RunDrape("study '" + WriteStudy(R"(, "time_limit_s": 300)").string() + "' -o '" +
                     out.string() + "' --emit slurm");
  ASSERT_EQ(emitted.exit_code, 0) << emitted.output;
  const std::string script = ReadText(out / "jobs.slurm");
  EXPECT_NE(script.find("#SBATCH --array=0-4\n"), std::string::npos) << script;
  EXPECT_NE(script.find("runs=( reference run_001 run_002 run_003 run_004 )"), std::string::npos)
      << script;
  EXPECT_NE(script.find("'--time-limit' '300'"), std::string::npos) << script;
  const test::CommandResult task =
      test::RunCommand("SLURM_ARRAY_TASK_ID=2 bash '" + (out / "jobs.slurm").string() + "'");
  ASSERT_EQ(task.exit_code, 0) << task.output;
  EXPECT_NE(ReadText(out / "runs" / "run_002" / "result" / "result.json").find("\"converged\""),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out / "runs" / "run_001" / "result" / "result.json"));
}

TEST_F(StudyCli, ABadStudyIsRefusedWithItsKey) {
  const fs::path file = dir_ / "bad.json";
  std::ofstream(file) << R"({"drape_study": 1, "scene": ")"
                      << (test::ScenesDir() / "strip-fold.json").string()
                      << R"(", "grid": {"solver.tolerance": [1e-3, 2]}})";
  const test::CommandResult r =
      test::RunDrape("study '" + file.string() + "' -o '" + (dir_ / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("run_002 (solver.tolerance = 2): solver.tolerance: must lie in (0, 1)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

}  // namespace
}  // namespace drape
