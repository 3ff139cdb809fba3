// The points a user drags to shape a move's path, and the path that results
// from dragging one. Every handle is a point in space:
//  line       0: where the held point ends (start + by)
//  arc        0: the centre; 1: where the held point ends (sets the angle
//             about the unchanged axis); 2: the axis' tip, centre + L·axis
//             with L the start's distance from the centre (sets the axis)
//  keyframes  k: the k-th keyframe (start + pₖ)
// `start` is where the held point (a gripper's centroid) is when the stage
// begins.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/model/scene.h"

namespace drape {

struct ShellModel;

// A stage's move of a gripper or an obstacle and where the carried point
// is when that stage begins (after every earlier move of it): the
// gripper's held nodes' centroid, or the obstacle's anchor (ObstacleAnchor).
struct CarriedMove {
  int stage = 0, move = 0;  // indices into scene.stages and its moves
  std::string carried;      // the gripper's or the obstacle's name
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
};

// Every gripper move of the scene in stage order (grippers the model does
// not hold are left out).
std::vector<CarriedMove> GripperMoves(const Scene& scene, const ShellModel& model);
// Every obstacle move in stage order (meshes, which have no anchor, left out).
std::vector<CarriedMove> ObstacleMoves(const Scene& scene);

// The held point's way along `path` from `start`, at samples + 1 equal steps
// of λ (for drawing the path).
std::vector<Eigen::Vector3d> SamplePath(const Path& path,
                                        const Eigen::Vector3d& start,
                                        int samples = 48);

std::vector<Eigen::Vector3d> PathHandlePoints(const Path& path, const Eigen::Vector3d& start);

// `path` with handle `handle` moved to `to`. An arc's end handle is taken
// into the plane normal to the axis through the centre; the new angle is
// the one of the dragged direction nearest the old angle (so a drag past
// 180° keeps turning the same way). Throws std::out_of_range for a handle
// the path does not have.
Path MovePathHandle(const Path& path,
                    const Eigen::Vector3d& start,
                    int handle,
                    const Eigen::Vector3d& to);

}  // namespace drape
