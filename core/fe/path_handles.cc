#include "core/fe/path_handles.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "core/fe/prescribed_motion.h"
#include "core/fe/shell_model.h"
#include "core/model/obstacle_anchor.h"
#include "core/model/overloaded.h"
#include "core/model/vec3_eigen.h"

namespace drape {
namespace {

void CheckHandle(int handle, size_t count) {
  if (handle < 0 || static_cast<size_t>(handle) >= count)
    throw std::out_of_range("the path has no handle " + std::to_string(handle));
}

// The angle [deg] about `axis` that takes `from` to `to` (both seen in the
// plane normal to the axis), of the values θ + 360k the one nearest `near`.
double AngleAbout(const Eigen::Vector3d& axis,
                  const Eigen::Vector3d& from,
                  const Eigen::Vector3d& to,
                  double near) {
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d f = from - a * a.dot(from), t = to - a * a.dot(to);
  double angle = std::atan2(a.dot(f.cross(t)), f.dot(t)) * 180.0 / M_PI;
  angle += 360.0 * std::round((near - angle) / 360.0);
  return angle;
}

// How far an arc's axis handle sits from the centre: as far as the held
// point (so it is drawn at the scale of the motion), 5 cm when that is 0.
double AxisLength(const Eigen::Vector3d& center, const Eigen::Vector3d& start) {
  const double r = (start - center).norm();
  return r > 0 ? r : 0.05;
}

// The moves that carry a point named in `at` (by the Move member `carried`:
// its gripper or its obstacle), each starting where the earlier ones left it.
std::vector<CarriedMove> Walk(const Scene& scene,
                              std::map<std::string, Eigen::Vector3d> at,
                              std::string Move::*carried) {
  std::vector<CarriedMove> moves;
  for (size_t s = 0; s < scene.stages.size(); ++s)
    for (size_t m = 0; m < scene.stages[s].moves.size(); ++m) {
      const Move& move = scene.stages[s].moves[m];
      const auto it = at.find(move.*carried);
      if (it == at.end()) continue;
      moves.push_back({static_cast<int>(s), static_cast<int>(m), it->first, it->second});
      it->second = MotionAt(move.path, 1.0).Apply(it->second);
    }
  return moves;
}

}  // namespace

std::vector<CarriedMove> GripperMoves(const Scene& scene, const ShellModel& model) {
  std::map<std::string, Eigen::Vector3d> at;
  for (const HeldNodes& g : model.grippers) {
    if (g.nodes.empty()) continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int node : g.nodes) centroid += model.reference.positions.row(node).transpose();
    at[g.name] = centroid / static_cast<double>(g.nodes.size());
  }
  return Walk(scene, std::move(at), &Move::gripper);
}

std::vector<CarriedMove> ObstacleMoves(const Scene& scene) {
  std::map<std::string, Eigen::Vector3d> at;
  for (const Obstacle& o : scene.obstacles)
    if (const auto anchor = ObstacleAnchor(o)) at[o.name] = *anchor;
  return Walk(scene, std::move(at), &Move::obstacle);
}

std::vector<Eigen::Vector3d> SamplePath(const Path& path,
                                        const Eigen::Vector3d& start,
                                        int samples) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i <= samples; ++i)
    line.push_back(MotionAt(path, static_cast<double>(i) / samples).Apply(start));
  return line;
}

std::vector<Eigen::Vector3d> PathHandlePoints(const Path& path, const Eigen::Vector3d& start) {
  return std::visit(
      Overloaded{
          [&](const LinePath& p) { return std::vector<Eigen::Vector3d>{start + ToEigen(p.by)}; },
          [&](const ArcPath& p) {
            const Eigen::Vector3d c = ToEigen(p.center);
            return std::vector<Eigen::Vector3d>{
                c,
                MotionAt(p, 1.0).Apply(start),
                c + AxisLength(c, start) * ToEigen(p.axis).normalized()};
          },
          [&](const KeyframesPath& p) {
            std::vector<Eigen::Vector3d> points;
            for (const Vec3& k : p.points) points.push_back(start + ToEigen(k));
            return points;
          },
      },
      path);
}

Path MovePathHandle(const Path& path,
                    const Eigen::Vector3d& start,
                    int handle,
                    const Eigen::Vector3d& to) {
  return std::visit(Overloaded{
                        [&](LinePath p) -> Path {
                          CheckHandle(handle, 1);
                          p.by = ToVec3(to - start);
                          return p;
                        },
                        [&](ArcPath p) -> Path {
                          CheckHandle(handle, 3);
                          const Eigen::Vector3d c = ToEigen(p.center);
                          if (handle == 0) {
                            p.center = ToVec3(to);
                          } else if (handle == 1) {
                            p.angle_deg =
                                AngleAbout(ToEigen(p.axis), start - c, to - c, p.angle_deg);
                          } else if ((to - c).norm() > 1e-9 * AxisLength(c, start)) {
                            // (A tip dropped on the centre has no direction.)
                            p.axis = ToVec3((to - c).normalized());
                          }
                          return p;
                        },
                        [&](KeyframesPath p) -> Path {
                          CheckHandle(handle, p.points.size());
                          p.points[static_cast<size_t>(handle)] = ToVec3(to - start);
                          return p;
                        },
                    },
                    path);
}

}  // namespace drape
