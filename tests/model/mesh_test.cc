#include "core/model/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

namespace drape {
namespace {

// Whether `text` contains `part`, saying both when it does not.
testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

constexpr double kPi = 3.14159265358979323846;

// Quality every Gmsh mesh below must reach. Measured on Debian's Gmsh 4.8.4
// (Frontal-Delaunay + simple full-quad recombination) over these parts and
// element sizes: smallest angle ≥ 41.9°, largest ≤ 138.5°, aspect ratio
// ≤ 2.81 (a finer sweep of sizes: 37°, 139°, 2.8). Poorer settings fail them:
// simple recombination + subdivision gave 29°, 156°, 4.5; Delaunay + Blossom
// full-quad 30°, 175°. The limits leave a margin for other platforms, no more.
constexpr double kMinAngleDeg = 30;
constexpr double kMaxAngleDeg = 150;
constexpr double kMaxAspectRatio = 3.2;

// Twice the signed area of quad e projected on xy, from the positions alone.
double TwiceArea(const Mesh& mesh, int e) {
  double twice = 0;
  for (int k = 0; k < 4; ++k) {
    const auto a = mesh.positions.row(mesh.quads(e, k));
    const auto b = mesh.positions.row(mesh.quads(e, (k + 1) % 4));
    twice += a(0) * b(1) - b(0) * a(1);
  }
  return twice;
}

double ShoelaceArea(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto& a = polygon[i];
    const auto& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

// Edges used by one quad only, as (from, to) in the quads' own direction.
std::vector<std::pair<int, int>> BoundaryEdges(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> count;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      int a = mesh.quads(e, k), b = mesh.quads(e, (k + 1) % 4);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<std::pair<int, int>> edges;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) {
      int a = mesh.quads(e, k), b = mesh.quads(e, (k + 1) % 4);
      if (count[{std::min(a, b), std::max(a, b)}] == 1) edges.emplace_back(a, b);
    }
  return edges;
}

// Structural checks every mesh must pass: indices in range, four distinct
// nodes per quad, every node used, every quad counter-clockwise from +z, all
// nodes at the elevation.
void ExpectWellFormed(const Mesh& mesh, double elevation) {
  ASSERT_GT(mesh.ElementCount(), 0);
  std::vector<int> uses(mesh.NodeCount(), 0);
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    for (int k = 0; k < 4; ++k) {
      ASSERT_GE(mesh.quads(e, k), 0);
      ASSERT_LT(mesh.quads(e, k), mesh.NodeCount());
      ++uses[mesh.quads(e, k)];
      for (int l = 0; l < k; ++l) ASSERT_NE(mesh.quads(e, k), mesh.quads(e, l)) << "quad " << e;
    }
    EXPECT_GT(TwiceArea(mesh, e), 0) << "quad " << e << " is not counter-clockwise from +z";
  }
  EXPECT_EQ(std::count(uses.begin(), uses.end(), 0), 0) << "unused nodes";
  EXPECT_TRUE((mesh.positions.col(2).array() == elevation).all());
}

// Nodes in rows of increasing y, each row in increasing x, and elements
// likewise by centroid: y never decreases by more than a rounding-level
// tolerance, and where y stays within it, x increases.
void ExpectRowMajorNumbering(const Mesh& mesh) {
  const double tol =
      1e-8 * (mesh.positions.colwise().maxCoeff() - mesh.positions.colwise().minCoeff()).norm();
  auto check = [tol](const Eigen::MatrixXd& p, const char* what) {
    for (Eigen::Index i = 1; i < p.rows(); ++i) {
      const bool up = p(i, 1) > p(i - 1, 1);
      const bool along_row = std::abs(p(i, 1) - p(i - 1, 1)) <= tol && p(i, 0) > p(i - 1, 0);
      ASSERT_TRUE(up || along_row) << what << " " << i << " is out of row order";
    }
  };
  check(mesh.positions.leftCols<2>(), "node");
  Eigen::MatrixXd centroids(mesh.ElementCount(), 2);
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    centroids.row(e).setZero();
    for (int k = 0; k < 4; ++k)
      centroids.row(e) += 0.25 * mesh.positions.row(mesh.quads(e, k)).head<2>();
  }
  check(centroids, "element");
}

void ExpectGoodQuality(const Mesh& mesh, const std::string& label) {
  const MeshQuality q = MeasureQuality(mesh);
  std::cout << "[ quality  ] " << label << ": " << mesh.ElementCount() << " quads, angles "
            << q.min_angle_deg << "°–" << q.max_angle_deg << "°, aspect ratio "
            << q.max_aspect_ratio << "\n";
  EXPECT_GT(q.min_angle_deg, kMinAngleDeg) << label;
  EXPECT_LT(q.max_angle_deg, kMaxAngleDeg) << label;
  EXPECT_LT(q.max_aspect_ratio, kMaxAspectRatio) << label;
  EXPECT_GT(q.min_signed_area, 0) << label;
}

void ExpectSameMesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.NodeCount(), b.NodeCount());
  ASSERT_EQ(a.ElementCount(), b.ElementCount());
  EXPECT_TRUE(a.positions == b.positions);  // bitwise
  EXPECT_TRUE(a.quads == b.quads);
}

// Every boundary node lies on some edge of `polygon` (within tol), and every
// polygon vertex is a node.
void ExpectBoundaryOnPolygon(const Mesh& mesh, const std::vector<Eigen::Vector2d>& polygon) {
  const double size =
      1e-9 * (mesh.positions.colwise().maxCoeff() - mesh.positions.colwise().minCoeff()).norm();
  auto distance_to_outline = [&](const Eigen::Vector2d& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (a + t * (b - a) - p).norm());
    }
    return best;
  };
  for (const auto& [a, b] : BoundaryEdges(mesh)) {
    EXPECT_LE(distance_to_outline(mesh.positions.row(a).head<2>()), size) << "node " << a;
  }
  for (const auto& v : polygon) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int n = 0; n < mesh.NodeCount(); ++n)
      nearest = std::min(nearest, (mesh.positions.row(n).head<2>().transpose() - v).norm());
    EXPECT_LE(nearest, size) << "outline vertex (" << v.x() << ", " << v.y() << ") is not a node";
  }
}

std::vector<Eigen::Vector2d> Reversed(std::vector<Eigen::Vector2d> polygon) {
  std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// An L: 2 × 2 square [m] without its upper-right 1 × 1 quarter (area 3).
const std::vector<Eigen::Vector2d> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

// A shirt front panel [m] as a cutter gives it: concave armholes and
// neckline drawn as polylines.
const std::vector<Eigen::Vector2d> kFrontPanel = {{0.00, 0.00},
                                                  {0.50, 0.00},
                                                  {0.50, 0.42},
                                                  {0.47, 0.47},
                                                  {0.45, 0.53},
                                                  {0.445, 0.60},
                                                  {0.44, 0.66},
                                                  {0.34, 0.70},
                                                  {0.31, 0.66},
                                                  {0.28, 0.63},
                                                  {0.25, 0.62},
                                                  {0.22, 0.63},
                                                  {0.19, 0.66},
                                                  {0.16, 0.70},
                                                  {0.06, 0.66},
                                                  {0.055, 0.60},
                                                  {0.05, 0.53},
                                                  {0.03, 0.47},
                                                  {0.00, 0.42}};

// ---------------------------------------------------------------- rectangle

TEST(MeshRectangle, CountsAndNodePositions) {
  const Mesh mesh = MeshRectangle(0.6, 0.4, {1.0, -2.0}, 3, 2, 0.05);
  ASSERT_EQ(mesh.NodeCount(), 12);
  ASSERT_EQ(mesh.ElementCount(), 6);
  // Node (i, j) = j * 4 + i sits at (0.7 + 0.2 i, -2.2 + 0.2 j, 0.05).
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 3; ++i) {
      const int n = j * 4 + i;
      EXPECT_NEAR(mesh.positions(n, 0), 0.7 + 0.2 * i, 1e-15) << n;
      EXPECT_NEAR(mesh.positions(n, 1), -2.2 + 0.2 * j, 1e-15) << n;
      EXPECT_EQ(mesh.positions(n, 2), 0.05) << n;
    }
}

TEST(MeshRectangle, ElementsRowByRowCounterClockwise) {
  const Mesh mesh = MeshRectangle(2, 2, {0, 0}, 2, 2, 0);
  Eigen::Matrix<int, 4, 4> expected;
  expected << 0, 1, 4, 3,  //
      1, 2, 5, 4,          //
      3, 4, 7, 6,          //
      4, 5, 8, 7;
  EXPECT_TRUE(mesh.quads == expected) << mesh.quads;
  ExpectWellFormed(mesh, 0);
  ExpectRowMajorNumbering(mesh);
}

TEST(MeshRectangle, AreaIsTheRectangleAndQuadsAreSquare) {
  for (auto [sx, sy, nx, ny] : {std::tuple{0.37, 0.21, 13, 7},
                                std::tuple{2.0, 0.02, 80, 1},
                                std::tuple{1e-3, 5e3, 3, 101}}) {
    const Mesh mesh = MeshRectangle(sx, sy, {0.3, -0.7}, nx, ny, -1.5);
    EXPECT_EQ(mesh.NodeCount(), (nx + 1) * (ny + 1));
    EXPECT_EQ(mesh.ElementCount(), nx * ny);
    EXPECT_NEAR(ProjectedArea(mesh), sx * sy, 1e-12 * sx * sy);
    ExpectWellFormed(mesh, -1.5);
    const MeshQuality q = MeasureQuality(mesh);
    EXPECT_NEAR(q.min_angle_deg, 90, 1e-6);
    EXPECT_NEAR(q.max_angle_deg, 90, 1e-6);
    const double ratio = (sx / nx) / (sy / ny);
    EXPECT_NEAR(q.max_aspect_ratio, std::max(ratio, 1 / ratio), 1e-6 * std::max(ratio, 1 / ratio));
  }
}

TEST(MeshRectangle, RejectsBadSizesAndCounts) {
  auto message = [](auto make) {
    try {
      make();
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no MeshError");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(Contains(message([] { MeshRectangle(1, 1, {0, 0}, 0, 1, 0); }), "nx = 0"));
  EXPECT_TRUE(Contains(message([] { MeshRectangle(1, 1, {0, 0}, 1, -3, 0); }), "ny = -3"));
  EXPECT_TRUE(Contains(message([] { MeshRectangle(0, 1, {0, 0}, 1, 1, 0); }), "size_x = 0"));
  EXPECT_TRUE(Contains(message([] { MeshRectangle(1, -2, {0, 0}, 1, 1, 0); }), "size_y = -2"));
  EXPECT_TRUE(Contains(message([&] { MeshRectangle(nan, 1, {0, 0}, 1, 1, 0); }), "size_x = nan"));
  EXPECT_TRUE(Contains(message([&] { MeshRectangle(1, inf, {0, 0}, 1, 1, 0); }), "size_y = inf"));
  EXPECT_TRUE(Contains(message([&] { MeshRectangle(1, 1, {nan, 0}, 1, 1, 0); }), "center.x"));
  EXPECT_TRUE(Contains(message([&] { MeshRectangle(1, 1, {0, 0}, 1, 1, inf); }), "elevation"));
  EXPECT_TRUE(Contains(message([] {
                         MeshRectangle(1, 1, {0, 0}, 100000, 100000, 0);
                       }),
                       "node count"));
}

// ------------------------------------------------------- area and quality

TEST(MeshProjectedArea, ClockwiseQuadsCountNegative) {
  Mesh mesh = MeshRectangle(3, 2, {0, 0}, 3, 2, 0);
  EXPECT_NEAR(ProjectedArea(mesh), 6, 1e-12);
  mesh.quads.row(0) = mesh.quads.row(0).reverse().eval();  // one unit quad clockwise
  EXPECT_NEAR(ProjectedArea(mesh), 4, 1e-12);
  EXPECT_NEAR(MeasureQuality(mesh).min_signed_area, -1, 1e-12);
}

Mesh SingleQuad(std::vector<Eigen::Vector2d> corners) {
  Mesh mesh;
  mesh.positions.resize(4, 3);
  for (int k = 0; k < 4; ++k) mesh.positions.row(k) << corners[k].x(), corners[k].y(), 0;
  mesh.quads.resize(1, 4);
  mesh.quads << 0, 1, 2, 3;
  return mesh;
}

TEST(MeshMeasureQuality, TrapezoidAnglesAndAspectRatio) {
  // Base 2, top 1, height 1: base angles atan(1 / 0.5) = 63.43°, top 116.57°;
  // edges 2, √1.25, 1, √1.25; area 1.5.
  const MeshQuality q = MeasureQuality(SingleQuad({{0, 0}, {2, 0}, {1.5, 1}, {0.5, 1}}));
  EXPECT_NEAR(q.min_angle_deg, std::atan(2.0) * 180 / kPi, 1e-9);
  EXPECT_NEAR(q.max_angle_deg, 180 - std::atan(2.0) * 180 / kPi, 1e-9);
  EXPECT_NEAR(q.max_aspect_ratio, 2.0, 1e-12);
  EXPECT_NEAR(q.min_signed_area, 1.5, 1e-12);
  // The same quad numbered clockwise: same angles, negative area.
  const MeshQuality r = MeasureQuality(SingleQuad({{0, 0}, {0.5, 1}, {1.5, 1}, {2, 0}}));
  EXPECT_NEAR(r.min_angle_deg, q.min_angle_deg, 1e-9);
  EXPECT_NEAR(r.max_angle_deg, q.max_angle_deg, 1e-9);
  EXPECT_NEAR(r.min_signed_area, -1.5, 1e-12);
}

TEST(MeshMeasureQuality, ReentrantCornerReadsMoreThan180) {
  // A dart: the corner at (0.5, 1) is re-entrant. Its edges leave at 116.57°
  // and 243.43°, so the interior angle is 360 − 126.87 = 233.13°.
  const MeshQuality q = MeasureQuality(SingleQuad({{0, 0}, {2, 1}, {0, 2}, {0.5, 1}}));
  EXPECT_NEAR(q.max_angle_deg, 360 - 2 * std::atan2(1.0, 0.5) * 180 / kPi, 1e-9);
  EXPECT_GT(q.max_angle_deg, 180);
}

// -------------------------------------------------------------------- disk

// The shortest and longest boundary edges of a mesh.
std::pair<double, double> BoundaryEdgeRange(const Mesh& mesh) {
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (const auto& [a, b] : BoundaryEdges(mesh)) {
    const double length = (mesh.positions.row(a) - mesh.positions.row(b)).norm();
    shortest = std::min(shortest, length);
    longest = std::max(longest, length);
  }
  return {shortest, longest};
}

double MeanEdge(const Mesh& mesh) {
  double sum = 0;
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k)
      sum += (mesh.positions.row(mesh.quads(e, k)) - mesh.positions.row(mesh.quads(e, (k + 1) % 4)))
                 .norm();
  return sum / (4.0 * mesh.ElementCount());
}

TEST(MeshDisk, WellFormedAllQuadsCounterClockwise) {
  const Mesh mesh = MeshDisk(0.5, {0.2, -0.1}, 0.05, 0.3);
  ExpectWellFormed(mesh, 0.3);
  ExpectRowMajorNumbering(mesh);
  // Every boundary edge runs counter-clockwise around the centre.
  for (const auto& [a, b] : BoundaryEdges(mesh)) {
    const Eigen::Vector2d pa =
        mesh.positions.row(a).head<2>().transpose() - Eigen::Vector2d(0.2, -0.1);
    const Eigen::Vector2d pb =
        mesh.positions.row(b).head<2>().transpose() - Eigen::Vector2d(0.2, -0.1);
    EXPECT_GT(pa.x() * pb.y() - pa.y() * pb.x(), 0);
  }
}

TEST(MeshDisk, BoundaryNodesLieOnTheCircle) {
  const double r = 0.5;
  const Mesh mesh = MeshDisk(r, {0.2, -0.1}, 0.05, 0);
  const auto edges = BoundaryEdges(mesh);
  // About 2πr / h boundary edges.
  EXPECT_GT(edges.size(), 0.8 * 2 * kPi * r / 0.05);
  EXPECT_LT(edges.size(), 2.0 * 2 * kPi * r / 0.05);
  for (const auto& [a, b] : edges) {
    const double d = std::hypot(mesh.positions(a, 0) - 0.2, mesh.positions(a, 1) + 0.1);
    EXPECT_NEAR(d, r, 1e-12 * r) << "node " << a;
  }
}

// The mesh is a polygon inscribed in the circle. A chord c subtends
// θ = 2 asin(c / 2r) and misses the segment r²(θ − sin θ)/2 = (r²θ/2)(1 − sin θ/θ);
// (1 − sin θ/θ) grows with θ and Σ θ = 2π, so with the shortest and longest
// chords πr² (1 − sin θ_min / θ_min) ≤ πr² − area ≤ πr² (1 − sin θ_max / θ_max),
// about πr² θ² / 6 with θ ≈ h / r.
TEST(MeshDisk, AreaWithinInscribedPolygonErrorAndConverges) {
  const double r = 0.5;
  auto missing = [r](double chord) {
    const double theta = 2 * std::asin(chord / (2 * r));
    return kPi * r * r * (1 - std::sin(theta) / theta);
  };
  double previous_error = 0;
  for (double h : {0.1, 0.05, 0.025}) {
    const Mesh mesh = MeshDisk(r, {0.2, -0.1}, h, 0);
    const auto [c_min, c_max] = BoundaryEdgeRange(mesh);
    EXPECT_LT(c_max, 1.5 * h);
    const double error = kPi * r * r - ProjectedArea(mesh);
    std::cout << "[ disk area] h = " << h << ": error " << error << " in [" << missing(c_min)
              << ", " << missing(c_max) << "]\n";
    EXPECT_GT(error, 0);
    // Gmsh spaces the arcs' nodes evenly, so the bounds nearly meet: allow rounding.
    EXPECT_GE(error, missing(c_min) * (1 - 1e-6));
    EXPECT_LE(error, missing(c_max) * (1 + 1e-6));
    // Second order in h: halving h divides the error by about 4.
    if (previous_error > 0) {
      EXPECT_LT(error, previous_error / 2.5);
    }
    previous_error = error;
  }
}

TEST(MeshDisk, QualityAcrossElementSizes) {
  for (double h : {0.3, 0.2, 0.13, 0.1, 0.07, 0.05, 0.031, 0.02}) {
    const Mesh mesh = MeshDisk(1.0, {0, 0}, h, 0);
    ExpectGoodQuality(mesh, "disk r = 1, h = " + std::to_string(h));
    // Edges follow element_size. Gmsh's full-quad mode gives each quarter
    // arc (length L) 4·ceil(L / 4h) segments, so a coarse disk comes out finer.
    const double mean = MeanEdge(mesh);
    std::cout << "[ edges    ] mean edge / h = " << mean / h << "\n";
    EXPECT_LT(mean, 1.1 * h);
    EXPECT_GT(mean, (h <= 0.05 ? 0.8 : 0.45) * h);
  }
}

TEST(MeshDisk, RepeatedCallsGiveIdenticalMeshes) {
  const Mesh first = MeshDisk(0.3, {0.01, 0.02}, 0.03, 0.1);
  const Mesh other = MeshPolygon(kL, 0.2, 0);  // Gmsh's state changes in between
  const Mesh second = MeshDisk(0.3, {0.01, 0.02}, 0.03, 0.1);
  ExpectSameMesh(first, second);
}

TEST(MeshDisk, ConcurrentCallsAreSerialised) {
  const Mesh reference = MeshDisk(0.3, {0, 0}, 0.04, 0);
  std::vector<Mesh> meshes(4);
  std::vector<std::thread> threads;
  for (auto& mesh : meshes)
    threads.emplace_back([&mesh] { mesh = MeshDisk(0.3, {0, 0}, 0.04, 0); });
  for (auto& thread : threads) thread.join();
  for (const auto& mesh : meshes) ExpectSameMesh(reference, mesh);
}

TEST(MeshDisk, RejectsBadInput) {
  auto message = [](double radius, double size, double elevation = 0) {
    try {
      MeshDisk(radius, {0, 0}, size, elevation);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no MeshError");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(Contains(message(0, 0.1), "radius = 0"));
  EXPECT_TRUE(Contains(message(-1, 0.1), "radius = -1"));
  EXPECT_TRUE(Contains(message(nan, 0.1), "radius = nan"));
  EXPECT_TRUE(Contains(message(1, 0), "element_size = 0"));
  EXPECT_TRUE(Contains(message(1, -0.1), "element_size = -0.1"));
  EXPECT_TRUE(Contains(message(1, inf), "element_size = inf"));
  EXPECT_TRUE(Contains(message(1, 0.1, nan), "elevation"));
  // π / 1e-6 ≈ 3 million elements: too many.
  EXPECT_TRUE(Contains(message(1, 1e-3), "element_size = 0.001"));
  EXPECT_THROW(MeshDisk(1, {inf, 0}, 0.1, 0), MeshError);
}

// ----------------------------------------------------------------- polygon

TEST(MeshPolygon, LShapeEitherOrientation) {
  for (const auto& outline : {kL, Reversed(kL)}) {
    const Mesh mesh = MeshPolygon(outline, 0.1, -0.2);
    ExpectWellFormed(mesh, -0.2);
    ExpectRowMajorNumbering(mesh);
    ExpectBoundaryOnPolygon(mesh, outline);
    EXPECT_NEAR(ProjectedArea(mesh), 3.0, 1e-9 * 3.0);
    ExpectGoodQuality(mesh, "L, h = 0.1");
  }
}

TEST(MeshPolygon, CuttingPatternEitherOrientation) {
  const double area = ShoelaceArea(kFrontPanel);
  ASSERT_GT(area, 0);
  for (const auto& outline : {kFrontPanel, Reversed(kFrontPanel)}) {
    for (double h : {0.05, 0.02, 0.01}) {
      const Mesh mesh = MeshPolygon(outline, h, 0.75);
      ExpectWellFormed(mesh, 0.75);
      ExpectRowMajorNumbering(mesh);
      ExpectBoundaryOnPolygon(mesh, outline);
      EXPECT_NEAR(ProjectedArea(mesh), area, 1e-9 * area);
      ExpectGoodQuality(mesh, "front panel, h = " + std::to_string(h));
    }
  }
}

TEST(MeshPolygon, QualityOfTheLAcrossElementSizes) {
  for (double h : {0.3, 0.2, 0.13, 0.07, 0.05, 0.031, 0.02}) {
    const Mesh mesh = MeshPolygon(kL, h, 0);
    ExpectGoodQuality(mesh, "L, h = " + std::to_string(h));
    EXPECT_NEAR(ProjectedArea(mesh), 3.0, 1e-9 * 3.0);
  }
}

TEST(MeshPolygon, RepeatedCallsGiveIdenticalMeshes) {
  ExpectSameMesh(MeshPolygon(kFrontPanel, 0.02, 0), MeshPolygon(kFrontPanel, 0.02, 0));
}

TEST(MeshPolygon, RejectsBadOutlines) {
  auto message = [](const std::vector<Eigen::Vector2d>& outline, double size = 0.1) {
    try {
      MeshPolygon(outline, size, 0);
    } catch (const MeshError& e) {
      return std::string(e.what());
    }
    return std::string("no MeshError");
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(Contains(message({{0, 0}, {1, 0}}), "at least 3 vertices"));
  EXPECT_TRUE(Contains(message({}), "at least 3 vertices"));
  // Closed (last == first) and a vertex visited twice.
  EXPECT_TRUE(Contains(message({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}), "same point"));
  EXPECT_TRUE(Contains(message({{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}), "same point"));
  // A bow tie, a vertex touching another edge, a spike folding back.
  EXPECT_TRUE(Contains(message({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), "intersect"));
  EXPECT_TRUE(Contains(message({{0, 0}, {2, 0}, {2, 2}, {1, 0}, {0, 2}}), "intersect"));
  EXPECT_TRUE(Contains(message({{0, 0}, {2, 0}, {1, 0}, {1, 1}}), "folds back"));
  // All on one line.
  EXPECT_TRUE(Contains(message({{0, 0}, {1, 0}, {2, 0}}), "folds back"));
  EXPECT_TRUE(Contains(message({{0, 0}, {1, nan}, {0, 1}}), "outline[1].y"));
  // Bad element sizes.
  EXPECT_TRUE(Contains(message(kL, 0), "element_size = 0"));
  EXPECT_TRUE(Contains(message(kL, -1), "element_size = -1"));
  EXPECT_TRUE(Contains(message(kL, 1e-3), "element_size = 0.001"));  // 3 million elements
}

TEST(MeshPolygon, NarrowNeckGivesValidQuadsOrNamesTheGap) {
  // A notch whose tip comes within `gap` of the bottom edge. Far below the
  // element size Gmsh cannot quad-mesh the neck; whatever it makes must be
  // strictly convex quads, or the call fails saying where the outline is narrow.
  for (double gap : {0.05, 0.01, 0.003, 1e-4}) {
    for (double h : {0.1, 0.03}) {
      const std::vector<Eigen::Vector2d> notch = {{0, 0}, {1, 0}, {1, 1}, {0.5, gap}, {0, 1}};
      try {
        const Mesh mesh = MeshPolygon(notch, h, 0);
        ExpectWellFormed(mesh, 0);
        EXPECT_LT(MeasureQuality(mesh).max_angle_deg, 180) << "gap " << gap << ", h " << h;
        EXPECT_NEAR(ProjectedArea(mesh), ShoelaceArea(notch), 1e-9);
      } catch (const MeshError& e) {
        EXPECT_LT(gap, 0.01) << e.what();
        EXPECT_TRUE(Contains(e.what(), "narrowest gap is"));
        EXPECT_TRUE(Contains(e.what(), "(vertex 3 to edge 0 (vertices 0-1))"));
      }
    }
  }
}

TEST(MeshPolygon, AcceptsStraightAnglesAndSlivers) {
  // A collinear vertex on an edge and a thin notch are legal simple polygons.
  const std::vector<Eigen::Vector2d> notched = {
      {0, 0}, {1, 0}, {2, 0}, {2, 1}, {1.02, 1}, {1.01, 0.5}, {1.0, 1}, {0, 1}};
  const Mesh mesh = MeshPolygon(notched, 0.1, 0);
  ExpectWellFormed(mesh, 0);
  EXPECT_NEAR(ProjectedArea(mesh), ShoelaceArea(notched), 1e-9 * ShoelaceArea(notched));
}

}  // namespace
}  // namespace drape
