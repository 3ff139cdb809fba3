// Rigid obstacles as signed-distance shapes.
//
// Contact needs, at a point x, the signed distance d(x) to the obstacle's
// surface (> 0 outside), its gradient n = ∇d (the outward unit normal of the
// closest surface point) and its Hessian ∇∇d (the consistent tangent of a
// penalty on d over a curved surface needs it: for a sphere of radius R it is
// (I − n nᵀ)/|x − c|).
#pragma once

#include "core/model/scene.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <filesystem>
#include <memory>
#include <optional>

namespace drape {

struct DistanceQuery {
  double distance = 0;                                // signed [m], > 0 outside
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // ∇d, unit
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();  // ∇∇d [1/m], symmetric
};

class ObstacleGeometry {
 public:
  virtual ~ObstacleGeometry() = default;
  virtual DistanceQuery Query(const Eigen::Vector3d& x) const = 0;
  // Whether the obstacle is a convex body: its distance is then a convex
  // function outside it, so d(x + s) ≥ d(x) + ∇d(x)·s for every s (what a
  // step's collision bound relies on).
  virtual bool IsConvex() const { return false; }
  // The smallest axis-aligned box holding the obstacle; none when it has no
  // end (a plane, an endless rod).
  virtual std::optional<Eigen::AlignedBox3d> Bounds() const { return std::nullopt; }
};

// The geometry of a scene's obstacle. A mesh obstacle's file is read relative
// to `scene_dir` (unless the reader resolved it); unreadable or open meshes
// throw SceneError at `where` (the obstacle's JSON path, e.g. "obstacles[1]").
std::unique_ptr<ObstacleGeometry> MakeObstacleGeometry(const Obstacle& obstacle,
                                                       const std::filesystem::path& scene_dir,
                                                       const std::string& where = "obstacles");

}  // namespace drape
