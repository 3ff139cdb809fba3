#include "core/model/mesh_transfer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/imperfection.h"
#include "core/model/mesh.h"

namespace drape {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Deformation = std::function<Eigen::Vector3d(double x, double y)>;

Eigen::MatrixX3d Deform(const Mesh& mesh, const Deformation& phi) {
  Eigen::MatrixX3d deformed(mesh.NodeCount(), 3);
  for (int n = 0; n < mesh.NodeCount(); ++n)
    deformed.row(n) = phi(mesh.positions(n, 0), mesh.positions(n, 1)).transpose();
  return deformed;
}

// Whether `text` contains `part`, saying both when it does not.
testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The message of the std::invalid_argument `call` throws ("" if none).
std::string InvalidArgumentMessage(const std::function<void()>& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "no std::invalid_argument thrown";
  return "";
}

// Points uniform in [x0, x1] × [y0, y1].
Eigen::MatrixX2d RandomPoints(
    int count, double x0, double x1, double y0, double y1, std::uint64_t seed) {
  SplitMix64 random(seed);
  Eigen::MatrixX2d points(count, 2);
  for (int k = 0; k < count; ++k) {
    points(k, 0) = x0 + (x1 - x0) * random.NextUniform();
    points(k, 1) = y0 + (y1 - y0) * random.NextUniform();
  }
  return points;
}

// An nx × ny mesh of [0, size_x] × [0, size_y] whose interior nodes are moved
// by up to ±amount of the spacing in x and y (amount < 1/4 keeps every quad
// convex), and whose reference z is a random imperfection that must not
// matter.
Mesh DistortedRectangle(
    double size_x, double size_y, int nx, int ny, double amount, std::uint64_t seed) {
  Mesh mesh = MeshRectangle(size_x, size_y, {0.5 * size_x, 0.5 * size_y}, nx, ny, 0.0);
  SplitMix64 random(seed);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const int n = j * (nx + 1) + i;
      mesh.positions(n, 2) = 1e-3 * (random.NextUniform() - 0.5);
      if (i == 0 || i == nx || j == 0 || j == ny) continue;
      mesh.positions(n, 0) += amount * (2 * random.NextUniform() - 1) * size_x / nx;
      mesh.positions(n, 1) += amount * (2 * random.NextUniform() - 1) * size_y / ny;
    }
  return mesh;
}

// A tensor grid of axis-aligned rectangles with uneven spacing: x·y is then
// bilinear in each quad's (ξ, η) too.
Mesh UnevenGrid(const std::vector<double>& xs, const std::vector<double>& ys) {
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  Mesh mesh;
  mesh.positions.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) mesh.positions.row(j * (nx + 1) + i) << xs[i], ys[j], 0.0;
  mesh.quads.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n = j * (nx + 1) + i;
      mesh.quads.row(j * nx + i) << n, n + 1, n + nx + 2, n + nx + 1;
    }
  return mesh;
}

const Deformation kAffine = [](double x, double y) -> Eigen::Vector3d {
  return Eigen::Vector3d(
      0.1 + 0.9 * x - 0.3 * y, -0.2 + 0.25 * x + 1.1 * y, 0.05 + 0.4 * x - 0.6 * y);
};

// Affine plus x·y terms: bilinear in (x, y).
const Deformation kBilinear = [](double x, double y) -> Eigen::Vector3d {
  return kAffine(x, y) + Eigen::Vector3d(0.7, -0.4, 1.3) * x * y;
};

double MaxRowDistance(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  return (a - b).rowwise().norm().maxCoeff();
}

Eigen::MatrixX3d Evaluate(const Deformation& phi, const Eigen::MatrixX2d& at) {
  Eigen::MatrixX3d values(at.rows(), 3);
  for (Eigen::Index k = 0; k < at.rows(); ++k) values.row(k) = phi(at(k, 0), at(k, 1)).transpose();
  return values;
}

TEST(MeshTransfer, AffineDeformationIsExactOnDistortedQuads) {
  const Mesh mesh = DistortedRectangle(2.0, 1.0, 8, 5, 0.2, 11);
  ASSERT_GT(MeasureQuality(mesh).max_angle_deg - MeasureQuality(mesh).min_angle_deg, 20.0)
      << "the mesh should be visibly distorted";
  const Eigen::MatrixX3d deformed = Deform(mesh, kAffine);
  Eigen::MatrixX2d at = RandomPoints(2000, 0.0, 2.0, 0.0, 1.0, 3);
  EXPECT_LE(MaxRowDistance(InterpolateDeformed(mesh, deformed, at), Evaluate(kAffine, at)), 1e-12);
  // The nodes and the midpoints of the quads' edges: on shared edges.
  at = mesh.positions.leftCols<2>();
  EXPECT_LE(MaxRowDistance(InterpolateDeformed(mesh, deformed, at), deformed), 1e-12);
  Eigen::MatrixX2d midpoints(4 * mesh.ElementCount(), 2);
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      midpoints.row(4 * e + k) =
          0.5 * (mesh.positions.row(mesh.quads(e, k)).leftCols<2>() +
                 mesh.positions.row(mesh.quads(e, (k + 1) % 4)).leftCols<2>());
  EXPECT_LE(
      MaxRowDistance(InterpolateDeformed(mesh, deformed, midpoints), Evaluate(kAffine, midpoints)),
      1e-12);
}

TEST(MeshTransfer, BilinearDeformationIsExactOnRectangleGrids) {
  const Mesh even = MeshRectangle(2.0, 1.0, {1.0, 0.5}, 7, 3, 0.0);
  const Mesh uneven = UnevenGrid({0.0, 0.1, 0.45, 0.5, 1.2, 1.3, 2.0}, {0.0, 0.3, 0.35, 0.8, 1.0});
  const Eigen::MatrixX2d at = RandomPoints(2000, 0.0, 2.0, 0.0, 1.0, 5);
  for (const Mesh* mesh : {&even, &uneven}) {
    const Eigen::MatrixX3d interpolated = InterpolateDeformed(*mesh, Deform(*mesh, kBilinear), at);
    EXPECT_LE(MaxRowDistance(interpolated, Evaluate(kBilinear, at)), 1e-12);
  }
}

// Isoparametric bilinear quads reproduce x·y only where x and y are each
// affine in one of (ξ, η): axis-aligned rectangles. On a distorted quad x·y
// has ξ², η² terms, so "bilinear in (x, y) is exact on any quad" is false;
// this pins the limit down rather than leaving it to a surprise.
TEST(MeshTransfer, BilinearTermIsOnlyApproximatedOnDistortedQuads) {
  const Mesh mesh = DistortedRectangle(2.0, 1.0, 8, 5, 0.2, 11);
  const Eigen::MatrixX2d at = RandomPoints(2000, 0.0, 2.0, 0.0, 1.0, 3);
  const double error = MaxRowDistance(InterpolateDeformed(mesh, Deform(mesh, kBilinear), at),
                                      Evaluate(kBilinear, at));
  EXPECT_GT(error, 1e-4);
  EXPECT_LT(error, 1e-1);
}

// A bend about an axis along y: x ↦ (R sin(x/R), y, R(1 − cos(x/R))).
Eigen::Vector3d Bend(double x, double y) {
  constexpr double kRadius = 0.4;
  return {kRadius * std::sin(x / kRadius), y, kRadius * (1 - std::cos(x / kRadius))};
}

TEST(MeshTransfer, SmoothDeformationConvergesAtSecondOrder) {
  const Eigen::MatrixX2d at = RandomPoints(20000, 0.0, 1.0, 0.0, 0.5, 7);
  const Eigen::MatrixX3d exact = Evaluate(Bend, at);
  // A smooth mesh distortion keeps the second order; random node jitter would not.
  const auto warped = [](Mesh mesh) {
    for (int n = 0; n < mesh.NodeCount(); ++n) {
      const double x = mesh.positions(n, 0), y = mesh.positions(n, 1);
      mesh.positions(n, 0) += 0.06 * std::sin(kPi * x) * std::sin(2 * kPi * y);
      mesh.positions(n, 1) += 0.03 * std::sin(2 * kPi * x) * std::sin(2 * kPi * y);
    }
    return mesh;
  };
  for (const bool warp : {false, true}) {
    for (const int n : {8, 16}) {
      Mesh coarse = MeshRectangle(1.0, 0.5, {0.5, 0.25}, n, n, 0.0);
      Mesh fine = MeshRectangle(1.0, 0.5, {0.5, 0.25}, 2 * n, 2 * n, 0.0);
      if (warp) {
        coarse = warped(coarse);
        fine = warped(fine);
      }
      const Eigen::VectorXd e_coarse =
          (InterpolateDeformed(coarse, Deform(coarse, Bend), at) - exact).rowwise().norm();
      const Eigen::VectorXd e_fine =
          (InterpolateDeformed(fine, Deform(fine, Bend), at) - exact).rowwise().norm();
      const double rms_ratio = e_coarse.norm() / e_fine.norm();
      const double max_ratio = e_coarse.maxCoeff() / e_fine.maxCoeff();
      std::cout << (warp ? "warped" : "rectangle") << " n = " << n << ": rms error "
                << e_coarse.norm() / std::sqrt(at.rows()) << " -> "
                << e_fine.norm() / std::sqrt(at.rows()) << " (ratio " << rms_ratio
                << "), max error " << e_coarse.maxCoeff() << " -> " << e_fine.maxCoeff()
                << " (ratio " << max_ratio << ")\n";
      EXPECT_GT(rms_ratio, 3.5);
      EXPECT_LT(rms_ratio, 4.5);
      EXPECT_GT(max_ratio, 3.5);
      EXPECT_LT(max_ratio, 4.5);
    }
  }
}

TEST(MeshTransfer, DistanceOfARunToItselfIsZero) {
  const Mesh mesh = DistortedRectangle(1.0, 0.5, 12, 7, 0.2, 13);
  const Eigen::MatrixX3d deformed = Deform(mesh, Bend);
  const ShapeDistance distance = DeformedDistance(mesh, deformed, mesh, deformed);
  // Zero up to rounding: Newton lands on a corner's (ξ, η) to the last bit or so.
  EXPECT_LE(distance.max, 1e-15);
  EXPECT_LE(distance.rms, 1e-15);
  EXPECT_GE(distance.node, 0);
  EXPECT_LT(distance.node, mesh.NodeCount());
}

TEST(MeshTransfer, DifferentMeshesOfABilinearDeformationAgree) {
  const Mesh coarse = MeshRectangle(2.0, 0.8, {0.3, -0.1}, 10, 4, 0.0);
  const Mesh fine = MeshRectangle(2.0, 0.8, {0.3, -0.1}, 40, 16, 0.0);
  const Mesh odd = MeshRectangle(2.0, 0.8, {0.3, -0.1}, 13, 7, 0.0);  // nodes not shared
  const Eigen::MatrixX3d on_coarse = Deform(coarse, kBilinear);
  const Eigen::MatrixX3d on_fine = Deform(fine, kBilinear);
  const Eigen::MatrixX3d on_odd = Deform(odd, kBilinear);
  EXPECT_LE(DeformedDistance(coarse, on_coarse, fine, on_fine).max, 1e-12);
  EXPECT_LE(DeformedDistance(fine, on_fine, coarse, on_coarse).max, 1e-12);
  EXPECT_LE(DeformedDistance(coarse, on_coarse, odd, on_odd).max, 1e-12);
  EXPECT_LE(DeformedDistance(fine, on_fine, odd, on_odd).max, 1e-12);
}

TEST(MeshTransfer, DistanceBetweenTwoDeformationsIsTheAnalyticOneAtTheNodes) {
  // A is only sampled at its nodes, so it may be anything; B is bilinear on
  // rectangles, so its interpolation is exact and the expected distance is
  // |φ_A − φ_B| at A's nodes.
  const Mesh mesh_a = DistortedRectangle(1.0, 0.5, 10, 4, 0.2, 17);
  const Mesh mesh_b = MeshRectangle(1.0, 0.5, {0.5, 0.25}, 13, 7, 0.0);
  const ShapeDistance distance =
      DeformedDistance(mesh_a, Deform(mesh_a, Bend), mesh_b, Deform(mesh_b, kBilinear));
  double max = -1, sum2 = 0;
  int node = -1;
  for (int n = 0; n < mesh_a.NodeCount(); ++n) {
    const double x = mesh_a.positions(n, 0), y = mesh_a.positions(n, 1);
    const double d = (Bend(x, y) - kBilinear(x, y)).norm();
    sum2 += d * d;
    if (d > max) {
      max = d;
      node = n;
    }
  }
  EXPECT_NEAR(distance.max, max, 1e-12);
  EXPECT_EQ(distance.node, node);
  EXPECT_NEAR(distance.rms, std::sqrt(sum2 / mesh_a.NodeCount()), 1e-12);
  EXPECT_GT(distance.max, 0.1);  // a real difference, not a trivially passing zero
}

TEST(MeshTransfer, PointsOutsideARectangleTakeTheClampedValue) {
  const Mesh mesh = MeshRectangle(1.0, 1.0, {0.5, 0.5}, 5, 5, 0.0);
  const Eigen::MatrixX3d deformed = Deform(mesh, kBilinear);
  Eigen::MatrixX2d at(6, 2);
  Eigen::MatrixX2d nearest(6, 2);
  at << 1.3, 0.5, -0.2, 1.4, 0.25, -7.0, 1e6, 1e6, -0.01, 0.37, 0.5, 1.0 + 1e-13;
  nearest << 1.0, 0.5, 0.0, 1.0, 0.25, 0.0, 1.0, 1.0, 0.0, 0.37, 0.5, 1.0;
  EXPECT_LE(MaxRowDistance(InterpolateDeformed(mesh, deformed, at), Evaluate(kBilinear, nearest)),
            1e-12);
}

// Quarter annulus 1 ≤ r ≤ 2, 0 ≤ θ ≤ π/2, meshed nr × nt: a curved outline
// whose chords leave points of the true part outside the mesh.
Eigen::Vector2d AnnulusNode(int i, int j, int nr, int nt) {
  const double r = 1.0 + static_cast<double>(i) / nr, theta = 0.5 * kPi * j / nt;
  return {r * std::cos(theta), r * std::sin(theta)};
}

TEST(MeshTransfer, PointsOutsideACurvedOutlineTakeTheNearestBoundaryPoint) {
  constexpr int kNr = 6, kNt = 24;
  Mesh mesh;
  mesh.positions.resize((kNr + 1) * (kNt + 1), 3);
  for (int j = 0; j <= kNt; ++j)
    for (int i = 0; i <= kNr; ++i) {
      const Eigen::Vector2d p = AnnulusNode(i, j, kNr, kNt);
      mesh.positions.row(j * (kNr + 1) + i) << p.x(), p.y(), 0.0;
    }
  mesh.quads.resize(kNr * kNt, 4);
  for (int j = 0; j < kNt; ++j)
    for (int i = 0; i < kNr; ++i) {
      const int n = j * (kNr + 1) + i;
      mesh.quads.row(j * kNr + i) << n, n + 1, n + kNr + 2, n + kNr + 1;
    }
  ASSERT_GT(ProjectedArea(mesh), 0);

  // The outline, counter-clockwise: θ = 0 side, outer arc, θ = π/2 side, inner arc.
  std::vector<Eigen::Vector2d> outline;
  for (int i = 0; i < kNr; ++i) outline.push_back(AnnulusNode(i, 0, kNr, kNt));
  for (int j = 0; j < kNt; ++j) outline.push_back(AnnulusNode(kNr, j, kNr, kNt));
  for (int i = kNr; i > 0; --i) outline.push_back(AnnulusNode(i, kNt, kNr, kNt));
  for (int j = kNt; j > 0; --j) outline.push_back(AnnulusNode(0, j, kNr, kNt));
  const auto nearest_on_part = [&](const Eigen::Vector2d& p) {
    bool inside = false;  // crossing number
    Eigen::Vector2d best;
    double best_distance = 1e300;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Eigen::Vector2d a = outline[k], b = outline[(k + 1) % outline.size()];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
        inside = !inside;
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const Eigen::Vector2d q = a + t * (b - a);
      if ((q - p).norm() < best_distance) {
        best_distance = (q - p).norm();
        best = q;
      }
    }
    return inside ? p : best;
  };

  const Eigen::MatrixX2d at = RandomPoints(5000, -3.0, 5.0, -3.0, 5.0, 19);
  Eigen::MatrixX2d nearest(at.rows(), 2);
  int outside = 0;
  for (Eigen::Index k = 0; k < at.rows(); ++k) {
    nearest.row(k) = nearest_on_part(at.row(k).transpose()).transpose();
    if (nearest.row(k) != at.row(k)) ++outside;
  }
  ASSERT_GT(outside, 4000);
  ASSERT_GT(at.rows() - outside, 100);
  // Affine: exact along every edge, so any other nearest point would show.
  EXPECT_LE(MaxRowDistance(InterpolateDeformed(mesh, Deform(mesh, kAffine), at),
                           Evaluate(kAffine, nearest)),
            1e-12);

  // Points between the outer arc and its chords: in the part, off the mesh.
  Eigen::MatrixX2d sliver(kNt, 2), chord_point(kNt, 2);
  for (int j = 0; j < kNt; ++j) {
    const double theta = 0.5 * kPi * (j + 0.5) / kNt;
    sliver.row(j) << 1.9999 * std::cos(theta), 1.9999 * std::sin(theta);
    // The chord's midpoint is the nearest point for a point on its bisector.
    chord_point.row(j) =
        (0.5 * (AnnulusNode(kNr, j, kNr, kNt) + AnnulusNode(kNr, j + 1, kNr, kNt))).transpose();
  }
  EXPECT_LE(MaxRowDistance(InterpolateDeformed(mesh, Deform(mesh, kAffine), sliver),
                           Evaluate(kAffine, chord_point)),
            1e-12);
}

TEST(MeshTransfer, RejectsEmptyMeshesMismatchedRowsAndBadInput) {
  const Mesh mesh = MeshRectangle(1.0, 1.0, {0.5, 0.5}, 3, 2, 0.0);
  const Eigen::MatrixX3d deformed = Deform(mesh, kAffine);
  const Eigen::MatrixX2d at = RandomPoints(3, 0.0, 1.0, 0.0, 1.0, 23);

  std::string message =
      InvalidArgumentMessage([&] { InterpolateDeformed(Mesh{}, Eigen::MatrixX3d(0, 3), at); });
  EXPECT_TRUE(Contains(message, "InterpolateDeformed"));
  EXPECT_TRUE(Contains(message, "mesh is empty"));

  message = InvalidArgumentMessage([&] { InterpolateDeformed(mesh, deformed.topRows(5), at); });
  EXPECT_TRUE(Contains(message, "deformed has 5 rows but mesh has 12 nodes"));

  message =
      InvalidArgumentMessage([&] { DeformedDistance(mesh, deformed, mesh, deformed.topRows(11)); });
  EXPECT_TRUE(Contains(message, "DeformedDistance"));
  EXPECT_TRUE(Contains(message, "deformed_b has 11 rows but mesh_b has 12 nodes"));

  message = InvalidArgumentMessage(
      [&] { DeformedDistance(Mesh{}, Eigen::MatrixX3d(0, 3), mesh, deformed); });
  EXPECT_TRUE(Contains(message, "mesh_a is empty"));

  Mesh broken = mesh;
  broken.quads(4, 2) = 12;
  message = InvalidArgumentMessage([&] { InterpolateDeformed(broken, deformed, at); });
  EXPECT_TRUE(Contains(message, "quad 4 of mesh names node 12, outside 0..11"));

  Eigen::MatrixX2d bad_at = at;
  bad_at(1, 0) = std::nan("");
  message = InvalidArgumentMessage([&] { InterpolateDeformed(mesh, deformed, bad_at); });
  EXPECT_TRUE(Contains(message, "point 1 of `at` is not finite"));

  Eigen::MatrixX3d bad_deformed = deformed;
  bad_deformed(7, 2) = std::numeric_limits<double>::infinity();
  message = InvalidArgumentMessage([&] { DeformedDistance(mesh, bad_deformed, mesh, deformed); });
  EXPECT_TRUE(Contains(message, "row 7 of deformed_a is not finite"));

  EXPECT_EQ(InterpolateDeformed(mesh, deformed, Eigen::MatrixX2d(0, 2)).rows(), 0);
}

// The size the brief asks to be fast: timings are printed, not asserted.
TEST(MeshTransfer, TimesA200x200ReferenceAgainstA100x100Run) {
  const Mesh reference = DistortedRectangle(1.0, 0.5, 200, 200, 0.2, 29);
  const Mesh run = DistortedRectangle(1.0, 0.5, 100, 100, 0.2, 31);
  const Eigen::MatrixX3d on_reference = Deform(reference, Bend);
  const Eigen::MatrixX3d on_run = Deform(run, Bend);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const ShapeDistance forward = DeformedDistance(reference, on_reference, run, on_run);
  const auto middle = Clock::now();
  const ShapeDistance backward = DeformedDistance(run, on_run, reference, on_reference);
  const auto end = Clock::now();
  const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
  std::cout << "200x200 reference (" << reference.NodeCount() << " nodes) on 100x100 run ("
            << run.ElementCount() << " quads): " << ms(middle - start) << " ms, max " << forward.max
            << " m at node " << forward.node << ", rms " << forward.rms << " m\n"
            << "100x100 run (" << run.NodeCount() << " nodes) on 200x200 reference ("
            << reference.ElementCount() << " quads): " << ms(end - middle) << " ms, max "
            << backward.max << " m, rms " << backward.rms << " m\n";
  // Bilinear interpolation error of the bend (curvature 1/R = 2.5 /m) on
  // quads of about 0.01 m × 0.005 m: of order h²/(8R), well under 1e-4 m.
  EXPECT_LT(forward.max, 1e-4);
  EXPECT_LT(backward.max, 1e-4);
}

}  // namespace
}  // namespace drape
