// The collision-free step filter of self-contact (issue 17): additive
// continuous collision detection (C-IPC, Li, Kaufman, Jiang et al. 2021,
// Algorithm 1). For a pair moving linearly from x by Δx, the largest
// fraction of the step that keeps its distance above the offset ξ: the
// pair advances conservatively, by the gap over a bound on how fast the
// gap can close, and stops once the gap has shrunk to `keep` of what it was
// (so the barrier stays finite and the next step has room).
#pragma once

#include <Eigen/Core>

namespace drape {

struct AccdSettings {
  double offset = 0;  // ξ [m]
  double keep = 0.1;  // stop at this fraction of the starting gap d − ξ
  // Advance no further than this: a caller taking the least bound over many
  // pairs passes the least so far, and a pair that reaches it cannot lower
  // it. Sliding at a small gap advances by gap / closing speed a step, so
  // without it one such pair costs thousands of distance evaluations.
  double max_t = 1;
  // Advancement steps before giving up; the part advanced so far is still
  // safe and is returned.
  int max_steps = 10000;
};

// Point p against triangle (a, b, c), each moving by its Δ over the step;
// returns t ∈ [0, max_t].
double PointTriangleStepBound(const Eigen::Vector3d& p,
                              const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c,
                              const Eigen::Vector3d& dp,
                              const Eigen::Vector3d& da,
                              const Eigen::Vector3d& db,
                              const Eigen::Vector3d& dc,
                              const AccdSettings& settings);

// Edge (a0, a1) against edge (b0, b1); returns t ∈ [0, max_t].
double EdgeEdgeStepBound(const Eigen::Vector3d& a0,
                         const Eigen::Vector3d& a1,
                         const Eigen::Vector3d& b0,
                         const Eigen::Vector3d& b1,
                         const Eigen::Vector3d& da0,
                         const Eigen::Vector3d& da1,
                         const Eigen::Vector3d& db0,
                         const Eigen::Vector3d& db1,
                         const AccdSettings& settings);

}  // namespace drape
