// The OBJ and STL readers of mesh obstacles under seeded mutations of the
// shipped meshes and of small solids (reader_fuzz_test.cc says what is
// asked of every reader), then the regression the fuzzing left.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "core/model/obstacle_geometry.h"
#include "core/model/scene_error.h"
#include "core/model/triangle_mesh_geometry.h"
#include "support/fuzz_files.h"
#include "support/fuzz_input.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::AllFinite;
using test::Contains;
using test::FuzzAlphabet;
using test::FuzzInputs;
using test::FuzzTally;
using test::Mutator;
using test::ReadBytes;
using test::ShippedFiles;
using test::TempFile;

// ---- OBJ and STL --------------------------------------------------------------

struct Solid {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;  // outward, 0-based
};

Solid Tetrahedron() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
          {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

std::string AsciiStl(const Solid& s) {
  std::ostringstream out;
  out << "solid fuzz\n";
  for (const auto& f : s.faces) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const int v : f)
      out << "      vertex " << s.vertices[v].x() << ' ' << s.vertices[v].y() << ' '
          << s.vertices[v].z() << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid fuzz\n";
  return out.str();
}

std::string BinaryStl(const Solid& s) {
  std::string bytes(80, ' ');
  const std::uint32_t count = static_cast<std::uint32_t>(s.faces.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : s.faces) {
    float values[12] = {};  // normal, then the corners
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = static_cast<float>(s.vertices[f[k]][c]);
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    bytes.append(2, '\0');
  }
  return bytes;
}

struct MeshSeed {
  std::string extension;
  std::string bytes;
};

// The shipped meshes, and small ones that reach what they do not: OBJ with
// texture/normal indices, negative indices, quads and comments; ASCII and
// binary STL of a tetrahedron.
std::vector<MeshSeed> MeshSeeds() {
  std::vector<MeshSeed> seeds;
  for (const fs::path& file : ShippedFiles({".obj", ".stl"}))
    seeds.push_back({file.extension().string(), ReadBytes(file)});
  seeds.push_back({".obj",
                   "# cube\no cube\nv -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                   "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvn 0 0 1\n"
                   "g sides\nusemtl none\ns off\n"
                   "f 1/1/1 4/1/1 3/1/1 2/1/1\nf 5//1 6//1 7//1 8//1\nf 1 2 6 5\n"
                   "f -6 -5 -1 -2\nf 3 4 8 7\nf 4/1 1/1 5/1 8/1\n"});
  seeds.push_back(
      {".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"});
  seeds.push_back({".stl", AsciiStl(Tetrahedron())});
  seeds.push_back({".stl", BinaryStl(Tetrahedron())});
  return seeds;
}

FuzzAlphabet MeshAlphabet() {
  return {"0123456789.-+eE /#\n\t vftn",
          {"v ",
           "f ",
           "vt ",
           "vn ",
           "v 0 0 0\n",
           "f 1 2 3\n",
           "f -1 -2 -3\n",
           "/",
           "//",
           "1e308",
           "-1e308",
           "1e-320",
           "nan",
           "inf",
           "0",
           "-1",
           "0",
           "99999999999999999999",
           "-9223372036854775808",
           "solid",
           "facet normal 0 0 1\n",
           "outer loop\n",
           "vertex 0 0 0\n",
           "vertex 1e38 1e38 1e38\n",
           "endloop\n",
           "endfacet\n",
           "endsolid\n",
           "\r\n",
           "\n"},
          true};
}

// A few points around and far from where the seeds lie.
const std::vector<Eigen::Vector3d>& QueryPoints() {
  static const std::vector<Eigen::Vector3d> points = {{0, 0, 0},
                                                      {0.25, 0.25, 0.25},
                                                      {0.5, 0.5, 0.5},
                                                      {2, 0.1, -0.3},
                                                      {-3, 5, 1},
                                                      {0, 0, 0.6},
                                                      {1e3, -2e3, 5e2},
                                                      {1e-9, 0, 0}};
  return points;
}

TEST(ReaderFuzzMesh, MutatedObjAndStlGiveAGeometryOrASceneError) {
  const std::vector<MeshSeed> seeds = MeshSeeds();
  // The dress form is slow to check: fuzzed once in 32 inputs.
  std::vector<std::string> small, all, small_extension, all_extension;
  for (const MeshSeed& s : seeds) {
    all.push_back(s.bytes);
    all_extension.push_back(s.extension);
    if (s.bytes.size() < 20000) {
      small.push_back(s.bytes);
      small_extension.push_back(s.extension);
    }
  }
  Mutator mutator(3840, MeshAlphabet());
  FuzzTally tally{"OBJ/STL meshes"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const bool any = i % 32 == 0;
    std::size_t picked = 0;
    const std::string bytes = mutator.Make(any ? all : small, &picked);
    // Mostly the seed's own extension (any case); sometimes the other one.
    std::string extension = (any ? all_extension : small_extension)[picked];
    if (mutator.Below(8) == 0) extension = extension == ".obj" ? ".stl" : ".obj";
    if (mutator.Below(8) == 0)
      std::ranges::transform(
          extension, extension.begin(), [](unsigned char c) { return std::toupper(c); });
    const TempFile file(extension, bytes);
    try {
      const auto geometry = MakeTriangleMeshGeometry(file.path(), "fuzz");
      for (const Eigen::Vector3d& x : QueryPoints()) {
        const DistanceQuery q = geometry->Query(x);
        ASSERT_TRUE(std::isfinite(q.distance) && AllFinite(q.normal) && AllFinite(q.hessian))
            << "query at " << x.transpose() << " of " << extension << ":\n"
            << bytes;
      }
      ++tally.accepted;
    } catch (const SceneError& e) {
      ASSERT_EQ(e.where(), "fuzz") << e.what();
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

std::string MeshMessage(const std::string& name, const std::string& content) {
  const TempFile file(fs::path(name).extension().string(), content);
  try {
    const auto geometry = MakeTriangleMeshGeometry(file.path(), "obstacles[0].mesh.file");
    const DistanceQuery q = geometry->Query(Eigen::Vector3d(0.1, 0.1, 0.1));
    ADD_FAILURE() << "no SceneError; distance " << q.distance;
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Coordinates this large are finite, but the cross products and the volume
// made of them are not: the mesh passed every check and the distance was NaN.
TEST(ReaderFuzzRegression, MeshRefusesCoordinatesTooLargeToComputeWith) {
  // Corners of a cube 3e308 wide: every edge vector is 0 or ±inf, every
  // cross product NaN, so no triangle looked degenerate.
  const std::string obj =
      "v 1.5e308 1.5e308 1.5e308\nv 1.5e308 -1.5e308 -1.5e308\n"
      "v -1.5e308 1.5e308 -1.5e308\nv -1.5e308 -1.5e308 1.5e308\n"
      "f 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  const std::string message = MeshMessage("big.obj", obj);
  EXPECT_TRUE(Contains(message, "obstacles[0].mesh.file: mesh '"));
  EXPECT_TRUE(Contains(message, "line 1: coordinate '1.5e308' is too large"));
  std::string stl = AsciiStl(Tetrahedron());
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex 1 -2e150 0");
  EXPECT_TRUE(Contains(MeshMessage("big.stl", stl), "coordinate '-2e150' is too large"));
}

}  // namespace
}  // namespace drape
