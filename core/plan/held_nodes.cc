#include "core/plan/held_nodes.h"

#include <algorithm>
#include <limits>

namespace drape {

int ReleaseStage(const Scene& scene, const std::string& gripper) {
  for (size_t s = 0; s < scene.stages.size(); ++s)
    for (const std::string& name : scene.stages[s].release)
      if (name == gripper) return static_cast<int>(s);
  return std::numeric_limits<int>::max();
}

Eigen::Vector3d Centroid(const Eigen::Matrix<double, Eigen::Dynamic, 3>& x,
                         const std::vector<int>& nodes) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int n : nodes) sum += x.row(n).transpose();
  return sum / static_cast<double>(std::max<size_t>(1, nodes.size()));
}

}  // namespace drape
