#include "core/measure/drape_coefficient.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace drape {

DrapeMeasurement MeasureDrape(const Eigen::MatrixX3d& positions,
                              const Eigen::Matrix<int, Eigen::Dynamic, 4>& quads,
                              const DrapeTestOptions& options) {
  if (!(options.disc_radius > 0) || !(options.specimen_area > 0))
    throw std::invalid_argument("the support disc's radius and the specimen's area must be > 0");
  DrapeMeasurement m;
  m.disc_area = M_PI * options.disc_radius * options.disc_radius;
  m.specimen_area = options.specimen_area;
  if (!(m.disc_area < m.specimen_area))
    throw std::invalid_argument("the support disc (" + std::to_string(m.disc_area * 1e4) +
                                " cm²) is not smaller than the specimen (" +
                                std::to_string(m.specimen_area * 1e4) + " cm²): nothing hangs");
  const ShadowPlane plane = ShadowPlane::Across(options.down, options.centre);
  m.shadow = CastShadow(positions, quads, plane);
  m.shadow_area = m.shadow.area;
  m.drape_coefficient = (m.shadow_area - m.disc_area) / (m.specimen_area - m.disc_area);
  m.profile = ShadowProfile(m.shadow, Eigen::Vector2d::Zero(), options.profile_samples);
  const double hanging = std::sqrt(m.specimen_area / M_PI) - options.disc_radius;
  m.nodes = FindDrapeNodes(m.profile, options.node_prominence * hanging);
  return m;
}

std::string DrapeSummary(const DrapeMeasurement& m) {
  char text[96];
  std::snprintf(text,
                sizeof text,
                "drape coefficient %.3f · %zu %s",
                m.drape_coefficient,
                m.nodes.size(),
                m.nodes.size() == 1 ? "node" : "nodes");
  return text;
}

}  // namespace drape
