#include "core/model/obstacle_geometry.h"

#include "core/model/scene_error.h"
#include "core/model/triangle_mesh_geometry.h"
#include "support/test_paths.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace drape {
namespace {

namespace fs = std::filesystem;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Rng = std::mt19937_64;
using Faces = std::vector<std::vector<int>>;  // 0-based vertex indices, counter-clockwise outside

std::unique_ptr<ObstacleGeometry> Make(const ObstacleShape& shape) {
  return MakeObstacleGeometry(Obstacle{"test", shape}, {});
}

double Uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
Vector3d UnitVector(Rng& rng) {
  std::normal_distribution<double> normal;
  return Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}
Vector3d InBox(Rng& rng, const Vector3d& lo, const Vector3d& hi) {
  return {Uniform(rng, lo.x(), hi.x()), Uniform(rng, lo.y(), hi.y()), Uniform(rng, lo.z(), hi.z())};
}
// Two unit vectors completing `axis` to a right-handed frame.
std::pair<Vector3d, Vector3d> Frame(const Vector3d& axis) {
  const Vector3d u = axis.unitOrthogonal();
  return {u, axis.cross(u)};
}

// The normal must be the gradient of the distance and the Hessian the
// gradient of the normal, by central differences; the step is far below the
// samplers' 1e-2 margin to the surfaces where d is not C², so both sides of
// every difference are in the same region.
::testing::AssertionResult DerivativesMatch(const ObstacleGeometry& g, const Vector3d& x) {
  constexpr double kStep = 1e-6;
  const DistanceQuery q = g.Query(x);
  Vector3d normal_fd;
  Matrix3d hessian_fd;
  for (int k = 0; k < 3; ++k) {
    const Vector3d step = kStep * Vector3d::Unit(k);
    const DistanceQuery plus = g.Query(x + step), minus = g.Query(x - step);
    normal_fd[k] = (plus.distance - minus.distance) / (2 * kStep);
    hessian_fd.col(k) = (plus.normal - minus.normal) / (2 * kStep);
  }
  const double scale = std::max(1.0, q.hessian.norm());
  std::ostringstream why;
  if (std::abs(q.normal.norm() - 1.0) > 1e-12) why << "|normal| = " << q.normal.norm() << "; ";
  if ((q.hessian - q.hessian.transpose()).norm() > 1e-12 * scale) why << "hessian not symmetric; ";
  if ((normal_fd - q.normal).norm() > 1e-6) {
    why << "normal " << q.normal.transpose() << " but FD " << normal_fd.transpose() << "; ";
  }
  if ((hessian_fd - q.hessian).norm() > 1e-6 * scale) {
    why << "hessian\n" << q.hessian << "\nbut FD\n" << hessian_fd << "\n";
  }
  if (why.str().empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "at x = " << x.transpose() << " (d = " << q.distance << "): " << why.str();
}

// A sampler returns a point in one region of a shape, or nothing to reject.
using Sampler = std::function<std::optional<Vector3d>(Rng&)>;

// Checks `count` points of each named region, and that inside and outside
// both occur over all of them when `expect_both_signs`.
void CheckDerivatives(const ObstacleGeometry& g,
                      const std::vector<std::pair<std::string, Sampler>>& regions,
                      bool expect_both_signs = true,
                      int count = 100) {
  Rng rng(12345);
  int inside = 0, outside = 0;
  for (const auto& [name, sample] : regions) {
    SCOPED_TRACE(name);
    for (int accepted = 0, tries = 0; accepted < count; ++tries) {
      ASSERT_LT(tries, 100 * count) << "sampler rejects nearly everything";
      const std::optional<Vector3d> x = sample(rng);
      if (!x) continue;
      ++accepted;
      EXPECT_TRUE(DerivativesMatch(g, *x));
      (g.Query(*x).distance < 0 ? inside : outside)++;
    }
  }
  if (expect_both_signs) {
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);
  }
}

void ExpectQuery(const DistanceQuery& q,
                 double distance,
                 const Vector3d& normal,
                 double tolerance = 1e-12) {
  EXPECT_NEAR(q.distance, distance, tolerance);
  EXPECT_LT((q.normal - normal).norm(), tolerance)
      << q.normal.transpose() << " vs " << normal.transpose();
}

// ---- files ------------------------------------------------------------------

// A directory of its own per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("drape-mesh-" + std::to_string(getpid()) + "-" +
                                         info->test_suite_name() + "-" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  fs::path Write(const std::string& name, const std::string& content) const {
    const fs::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string ObjText(const std::vector<Vector3d>& vertices, const Faces& faces) {
  std::ostringstream out;
  out.precision(17);
  for (const Vector3d& v : vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
  for (const auto& face : faces) {
    out << "f";
    for (int i : face) out << " " << i + 1;
    out << "\n";
  }
  return out.str();
}

std::string BinaryStl(const std::vector<Vector3d>& vertices, const Faces& triangles) {
  std::string bytes(80, ' ');
  // Binary files that start like ASCII ones exist; the size must decide.
  std::memcpy(bytes.data(), "solid binary", 12);
  const std::uint32_t count = static_cast<std::uint32_t>(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : triangles) {
    float values[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = static_cast<float>(vertices[t[k]][c]);
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    bytes.append(2, '\0');
  }
  return bytes;
}

// ---- test meshes ------------------------------------------------------------

struct TestMesh {
  std::vector<Vector3d> vertices;
  Faces faces;
};

// |x| + |y| + |z| = 1.
TestMesh Octahedron() {
  TestMesh m;
  for (int k = 0; k < 3; ++k) {
    m.vertices.push_back(Vector3d::Unit(k));
    m.vertices.push_back(-Vector3d::Unit(k));
  }
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const int a = sx, b = 2 + sy, c = 4 + sz;  // +x or −x, ...
        // Odd number of minus signs: (x, y, z) runs clockwise seen from outside.
        if ((sx + sy + sz) % 2 == 0)
          m.faces.push_back({a, b, c});
        else
          m.faces.push_back({a, c, b});
      }
  return m;
}

// The surface of a union of unit voxels, as quads, each square of the grid
// its own face.
TestMesh VoxelSurface(const std::vector<std::array<int, 3>>& voxels) {
  TestMesh m;
  std::map<std::array<int, 3>, int> index;
  auto vertex = [&](std::array<int, 3> p) {
    const auto [it, inserted] = index.try_emplace(p, static_cast<int>(m.vertices.size()));
    if (inserted) m.vertices.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  auto filled = [&](std::array<int, 3> p) {
    return std::find(voxels.begin(), voxels.end(), p) != voxels.end();
  };
  for (const auto& v : voxels)
    for (int a = 0; a < 3; ++a)
      for (int s : {-1, 1}) {
        std::array<int, 3> neighbour = v;
        neighbour[a] += s;
        if (filled(neighbour)) continue;
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        std::array<int, 3> p0 = v;
        if (s > 0) p0[a] += 1;
        std::array<int, 3> p1 = p0, p2 = p0, p3 = p0;
        p1[b] += 1;
        p2[b] += 1;
        p2[c] += 1;
        p3[c] += 1;
        // e_b × e_c = e_a: counter-clockwise seen from +a.
        if (s > 0)
          m.faces.push_back({vertex(p0), vertex(p1), vertex(p2), vertex(p3)});
        else
          m.faces.push_back({vertex(p0), vertex(p3), vertex(p2), vertex(p1)});
      }
  return m;
}

Faces Triangulated(const Faces& faces) {
  Faces triangles;
  for (const auto& f : faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) triangles.push_back({f[0], f[k], f[k + 1]});
  return triangles;
}

// An icosahedron subdivided `levels` times, on the sphere of `radius` about 0.
TestMesh Icosphere(int levels, double radius) {
  TestMesh m;
  const double phi = (1 + std::sqrt(5.0)) / 2;
  for (double s : {-1.0, 1.0})
    for (double t : {-1.0, 1.0}) {
      m.vertices.emplace_back(0, s, t * phi);
      m.vertices.emplace_back(s, t * phi, 0);
      m.vertices.emplace_back(t * phi, 0, s);
    }
  for (auto& v : m.vertices) v.normalize();
  // The 20 faces: the triples of mutually nearest vertices.
  double shortest = 10;
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      shortest = std::min(shortest, (m.vertices[i] - m.vertices[j]).norm());
  auto near = [&](int i, int j) {
    return (m.vertices[i] - m.vertices[j]).norm() < shortest * 1.01;
  };
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k)
        if (near(i, j) && near(j, k) && near(i, k)) m.faces.push_back({i, j, k});
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return it->second;
    };
    Faces finer;
    for (const auto& f : m.faces) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({ab, f[1], bc});
      finer.push_back({ca, bc, f[2]});
      finer.push_back({ab, bc, ca});
    }
    m.faces = std::move(finer);
  }
  for (auto& f : m.faces) {
    const Vector3d &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    if ((b - a).cross(c - a).dot(a + b + c) < 0) std::swap(f[1], f[2]);
  }
  for (auto& v : m.vertices) v *= radius;
  return m;
}

// The face normals of `m` (planar faces).
std::vector<Vector3d> FaceNormals(const TestMesh& m) {
  std::vector<Vector3d> normals;
  for (const auto& f : m.faces)
    normals.push_back((m.vertices[f[1]] - m.vertices[f[0]])
                          .cross(m.vertices[f[2]] - m.vertices[f[0]])
                          .normalized());
  return normals;
}

// ---- analytic shapes --------------------------------------------------------

TEST(ObstacleGeometry, PlaneDistanceAndDerivatives) {
  const Vector3d point(0.1, -0.2, 0.3), normal = Vector3d(1, 2, 2) / 3;
  const auto g = Make(PlaneShape{{0.1, -0.2, 0.3}, {1.0 / 3, 2.0 / 3, 2.0 / 3}});
  Rng rng(1);
  for (int i = 0; i < 20; ++i) {
    const Vector3d x = InBox(rng, Vector3d::Constant(-1), Vector3d::Constant(1));
    ExpectQuery(g->Query(x), normal.dot(x - point), normal);
    EXPECT_EQ(g->Query(x).hessian, Matrix3d::Zero());
  }
  CheckDerivatives(*g, {{"anywhere", [](Rng& r) -> std::optional<Vector3d> {
                           return InBox(r, Vector3d::Constant(-1), Vector3d::Constant(1));
                         }}});
}

TEST(ObstacleGeometry, SphereDistanceAndDerivatives) {
  const Vector3d center(0.1, 0.2, -0.3);
  const double radius = 0.5;
  const auto g = Make(SphereShape{{0.1, 0.2, -0.3}, radius});
  ExpectQuery(g->Query(center + Vector3d(0, 0.3, 0.4)), 0.0, Vector3d(0, 0.6, 0.8));
  ExpectQuery(g->Query(center + Vector3d(2, 0, 0)), 1.5, Vector3d::UnitX());
  ExpectQuery(g->Query(center + Vector3d(0, -0.1, 0)), -0.4, -Vector3d::UnitY());
  // Away from the centre, where the normal is undefined.
  CheckDerivatives(*g, {{"around", [&](Rng& r) -> std::optional<Vector3d> {
                           return center + Uniform(r, 0.1, 1.5) * UnitVector(r);
                         }}});
}

TEST(ObstacleGeometry, InfiniteCylinderDerivatives) {
  const Vector3d point(0.2, -0.1, 0.4), axis = Vector3d(1, 1, 0).normalized();
  const auto g = Make(CylinderShape{{0.2, -0.1, 0.4}, {axis.x(), axis.y(), axis.z()}, 0.3, {}});
  const auto [u, w] = Frame(axis);
  ExpectQuery(g->Query(point + 5 * axis + 0.7 * u), 0.4, u);
  ExpectQuery(g->Query(point - 3 * axis - 0.1 * w), -0.2, -w);
  CheckDerivatives(*g, {{"around", [&](Rng& r) -> std::optional<Vector3d> {
                           const double angle = Uniform(r, 0, 2 * std::numbers::pi);
                           return point + Uniform(r, -2, 2) * axis +
                                  Uniform(r, 0.05, 1.0) *
                                      (std::cos(angle) * u + std::sin(angle) * w);
                         }}});
}

// A tilted finite cylinder, sampled in (t along the axis, ρ from it).
TEST(ObstacleGeometry, FiniteCylinderDerivativesBySideCapAndRim) {
  const Vector3d point(0.1, 0, 0.2), axis = Vector3d(0.2, -0.3, 1).normalized();
  const double radius = 0.3, half = 0.4, m = 1e-2;
  const auto g =
      Make(CylinderShape{{0.1, 0, 0.2}, {axis.x(), axis.y(), axis.z()}, radius, 2 * half});
  const auto [u, w] = Frame(axis);
  auto at = [&](Rng& r, double t, double rho) -> std::optional<Vector3d> {
    const double angle = Uniform(r, 0, 2 * std::numbers::pi);
    const double sign = Uniform(r, -1, 1) < 0 ? -1 : 1;
    return point + sign * t * axis + rho * (std::cos(angle) * u + std::sin(angle) * w);
  };
  CheckDerivatives(
      *g,
      {{"side outside",
        [&](Rng& r) { return at(r, Uniform(r, 0, half - m), Uniform(r, radius + m, 3 * radius)); }},
       {"cap outside",
        [&](Rng& r) { return at(r, Uniform(r, half + m, 3 * half), Uniform(r, m, radius - m)); }},
       {"rim",
        [&](Rng& r) {
          return at(r, Uniform(r, half + m, 3 * half), Uniform(r, radius + m, 3 * radius));
        }},
       {"side inside",
        [&](Rng& r) -> std::optional<Vector3d> {
          const double t = Uniform(r, 0, half), rho = Uniform(r, 0.05, radius - m);
          if ((rho - radius) - (t - half) < m) return std::nullopt;
          return at(r, t, rho);
        }},
       {"cap inside", [&](Rng& r) -> std::optional<Vector3d> {
          const double t = Uniform(r, 0, half - m), rho = Uniform(r, 0.05, radius);
          if ((t - half) - (rho - radius) < m) return std::nullopt;
          return at(r, t, rho);
        }}});
}

TEST(ObstacleGeometry, FiniteCylinderClosedForm) {
  const auto g = Make(CylinderShape{{0, 0, 0}, {0, 0, 1}, 0.3, 0.8});
  ExpectQuery(g->Query({0, 0.5, 0.1}), 0.2, Vector3d::UnitY());
  ExpectQuery(g->Query({0.1, 0, -0.6}), 0.2, -Vector3d::UnitZ());
  ExpectQuery(g->Query({0.1, 0, 0.3}), -0.1, Vector3d::UnitZ());
  // Rim: 0.2 beyond the side, 0.3 beyond the cap.
  const DistanceQuery rim = g->Query({0.5, 0, 0.7});
  const double d = std::sqrt(0.13);
  ExpectQuery(rim, d, Vector3d(0.2, 0, 0.3) / d);
  // Along the rim circle the normal turns as on a torus of tube radius d
  // about a circle of radius 0.3 seen from ρ = 0.5: (1 − 0.3/0.5)/d.
  EXPECT_NEAR(rim.hessian(1, 1), 0.4 / d, 1e-12);
}

// Box [0,1]×[0,0.8]×[0,0.6] with edges rounded by 0.1, sampled by q, the
// excess over the inner box's half-widths (0.4, 0.3, 0.2) per axis.
TEST(ObstacleGeometry, RoundedBoxDerivativesByFaceEdgeCornerAndInside) {
  const double r = 0.1, m = 1e-2;
  const auto g = Make(BoxShape{{0, 0, 0}, {1, 0.8, 0.6}, r});
  const Vector3d center(0.5, 0.4, 0.3), inner(0.4, 0.3, 0.2);
  // `beyond` random axes get q in [m, 0.3] (inside the rounding when
  // q < r), the others stay m inside the inner box's slab.
  auto region = [&](int beyond) {
    return [=](Rng& rng) -> std::optional<Vector3d> {
      std::array<int, 3> axes{0, 1, 2};
      std::shuffle(axes.begin(), axes.end(), rng);
      Vector3d x;
      for (int i = 0; i < 3; ++i) {
        const int k = axes[i];
        const double a =
            i < beyond ? inner[k] + Uniform(rng, m, 0.3) : Uniform(rng, 0, inner[k] - m);
        x[k] = center[k] + (Uniform(rng, -1, 1) < 0 ? -a : a);
      }
      return x;
    };
  };
  CheckDerivatives(*g,
                   {{"face", region(1)},
                    {"edge", region(2)},
                    {"corner", region(3)},
                    {"inner box", [&](Rng& rng) -> std::optional<Vector3d> {
                       const Vector3d x = InBox(rng, center - inner, center + inner);
                       std::array<double, 3> q;
                       for (int k = 0; k < 3; ++k) q[k] = std::abs(x[k] - center[k]) - inner[k];
                       std::sort(q.begin(), q.end());
                       if (q[2] - q[1] < m) return std::nullopt;  // the medial surface
                       return x;
                     }}});
}

TEST(ObstacleGeometry, RoundedBoxClosedForm) {
  // Inner box [0.1, 0.9]³.
  const auto g = Make(BoxShape{{0, 0, 0}, {1, 1, 1}, 0.1});
  ExpectQuery(g->Query({0.5, 0.5, 1.3}), 0.3, Vector3d::UnitZ());
  ExpectQuery(
      g->Query({1.5, 1.5, 0.5}), 0.6 * std::sqrt(2.0) - 0.1, Vector3d(1, 1, 0).normalized());
  ExpectQuery(
      g->Query({1.2, 1.3, 1.4}), std::sqrt(0.5) - 0.1, Vector3d(0.3, 0.4, 0.5).normalized());
  ExpectQuery(g->Query({0.5, 0.5, 0.8}), -0.2, Vector3d::UnitZ());
  ExpectQuery(g->Query({0.5, 0.05, 0.5}), -0.05, -Vector3d::UnitY());
  // Inside the sharp box but outside the rounded corner.
  ExpectQuery(
      g->Query({0.98, 0.98, 0.98}), 0.08 * std::sqrt(3.0) - 0.1, Vector3d::Ones().normalized());
  const DistanceQuery edge = g->Query({1.5, 1.5, 0.5});
  const double rho = 0.6 * std::sqrt(2.0);
  EXPECT_NEAR(edge.hessian(2, 2), 0.0, 1e-12);
  EXPECT_NEAR(edge.hessian(0, 0), 0.5 / rho, 1e-12);
  EXPECT_NEAR(edge.hessian(0, 1), -0.5 / rho, 1e-12);
}

TEST(ObstacleGeometry, MeshShapeUsesResolvedPath) {
  const fs::path cube = test::SourceDir() / "resources" / "forms" / "unit-cube.stl";
  // The resolved path wins over the scene directory.
  const auto resolved =
      MakeObstacleGeometry(Obstacle{"form", MeshShape{"cube.stl", cube.string()}}, "/no/such/dir");
  ExpectQuery(resolved->Query({0.5, 0.5, 1.25}), 0.25, Vector3d::UnitZ());
  // Without it, the file is relative to the scene.
  const auto relative =
      MakeObstacleGeometry(Obstacle{"form", MeshShape{"unit-cube.stl", ""}}, cube.parent_path());
  ExpectQuery(relative->Query({0.5, 0.5, 0.75}), -0.25, Vector3d::UnitZ());
}

TEST(ObstacleGeometry, MeshShapeErrorNamesObstacle) {
  try {
    MakeObstacleGeometry(
        Obstacle{"mannequin", MeshShape{"gone.obj", ""}}, "/no/such/dir", "obstacles[3]");
    ADD_FAILURE() << "no SceneError";
  } catch (const SceneError& error) {
    EXPECT_EQ(error.where(), "obstacles[3].mesh.file");
    EXPECT_NE(error.message().find("cannot read"), std::string::npos) << error.message();
    EXPECT_NE(error.message().find("/no/such/dir/gone.obj"), std::string::npos) << error.message();
  }
}

// ---- triangle meshes --------------------------------------------------------

// A point of a region of a convex polytope and what the query must give there.
struct Expected {
  Vector3d x;
  double distance;
  Vector3d normal;
};

// Outside a convex polytope, x = c + s·m with m inside the normal cone at
// the boundary point c has closest point c, so d = s and ∇d = m; m a margin
// inside the cone keeps x away from the other regions. Inside, d is the
// largest of the face planes' distances, away from where two tie.
class ConvexRegions {
 public:
  explicit ConvexRegions(const TestMesh& mesh) : mesh_(mesh), normals_(FaceNormals(mesh)) {}

  Expected Face(Rng& rng) const {
    const int f = Pick(rng, mesh_.faces.size());
    Vector3d w;
    do {
      w = InBox(rng, Vector3d::Zero(), Vector3d::Ones());
      w /= w.sum();
    } while (w.minCoeff() < 0.1);
    const auto& face = mesh_.faces[f];
    const Vector3d c = w[0] * V(face[0]) + w[1] * V(face[1]) + w[2] * V(face[2]);
    const double s = Uniform(rng, kMargin, 1);
    return {c + s * normals_[f], s, normals_[f]};
  }

  Expected Edge(Rng& rng) const {
    const int f = Pick(rng, mesh_.faces.size()), k = Pick(rng, 3);
    const int a = mesh_.faces[f][k], b = mesh_.faces[f][(k + 1) % 3];
    int other = -1;
    for (std::size_t g = 0; g < mesh_.faces.size(); ++g) {
      const auto& face = mesh_.faces[g];
      if (static_cast<int>(g) != f && std::count(face.begin(), face.end(), a) &&
          std::count(face.begin(), face.end(), b))
        other = static_cast<int>(g);
    }
    const double alpha = Uniform(rng, 0.15, 0.85);
    const Vector3d m = (alpha * normals_[f] + (1 - alpha) * normals_[other]).normalized();
    const double s = Uniform(rng, kMargin, 1);
    return {V(a) + Uniform(rng, 0.1, 0.9) * (V(b) - V(a)) + s * m, s, m};
  }

  Expected Vertex(Rng& rng) const {
    const int f = Pick(rng, mesh_.faces.size());
    const int v = mesh_.faces[f][Pick(rng, 3)];
    Vector3d m = Vector3d::Zero();
    for (std::size_t g = 0; g < mesh_.faces.size(); ++g) {
      const auto& face = mesh_.faces[g];
      if (std::count(face.begin(), face.end(), v)) m += Uniform(rng, 0.2, 1) * normals_[g];
    }
    m.normalize();
    const double s = Uniform(rng, kMargin, 1);
    return {V(v) + s * m, s, m};
  }

  std::optional<Expected> Inside(Rng& rng) const {
    Eigen::AlignedBox3d box;
    for (const Vector3d& v : mesh_.vertices) box.extend(v);
    const Vector3d x = InBox(rng, box.min(), box.max());
    std::vector<std::pair<double, int>> planes;
    for (std::size_t f = 0; f < normals_.size(); ++f)
      planes.emplace_back(normals_[f].dot(x - V(mesh_.faces[f][0])), static_cast<int>(f));
    std::sort(planes.rbegin(), planes.rend());
    // The medial surface, where two planes tie; d changes by at most 2|Δx| between planes,
    // so a 1e-3 gap is far more than the FD steps cross.
    if (planes[0].first >= 0 || planes[0].first - planes[1].first < 1e-3) return std::nullopt;
    return Expected{x, planes[0].first, normals_[planes[0].second]};
  }

  // The regions as point samplers for CheckDerivatives (CheckDistances
  // checks d and ∇d themselves).
  std::vector<std::pair<std::string, Sampler>> Samplers() const {
    auto points = [](auto sample) -> Sampler {
      return [=](Rng& rng) -> std::optional<Vector3d> {
        const std::optional<Expected> e = sample(rng);
        if (!e) return std::nullopt;
        return e->x;
      };
    };
    return {{"face", points([this](Rng& r) { return std::optional(Face(r)); })},
            {"edge", points([this](Rng& r) { return std::optional(Edge(r)); })},
            {"vertex", points([this](Rng& r) { return std::optional(Vertex(r)); })},
            {"inside", points([this](Rng& r) { return Inside(r); })}};
  }

  void CheckDistances(const ObstacleGeometry& g, int count = 300) const {
    Rng rng(99);
    for (int i = 0; i < count; ++i) {
      for (const Expected& e : {Face(rng), Edge(rng), Vertex(rng)}) {
        SCOPED_TRACE(::testing::Message() << "x = " << e.x.transpose());
        ExpectQuery(g.Query(e.x), e.distance, e.normal, 1e-12);
      }
      if (const std::optional<Expected> e = Inside(rng)) {
        SCOPED_TRACE(::testing::Message() << "inside, x = " << e->x.transpose());
        ExpectQuery(g.Query(e->x), e->distance, e->normal, 1e-12);
      }
    }
  }

 private:
  static constexpr double kMargin = 2e-2;
  static int Pick(Rng& rng, std::size_t n) {
    return std::uniform_int_distribution<int>(0, static_cast<int>(n) - 1)(rng);
  }
  const Vector3d& V(int i) const { return mesh_.vertices[i]; }

  const TestMesh& mesh_;
  std::vector<Vector3d> normals_;
};

TEST(TriangleMesh, OctahedronDerivativesByFaceEdgeVertexAndInside) {
  const TempDir dir;
  const TestMesh octahedron = Octahedron();
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("octahedron.obj", ObjText(octahedron.vertices, octahedron.faces)), "test");
  const ConvexRegions regions(octahedron);
  CheckDerivatives(*g, regions.Samplers());
  regions.CheckDistances(*g);

  const double s3 = std::sqrt(3.0);
  ExpectQuery(g->Query({0.1, 0.2, 0.3}), (0.6 - 1) / s3, Vector3d::Ones() / s3);
  ExpectQuery(g->Query({1, 1, 1}), 2 / s3, Vector3d::Ones() / s3);
  ExpectQuery(g->Query({0.8, 0.8, 0}), std::sqrt(0.18), Vector3d(1, 1, 0).normalized());
  ExpectQuery(g->Query({0, 0, -1.5}), 0.5, -Vector3d::UnitZ());
  // Edge and vertex curvature: a zero-radius cylinder and sphere.
  EXPECT_NEAR(g->Query({0, 0, -1.5}).hessian(0, 0), 2.0, 1e-12);
  EXPECT_NEAR(g->Query({0.8, 0.8, 0}).hessian(2, 2), 1 / std::sqrt(0.18), 1e-12);
}

// Sharp edges (faces at 70.5°) and corners: near a face, beside an edge, the
// face's own normal would give the wrong sign; the pseudo-normals do not.
TEST(TriangleMesh, TetrahedronSignsAtSharpEdgesAndCorners) {
  TestMesh tetrahedron{{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                       {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}};
  for (auto& v : tetrahedron.vertices) v = 0.3 * v + Vector3d(0.1, 0.2, 0.3);
  const TempDir dir;
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("tetrahedron.stl", BinaryStl(tetrahedron.vertices, tetrahedron.faces)), "test");
  const ConvexRegions regions(tetrahedron);
  CheckDerivatives(*g, regions.Samplers());
  // Within the single-precision STL's rounding of the corners.
  Rng rng(5);
  for (int i = 0; i < 1000; ++i)
    for (const Expected& e : {regions.Edge(rng), regions.Vertex(rng)}) {
      const DistanceQuery q = g->Query(e.x);
      EXPECT_NEAR(q.distance, e.distance, 1e-6) << e.x.transpose();
      EXPECT_GT(q.normal.dot(e.normal), 1 - 1e-6) << e.x.transpose();
    }
}

// Angle weights (Bærentzen & Aanæs): one face of a tetrahedron split into a
// fan of thin triangles at corner A must not outweigh A's other two faces,
// or points near those faces, in A's region, get the wrong sign.
TEST(TriangleMesh, VertexPseudoNormalIsAngleWeighted) {
  const Vector3d a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  TestMesh fanned{{a, b, c, d}, {{0, 3, 1}, {0, 2, 3}}};
  // Faces ABC (fanned from A) and DCB (fanned from D) share the points on BC.
  constexpr int kSplit = 12;
  for (int i = 1; i < kSplit; ++i) fanned.vertices.push_back(b + (c - b) * i / kSplit);
  auto on_bc = [&](int i) { return i == 0 ? 1 : i == kSplit ? 2 : 3 + i; };
  for (int i = 0; i < kSplit; ++i) {
    fanned.faces.push_back({0, on_bc(i), on_bc(i + 1)});
    fanned.faces.push_back({3, on_bc(i + 1), on_bc(i)});
  }
  const TempDir dir;
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("fanned.obj", ObjText(fanned.vertices, fanned.faces)), "test");
  const std::vector<Vector3d> normals = FaceNormals(fanned);
  const Vector3d abd = normals[0], acd = normals[1], abc = normals[2];
  const std::array<Vector3d, 2> near_abd_and_acd = {0.9 * abd + 0.05 * (abc + acd),
                                                    0.9 * acd + 0.05 * (abc + abd)};
  for (const Vector3d& m : near_abd_and_acd) {
    for (double s : {1e-3, 0.1, 1.0}) {
      const Vector3d x = a + s * m.normalized();
      ExpectQuery(g->Query(x), s, m.normalized(), 1e-12);
      EXPECT_TRUE(DerivativesMatch(*g, x));
    }
  }
}

// Many small faces: the tree has to find the closest of 320.
TEST(TriangleMesh, IcosphereMatchesConvexConstruction) {
  const TestMesh sphere = Icosphere(2, 0.7);
  const TempDir dir;
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("sphere.obj", ObjText(sphere.vertices, sphere.faces)), "test");
  const ConvexRegions regions(sphere);
  CheckDerivatives(*g, regions.Samplers(), true, 50);
  regions.CheckDistances(*g, 100);
}

// A 2×2×2 block without its (1,1,1) voxel: inside, near the notch, the
// closest points are its reflex edges and corner.
TEST(TriangleMesh, ConcaveEdgeAndVertexFromInside) {
  std::vector<std::array<int, 3>> voxels;
  for (int i = 0; i < 8; ++i)
    if (i != 7) voxels.push_back({i & 1, (i >> 1) & 1, (i >> 2) & 1});
  const TestMesh block = VoxelSurface(voxels);
  const TempDir dir;
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("notched.obj", ObjText(block.vertices, block.faces)), "test");

  auto corner = [](Rng& rng) -> std::optional<Vector3d> {
    return InBox(rng, Vector3d::Constant(0.75), Vector3d::Constant(0.98));
  };
  auto edge = [](Rng& rng) -> std::optional<Vector3d> {
    Vector3d x = InBox(rng, Vector3d::Constant(0.75), Vector3d::Constant(0.98));
    x[std::uniform_int_distribution<int>(0, 2)(rng)] = Uniform(rng, 1.4, 1.6);
    return x;
  };
  CheckDerivatives(*g, {{"reflex corner", corner}, {"reflex edge", edge}}, false);

  const Vector3d x(0.9, 0.8, 0.7);
  const Vector3d away = x - Vector3d::Ones();
  ExpectQuery(g->Query(x), -away.norm(), -away.normalized());
  const Vector3d y(1.5, 0.9, 0.8), off(0, -0.1, -0.2);
  ExpectQuery(g->Query(y), -off.norm(), -off.normalized());
  // Outside, in the notch: the nearest notch face.
  ExpectQuery(g->Query({1.5, 1.9, 1.2}), 0.2, Vector3d::UnitZ());
}

TEST(TriangleMesh, UnitCubeStlMatchesSharpBox) {
  const auto mesh =
      MakeTriangleMeshGeometry(test::SourceDir() / "resources" / "forms" / "unit-cube.stl", "test");
  const auto box = Make(BoxShape{{0, 0, 0}, {1, 1, 1}, 0.0});
  Rng rng(7);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d x = InBox(rng, Vector3d::Constant(-1), Vector3d::Constant(2));
    const DistanceQuery a = mesh->Query(x), b = box->Query(x);
    SCOPED_TRACE(::testing::Message() << "x = " << x.transpose());
    EXPECT_NEAR(a.distance, b.distance, 1e-14);
    EXPECT_LT((a.normal - b.normal).norm(), 1e-12);
    EXPECT_LT((a.hessian - b.hessian).norm(), 1e-10 * std::max(1.0, b.hessian.norm()));
  }
}

// Vertices on the sphere, flat triangles within it: the mesh lies between
// the sphere and the sphere shrunk by the largest sagitta.
TEST(TriangleMesh, IcosphereBinaryStlWithinChordOfSphere) {
  const double radius = 0.5;
  const TestMesh sphere = Icosphere(4, radius);
  ASSERT_EQ(sphere.faces.size(), 5120u);
  double sagitta = 0;
  for (const auto& f : sphere.faces) {
    const Vector3d &a = sphere.vertices[f[0]], &b = sphere.vertices[f[1]],
                   &c = sphere.vertices[f[2]];
    sagitta = std::max(sagitta, radius - std::abs((b - a).cross(c - a).normalized().dot(a)));
  }
  const TempDir dir;
  const auto g = MakeTriangleMeshGeometry(
      dir.Write("sphere.stl", BinaryStl(sphere.vertices, sphere.faces)), "test");
  const double float_error = 1e-7;  // the STL's single precision
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    const Vector3d x = Uniform(rng, 0.1, 1.5) * UnitVector(rng);
    const double exact = x.norm() - radius;
    const DistanceQuery q = g->Query(x);
    EXPECT_GE(q.distance, exact - float_error) << x.transpose();
    EXPECT_LE(q.distance, exact + sagitta + float_error) << x.transpose();
    EXPECT_GT(q.normal.dot(x.normalized()), 0.99) << x.transpose();
  }
  EXPECT_LT(sagitta, 2e-3);
}

// One octahedron, spelled many ways in OBJ and STL: all read alike.
TEST(TriangleMesh, ObjAndStlSpellingsAgree) {
  const TempDir dir;
  const TestMesh o = Octahedron();
  const std::string plain = ObjText(o.vertices, o.faces);
  std::string vertices;
  for (const Vector3d& v : o.vertices)
    vertices += "v " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " +
                std::to_string(v.z()) + "\n";
  std::string slashes = "# octahedron\r\nmtllib none.mtl\r\no octahedron\r\n" + vertices +
                        "vt 0 0\r\nvn 0 0 1\r\ns off\r\n";
  std::string negative = vertices;
  std::string reversed;  // inward-facing: turned outward silently
  for (const auto& f : o.faces) {
    slashes += "f " + std::to_string(f[0] + 1) + "/1/1 " + std::to_string(f[1] + 1) + "//1 " +
               std::to_string(f[2] + 1) + "/1   # a face\r\n";
    negative += "f " + std::to_string(f[0] - 6) + " " + std::to_string(f[1] - 6) + " " +
                std::to_string(f[2] - 6) + "\n";
    reversed += "f " + std::to_string(f[2] + 1) + " " + std::to_string(f[1] + 1) + " " +
                std::to_string(f[0] + 1) + "\n";
  }
  reversed = vertices + reversed;
  std::string ascii = "solid octahedron\n";
  for (const auto& f : o.faces) {
    ascii += "facet normal 0 0 0\n outer loop\n";
    for (int i : f)
      ascii += "  vertex " + std::to_string(o.vertices[i].x()) + " " +
               std::to_string(o.vertices[i].y()) + " " + std::to_string(o.vertices[i].z()) + "\n";
    ascii += " endloop\nendfacet\n";
  }
  ascii += "endsolid octahedron\n";
  // Duplicated vertices along a seam, as some exporters write them.
  const TestMesh split{[&] {
                         auto vs = o.vertices;
                         vs.push_back(o.vertices[0]);
                         return vs;
                       }(),
                       [&] {
                         Faces fs = o.faces;
                         for (int i = 0; i < 4; ++i)
                           for (int& c : fs[i])
                             if (c == 0) c = 6;
                         return fs;
                       }()};

  const std::vector<std::pair<std::string, std::string>> files = {
      {"plain.obj", plain},
      {"slashes.OBJ", slashes},
      {"negative.obj", negative},
      {"reversed.obj", reversed},
      {"ascii.Stl", ascii},
      {"binary.stl", BinaryStl(o.vertices, o.faces)},
      {"split.obj", ObjText(split.vertices, split.faces)}};
  const auto reference = MakeTriangleMeshGeometry(dir.Write("plain.obj", plain), "test");
  Rng rng(11);
  std::vector<Vector3d> points;
  for (int i = 0; i < 200; ++i)
    points.push_back(InBox(rng, -1.5 * Vector3d::Ones(), 1.5 * Vector3d::Ones()));
  for (const auto& [name, content] : files) {
    SCOPED_TRACE(name);
    std::unique_ptr<ObstacleGeometry> g;
    ASSERT_NO_THROW(g = MakeTriangleMeshGeometry(dir.Write(name, content), "test"));
    for (const Vector3d& x : points) {
      const DistanceQuery a = g->Query(x), b = reference->Query(x);
      EXPECT_NEAR(a.distance, b.distance, 1e-12) << x.transpose();
      EXPECT_LT((a.normal - b.normal).norm(), 1e-9) << x.transpose();
    }
  }
}

TEST(TriangleMesh, DressFormSignOnAxisAndFarAway) {
  const fs::path file = test::SourceDir() / "resources" / "forms" / "dress-form.obj";
  const auto g = MakeTriangleMeshGeometry(file, "test");
  for (double z = 0.01; z < 0.6; z += 0.01) {
    const DistanceQuery q = g->Query({0, 0, z});
    EXPECT_LT(q.distance, 0) << "z = " << z;
    EXPECT_GT(q.distance, -0.2) << "z = " << z;
  }
  for (const Vector3d& x : {Vector3d(2, 0, 0.3),
                            Vector3d(0, -2, 0.3),
                            Vector3d(0, 0, -1),
                            Vector3d(1, 1, 1),
                            Vector3d(0, 0, 1.6)}) {
    const DistanceQuery q = g->Query(x);
    EXPECT_GT(q.distance, 0.5) << x.transpose();
    EXPECT_LE(q.distance, x.norm()) << x.transpose();
  }
  // Straight above the neck's flat cap, whose centre is a vertex: flat, so
  // no curvature even though the closest feature is a vertex.
  const DistanceQuery above = g->Query({0, 0, 0.7});
  ExpectQuery(above, 0.1, Vector3d::UnitZ(), 1e-9);
  EXPECT_EQ(above.hessian, Matrix3d::Zero());
  // Beside the waist, the profile in the plane y = 0 (a polyline of mesh
  // edges, read back from the file) is as near as the mesh, to within the
  // facets' sagitta.
  std::vector<Eigen::Vector2d> profile;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword;
    double x, y, z;
    if (words >> keyword >> x >> y >> z && keyword == "v" && y == 0 && x > 0)
      profile.emplace_back(x, z);
  }
  ASSERT_EQ(profile.size(), 40u);
  const Eigen::Vector2d beside(0.2, 0.28);
  double nearest = 1;
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const Eigen::Vector2d a = profile[i], ab = profile[i + 1] - a;
    const double t = std::clamp((beside - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (beside - a - t * ab).norm());
  }
  const double d = g->Query({0.2, 0, 0.28}).distance;
  EXPECT_LE(d, nearest + 1e-12);
  EXPECT_GE(d, nearest - 1e-3);
}

// ---- bad files --------------------------------------------------------------

struct BadFile {
  std::string name;                   // as written into the temp directory; empty: not written
  std::string content;                //
  std::vector<std::string> expected;  // each must appear in the message
};

std::string CubeObj(const std::function<void(Faces&, std::vector<Vector3d>&)>& edit = {}) {
  TestMesh cube = VoxelSurface({{0, 0, 0}});
  Faces triangles = Triangulated(cube.faces);
  if (edit) edit(triangles, cube.vertices);
  return ObjText(cube.vertices, triangles);
}

TEST(TriangleMesh, BadFilesNameTheProblemAndWhere) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const std::vector<BadFile> cases = {
      {"missing.obj", "", {"cannot read", "missing.obj"}},
      {"form.ply", "ply\nformat ascii 1.0\n", {"unknown mesh format", "'.ply'", ".obj or .stl"}},
      {"noextension", "v 0 0 0\n", {"unknown mesh format"}},
      {"empty.obj", "", {"no triangles"}},
      {"empty.stl", "", {"no triangles"}},
      {"vertices-only.obj", tri, {"no triangles"}},
      {"bad-number.obj", "# a comment\nv 0 0 0\nv 1 0 x1\n", {"line 3", "bad number", "'x1'"}},
      {"short-vertex.obj", "v 0 0 0\nv 1 0\n", {"line 2", "three coordinates"}},
      {"out-of-range.obj", tri + "f 1 2 4\n", {"line 4", "vertex index 4", "out of range"}},
      {"negative-out-of-range.obj", tri + "f 1 2 -4\n", {"line 4", "-4", "out of range"}},
      {"zero-index.obj", tri + "f 0 1 2\n", {"line 4", "index 0"}},
      {"bad-index.obj", "\n\n" + tri + "f 1 2 3a\n", {"line 6", "bad vertex index", "'3a'"}},
      {"two-vertex-face.obj", tri + "f 1 2\n", {"line 4", "three vertices"}},
      {"degenerate.obj",
       CubeObj([](Faces& t, std::vector<Vector3d>& v) {
         v.push_back((v[0] + v[1]) / 2);
         t.push_back({0, 8, 1});  // flat along the cube's edge from vertex 1 to 2
       }),
       {"1 degenerate triangle", "zero area", "triangle 13 (line 22)"}},
      {"open.obj",
       CubeObj([](Faces& t, std::vector<Vector3d>&) { t.erase(t.begin(), t.begin() + 2); }),
       {"not closed", "4 edges belong to only one triangle", "vertex"}},
      {"non-manifold.obj",
       CubeObj([](Faces& t, std::vector<Vector3d>& v) {
         v.push_back((v[0] + v[1]) / 2 + Vector3d(-1, -1, 0));
         t.push_back({0, 8, 1});  // a fin on the cube's edge from vertex 1 to 2
       }),
       {"1 non-manifold edge", "up to 3", "vertex 1 (0, 0, 0)", "vertex 2 (0, 0, 1)"}},
      {"inconsistent.obj",
       CubeObj([](Faces& t, std::vector<Vector3d>&) {
         std::swap(t[0][1], t[0][2]);
         std::swap(t[1][1], t[1][2]);
       }),
       {"inconsistently oriented", "4 edges", "triangle 1", "line"}},
      {"flat.obj", tri + "f 1 2 3\nf 1 3 2\n", {"encloses no volume"}},
      {"bad-number.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 abc\n",
       {"line 4", "bad number", "'abc'"}},
      {"short-facet.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n",
       {"line 6", "three vertices"}},
      {"not-stl.stl", "hello\n", {"neither ASCII STL", "nor binary STL"}},
      {"open.stl",
       "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endloop\nendfacet\nendsolid x\n",
       {"not closed", "3 edges"}},
  };
  const TempDir dir;
  for (const BadFile& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path file =
        c.name == "missing.obj" ? dir.path() / c.name : dir.Write(c.name, c.content);
    try {
      MakeTriangleMeshGeometry(file, "obstacles[2].mesh.file");
      ADD_FAILURE() << "no SceneError";
    } catch (const SceneError& error) {
      EXPECT_EQ(error.where(), "obstacles[2].mesh.file");
      EXPECT_NE(error.message().find(c.name), std::string::npos) << error.message();
      EXPECT_EQ(error.message().find('\n'), std::string::npos) << error.message();
      for (const std::string& part : c.expected)
        EXPECT_NE(error.message().find(part), std::string::npos)
            << "\"" << part << "\" not in: " << error.message();
    }
  }
}

}  // namespace
}  // namespace drape
