#include "core/geometry/primitive_distance.h"

#include <Eigen/Geometry>

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <vector>

namespace drape {
namespace {

using V3 = Eigen::Vector3d;

// The closest point of segment (a, b) to p as a parameter in [0, 1].
double SegmentParameter(const V3& p, const V3& a, const V3& b) {
  const V3 ab = b - a;
  const double length2 = ab.squaredNorm();
  return length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
}

}  // namespace

PointTriangleDistance PointTriangle(const V3& p, const V3& a, const V3& b, const V3& c) {
  PointTriangleDistance out;
  const V3 ab = b - a, ac = c - a, ap = p - a;
  auto finish = [&](double u, double v, double w, TriangleRegion region) {
    out.barycentric = V3(u, v, w);
    out.region = region;
    out.squared = (p - (u * a + v * b + w * c)).squaredNorm();
    return out;
  };
  if (ab.cross(ac).squaredNorm() <= 1e-30 * ab.squaredNorm() * ac.squaredNorm()) {
    // Degenerate: the nearest of its three edges.
    const double s_ab = SegmentParameter(p, a, b), s_bc = SegmentParameter(p, b, c),
                 s_ca = SegmentParameter(p, c, a);
    const double d_ab = (p - (a + s_ab * ab)).squaredNorm();
    const double d_bc = (p - (b + s_bc * (c - b))).squaredNorm();
    const double d_ca = (p - (c + s_ca * (a - c))).squaredNorm();
    if (d_ab <= d_bc && d_ab <= d_ca) return finish(1 - s_ab, s_ab, 0, TriangleRegion::kEdge0);
    if (d_bc <= d_ca) return finish(0, 1 - s_bc, s_bc, TriangleRegion::kEdge1);
    return finish(s_ca, 0, 1 - s_ca, TriangleRegion::kEdge2);
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0, TriangleRegion::kVertex0);
  const V3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0, TriangleRegion::kVertex1);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0, TriangleRegion::kEdge0);
  }
  const V3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1, TriangleRegion::kVertex2);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w, TriangleRegion::kEdge2);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w, TriangleRegion::kEdge1);
  }
  const double denominator = 1 / (va + vb + vc);  // the face
  const double v = vb * denominator, w = vc * denominator;
  return finish(1 - v - w, v, w, TriangleRegion::kFace);
}

EdgeEdgeDistance EdgeEdge(const V3& a0, const V3& a1, const V3& b0, const V3& b1) {
  EdgeEdgeDistance out;
  const V3 d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0, t = 0;
  if (a <= 0 && e <= 0) {
    // Both points.
  } else if (a <= 0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2);
      const double denominator = a * e - b * b;
      // Parallel (denominator 0 to round-off): any s; take 0 and clamp t.
      s = denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  out.s = s;
  out.t = t;
  out.squared = ((a0 + s * d1) - (b0 + t * d2)).squaredNorm();
  return out;
}

}  // namespace drape

namespace drape {
namespace {

// f = min_y |r(x, y)|², r = Σ_i w_i(y) x_i with w affine in y: w = w* + Σ_k
// (y_k − y_k*) e_k over the free parameters (columns of `e`), at the
// minimiser y* where w = `w`.
// At most two free parameters: fixed-size storage, no allocation per pair.
using FreeDirections = Eigen::Matrix<double, 4, Eigen::Dynamic, Eigen::ColMajor, 4, 2>;

DistanceDerivatives Envelope(const std::array<const Eigen::Vector3d*, 4>& x,
                             const Eigen::Vector4d& w,
                             const FreeDirections& e) {
  DistanceDerivatives out;
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) r += w(i) * *x[i];
  out.squared = r.squaredNorm();
  for (int i = 0; i < 4; ++i) {
    out.gradient.segment<3>(3 * i) = 2 * w(i) * r;
    for (int j = 0; j < 4; ++j)
      out.hessian.block<3, 3>(3 * i, 3 * j) = 2 * w(i) * w(j) * Eigen::Matrix3d::Identity();
  }
  const int m = static_cast<int>(e.cols());
  if (m == 0) return out;
  Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, 2> d(3, m);  // ∂r/∂y_k
  for (int k = 0; k < m; ++k) {
    d.col(k).setZero();
    for (int i = 0; i < 4; ++i) d.col(k) += e(i, k) * *x[i];
  }
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 2, 2> g_yy =
      2 * d.transpose() * d;
  Eigen::Matrix<double, 12, Eigen::Dynamic, Eigen::ColMajor, 12, 2> g_xy(12, m);
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < 4; ++i) g_xy.block<3, 1>(3 * i, k) = 2 * (e(i, k) * r + w(i) * d.col(k));
  out.hessian -= g_xy * g_yy.ldlt().solve(g_xy.transpose());
  return out;
}

constexpr double kInterior = 1e-12;  // a parameter this far inside its range is free

}  // namespace

DistanceDerivatives PointTriangleDerivatives(const Eigen::Vector3d& p,
                                             const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b,
                                             const Eigen::Vector3d& c) {
  const PointTriangleDistance closest = PointTriangle(p, a, b, c);
  const Eigen::Vector3d& u = closest.barycentric;
  const Eigen::Vector4d w(1, -u(0), -u(1), -u(2));
  // Free directions of the closest point: along each edge between two
  // vertices with a nonzero weight (two directions on the face, one on an
  // edge, none at a vertex). Moving weight from vertex i to vertex j changes
  // w by +1 at i, −1 at j (w holds −u).
  const bool in[3] = {u(0) > kInterior, u(1) > kInterior, u(2) > kInterior};
  const int count = in[0] + in[1] + in[2];
  auto along = [](int from, int to) {
    Eigen::Vector4d v = Eigen::Vector4d::Zero();
    v(1 + from) = 1;
    v(1 + to) = -1;
    return v;
  };
  FreeDirections e(4, count == 3 ? 2 : count == 2 ? 1 : 0);
  if (count == 3) {
    e.col(0) = along(0, 1);
    e.col(1) = along(0, 2);
  } else if (count == 2) {
    int i = 0;
    while (!in[i]) ++i;
    int j = i + 1;
    while (!in[j]) ++j;
    e.col(0) = along(i, j);
  }
  return Envelope({&p, &a, &b, &c}, w, e);
}

DistanceDerivatives EdgeEdgeDerivatives(const Eigen::Vector3d& a0,
                                        const Eigen::Vector3d& a1,
                                        const Eigen::Vector3d& b0,
                                        const Eigen::Vector3d& b1) {
  const EdgeEdgeDistance closest = EdgeEdge(a0, a1, b0, b1);
  const double s = closest.s, t = closest.t;
  const Eigen::Vector4d w(1 - s, s, -(1 - t), -t);
  bool free_s = s > kInterior && s < 1 - kInterior;
  const bool free_t = t > kInterior && t < 1 - kInterior;
  if (free_s && free_t) {
    // Nearly parallel: the closest points slide along both edges together
    // (g_yy singular); hold s, a point of one edge against the other.
    const Eigen::Vector3d u = a1 - a0, v = b1 - b0;
    const double sin2 = u.cross(v).squaredNorm() / (u.squaredNorm() * v.squaredNorm());
    if (!(sin2 > 1e-10)) free_s = false;
  }
  FreeDirections e(4, int(free_s) + int(free_t));
  int k = 0;
  if (free_s) e.col(k++) = Eigen::Vector4d(-1, 1, 0, 0);
  if (free_t) e.col(k++) = Eigen::Vector4d(0, 0, 1, -1);
  return Envelope({&a0, &a1, &b0, &b1}, w, e);
}

}  // namespace drape
