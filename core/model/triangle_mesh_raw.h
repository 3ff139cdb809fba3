// A triangle mesh obstacle on its way from its file to distance queries:
// read with its vertices merged (triangle_mesh_reader.cc), checked closed and
// turned outward (triangle_mesh_checks.cc), then indexed for the queries
// (triangle_mesh_geometry.cc). Each step keeps what its messages need to
// point the user back into the file. Internal to core/model.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/model/scene_error.h"

namespace drape {
namespace triangle_mesh {

// Triangles as read, vertices already merged, with what messages need to
// point the user back into the file.
struct RawMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<int> vertex_label;  // the vertex's number in messages (1-based)
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_line;  // source line of the face or facet; 0 if none (binary STL)
};

inline std::string Plural(std::size_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Every error names the obstacle (`where`) and the file.
class Reporter {
 public:
  Reporter(const std::filesystem::path& file, std::string where)
      : where_(std::move(where)), name_(file.filename().string()) {}

  [[noreturn]] void Fail(const std::string& what) const {
    throw SceneError(where_, "mesh '" + name_ + "': " + what);
  }
  [[noreturn]] void FailAt(int line, const std::string& what) const {
    Fail("line " + std::to_string(line) + ": " + what);
  }

 private:
  std::string where_;
  std::string name_;
};

// One triangle's side of an undirected edge: its local edge `local` runs
// from its corner `local` to corner `local + 1`.
struct HalfEdge {
  int lo, hi;  // the undirected edge, lo < hi
  int triangle;
  int local;
  bool forward;  // runs lo → hi
};

// The mesh in an OBJ or STL file (by its extension), vertices merged.
RawMesh ReadMesh(const std::filesystem::path& file, const Reporter& report);

// The half-edges of a closed, consistently oriented mesh, now facing outward.
std::vector<HalfEdge> CheckAndOrient(RawMesh& mesh, const Reporter& report);

}  // namespace triangle_mesh
}  // namespace drape
