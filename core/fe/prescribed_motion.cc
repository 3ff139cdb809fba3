#include "core/fe/prescribed_motion.h"

#include <algorithm>
#include <cmath>

#include "core/mechanics/director.h"
#include "core/model/overloaded.h"
#include "core/model/vec3_eigen.h"

namespace drape {
namespace {

// Keyframe k (k = 0 is the start, offset zero).
Eigen::Vector3d Key(const KeyframesPath& k, int i) {
  return i <= 0 ? Eigen::Vector3d::Zero()
                : ToEigen(k.points[std::min<size_t>(i, k.points.size()) - 1]);
}

void Keyframes(const KeyframesPath& k, double lambda, RigidMotion& m) {
  const int n = static_cast<int>(k.points.size());
  const double t = lambda * n;
  const int i = std::clamp(static_cast<int>(std::floor(t)), 0, n - 1);
  const double s = t - i;  // in [0, 1] within segment i → i + 1
  const Eigen::Vector3d p0 = Key(k, i), p1 = Key(k, i + 1);
  if (k.interpolation == Interpolation::kLinear) {
    m.translation = p0 + s * (p1 - p0);
    m.translation_rate = n * (p1 - p0);
    return;
  }
  // Catmull–Rom tangents (one-sided at the ends), per unit of s.
  const Eigen::Vector3d m0 =
      i == 0 ? Eigen::Vector3d(p1 - p0) : Eigen::Vector3d(0.5 * (p1 - Key(k, i - 1)));
  const Eigen::Vector3d m1 =
      i + 1 == n ? Eigen::Vector3d(p1 - p0) : Eigen::Vector3d(0.5 * (Key(k, i + 2) - p0));
  const double s2 = s * s, s3 = s2 * s;
  m.translation = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 +
                  (s3 - s2) * m1;
  m.translation_rate = n * ((6 * s2 - 6 * s) * p0 + (3 * s2 - 4 * s + 1) * m0 +
                            (-6 * s2 + 6 * s) * p1 + (3 * s2 - 2 * s) * m1);
}

}  // namespace

RigidMotion MotionAt(const Path& path, double lambda) {
  lambda = std::clamp(lambda, 0.0, 1.0);
  RigidMotion m;
  std::visit(Overloaded{
                 [&](const LinePath& l) {
                   m.translation = lambda * ToEigen(l.by);
                   m.translation_rate = ToEigen(l.by);
                 },
                 [&](const ArcPath& a) {
                   const Eigen::Vector3d w = ToEigen(a.axis) * (a.angle_deg * M_PI / 180.0);
                   m.center = ToEigen(a.center);
                   m.rotation = ExpRotation(lambda * w);
                   m.angular_rate = w;
                 },
                 [&](const KeyframesPath& k) { Keyframes(k, lambda, m); },
             },
             path);
  return m;
}

double PathLength(const Path& path, const Eigen::Vector3d& x0) {
  // Sampled: exact for lines and arcs up to rounding, close for keyframes.
  constexpr int kSamples = 256;
  double length = 0;
  Eigen::Vector3d previous = MotionAt(path, 0).Apply(x0);
  for (int i = 1; i <= kSamples; ++i) {
    const Eigen::Vector3d x = MotionAt(path, static_cast<double>(i) / kSamples).Apply(x0);
    length += (x - previous).norm();
    previous = x;
  }
  return length;
}

}  // namespace drape
