// GripperDrag: the live drag's frames (core/solve/gripper_drag.h), and the
// scene a drag leaves.
#include "core/solve/gripper_drag.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

Scene CornerLift() {
  return ReadScene((test::SourceDir() / "tests" / "data" / "corner-lift-20x20.json").string());
}

// How far a frame may be from the equilibrium it previews [m], 5e-4 of the
// part's size: the frames of FramesFollowTheHandleNearEquilibrium were
// measured at most 2.7e-5 m from it (the workbench's, 7e-5 m).
constexpr double kFrameDistance = 1e-4;

double LargestDistance(const ShellState& a, const ShellState& b) {
  return (a.positions - b.positions).rowwise().norm().maxCoeff();
}

// Frames at the same offset until the residual meets `tolerance` or stops
// falling (its round-off floor).
DragFrame Settle(GripperDrag& drag, double tolerance) {
  DragFrame frame = drag.MoveTo(drag.offset());
  for (int k = 0; k < 20 && frame.residual_ratio > tolerance; ++k) {
    const DragFrame next = drag.MoveTo(drag.offset());
    if (next.residual_ratio >= 0.5 * frame.residual_ratio) return next;
    frame = next;
  }
  return frame;
}

// Every tenth frame, the whole fabric against the equilibrium a frame
// previews: the dragged scene solved from the flat sheet to its tolerance
// (1e-8), the gripper moved to the frame's offset. A frame stops at 1e-4 of
// the force level (DragSettings::tolerance): measured 2.5e-6 to 2.7e-5 m
// from the equilibrium at frames 10 to 40 (5 cm of lift).
TEST(GripperDrag, FramesFollowTheHandleNearEquilibrium) {
  const Scene scene = CornerLift();
  const SolverOptions options = SolverOptions::FromScene(scene.solver);
  ShellSolver solver(scene, options);
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  GripperDrag drag(solver.BasisForDrag("corner"), DragSettings{});
  const Eigen::Vector3d by(0, 0, 0.05);
  double worst = 0;
  for (int f = 1; f <= 40; ++f) {
    const DragFrame frame = drag.MoveTo(by * f / 40.0);
    EXPECT_EQ(frame.frame, f);
    ASSERT_TRUE(std::isfinite(frame.residual_ratio)) << "frame " << f;
    // The bound a frame is held to (DragSettings::worst_ratio).
    EXPECT_LE(frame.residual_ratio, 1e-2) << "frame " << f;
    EXPECT_GE(frame.factorizations, 1);
    if (f % 10 != 0) continue;
    ShellSolver plain(DraggedScene(scene, "corner", frame.offset), options);
    ASSERT_TRUE(plain.Solve({}).IsComplete()) << "frame " << f;
    const double distance = LargestDistance(drag.state(), plain.state());
    std::printf("frame %d: residual ratio %.3g, %.3g m from the equilibrium\n",
                f,
                frame.residual_ratio,
                distance);
    EXPECT_LT(distance, kFrameDistance) << "frame " << f;
    worst = std::max(worst, distance);
  }
  EXPECT_NEAR((drag.offset() - by).norm(), 0, 1e-15) << "the gripper caught up with the handle";
  std::printf("largest distance %.3g m\n", worst);
}

TEST(GripperDrag, AFrameOutOfTimeLeavesTheRestToTheNext) {
  // The whole 3 cm lift at once cannot be one sub-step; with no time to
  // spare a frame keeps its first successful sub-step and stops there,
  // and the frames after it catch up with the handle.
  const Scene scene = CornerLift();
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  DragSettings settings;
  settings.budget_seconds = 0;
  GripperDrag drag(solver.BasisForDrag("corner"), settings);
  const Eigen::Vector3d by(0, 0, 0.03);
  const DragFrame first = drag.MoveTo(by);
  EXPECT_GT(first.offset.z(), 0);
  EXPECT_LT(first.offset.z(), by.z()) << "one sub-step took the whole lift";
  EXPECT_LE(first.residual_ratio, settings.worst_ratio);
  DragFrame last = first;
  int frames = 1;
  for (; frames < 40 && (last.offset - by).norm() > 0; ++frames) last = drag.MoveTo(by);
  std::printf("caught up in %d frames\n", frames);
  EXPECT_NEAR((last.offset - by).norm(), 0, 1e-15) << "the gripper caught up with the handle";
  EXPECT_LE(last.residual_ratio, settings.worst_ratio);
}

TEST(GripperDrag, TheStripFoldsEndLiftsOffTheFoldWithItsHandle) {
  // The folded strip's end lifted 2 cm in 20 frames: the end comes off the
  // layer below, table contact changes node by node. Frames that kept a
  // stale tangent across such a change once left the end stuck at 1.86 cm
  // whatever the handle did.
  const Scene scene = ReadScene((test::ScenesDir() / "strip-fold.json").string());
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  DragSettings settings;
  GripperDrag drag(solver.BasisForDrag("end"), settings);
  const Eigen::Vector3d by(0, 0, 0.02);
  DragFrame frame;
  for (int f = 1; f <= 20; ++f) {
    frame = drag.MoveTo(by * f / 20.0);
    ASSERT_LE(frame.residual_ratio, settings.worst_ratio) << "frame " << f;
  }
  // A frame out of time (DragSettings::budget_seconds, a slow machine)
  // leaves some of its motion to the next: a few more at the handle.
  for (int f = 0; f < 20 && (frame.offset - by).norm() > 0; ++f) frame = drag.MoveTo(by);
  EXPECT_NEAR(frame.offset.z(), by.z(), 1e-12) << "the end caught up with the handle";
  EXPECT_LE(frame.residual_ratio, settings.worst_ratio);
}

TEST(GripperDrag, ASettledDragIsTheDraggedSceneSolvedFromTheStart) {
  // Two ways to the same equilibrium: frames from the run's end, and the
  // continuation of the dragged scene from the flat sheet.
  const Scene scene = CornerLift();
  const SolverOptions options = SolverOptions::FromScene(scene.solver);
  ShellSolver solver(scene, options);
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  DragSettings settings;
  settings.tolerance = options.tolerance;
  GripperDrag drag(solver.BasisForDrag("corner"), settings);
  const Eigen::Vector3d by(0, 0, 0.03);
  for (int f = 1; f <= 20; ++f) drag.MoveTo(by * f / 20.0);
  const DragFrame settled = Settle(drag, options.tolerance);
  std::printf("settled at %.3g\n", settled.residual_ratio);

  const Scene dragged = DraggedScene(scene, "corner", by);
  ShellSolver plain(dragged, options);
  const SolveSummary summary = plain.Solve({});
  ASSERT_TRUE(summary.IsComplete());
  std::printf("%s\n", summary.FullReport().c_str());
  // 1e-6 of the part's size (20 cm).
  std::printf("distance %.3g\n", LargestDistance(drag.state(), plain.state()));
  EXPECT_LT(LargestDistance(drag.state(), plain.state()), 1e-6 * 0.2);
}

TEST(GripperDrag, ASmallLiftBendsAStripAsAProppedCantilever) {
  // A weightless strip clamped at x = 0, its tip held by a pin lifted by δ:
  // w(x) = δ x² (3L − x) / (2L³), so w(L/2) = 5δ/16 (beam theory, ν = 0).
  // δ ≪ h keeps the membrane's stretching (∝ (δ/h)²) below 1e-4 of it.
  test::StripSpec spec;
  Scene scene = test::CantileverStrip(spec);
  scene.grippers.push_back({"tip", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kPosition});
  scene.stages.push_back(Stage{.name = "rest", .kind = StageKind::kHold});
  scene.solver.tolerance = 1e-10;
  const SolverOptions options = SolverOptions::FromScene(scene.solver);
  ShellSolver solver(scene, options);
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  DragSettings settings;
  settings.tolerance = 1e-10;
  GripperDrag drag(solver.BasisForDrag("tip"), settings);
  const double delta = 2e-6;
  for (int f = 1; f <= 10; ++f) drag.MoveTo(Eigen::Vector3d(0, 0, delta * f / 10));
  Settle(drag, 1e-10);
  double w = 0;
  int count = 0;
  for (int i = 0; i < drag.state().NodeCount(); ++i)
    if (std::abs(solver.model().mesh.positions(i, 0) - spec.length / 2) < 1e-9) {
      w += drag.state().positions(i, 2);
      ++count;
    }
  ASSERT_EQ(count, 2);
  EXPECT_NEAR(w / count / delta, 5.0 / 16.0, 1e-3);
}

TEST(GripperDrag, PushedPastEulersLoadAStripSnapsOntoItsBuckledShape) {
  // A strip clamped at both ends, its right end dragged towards its left by
  // Δ = 1e-3 L. Straight, it carries at most P = 4π²EI/L² (clamped–clamped),
  // reached after a shortening ε L = π²h²/(3L) (4e-6 m here); past it the
  // straight strip is a saddle the drag would follow (it stays symmetric), so
  // a frame snaps. Buckled, it takes the shape w = (a/2)(1 − cos 2πx/L) whose
  // arc takes up the rest of the shortening: ∫ ½ w'² dx = a²π²/(4L), so
  // a = (2/π) √((Δ − εL) L) (first order in Δ/L).
  test::StripSpec spec;
  Scene scene = test::CantileverStrip(spec);
  scene.grippers.push_back({"end", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kClamp});
  scene.stages.push_back(Stage{.name = "rest", .kind = StageKind::kHold});
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ASSERT_TRUE(solver.Solve({}).IsComplete());
  GripperDrag drag(solver.BasisForDrag("end"), DragSettings{});
  const double length = spec.length, h = spec.thickness;
  const double shortening = 1e-3 * length;
  int snaps = 0;
  for (int f = 1; f <= 8; ++f) {
    const DragFrame frame = drag.MoveTo(Eigen::Vector3d(-shortening * f / 8, 0, 0));
    snaps += frame.snapped;
    if (frame.snapped) EXPECT_GT(frame.energy_released, 0) << "frame " << f;
  }
  const DragFrame last = Settle(drag, 1e-8);
  EXPECT_EQ(snaps, 1);
  EXPECT_NEAR(drag.offset().x(), -shortening, 1e-12);
  const double critical = kPi * kPi * h * h / (3 * length);
  const double amplitude = 2 / kPi * std::sqrt((shortening - critical) * length);
  double mid = 0;
  for (int i = 0; i < drag.state().NodeCount(); ++i)
    if (std::abs(solver.model().mesh.positions(i, 0) - length / 2) < 1e-9)
      mid = std::max(mid, std::abs(drag.state().positions(i, 2)));
  std::printf(
      "buckled: mid deflection %.4e m, first-order elastica %.4e m (%+.2f %%); residual %.1e\n",
      mid,
      amplitude,
      100 * (mid / amplitude - 1),
      last.residual_ratio);
  EXPECT_NEAR(mid / amplitude, 1.0, 5e-3);  // measured +0.07 %
}

TEST(GripperDrag, TheDraggedSceneExtendsItsOwnDragStage) {
  const Scene scene = CornerLift();
  const Scene once = DraggedScene(scene, "corner", {0, 0, 0.01});
  ASSERT_EQ(once.stages.size(), scene.stages.size() + 1);
  EXPECT_EQ(once.stages.back().name, "drag corner");
  EXPECT_EQ(once.stages.back().kind, StageKind::kMove);
  const Scene twice = DraggedScene(once, "corner", {0.02, 0, -0.005});
  ASSERT_EQ(twice.stages.size(), once.stages.size()) << "a second drag extends the first";
  const auto& line = std::get<LinePath>(twice.stages.back().moves.at(0).path);
  EXPECT_DOUBLE_EQ(line.by[0], 0.02);
  EXPECT_DOUBLE_EQ(line.by[1], 0);
  EXPECT_DOUBLE_EQ(line.by[2], 0.005);
}

TEST(GripperDrag, SaysWhatCannotBeDragged) {
  const Scene scene = CornerLift();
  ShellSolver before(scene, SolverOptions::FromScene(scene.solver));
  try {
    before.BasisForDrag("corner");
    ADD_FAILURE() << "a run not yet solved has no end state";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did not complete"), std::string::npos) << e.what();
  }
  ASSERT_TRUE(before.Solve({}).IsComplete());
  try {
    before.BasisForDrag("hand");
    ADD_FAILURE() << "no gripper 'hand'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has no gripper 'hand' (it has 'corner')"),
              std::string::npos)
        << e.what();
  }
  test::StripSpec spec;
  Scene released = test::HeavyStrip(spec, 1.0, 0.1);
  released.grippers.push_back(
      {"corner", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kPosition});
  released.stages.back().release = {"corner"};
  ShellSolver solver(released, SolverOptions::FromScene(released.solver));
  const SolveSummary summary = solver.Solve({});
  ASSERT_TRUE(summary.IsComplete()) << summary.message;
  try {
    solver.BasisForDrag("corner");
    ADD_FAILURE() << "a released gripper holds nothing";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("released"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace drape
