#include "core/model/obstacle_geometry.h"

#include "core/model/mesh_placement.h"
#include "core/model/overloaded.h"
#include "core/model/triangle_mesh_geometry.h"
#include "core/model/vec3_eigen.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace drape {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Any unit vector perpendicular to `a`, for points exactly on an axis or at a
// centre, where the normal is not defined and any choice is as good.
Vector3d AnyPerpendicular(const Vector3d& a) {
  const Vector3d trial = std::abs(a.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
  return a.cross(trial).normalized();
}

class PlaneGeometry final : public ObstacleGeometry {
 public:
  bool IsConvex() const override { return true; }
  explicit PlaneGeometry(const PlaneShape& s)
      : point_(ToEigen(s.point)), normal_(ToEigen(s.normal).normalized()) {}

  DistanceQuery Query(const Vector3d& x) const override {
    return {normal_.dot(x - point_), normal_, Matrix3d::Zero()};
  }

 private:
  Vector3d point_, normal_;
};

class SphereGeometry final : public ObstacleGeometry {
 public:
  bool IsConvex() const override { return true; }
  explicit SphereGeometry(const SphereShape& s) : center_(ToEigen(s.center)), radius_(s.radius) {}

  DistanceQuery Query(const Vector3d& x) const override {
    const Vector3d r = x - center_;
    const double rho = r.norm();
    if (rho == 0.0) return {-radius_, Vector3d::UnitZ(), Matrix3d::Zero()};
    const Vector3d n = r / rho;
    return {rho - radius_, n, (Matrix3d::Identity() - n * n.transpose()) / rho};
  }
  std::optional<Eigen::AlignedBox3d> Bounds() const override {
    const Vector3d r = Vector3d::Constant(radius_);
    return Eigen::AlignedBox3d(center_ - r, center_ + r);
  }

 private:
  Vector3d center_;
  double radius_;
};

// A cylinder about an axis, infinite or with flat caps at ±length/2 from
// `point`. Regions: the side (distance to the axis), a cap (distance along
// the axis) and, outside both, the rim circle.
class CylinderGeometry final : public ObstacleGeometry {
 public:
  bool IsConvex() const override { return true; }
  explicit CylinderGeometry(const CylinderShape& s)
      : point_(ToEigen(s.point)),
        axis_(ToEigen(s.axis).normalized()),
        radius_(s.radius),
        half_length_(s.length ? 0.5 * *s.length : -1.0) {}

  DistanceQuery Query(const Vector3d& x) const override {
    const Vector3d v = x - point_;
    const double t = v.dot(axis_);
    const Vector3d radial = v - t * axis_;
    const double rho = radial.norm();
    const Vector3d e = rho > 0.0 ? Vector3d(radial / rho) : AnyPerpendicular(axis_);
    const double side = rho - radius_;
    const Matrix3d side_hessian =
        rho > 0.0
            ? Matrix3d((Matrix3d::Identity() - axis_ * axis_.transpose() - e * e.transpose()) / rho)
            : Matrix3d::Zero();
    if (half_length_ < 0.0) return {side, e, side_hessian};

    const double sign = t >= 0.0 ? 1.0 : -1.0;
    const double cap = std::abs(t) - half_length_;
    if (side > 0.0 && cap > 0.0) {  // nearest the rim circle
      const Vector3d to_rim = side * e + cap * sign * axis_;
      const double d = to_rim.norm();
      const Vector3d n = to_rim / d;
      // ∇n = (I − n nᵀ)(I − ∂c/∂x)/d, c the rim point: the rim curves only
      // circumferentially, by R/ρ.
      const Vector3d circumferential = axis_.cross(e);
      const Matrix3d h = (Matrix3d::Identity() - n * n.transpose() -
                          (radius_ / rho) * circumferential * circumferential.transpose()) /
                         d;
      return {d, n, h};
    }
    if (cap > side) return {cap, sign * axis_, Matrix3d::Zero()};
    return {side, e, side_hessian};
  }
  // A capped cylinder reaches, along each world axis k, half its length
  // times |a_k| from its middle, plus its radius times the sine √(1 − a_k²).
  std::optional<Eigen::AlignedBox3d> Bounds() const override {
    if (half_length_ < 0.0) return std::nullopt;
    const Eigen::Array3d a = axis_.array().abs();
    const Vector3d reach =
        (half_length_ * a + radius_ * (1.0 - a.square()).max(0.0).sqrt()).matrix();
    return Eigen::AlignedBox3d(point_ - reach, point_ + reach);
  }

 private:
  Vector3d point_, axis_;
  double radius_;
  double half_length_;  // < 0: infinite
};

// A box whose edges and corners are rounded with `edge_radius`: the set of
// points within edge_radius of the inner box shrunk by it, so the normal is
// continuous wherever the radius is positive.
class BoxGeometry final : public ObstacleGeometry {
 public:
  bool IsConvex() const override { return true; }
  explicit BoxGeometry(const BoxShape& s) : radius_(s.edge_radius) {
    const Vector3d lo = ToEigen(s.min), hi = ToEigen(s.max);
    center_ = 0.5 * (lo + hi);
    inner_half_ = 0.5 * (hi - lo) - Vector3d::Constant(radius_);
  }
  std::optional<Eigen::AlignedBox3d> Bounds() const override {
    const Vector3d half = inner_half_ + Vector3d::Constant(radius_);
    return Eigen::AlignedBox3d(center_ - half, center_ + half);
  }

  DistanceQuery Query(const Vector3d& x) const override {
    const Vector3d v = x - center_;
    Vector3d q, sign;
    for (int k = 0; k < 3; ++k) {
      sign[k] = v[k] >= 0.0 ? 1.0 : -1.0;
      q[k] = std::abs(v[k]) - inner_half_[k];
    }
    if ((q.array() <= 0.0).all()) {  // inside the inner box: nearest face
      int k;
      const double m = q.maxCoeff(&k);
      return {m - radius_, sign[k] * Vector3d::Unit(k), Matrix3d::Zero()};
    }
    // Outside the inner box: the nearest inner-box point is x clamped to it;
    // the Hessian is (P − n nᵀ)/|x − c| with P projecting on the axes along
    // which x lies beyond the inner box (zero on a face, an edge's cylinder,
    // a corner's sphere).
    Vector3d out = Vector3d::Zero();
    Matrix3d projector = Matrix3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (q[k] > 0.0) {
        out[k] = sign[k] * q[k];
        projector(k, k) = 1.0;
      }
    const double d = out.norm();
    const Vector3d n = out / d;
    return {d - radius_, n, (projector - n * n.transpose()) / d};
  }

 private:
  Vector3d center_, inner_half_;
  double radius_;
};

}  // namespace

std::unique_ptr<ObstacleGeometry> MakeObstacleGeometry(const Obstacle& obstacle,
                                                       const std::filesystem::path& scene_dir,
                                                       const std::string& where) {
  return std::visit(
      Overloaded{[](const PlaneShape& s) -> std::unique_ptr<ObstacleGeometry> {
                   return std::make_unique<PlaneGeometry>(s);
                 },
                 [](const SphereShape& s) -> std::unique_ptr<ObstacleGeometry> {
                   return std::make_unique<SphereGeometry>(s);
                 },
                 [](const CylinderShape& s) -> std::unique_ptr<ObstacleGeometry> {
                   return std::make_unique<CylinderGeometry>(s);
                 },
                 [](const BoxShape& s) -> std::unique_ptr<ObstacleGeometry> {
                   return std::make_unique<BoxGeometry>(s);
                 },
                 [&](const MeshShape& s) -> std::unique_ptr<ObstacleGeometry> {
                   const std::filesystem::path file = s.resolved_path.empty()
                                                          ? scene_dir / s.file
                                                          : std::filesystem::path(s.resolved_path);
                   return MakeTriangleMeshGeometry(file, where + ".mesh.file", MeshPlacement(s));
                 }},
      obstacle.shape);
}

}  // namespace drape
