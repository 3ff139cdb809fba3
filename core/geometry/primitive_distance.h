// Distances between the fabric's surface primitives, the geometry of
// self-contact (C-IPC, Li, Kaufman, Jiang et al. 2021): a point and a
// triangle, two edges. Each returns the squared distance and where the
// closest points lie, so a barrier can tell which region (face, edge,
// vertex) it is in.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace drape {

// Where on a triangle (a, b, c) its closest point to a point lies. Edge k
// runs from corner k to corner k + 1 (edge 2 from c to a).
enum class TriangleRegion : std::uint8_t {
  kFace,
  kEdge0,
  kEdge1,
  kEdge2,
  kVertex0,
  kVertex1,
  kVertex2
};

struct PointTriangleDistance {
  double squared = 0;
  TriangleRegion region = TriangleRegion::kFace;
  // The closest point of the triangle is Σ barycentric_i x_i.
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

// p against triangle (a, b, c), by the Voronoi regions of its vertices,
// edges and face (Ericson, Real-Time Collision Detection, §5.1.5). A
// degenerate triangle gives the distance to its edges.
PointTriangleDistance PointTriangle(const Eigen::Vector3d& p,
                                    const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b,
                                    const Eigen::Vector3d& c);

struct EdgeEdgeDistance {
  double squared = 0;
  // The closest points are a0 + s (a1 − a0) and b0 + t (b1 − b0).
  double s = 0, t = 0;
};

// Segment (a0, a1) against segment (b0, b1) (Ericson §5.1.9); degenerate
// segments included. Segments parallel to within ~1e-7 rad are taken as
// parallel (the closest-point formula divides by sin²θ): the distance is then
// exact to ~1e-7 of their length, and (s, t) one of the closest pairs.
EdgeEdgeDistance EdgeEdge(const Eigen::Vector3d& a0,
                          const Eigen::Vector3d& a1,
                          const Eigen::Vector3d& b0,
                          const Eigen::Vector3d& b1);

}  // namespace drape

namespace drape {

// The squared distance of a point–triangle (x = p, a, b, c) or edge–edge
// (x = a0, a1, b0, b1) pair as a function of its twelve coordinates, with
// its gradient and Hessian, for a barrier on it. In each region (vertex,
// edge, face; the edges' interiors or ends) the distance is min over the
// closest point's parameters y of |r(x, y)|², so by the envelope theorem
// ∇f = g_x and ∇²f = g_xx − g_xy g_yy⁻¹ g_yx at the minimiser. Exact within
// a region; across a region's border the Hessian jumps (the gradient is
// continuous). Nearly parallel edges make g_yy singular: their pairs need
// the barrier's mollifier, and are evaluated here as a point against the
// other edge.
struct DistanceDerivatives {
  double squared = 0;
  Eigen::Matrix<double, 12, 1> gradient = Eigen::Matrix<double, 12, 1>::Zero();
  Eigen::Matrix<double, 12, 12> hessian = Eigen::Matrix<double, 12, 12>::Zero();
};

DistanceDerivatives PointTriangleDerivatives(const Eigen::Vector3d& p,
                                             const Eigen::Vector3d& a,
                                             const Eigen::Vector3d& b,
                                             const Eigen::Vector3d& c);

DistanceDerivatives EdgeEdgeDerivatives(const Eigen::Vector3d& a0,
                                        const Eigen::Vector3d& a1,
                                        const Eigen::Vector3d& b0,
                                        const Eigen::Vector3d& b1);

}  // namespace drape
