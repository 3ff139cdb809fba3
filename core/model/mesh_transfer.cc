#include "core/model/mesh_transfer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace drape {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

[[noreturn]] void Fail(const char* function, const std::string& what) {
  throw std::invalid_argument(std::string(function) + ": " + what);
}

void Validate(const char* function,
              const char* mesh_name,
              const char* deformed_name,
              const Mesh& mesh,
              const Eigen::MatrixX3d& deformed) {
  const std::string mesh_str = mesh_name;
  const std::string deformed_str = deformed_name;
  if (mesh.ElementCount() == 0) Fail(function, mesh_str + " is empty (no quads)");
  if (deformed.rows() != mesh.positions.rows())
    Fail(function,
         deformed_str + " has " + std::to_string(deformed.rows()) + " rows but " + mesh_str +
             " has " + std::to_string(mesh.positions.rows()) + " nodes (one row per node)");
  const int nodes = mesh.NodeCount();
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      if (mesh.quads(e, k) < 0 || mesh.quads(e, k) >= nodes)
        Fail(function,
             "quad " + std::to_string(e) + " of " + mesh_str + " names node " +
                 std::to_string(mesh.quads(e, k)) + ", outside 0.." + std::to_string(nodes - 1));
  for (int n = 0; n < nodes; ++n) {
    if (!mesh.positions.row(n).leftCols<2>().allFinite())
      Fail(function,
           "reference x, y of node " + std::to_string(n) + " of " + mesh_str + " is not finite");
    if (!deformed.row(n).allFinite())
      Fail(function, "row " + std::to_string(n) + " of " + deformed_str + " is not finite");
  }
}

// A point of a quad in its parameters: node k of the quad has (ξ, η) =
// (0, 0), (1, 0), (1, 1), (0, 1) for k = 0..3.
struct QuadPoint {
  int quad = -1;
  double xi = 0;
  double eta = 0;
};

// Finds, for reference points, the quad containing them or else the nearest
// quad. Quads are filed in a uniform grid of cells by their reference
// bounding boxes, so a point only looks at the quads of its own cell (and,
// outside the mesh, of rings of cells around it until no farther cell can
// hold a nearer quad).
class QuadLocator {
 public:
  explicit QuadLocator(const Mesh& mesh) : mesh_(mesh), seen_(mesh.ElementCount(), -1) {
    const int count = mesh.ElementCount();
    box_.resize(count);
    lo_ = Eigen::Vector2d::Constant(kInfinity);
    Eigen::Vector2d hi = Eigen::Vector2d::Constant(-kInfinity);
    double size_sum = 0;
    for (int e = 0; e < count; ++e) {
      Box& box = box_[e];
      box.lo = box.hi = Corner(e, 0);
      for (int k = 1; k < 4; ++k) {
        box.lo = box.lo.cwiseMin(Corner(e, k));
        box.hi = box.hi.cwiseMax(Corner(e, k));
      }
      lo_ = lo_.cwiseMin(box.lo);
      hi = hi.cwiseMax(box.hi);
      size_sum += (box.hi - box.lo).maxCoeff();
    }
    const Eigen::Vector2d extent = hi - lo_;
    // Cells about the size of a quad keep a handful of quads per cell;
    // the cap bounds memory when a few huge quads sit among tiny ones.
    cell_ = size_sum / count;
    if (!(cell_ > 0)) cell_ = std::max(extent.maxCoeff(), 1.0);
    const double max_cells = 4.0 * count + 64;
    const double wanted = (extent.x() / cell_ + 1) * (extent.y() / cell_ + 1);
    if (wanted > max_cells) cell_ *= std::sqrt(wanted / max_cells);
    nx_ = std::max(1, static_cast<int>(std::ceil(extent.x() / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(extent.y() / cell_)));
    tolerance_ = 1e-12 * std::max(extent.maxCoeff(), cell_);

    // Compressed rows: start_[c] .. start_[c + 1] index the quads of cell c.
    start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill;
      if (pass == 1) {
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        quads_.resize(start_.back());
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for (int e = 0; e < count; ++e) {
        const int i0 = CellX(box_[e].lo.x()), i1 = CellX(box_[e].hi.x());
        const int j0 = CellY(box_[e].lo.y()), j1 = CellY(box_[e].hi.y());
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            const int c = j * nx_ + i;
            if (pass == 0)
              ++start_[c + 1];
            else
              quads_[fill[c]++] = e;
          }
      }
    }
  }

  QuadPoint Locate(const Eigen::Vector2d& p) {
    const int ci = CellX(p.x()), cj = CellY(p.y());
    for (int s = start_[cj * nx_ + ci]; s < start_[cj * nx_ + ci + 1]; ++s) {
      const int e = quads_[s];
      const Box& box = box_[e];
      if ((p.array() < box.lo.array() - tolerance_).any() ||
          (p.array() > box.hi.array() + tolerance_).any())
        continue;
      QuadPoint inside;
      if (Invert(e, p, &inside)) return inside;
    }
    return Nearest(p, ci, cj);
  }

 private:
  struct Box {
    Eigen::Vector2d lo, hi;
  };

  Eigen::Vector2d Corner(int e, int k) const {
    return mesh_.positions.row(mesh_.quads(e, k)).leftCols<2>().transpose();
  }

  // floor() in double before the cast: a far point would overflow an int.
  int CellX(double x) const {
    return static_cast<int>(std::clamp(std::floor((x - lo_.x()) / cell_), 0.0, nx_ - 1.0));
  }
  int CellY(double y) const {
    return static_cast<int>(std::clamp(std::floor((y - lo_.y()) / cell_), 0.0, ny_ - 1.0));
  }

  // Newton on x(ξ, η) = p from the quad's centre. Only a solution inside
  // [0, 1]² counts: there the bilinear map of a convex quad is one-to-one,
  // while outside it a second root can exist. A point Newton misses (a
  // degenerate quad) falls through to the nearest-boundary search.
  bool Invert(int e, const Eigen::Vector2d& p, QuadPoint* out) const {
    const Eigen::Vector2d p0 = Corner(e, 0);
    const Eigen::Vector2d a = Corner(e, 1) - p0;
    const Eigen::Vector2d b = Corner(e, 3) - p0;
    const Eigen::Vector2d c = Corner(e, 2) - Corner(e, 1) - Corner(e, 3) + p0;
    double xi = 0.5, eta = 0.5;
    for (int iteration = 0; iteration < 30; ++iteration) {
      const Eigen::Vector2d r = p0 + xi * a + eta * b + xi * eta * c - p;
      const Eigen::Vector2d d_xi = a + eta * c;
      const Eigen::Vector2d d_eta = b + xi * c;
      const double det = d_xi.x() * d_eta.y() - d_xi.y() * d_eta.x();
      if (!std::isfinite(det) || det == 0) return false;
      const double step_xi = -(d_eta.y() * r.x() - d_eta.x() * r.y()) / det;
      const double step_eta = -(-d_xi.y() * r.x() + d_xi.x() * r.y()) / det;
      xi += step_xi;
      eta += step_eta;
      if (!(std::abs(xi) < 1e3 && std::abs(eta) < 1e3)) return false;
      if (std::max(std::abs(step_xi), std::abs(step_eta)) < 1e-13) {
        constexpr double kSlack = 1e-12;
        if (xi < -kSlack || xi > 1 + kSlack || eta < -kSlack || eta > 1 + kSlack) return false;
        *out = {e, std::clamp(xi, 0.0, 1.0), std::clamp(eta, 0.0, 1.0)};
        return true;
      }
    }
    return false;
  }

  // The point of quad e's boundary nearest p: the quad's edges are straight
  // (the bilinear map is linear along each), so it is the nearest point of
  // four segments, and its (ξ, η) follow from the segment parameter.
  double NearestOnQuad(int e, const Eigen::Vector2d& p, QuadPoint* out) const {
    double best = kInfinity;
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector2d from = Corner(e, k);
      const Eigen::Vector2d along = Corner(e, (k + 1) % 4) - from;
      const double length2 = along.squaredNorm();
      const double t = length2 > 0 ? std::clamp((p - from).dot(along) / length2, 0.0, 1.0) : 0.0;
      const double distance = (from + t * along - p).norm();
      if (distance < best) {
        best = distance;
        static constexpr double kXi0[4] = {0, 1, 1, 0}, kXi1[4] = {1, 1, 0, 0};
        static constexpr double kEta0[4] = {0, 0, 1, 1}, kEta1[4] = {0, 1, 1, 0};
        *out = {e, kXi0[k] + t * (kXi1[k] - kXi0[k]), kEta0[k] + t * (kEta1[k] - kEta0[k])};
      }
    }
    return best;
  }

  // Distance from p to the slab of cells in column i (or row j); p's own
  // cell index is monotone with it, which makes the ring bound below valid.
  double ColumnDistance(int i, double x) const {
    const double from = lo_.x() + i * cell_;
    return std::max({0.0, from - x, x - (from + cell_)});
  }
  double RowDistance(int j, double y) const {
    const double from = lo_.y() + j * cell_;
    return std::max({0.0, from - y, y - (from + cell_)});
  }

  // Rings of cells around (ci, cj), nearest first. Every cell of ring ≥ r
  // lies in a column ci ± r' or row cj ± r' with r' ≥ r, so it is no nearer
  // than the nearest of the four lines at r; once that bound reaches the best
  // distance found, no unseen quad can be nearer (a quad's nearest point lies
  // in one of the cells it is filed in).
  QuadPoint Nearest(const Eigen::Vector2d& p, int ci, int cj) {
    ++query_;
    QuadPoint best_point;
    double best = kInfinity;
    for (int r = 0;; ++r) {
      double bound = kInfinity;
      if (ci - r >= 0) bound = std::min(bound, ColumnDistance(ci - r, p.x()));
      if (ci + r < nx_) bound = std::min(bound, ColumnDistance(ci + r, p.x()));
      if (cj - r >= 0) bound = std::min(bound, RowDistance(cj - r, p.y()));
      if (cj + r < ny_) bound = std::min(bound, RowDistance(cj + r, p.y()));
      if (bound == kInfinity || bound >= best) break;
      const int j0 = std::max(cj - r, 0), j1 = std::min(cj + r, ny_ - 1);
      const int i0 = std::max(ci - r, 0), i1 = std::min(ci + r, nx_ - 1);
      for (int j = j0; j <= j1; ++j) {
        const bool edge_row = j == cj - r || j == cj + r;
        for (int i = i0; i <= i1; ++i) {
          if (!edge_row && i != ci - r && i != ci + r) {
            // Interior of the ring's square: jump to its right side.
            if (ci + r > i) i = ci + r - 1;
            continue;
          }
          const int c = j * nx_ + i;
          for (int s = start_[c]; s < start_[c + 1]; ++s) {
            const int e = quads_[s];
            if (seen_[e] == query_) continue;
            seen_[e] = query_;
            QuadPoint candidate;
            const double distance = NearestOnQuad(e, p, &candidate);
            if (distance < best) {
              best = distance;
              best_point = candidate;
            }
          }
        }
      }
    }
    return best_point;
  }

  const Mesh& mesh_;
  std::vector<Box> box_;
  Eigen::Vector2d lo_;
  double cell_ = 1;
  double tolerance_ = 0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> start_;
  std::vector<int> quads_;
  // Quads already measured in the current Nearest query: a quad is filed in
  // every cell its box touches.
  std::vector<long long> seen_;
  long long query_ = 0;
};

Eigen::MatrixX3d InterpolateChecked(const Mesh& mesh,
                                    const Eigen::MatrixX3d& deformed,
                                    const Eigen::MatrixX2d& at) {
  QuadLocator locator(mesh);
  Eigen::MatrixX3d result(at.rows(), 3);
  for (Eigen::Index row = 0; row < at.rows(); ++row) {
    const QuadPoint q = locator.Locate(at.row(row).transpose());
    const double xi = q.xi, eta = q.eta;
    const double weight[4] = {(1 - xi) * (1 - eta), xi * (1 - eta), xi * eta, (1 - xi) * eta};
    Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 4; ++k) value += weight[k] * deformed.row(mesh.quads(q.quad, k));
    result.row(row) = value;
  }
  return result;
}

}  // namespace

Eigen::MatrixX3d InterpolateDeformed(const Mesh& mesh,
                                     const Eigen::MatrixX3d& deformed,
                                     const Eigen::MatrixX2d& at) {
  constexpr const char* kFunction = "InterpolateDeformed";
  Validate(kFunction, "mesh", "deformed", mesh, deformed);
  for (Eigen::Index row = 0; row < at.rows(); ++row)
    if (!at.row(row).allFinite())
      Fail(kFunction, "point " + std::to_string(row) + " of `at` is not finite");
  return InterpolateChecked(mesh, deformed, at);
}

ShapeDistance DeformedDistance(const Mesh& mesh_a,
                               const Eigen::MatrixX3d& deformed_a,
                               const Mesh& mesh_b,
                               const Eigen::MatrixX3d& deformed_b) {
  constexpr const char* kFunction = "DeformedDistance";
  Validate(kFunction, "mesh_a", "deformed_a", mesh_a, deformed_a);
  Validate(kFunction, "mesh_b", "deformed_b", mesh_b, deformed_b);
  const Eigen::MatrixX2d at = mesh_a.positions.leftCols<2>();
  const Eigen::MatrixX3d on_b = InterpolateChecked(mesh_b, deformed_b, at);
  ShapeDistance result;
  double sum2 = 0;
  for (int n = 0; n < mesh_a.NodeCount(); ++n) {
    const double distance = (deformed_a.row(n) - on_b.row(n)).norm();
    sum2 += distance * distance;
    if (distance > result.max || result.node < 0) {
      result.max = distance;
      result.node = n;
    }
  }
  result.rms = std::sqrt(sum2 / mesh_a.NodeCount());
  return result;
}

}  // namespace drape
