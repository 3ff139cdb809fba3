#include "core/solve/mesh_sequencing.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "core/mechanics/director.h"

#include "core/mechanics/bilinear_quad.h"

namespace drape {
namespace {

// Coarse elements by reference bounding box on a uniform grid, so that each
// fine node is located among a handful of candidates.
class ElementGrid {
 public:
  explicit ElementGrid(const Mesh& mesh) : mesh_(mesh) {
    lo_ = mesh.positions.leftCols<2>().colwise().minCoeff().transpose();
    const Eigen::Vector2d hi = mesh.positions.leftCols<2>().colwise().maxCoeff().transpose();
    cells_ = std::max(1, static_cast<int>(std::sqrt(mesh.ElementCount())));
    size_ = (hi - lo_).cwiseMax(1e-300) / cells_;
    buckets_.resize(static_cast<size_t>(cells_) * cells_);
    for (int e = 0; e < mesh.ElementCount(); ++e) {
      Eigen::Vector2d a = Eigen::Vector2d::Constant(INFINITY), b = -a;
      for (int k = 0; k < 4; ++k) {
        a = a.cwiseMin(mesh.positions.row(mesh.quads(e, k)).head<2>().transpose());
        b = b.cwiseMax(mesh.positions.row(mesh.quads(e, k)).head<2>().transpose());
      }
      const auto [i0, j0] = Cell(a);
      const auto [i1, j1] = Cell(b);
      for (int i = i0; i <= i1; ++i)
        for (int j = j0; j <= j1; ++j) buckets_[static_cast<size_t>(j) * cells_ + i].push_back(e);
    }
  }

  // The element holding `p` and (ξ, η) there; false outside every element.
  bool Locate(const Eigen::Vector2d& p, int& element, double& xi, double& eta) const {
    const auto [i, j] = Cell(p);
    for (int e : buckets_[static_cast<size_t>(j) * cells_ + i])
      if (LocateInElement(mesh_, e, Vec2{p.x(), p.y()}, xi, eta)) {
        element = e;
        return true;
      }
    return false;
  }

 private:
  std::pair<int, int> Cell(const Eigen::Vector2d& p) const {
    auto clamp = [&](double v) { return std::clamp(static_cast<int>(v), 0, cells_ - 1); };
    return {clamp((p.x() - lo_.x()) / size_.x()), clamp((p.y() - lo_.y()) / size_.y())};
  }

  const Mesh& mesh_;
  Eigen::Vector2d lo_, size_;
  int cells_ = 1;
  std::vector<std::vector<int>> buckets_;
};

// The hysteresis's history on the fine mesh: each fine element takes the
// slip of the coarse element under its centre, its Gauss points' mean per
// friction family (the slip is a field of the fabric, piecewise smooth).
std::vector<ElementSlip> ProlongatedSlip(const ShellState& coarse_state,
                                         const ShellModel& fine,
                                         const ElementGrid& grid) {
  if (coarse_state.bending_slip.empty()) return {};
  std::vector<ElementSlip> slip(fine.mesh.ElementCount(), ElementSlip::Zero());
  for (int e = 0; e < fine.mesh.ElementCount(); ++e) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int k = 0; k < 4; ++k)
      centre += 0.25 * fine.mesh.positions.row(fine.mesh.quads(e, k)).head<2>().transpose();
    int c = -1;
    double xi = 0, eta = 0;
    if (!grid.Locate(centre, c, xi, eta)) continue;
    const ElementSlip& from = coarse_state.bending_slip[c];
    for (int f = 0; f < kMaxFrictionFamilies; ++f) {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (int p = 0; p < 4; ++p) mean += 0.25 * from.col(2 * p + f);
      for (int p = 0; p < 4; ++p) slip[e].col(2 * p + f) = mean;
    }
  }
  return slip;
}

}  // namespace

Scene CoarsenedScene(const Scene& scene, int factor) {
  Scene coarse = scene;
  const auto [nx, ny] = *scene.fabric.mesh.elements;
  coarse.fabric.mesh.elements = std::array<int, 2>{nx / factor, ny / factor};
  coarse.solver.sequencing = 1;
  return coarse;
}

ShellState Prolongate(const ShellModel& coarse,
                      const ShellState& coarse_state,
                      const ShellModel& fine) {
  const ElementGrid grid(coarse.mesh);
  ShellState out = fine.reference;
  out.obstacles = coarse_state.obstacles;
  for (int i = 0; i < fine.NodeCount(); ++i) {
    const Eigen::Vector2d p = fine.mesh.positions.row(i).head<2>();
    int e = -1;
    double xi = 0, eta = 0;
    if (!grid.Locate(p, e, xi, eta)) continue;  // not on the coarse mesh: stays at rest
    Eigen::Vector4d n;
    BilinearShape(std::clamp(xi, -1.0, 1.0), std::clamp(eta, -1.0, 1.0), n);
    Eigen::Vector3d u = Eigen::Vector3d::Zero(), t = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      const int c = coarse.mesh.quads(e, k);
      u += n(k) * (coarse_state.positions.row(c) - coarse.reference.positions.row(c)).transpose();
      t += n(k) * coarse_state.Director(c);
    }
    out.positions.row(i) += u.transpose();
    if (t.norm() > 0) out.rotations[i] = RotationFromDirector(t.normalized());
  }
  out.bending_slip = ProlongatedSlip(coarse_state, fine, grid);
  for (const auto* group : {&fine.supports, &fine.grippers})
    for (const HeldNodes& held : *group)
      for (int node : held.nodes) {
        out.positions.row(node) = fine.reference.positions.row(node);
        if (held.fixity == Fixity::kClamp) out.rotations[node] = fine.reference.rotations[node];
      }
  return out;
}

}  // namespace drape
