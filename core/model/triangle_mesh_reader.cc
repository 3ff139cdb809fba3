// Reading a triangle mesh obstacle's file, OBJ or STL (ASCII or binary):
// every number and index is checked as it is read, so a bad file fails at
// its line rather than as a wrong distance later.
#include "core/model/triangle_mesh_raw.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>
#include <unordered_map>

namespace drape {
namespace triangle_mesh {
namespace {

using Eigen::Vector3d;

// Exact-coordinate merge: STL repeats every vertex per facet, and some OBJ
// exporters split vertices along seams; closedness can only be checked on
// shared vertices. -0.0 and 0.0 are the same point.
class VertexMerger {
 public:
  int Add(const Vector3d& p, int label, RawMesh& mesh) {
    const Key key{std::bit_cast<std::uint64_t>(p.x() + 0.0),
                  std::bit_cast<std::uint64_t>(p.y() + 0.0),
                  std::bit_cast<std::uint64_t>(p.z() + 0.0)};
    const auto [it, inserted] = index_.try_emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      mesh.vertices.push_back(p);
      mesh.vertex_label.push_back(label);
    }
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
      h ^= (h >> 29) ^ (k[1] * 0xBF58476D1CE4E5B9ull);
      h ^= (h >> 31) ^ (k[2] * 0x94D049BB133111EBull);
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::unordered_map<Key, int, Hash> index_;
};

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (true) {
    i = line.find_first_not_of(" \t\r\f\v", i);
    if (i == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", i), line.size());
    tokens.push_back(line.substr(i, end - i));
    i = end;
  }
  return tokens;
}

bool ParseDouble(std::string_view text, double& value) {
  // from_chars takes no '+', and a '+' may not be followed by another sign.
  if (text.starts_with('+')) {
    text.remove_prefix(1);
    if (text.starts_with('+') || text.starts_with('-')) return false;
  }
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size() &&
         std::isfinite(value);
}

// Larger coordinates overflow the cross products and volumes (cubes of
// coordinate differences) the checks and queries compute: NaN passed every
// check and the closest-triangle search found none. No obstacle is this
// large in any unit.
constexpr double kMaxCoordinate = 1e50;

// A vertex coordinate; the reason it is not one otherwise.
bool ParseCoordinate(std::string_view text, double& value, std::string& why) {
  if (!ParseDouble(text, value)) {
    why = "bad number '" + std::string(text) + "' in vertex";
    return false;
  }
  if (std::abs(value) > kMaxCoordinate) {
    why = "coordinate '" + std::string(text) + "' is too large (more than 1e50 in magnitude)";
    return false;
  }
  return true;
}

bool ParseInt(std::string_view text, long long& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && error == std::errc() && end == text.data() + text.size();
}

std::string Quoted(std::string_view text) {
  std::string quoted(1, '\'');
  quoted.append(text);
  quoted.push_back('\'');
  return quoted;
}

// Calls `line_fn(number, text)` for each line, without its end-of-line.
template <class F>
void ForEachLine(std::string_view text, F&& line_fn) {
  int number = 0;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    line_fn(++number, text.substr(0, end));
    text.remove_prefix(std::min(end + 1, text.size()));
  }
}

RawMesh ReadObj(std::string_view text, const Reporter& report) {
  struct Face {
    std::vector<long long> corners;  // 0-based file vertex indices, not yet range-checked
    int line;
  };
  std::vector<Vector3d> positions;
  std::vector<Face> faces;
  ForEachLine(text, [&](int line, std::string_view content) {
    content = content.substr(0, content.find('#'));
    const std::vector<std::string_view> tokens = Tokens(content);
    if (tokens.empty()) return;
    if (tokens[0] == "v") {
      // x y z, optionally w or r g b, which a rigid obstacle does not need.
      if (tokens.size() < 4) report.FailAt(line, "a vertex needs three coordinates");
      double values[3];
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        double value;
        std::string why;
        if (k <= 3 ? !ParseCoordinate(tokens[k], value, why) : !ParseDouble(tokens[k], value))
          report.FailAt(line, k <= 3 ? why : "bad number " + Quoted(tokens[k]) + " in vertex");
        if (k <= 3) values[k - 1] = value;
      }
      positions.emplace_back(values[0], values[1], values[2]);
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4) report.FailAt(line, "a face needs at least three vertices");
      Face face{{}, line};
      for (std::size_t k = 1; k < tokens.size(); ++k) {
        // v, v/vt, v//vn or v/vt/vn: only v matters here, but all must be numbers.
        const std::string_view token = tokens[k];
        const std::string_view v = token.substr(0, token.find('/'));
        long long index;
        if (!ParseInt(v, index))
          report.FailAt(line, "bad vertex index " + Quoted(token) + " in face");
        for (std::size_t slash = token.find('/'); slash != std::string_view::npos;) {
          const std::size_t next = token.find('/', slash + 1);
          const std::string_view part = token.substr(slash + 1, next - slash - 1);
          long long ignored;
          if (!part.empty() && !ParseInt(part, ignored))
            report.FailAt(line, "bad index " + Quoted(token) + " in face");
          slash = next;
        }
        const long long count = static_cast<long long>(positions.size());
        if (index == 0) report.FailAt(line, "vertex index 0 in face (OBJ counts from 1)");
        // Negative indices count back from the last vertex read so far.
        const long long resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0)
          report.FailAt(line,
                        "vertex index " + std::to_string(index) + " is out of range (" +
                            Plural(positions.size(), "vertex", "vertices") + " so far)");
        face.corners.push_back(resolved);
      }
      faces.push_back(std::move(face));
    }
    // vt, vn, g, o, s, usemtl, mtllib, l, ...: nothing an obstacle needs.
  });

  RawMesh mesh;
  VertexMerger merger;
  std::vector<int> merged(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    merged[i] = merger.Add(positions[i], static_cast<int>(i) + 1, mesh);
  for (const Face& face : faces) {
    for (const long long corner : face.corners)
      if (corner >= static_cast<long long>(positions.size()))
        report.FailAt(face.line,
                      "vertex index " + std::to_string(corner + 1) + " is out of range (" +
                          Plural(positions.size(), "vertex", "vertices") + " in the file)");
    for (std::size_t k = 1; k + 1 < face.corners.size(); ++k) {
      mesh.triangles.push_back(
          {merged[face.corners[0]], merged[face.corners[k]], merged[face.corners[k + 1]]});
      mesh.triangle_line.push_back(face.line);
    }
  }
  return mesh;
}

RawMesh ReadAsciiStl(std::string_view text, const Reporter& report) {
  RawMesh mesh;
  VertexMerger merger;
  std::vector<int> loop;
  int facet_line = 0;
  ForEachLine(text, [&](int line, std::string_view content) {
    const std::vector<std::string_view> tokens = Tokens(content);
    if (tokens.empty()) return;
    const std::string_view keyword = tokens[0];
    if (keyword == "solid" || keyword == "endsolid" || keyword == "outer" ||
        keyword == "endfacet") {
      return;
    }
    if (keyword == "facet") {
      facet_line = line;
      loop.clear();
    } else if (keyword == "vertex") {
      double xyz[3];
      if (tokens.size() != 4) report.FailAt(line, "a vertex needs three coordinates");
      for (int k = 0; k < 3; ++k) {
        std::string why;
        if (!ParseCoordinate(tokens[k + 1], xyz[k], why)) report.FailAt(line, why);
      }
      loop.push_back(
          merger.Add({xyz[0], xyz[1], xyz[2]}, static_cast<int>(mesh.vertices.size()) + 1, mesh));
    } else if (keyword == "endloop") {
      if (loop.size() < 3) report.FailAt(line, "a facet needs three vertices");
      for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
        mesh.triangles.push_back({loop[0], loop[k], loop[k + 1]});
        mesh.triangle_line.push_back(facet_line ? facet_line : line);
      }
      loop.clear();
    } else {
      report.FailAt(line, "unexpected " + Quoted(keyword) + " in ASCII STL");
    }
  });
  return mesh;
}

RawMesh ReadBinaryStl(std::string_view bytes) {
  static_assert(std::endian::native == std::endian::little, "binary STL is little-endian");
  RawMesh mesh;
  VertexMerger merger;
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  for (std::uint32_t t = 0; t < count; ++t) {
    const char* facet = bytes.data() + 84 + 50 * static_cast<std::size_t>(t);
    std::array<int, 3> triangle;
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 + 12 * k, 12);  // after the facet normal
      triangle[k] =
          merger.Add({xyz[0], xyz[1], xyz[2]}, static_cast<int>(mesh.vertices.size()) + 1, mesh);
    }
    mesh.triangles.push_back(triangle);
    mesh.triangle_line.push_back(0);
  }
  return mesh;
}

RawMesh ReadStl(std::string_view bytes, const Reporter& report) {
  // The size is the reliable test: binary files may start with "solid" too.
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count)) {
      RawMesh mesh = ReadBinaryStl(bytes);
      for (const Vector3d& v : mesh.vertices)
        if (!v.allFinite()) report.Fail("a vertex coordinate is not a finite number");
      return mesh;
    }
  }
  const std::vector<std::string_view> first = Tokens(bytes.substr(0, bytes.find('\n')));
  if (!first.empty() && first[0] != "solid")
    report.Fail("neither ASCII STL (it does not start with 'solid') nor binary STL (its size " +
                std::to_string(bytes.size()) + " is not 84 + 50 per triangle)");
  return ReadAsciiStl(bytes, report);
}

std::string LowerCase(std::string text) {
  for (char& c : text)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return text;
}

}  // namespace

RawMesh ReadMesh(const std::filesystem::path& file, const Reporter& report) {
  const std::string extension = LowerCase(file.extension().string());
  if (extension != ".obj" && extension != ".stl")
    report.Fail("unknown mesh format " + Quoted(file.extension().string()) +
                " (expected .obj or .stl)");
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error))
    report.Fail("cannot read mesh file " + Quoted(file.string()));
  std::ifstream in(file, std::ios::binary);
  if (!in) report.Fail("cannot read mesh file " + Quoted(file.string()));
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) report.Fail("cannot read mesh file " + Quoted(file.string()));
  return extension == ".obj" ? ReadObj(bytes, report) : ReadStl(bytes, report);
}

}  // namespace triangle_mesh
}  // namespace drape
