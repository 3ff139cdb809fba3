// Mesh files an obstacle cannot be made of (unreadable, unknown format, bad
// numbers and indices, degenerate, open, non-manifold, inconsistently
// oriented, enclosing nothing): one SceneError naming the problem and where.
#include "core/model/triangle_mesh_geometry.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/model/scene_error.h"
#include "support/obstacle_test_geometry.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;
using test::Faces;
using test::MeshDir;
using test::ObjText;
using test::TestMesh;
using test::Triangulated;
using test::VoxelSurface;

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
  const MeshDir dir;
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
