// Grippers moving along paths under arc-length continuation: the paper's
// strip fold without its table, finite rotations of a gripper, and the bad
// cases (a node asked to be in two places, nothing left holding the fabric).
// The longer runs are in path_following_slow_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <vector>

#include "core/fe/element_orientation.h"
#include "core/io/result_reader.h"
#include "core/io/result_writer.h"
#include "core/io/scene_reader.h"
#include "core/mechanics/director.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/solve/shell_solver.h"
#include "support/recorded_run.h"
#include "support/strip_scene.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::PrintStages;
using test::Probe;

TEST(PathFollowing, StripFoldWithoutTableCompletesTheFold) {
  const Scene scene = ReadScene(test::ScenesDir() / "strip-fold-no-table.json");
  test::Outcome run = test::SolveRecorded(scene);
  PrintStages("strip fold, acceleration on", run.summary);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  // R carries the left end on a semicircle about (0, 0, 0.75 h) onto
  // (0.1, 0, 1.5 h); T pulls it 1 cm further: (0.11, 0, 1.5 h), h = 0.0469 cm.
  const double h = 0.0469e-2;
  const Eigen::Vector3d end = Probe(run.steps.back(), "end");
  EXPECT_LT((end - Eigen::Vector3d(0.11, 0, 1.5 * h)).norm(), 1e-12);
  // The gripper turned the clamped end over: its director points down.
  const int gripped = 0;  // node 0 is the left edge's lower corner
  EXPECT_LT((run.steps.back().state.Director(gripped) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  // Half-way through R the end is at the top of the semicircle.
  bool passed_top = false;
  for (const auto& s : run.steps)
    if (s.stage == 1 && Probe(s, "end").z() > 0.099) passed_top = true;
  EXPECT_TRUE(passed_top);
  // Without a table the middle hangs below the held ends as a loop.
  EXPECT_LT(Probe(run.steps.back(), "fold").z(), -0.05);
}

TEST(PathFollowing, GripperTurnedTwoFullTurnsReturnsTheStripToItsStart) {
  // A heavy cantilever (α = 2) is turned by its clamping gripper through 720°
  // about the axis through the gripped edge: the finite-rotation update must
  // bring every node back to where the gravity stage left it.
  test::StripSpec spec;
  spec.elements = 20;
  Scene scene = test::HeavyStrip(spec, 2.0, 0.1);
  scene.stages[0].control = StepControl::kArcLength;
  // Converge every step to round-off, so that what remains is the error of
  // the rotation updates, not of the equilibrium tolerance.
  scene.solver.tolerance = 1e-12;
  scene.supports.clear();
  scene.grippers.push_back({"root", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kClamp});
  Stage turn;
  turn.name = "turn";
  turn.kind = StageKind::kMove;
  turn.initial_increment = 0.01;
  turn.moves.push_back({"root", ArcPath{{0, 0, 0}, {0, 1, 0}, 720.0}, {}});
  scene.stages.push_back(turn);
  test::Outcome run = test::SolveRecorded(scene);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const StepState* after_gravity = nullptr;
  for (const auto& s : run.steps)
    if (s.stage == 0) after_gravity = &s;
  ASSERT_NE(after_gravity, nullptr);
  const auto& a = after_gravity->state;
  const auto& b = run.steps.back().state;
  const double error = (b.positions - a.positions).cwiseAbs().maxCoeff();
  std::printf("  after 720°: max position change %.3e m (L = %.2f m), %d steps\n",
              error,
              spec.length,
              run.summary.stages[1].steps);
  EXPECT_LT(error, 1e-8 * spec.length);
  for (int i = 0; i < a.NodeCount(); ++i) EXPECT_LT((b.Director(i) - a.Director(i)).norm(), 1e-8);
}

// On a positive definite tangent the equilibrium path is a function of λ
// (implicit function theorem): between two steps that both end stable no
// limit point lies, so λ cannot fall. The 10 × 10 diagonal fold at the draft
// preset once turned back at λ = 0.899 with no negative pivot — the
// predictor went on in the direction of the step onto a stable branch,
// which had come back a little — unfolded the sheet and failed past
// λ = −1; the 40 × 40 fold never ended for the same reason.
TEST(PathFollowing, OnAStablePathTheLoadFactorNeverFalls) {
  Scene scene = ReadScene(test::ScenesDir() / "diagonal-fold.json");
  scene.solver = WithPreset(scene.solver, SolverPreset::kDraft);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  std::vector<StepState> steps;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    steps.push_back(s);
    return StepDecision::kContinue;
  }});
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  // The step onto a branch at a bifurcation may start behind it: that
  // switch is not a step along the path. (Until inside-out states were
  // refused this path crossed a "bifurcation" at λ = 0.9017, 0 → 4 negative
  // pivots; now one step there is cut back and the path crosses none. No
  // state the old run kept was inside out: the unkept state past the
  // crossing is the likely one.)
  std::set<int> switches;
  for (const StabilityEvent& e : summary.stability_events) switches.insert(e.step);
  for (const StepState& s : steps)
    EXPECT_FALSE(FindInvertedElement(solver.model(), s.state)) << "step " << s.step;
  int stable_pairs = 0;
  for (size_t i = 1; i < steps.size(); ++i) {
    const StepState &a = steps[i - 1], &b = steps[i];
    if (a.stage != b.stage || a.negative_pivots != 0 || b.negative_pivots != 0 ||
        switches.count(b.step))
      continue;
    ++stable_pairs;
    EXPECT_GE(b.lambda, a.lambda) << "stage " << b.stage << ", step " << b.step;
  }
  EXPECT_GT(stable_pairs, 30);
}

TEST(PathFollowing, ANodeAskedToBeInTwoPlacesIsRejected) {
  Scene scene = ReadScene(test::ScenesDir() / "strip-fold-no-table.json");
  // The far-end support also takes the gripped left edge: the gripper would
  // drag nodes the support holds still.
  scene.supports[0].select = Selection{EdgeSelection{Side::kBoundary}, {}};
  try {
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "stages[1].moves[0]");
    EXPECT_NE(std::string(e.what()).find("cannot be in two places"), std::string::npos) << e.what();
  }
}

TEST(PathFollowing, ReleasingTheLastHoldStopsWithAClearMessage) {
  Scene scene = ReadScene(test::ScenesDir() / "strip-fold-no-table.json");
  scene.supports.clear();
  Stage drop;
  drop.name = "drop";
  drop.kind = StageKind::kHold;
  drop.release = {"end"};
  scene.stages.resize(1);  // SW only, then let go
  scene.stages.push_back(drop);
  test::Outcome run = test::SolveRecorded(scene);
  EXPECT_EQ(run.summary.termination, Termination::kIllPosed);
  EXPECT_NE(run.summary.message.find("nothing holds the fabric"), std::string::npos)
      << run.summary.message;
  EXPECT_EQ(run.summary.stages.size(), 2u);
  EXPECT_FALSE(run.steps.empty()) << "the SW steps are kept";
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// A clamping gripper turned through 180°, 360° and 720° about the axis
// through its edge: at every step the gripped nodes' directors are the
// imposed rotation R(λθ) of their start, to round-off, and every number is
// finite — in the step the solver hands out and in states.bin read back
// (the turned-over end, t = −E₃ at 180°, once read back as NaN).
TEST(PathFollowing, ClampedGripperArcsImposeTheirRotationExactly) {
  for (double degrees : {180.0, 360.0, 720.0}) {
    SCOPED_TRACE(degrees);
    test::StripSpec spec;
    spec.elements = 10;
    Scene scene = test::HeavyStrip(spec, 1.0, 0.1);
    scene.supports.clear();
    scene.grippers.push_back({"root", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kClamp});
    Stage turn;
    turn.name = "turn";
    turn.kind = StageKind::kMove;
    turn.initial_increment = 0.02;
    turn.moves.push_back({"root", ArcPath{{0, 0, 0}, {0, 1, 0}, degrees}, {}});
    scene.stages.push_back(turn);
    const test::TempDir folder("clamped-arc-" + std::to_string(int(degrees)));
    const std::filesystem::path& dir = folder.path();
    ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
    std::vector<StepState> steps;
    ResultWriter writer(dir, scene, solver.model());
    const SolveSummary summary = solver.Solve({[&](const StepState& s) {
      writer.AddStep(s);
      steps.push_back(s);
      return StepDecision::kContinue;
    }});
    writer.Finish(summary);
    ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
    const std::vector<int>& gripped = solver.model().grippers[0].nodes;
    double worst = 0;
    int turned_over = 0;
    for (const StepState& s : steps) {
      ASSERT_TRUE(IsFinite(s.state)) << "step " << s.step;
      if (s.stage != 1) continue;
      const Eigen::Matrix3d r =
          ExpRotation(Eigen::Vector3d(0, 1, 0) * (s.lambda * degrees * M_PI / 180.0));
      for (int node : gripped) {
        const Eigen::Vector3d imposed = r * Eigen::Vector3d::UnitZ();  // flat start: t₀ = E₃
        worst = std::max(worst, (s.state.Director(node) - imposed).cwiseAbs().maxCoeff());
        turned_over += imposed.z() < -0.999;
      }
    }
    std::printf("  %g°: largest |t − R t₀| at the gripper %.2e, %d turned-over samples\n",
                degrees,
                worst,
                turned_over);
    EXPECT_LT(worst, 1e-12);
    // Read back as render and export do: every rebuilt rotation finite and
    // orthonormal, its director the stored one.
    const RunRecord record = ReadRunRecord(dir);
    ASSERT_EQ(record.states.size(), steps.size());
    for (size_t i = 0; i < record.states.size(); ++i) {
      const ShellState state = StateOf(record, i);
      ASSERT_TRUE(IsFinite(state)) << "step " << i + 1;
      for (int n = 0; n < state.NodeCount(); ++n)
        ASSERT_LT((state.Director(n) - record.states[i].directors.row(n).transpose()).norm(),
                  1e-15);
    }
  }
}

}  // namespace
}  // namespace drape
