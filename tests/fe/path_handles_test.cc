#include "core/fe/path_handles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "core/fe/prescribed_motion.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"

#include "support/test_paths.h"

namespace drape {
namespace {

// Where the held point is at the end of the stage: what a drag must set.
Eigen::Vector3d End(const Path& path, const Eigen::Vector3d& start) {
  return MotionAt(path, 1.0).Apply(start);
}

TEST(PathHandles, LineEndIsWhereTheHeldPointArrives) {
  const Eigen::Vector3d start(0.1, 0.2, 0.0);
  const Path line = LinePath{{0.0, 0.0, 0.3}};
  ASSERT_EQ(PathHandlePoints(line, start).size(), 1u);
  EXPECT_LT((PathHandlePoints(line, start)[0] - Eigen::Vector3d(0.1, 0.2, 0.3)).norm(), 1e-15);
  const Eigen::Vector3d to(-0.4, 0.5, 0.25);
  const Path moved = MovePathHandle(line, start, 0, to);
  EXPECT_LT((End(moved, start) - to).norm(), 1e-15);
  EXPECT_THROW(MovePathHandle(line, start, 1, to), std::out_of_range);
}

TEST(PathHandles, ArcHasItsCentreItsEndAndItsAxis) {
  // A quarter turn about z through the origin takes (1, 0, 0) to (0, 1, 0).
  const Eigen::Vector3d start(1, 0, 0);
  const Path arc = ArcPath{{0, 0, 0}, {0, 0, 1}, 90.0};
  const auto handles = PathHandlePoints(arc, start);
  ASSERT_EQ(handles.size(), 3u);
  EXPECT_LT(handles[0].norm(), 1e-15);
  EXPECT_LT((handles[1] - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
  // The axis' tip, as far from the centre as the start is.
  EXPECT_LT((handles[2] - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);

  // Tipped over to x, the axis now is x: a quarter turn about x leaves the
  // start, which lies on it, where it was.
  const auto tipped = std::get<ArcPath>(MovePathHandle(arc, start, 2, {3, 0, 0}));
  EXPECT_EQ(tipped.axis, (Vec3{1, 0, 0}));
  EXPECT_LT((End(tipped, start) - start).norm(), 1e-15);
  // About −y the start goes over the top: (1, 0, 0) → (0, 0, 1).
  const auto over = std::get<ArcPath>(MovePathHandle(arc, start, 2, {0, -0.5, 0}));
  EXPECT_LT((End(over, start) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
  // Dropped on the centre the tip has no direction: nothing changes.
  EXPECT_EQ(MovePathHandle(arc, start, 2, {0, 0, 0}), arc);

  // The centre moves; axis and angle stay.
  const auto centred = std::get<ArcPath>(MovePathHandle(arc, start, 0, {0.5, 0, 0}));
  EXPECT_EQ(centred.center, (Vec3{0.5, 0, 0}));
  EXPECT_EQ(centred.angle_deg, 90.0);
  EXPECT_EQ(centred.axis, (Vec3{0, 0, 1}));
}

TEST(PathHandles, DraggingAnArcsEndSetsTheAngleInTheAxisPlane) {
  const Eigen::Vector3d start(1, 0, 0);
  const Path arc = ArcPath{{0, 0, 0}, {0, 0, 1}, 90.0};
  // Dropped above the plane at 135°: the height does not count.
  const Eigen::Vector3d to(-std::sqrt(0.5), std::sqrt(0.5), 0.7);
  const auto moved = std::get<ArcPath>(MovePathHandle(arc, start, 1, to));
  EXPECT_NEAR(moved.angle_deg, 135.0, 1e-12);
  EXPECT_LT((End(moved, start) - Eigen::Vector3d(to.x(), to.y(), 0)).norm(), 1e-12);
  // Dragged clockwise past the start, the angle goes negative.
  const Path small = ArcPath{{0, 0, 0}, {0, 0, 1}, 10.0};
  EXPECT_NEAR(
      std::get<ArcPath>(MovePathHandle(small, start, 1, {0, -2, 0})).angle_deg, -90.0, 1e-12);
}

TEST(PathHandles, AnArcDraggedPastHalfATurnKeepsTurningTheSameWay) {
  // At 170° a drag to the direction of −170° means 190°, not back to −170°.
  const Eigen::Vector3d start(0.2, 0, 0);
  const Path arc = ArcPath{{0, 0, 0}, {0, 1, 0}, 170.0};
  const double a = -170.0 * M_PI / 180.0;
  // About +y a point (r, 0, 0) turned by θ is (r cos θ, 0, −r sin θ).
  const Eigen::Vector3d to(0.2 * std::cos(a), 0, -0.2 * std::sin(a));
  EXPECT_NEAR(std::get<ArcPath>(MovePathHandle(arc, start, 1, to)).angle_deg, 190.0, 1e-9);
  // And a fold already past a full turn stays there.
  const Path wound = ArcPath{{0, 0, 0}, {0, 1, 0}, 365.0};
  EXPECT_NEAR(std::get<ArcPath>(MovePathHandle(wound, start, 1, to)).angle_deg, 190.0, 1e-9);
}

TEST(PathHandles, KeyframeHandlesAreReachedAtTheirLambda) {
  const Eigen::Vector3d start(0, 0, 0.05);
  const Path keys =
      KeyframesPath{{{0, 0, 0.1}, {0.1, 0, 0.1}, {0.2, 0, 0}}, Interpolation::kSmooth};
  const auto handles = PathHandlePoints(keys, start);
  ASSERT_EQ(handles.size(), 3u);
  const Eigen::Vector3d to(0.15, 0.05, 0.2);
  const Path moved = MovePathHandle(keys, start, 1, to);
  // Keyframe k of n is reached at λ = k/n (1-based k).
  EXPECT_LT((MotionAt(moved, 2.0 / 3.0).Apply(start) - to).norm(), 1e-12);
  EXPECT_LT((MotionAt(moved, 1.0).Apply(start) - handles[2]).norm(), 1e-12);
  EXPECT_THROW(MovePathHandle(keys, start, 3, to), std::out_of_range);
  EXPECT_THROW(MovePathHandle(keys, start, -1, to), std::out_of_range);
}

TEST(PathHandles, EachMoveStartsWhereTheGrippersLastMoveEnded) {
  // The paper's strip fold: the left edge (x = −10 cm) turns 180° about the
  // y axis through (0, 0, c), which puts it at (10 cm, 0, 2c), then slides 1 cm
  // (c = 0.75 h: the end lands 1.5 h above the lower layer).
  const Scene scene = ReadScene(test::SourceDir() / "resources/scenes/strip-fold.json");
  const ShellModel model = BuildShellModel(scene);
  const auto moves = GripperMoves(scene, model);
  ASSERT_EQ(moves.size(), 2u);
  const double c = 0.75 * 0.0469e-2;
  EXPECT_EQ(moves[0].stage, 1);
  EXPECT_EQ(moves[0].carried, "end");
  EXPECT_LT((moves[0].start - Eigen::Vector3d(-0.1, 0, 0)).norm(), 1e-12);
  EXPECT_EQ(moves[1].stage, 2);
  EXPECT_EQ(moves[1].move, 0);
  EXPECT_LT((moves[1].start - Eigen::Vector3d(0.1, 0, 2 * c)).norm(), 1e-12);
  const auto line = SamplePath(scene.stages[2].moves[0].path, moves[1].start, 4);
  ASSERT_EQ(line.size(), 5u);
  EXPECT_LT((line[2] - Eigen::Vector3d(0.105, 0, 2 * c)).norm(), 1e-12);
}

TEST(PathHandles, ObstacleMovesStartAtTheAnchorWhereEarlierMovesLeftIt) {
  Scene scene = ReadScene(test::SourceDir() / "resources/scenes/strip-fold.json");
  // The table (its point at z = −c) lowered 1 cm by the fold stage, then
  // moved 2 cm along x by the slide.
  scene.stages[1].moves.push_back({"", LinePath{{0, 0, -0.01}}, "table"});
  scene.stages[2].moves.push_back({"", LinePath{{0.02, 0, 0}}, "table"});
  const auto moves = ObstacleMoves(scene);
  ASSERT_EQ(moves.size(), 2u);
  const double c = 0.02345e-2;
  EXPECT_EQ(moves[0].carried, "table");
  EXPECT_EQ(moves[0].move, 1);
  EXPECT_LT((moves[0].start - Eigen::Vector3d(0, 0, -c)).norm(), 1e-15);
  EXPECT_LT((moves[1].start - Eigen::Vector3d(0, 0, -c - 0.01)).norm(), 1e-15);
}

}  // namespace
}  // namespace drape
