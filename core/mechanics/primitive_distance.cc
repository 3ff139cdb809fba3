#include "core/mechanics/primitive_distance.h"

#include <Eigen/Geometry>

#include <algorithm>

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
  auto finish = [&](double u, double v, double w) {
    out.barycentric = V3(u, v, w);
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
    if (d_ab <= d_bc && d_ab <= d_ca) return finish(1 - s_ab, s_ab, 0);
    if (d_bc <= d_ca) return finish(0, 1 - s_bc, s_bc);
    return finish(s_ca, 0, 1 - s_ca);
  }
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0);  // vertex a
  const V3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0);  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {  // edge ab
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const V3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1);  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {  // edge ac
    const double w = d2 / (d2 - d6);
    return finish(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {  // edge bc
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - w, w);
  }
  const double denominator = 1 / (va + vb + vc);  // the face
  const double v = vb * denominator, w = vc * denominator;
  return finish(1 - v - w, v, w);
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
