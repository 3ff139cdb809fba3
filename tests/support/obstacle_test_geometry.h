// Shared by the obstacle-geometry tests (tests/model/obstacle_geometry_test.cc,
// triangle_mesh_test.cc, triangle_mesh_files_test.cc): random points, the
// distance query's derivatives against central differences, and closed test
// meshes written as OBJ or binary STL into a folder of the test's own.
#pragma once

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
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/model/obstacle_geometry.h"

namespace drape::test {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Rng = std::mt19937_64;
using Faces = std::vector<std::vector<int>>;  // 0-based vertex indices, counter-clockwise outside

inline std::unique_ptr<ObstacleGeometry> Make(const ObstacleShape& shape) {
  return MakeObstacleGeometry(Obstacle{"test", shape}, {});
}

inline double Uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}
inline Vector3d UnitVector(Rng& rng) {
  std::normal_distribution<double> normal;
  return Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}
inline Vector3d InBox(Rng& rng, const Vector3d& lo, const Vector3d& hi) {
  return {Uniform(rng, lo.x(), hi.x()), Uniform(rng, lo.y(), hi.y()), Uniform(rng, lo.z(), hi.z())};
}
// Two unit vectors completing `axis` to a right-handed frame.
inline std::pair<Vector3d, Vector3d> Frame(const Vector3d& axis) {
  const Vector3d u = axis.unitOrthogonal();
  return {u, axis.cross(u)};
}

// The normal must be the gradient of the distance and the Hessian the
// gradient of the normal, by central differences; the step is far below the
// samplers' 1e-2 margin to the surfaces where d is not C², so both sides of
// every difference are in the same region.
inline ::testing::AssertionResult DerivativesMatch(const ObstacleGeometry& g, const Vector3d& x) {
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
inline void CheckDerivatives(const ObstacleGeometry& g,
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

inline void ExpectQuery(const DistanceQuery& q,
                        double distance,
                        const Vector3d& normal,
                        double tolerance = 1e-12) {
  EXPECT_NEAR(q.distance, distance, tolerance);
  EXPECT_LT((q.normal - normal).norm(), tolerance)
      << q.normal.transpose() << " vs " << normal.transpose();
}

// ---- files ------------------------------------------------------------------

// A directory of its own per test, removed afterwards.
class MeshDir {
 public:
  MeshDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ =
        std::filesystem::temp_directory_path() / ("drape-mesh-" + std::to_string(getpid()) + "-" +
                                                  info->test_suite_name() + "-" + info->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~MeshDir() { std::filesystem::remove_all(path_); }
  MeshDir(const MeshDir&) = delete;
  MeshDir& operator=(const MeshDir&) = delete;

  std::filesystem::path Write(const std::string& name, const std::string& content) const {
    const std::filesystem::path file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::string ObjText(const std::vector<Vector3d>& vertices, const Faces& faces) {
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

inline std::string BinaryStl(const std::vector<Vector3d>& vertices, const Faces& triangles) {
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
inline TestMesh Octahedron() {
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
inline TestMesh VoxelSurface(const std::vector<std::array<int, 3>>& voxels) {
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

inline Faces Triangulated(const Faces& faces) {
  Faces triangles;
  for (const auto& f : faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) triangles.push_back({f[0], f[k], f[k + 1]});
  return triangles;
}

// An icosahedron subdivided `levels` times, on the sphere of `radius` about 0.
inline TestMesh Icosphere(int levels, double radius) {
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
inline std::vector<Vector3d> FaceNormals(const TestMesh& m) {
  std::vector<Vector3d> normals;
  for (const auto& f : m.faces)
    normals.push_back((m.vertices[f[1]] - m.vertices[f[0]])
                          .cross(m.vertices[f[2]] - m.vertices[f[0]])
                          .normalized());
  return normals;
}

}  // namespace drape::test
