// `drape drag`: frames.csv, the dragged scene and its released run (a
// 24-frame drag of a 20 × 20 sheet, then two runs of it: seconds here,
// minutes under the sanitizers, so the slow tier: tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "core/io/result_reader.h"
#include "core/io/scene_reader.h"
#include "core/solve/gripper_drag.h"
#include "core/solve/shell_solver.h"
#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// The released run and the dragged scene solved here are one computation
// (the scene written to scene.json and read back): measured the same bit for
// bit; 1e-12 m leaves room for round-off only.
constexpr double kSameRun = 1e-12;

std::string CornerLift() {
  return (test::SourceDir() / "tests" / "data" / "corner-lift-20x20.json").string();
}

TEST(DragCli, WritesEveryFrameAndTheReleasedRun) {
  test::TempDir dir("drag");
  const auto drag =
      test::RunDrape("drag " + CornerLift() + " --gripper corner --by '0,0,3 cm' --frames 24 -o " +
                     (dir / "drag").string());
  ASSERT_EQ(drag.exit_code, 0) << drag.output;
  EXPECT_NE(drag.output.find("dragged 'corner' in 24 frames"), std::string::npos) << drag.output;

  const auto rows = test::ReadCsv(dir / "drag" / "frames.csv");
  ASSERT_EQ(rows.size(), 25u);
  ASSERT_GE(rows[0].size(), 3u);
  EXPECT_EQ(rows[0][0], "frame");
  EXPECT_EQ(rows[0][1], "seconds");
  EXPECT_EQ(rows[0][2], "residual_ratio");
  EXPECT_EQ(rows[0].back(), "event");
  for (size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), rows[0].size()) << "row " << r;
    EXPECT_EQ(std::stoi(rows[r][0]), static_cast<int>(r));
    // Numbers, then the event (this drag lifts a corner: nothing snaps).
    for (size_t c = 0; c + 1 < rows[r].size(); ++c)
      EXPECT_TRUE(std::isfinite(std::stod(rows[r][c]))) << "row " << r << ", column " << c;
    EXPECT_EQ(rows[r].back(), "") << "row " << r;
    EXPECT_GT(std::stod(rows[r][1]), 0);
    EXPECT_LE(std::stod(rows[r][2]), 1e-2) << "row " << r;
  }

  // The released state is a plain run of the dragged scene the command wrote.
  const auto plain = test::RunDrape("run " + (dir / "drag" / "scene.json").string() + " -q -o " +
                                    (dir / "run").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const RunRecord released = ReadRunRecord(dir / "drag");
  const RunRecord again = ReadRunRecord(dir / "run");
  EXPECT_EQ(released.status, "converged");
  ASSERT_EQ(released.scene.stages.size(), 2u);
  EXPECT_EQ(released.scene.stages.back().name, "drag corner");
  ASSERT_EQ(released.states.size(), again.states.size());
  const ShellState a = StateOf(released, released.states.size() - 1);
  const ShellState b = StateOf(again, again.states.size() - 1);
  EXPECT_LE((a.positions - b.positions).rowwise().norm().maxCoeff(), 1e-6 * 0.2);

  // And it is the scene the drag asked for: the corner lifted 3 cm after
  // the stages, solved here from the scene file, every node (the fabric the
  // corner carries, not only the corner) at the released state's place.
  const Scene asked = DraggedScene(ReadScene(CornerLift()), "corner", {0, 0, 0.03});
  ShellSolver solver(asked, SolverOptions::FromScene(asked.solver));
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  const double distance = (a.positions - solver.state().positions).rowwise().norm().maxCoeff();
  std::printf("released state to the asked scene's: %.3g m\n", distance);
  EXPECT_LE(distance, kSameRun);
}

}  // namespace
}  // namespace drape
