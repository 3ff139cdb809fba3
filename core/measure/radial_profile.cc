#include "core/measure/radial_profile.h"

#include <algorithm>
#include <cmath>

namespace drape {
namespace {

// Where the ray centre + t·d (t ≥ 0) crosses the segment a–b: the largest t,
// or −1 where it does not.
double RayHit(const Eigen::Vector2d& centre,
              const Eigen::Vector2d& d,
              const Eigen::Vector2d& a,
              const Eigen::Vector2d& b) {
  const Eigen::Vector2d e = b - a;
  const Eigen::Vector2d w = a - centre;
  const double denominator = d.x() * e.y() - d.y() * e.x();
  if (denominator == 0) {
    // Parallel: on the ray's line only if collinear; then its far end.
    if (w.x() * d.y() - w.y() * d.x() != 0) return -1;
    return std::max({w.dot(d), (b - centre).dot(d), -1.0});
  }
  const double t = (w.x() * e.y() - w.y() * e.x()) / denominator;
  const double s = (w.x() * d.y() - w.y() * d.x()) / denominator;
  return (s >= 0 && s <= 1 && t >= 0) ? t : -1;
}

}  // namespace

RadialProfile ShadowProfile(const Shadow& shadow, const Eigen::Vector2d& centre, int samples) {
  RadialProfile profile;
  profile.angle.resize(samples);
  profile.radius.assign(samples, 0.0);
  for (int k = 0; k < samples; ++k) {
    const double angle = 2 * M_PI * k / samples;
    profile.angle[k] = angle;
    const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
    double& r = profile.radius[k];
    for (const auto& ring : shadow.rings)
      for (size_t i = 0, n = ring.size(); i < n; ++i)
        r = std::max(r, RayHit(centre, d, ring[i], ring[(i + 1) % n]));
  }
  return profile;
}

}  // namespace drape
