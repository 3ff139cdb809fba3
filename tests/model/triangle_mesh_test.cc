// Triangle-mesh obstacles (OBJ and STL): signed distance, normal and Hessian
// by face, edge, vertex and inside against convex constructions and central
// differences; sharp and reflex features, spellings of the same solid, and
// the shipped dress form.
#include "core/model/triangle_mesh_geometry.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/model/obstacle_geometry.h"
#include "support/obstacle_test_geometry.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using test::BinaryStl;
using test::CheckDerivatives;
using test::DerivativesMatch;
using test::ExpectQuery;
using test::FaceNormals;
using test::Faces;
using test::Icosphere;
using test::InBox;
using test::Make;
using test::MeshDir;
using test::ObjText;
using test::Octahedron;
using test::Rng;
using test::Sampler;
using test::TestMesh;
using test::Uniform;
using test::UnitVector;
using test::VoxelSurface;

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
  const MeshDir dir;
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
  const MeshDir dir;
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
  const MeshDir dir;
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
  const MeshDir dir;
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
  const MeshDir dir;
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
  const MeshDir dir;
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
  const MeshDir dir;
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
}  // namespace
}  // namespace drape
