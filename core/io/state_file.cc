#include "core/io/state_file.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace drape {
namespace {

constexpr char kMagic[8] = {'D', 'R', 'A', 'P', 'E', 'S', 'T', 'A'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint64_t kHeaderBytes = 8 + 16;
// Directors are written as unit vectors to rounding (~1e-15); far looser than
// that, still far from what a damaged file holds.
constexpr double kDirectorTolerance = 1e-6;

// The format is little-endian; so is every platform this builds on (x86-64,
// arm64), and the static_assert keeps it that way.
static_assert(std::endian::native == std::endian::little, "state files are little-endian");

void WriteOrThrow(std::FILE* f, const void* data, size_t bytes, const std::filesystem::path& path) {
  if (bytes && std::fwrite(data, 1, bytes, f) != bytes)
    throw std::runtime_error("cannot write '" + path.string() + "' (disk full?)");
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

namespace {

// The header and the mesh: the part of a state file that precedes the steps.
void WriteHeaderAndMesh(std::FILE* f, const Mesh& mesh, const std::filesystem::path& path) {
  const std::uint32_t header[4] = {kVersion,
                                   static_cast<std::uint32_t>(mesh.NodeCount()),
                                   static_cast<std::uint32_t>(mesh.ElementCount()),
                                   0};
  WriteOrThrow(f, kMagic, sizeof kMagic, path);
  WriteOrThrow(f, header, sizeof header, path);
  // Eigen stores column-major: write row by row so the file is node-major.
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x = mesh.positions;
  WriteOrThrow(f, x.data(), sizeof(double) * x.size(), path);
  Eigen::Matrix<std::int32_t, Eigen::Dynamic, 4, Eigen::RowMajor> q =
      mesh.quads.cast<std::int32_t>();
  WriteOrThrow(f, q.data(), sizeof(std::int32_t) * q.size(), path);
  if (mesh.ElementCount() % 2) {
    const std::int32_t pad = 0;
    WriteOrThrow(f, &pad, sizeof pad, path);
  }
  if (std::fflush(f) != 0)
    throw std::runtime_error("cannot write '" + path.string() + "' (disk full?)");
}

}  // namespace

StateFileWriter::StateFileWriter(const std::filesystem::path& file, const Mesh& mesh)
    : path_(file), nodes_(mesh.NodeCount()) {
  // The header and mesh go to a side file that takes the name only when it
  // is whole: a run killed while it writes them leaves no file that a reader
  // would take for a damaged state file.
  std::filesystem::path part = file;
  part += ".part";
  file_ = std::fopen(part.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot create '" + part.string() + "'");
  std::error_code ec;
  try {
    WriteHeaderAndMesh(file_, mesh, part);
    std::filesystem::rename(part, file, ec);
    if (ec) throw std::runtime_error("cannot create '" + file.string() + "': " + ec.message());
  } catch (...) {
    std::fclose(file_);
    std::filesystem::remove(part, ec);
    throw;
  }
}

StateFileWriter::~StateFileWriter() {
  if (file_) std::fclose(file_);
}

void StateFileWriter::Append(const StoredStep& step) {
  const std::int32_t ids[2] = {step.stage, step.step};
  WriteOrThrow(file_, ids, sizeof ids, path_);
  WriteOrThrow(file_, &step.lambda, sizeof step.lambda, path_);
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x = step.positions;
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> t = step.directors;
  WriteOrThrow(file_, x.data(), sizeof(double) * 3 * nodes_, path_);
  WriteOrThrow(file_, t.data(), sizeof(double) * 3 * nodes_, path_);
  std::fflush(file_);
}

namespace {

// Throws the reader's error for the file it reads.
using Fail = std::function<void(const std::string&)>;

std::string At(std::uint64_t offset) {
  return " (byte " + std::to_string(offset) + ")";
}

// The mesh after the header: n node positions and e quads, every number
// checked (readers downstream index nodes by them and compute with them).
Mesh ReadStoredMesh(std::FILE* f, std::uint64_t nodes, std::uint64_t elements, const Fail& fail) {
  const int n = static_cast<int>(nodes), e = static_cast<int>(elements);
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x(n, 3);
  Eigen::Matrix<std::int32_t, Eigen::Dynamic, 4, Eigen::RowMajor> q(e, 4);
  if (std::fread(x.data(), sizeof(double), x.size(), f) != static_cast<size_t>(x.size()) ||
      std::fread(q.data(), sizeof(std::int32_t), q.size(), f) != static_cast<size_t>(q.size()))
    fail("truncated mesh");
  if (e % 2) {
    std::int32_t pad;
    if (std::fread(&pad, sizeof pad, 1, f) != 1) fail("truncated mesh");
  }
  for (int i = 0; i < n; ++i)
    if (!x.row(i).allFinite())
      fail("node " + std::to_string(i) + " of the mesh: its position is not a finite number" +
           At(kHeaderBytes + 24 * static_cast<std::uint64_t>(i)));
  for (int i = 0; i < e; ++i)
    for (int c = 0; c < 4; ++c)
      if (q(i, c) < 0 || q(i, c) >= n)
        fail("quad " + std::to_string(i) + " has node " + std::to_string(q(i, c)) +
             ", outside the mesh's " + std::to_string(n) + " nodes" +
             At(kHeaderBytes + 24 * nodes + 16 * static_cast<std::uint64_t>(i) + 4 * c));
  Mesh mesh;
  mesh.positions = x;
  mesh.quads = q.cast<int>();
  return mesh;
}

// The records from `first_offset` on, each checked; a record cut off at the
// end (a crash while writing) ends the list.
std::vector<StoredStep> ReadStoredSteps(std::FILE* f,
                                        std::uint64_t nodes,
                                        std::uint64_t first_offset,
                                        const Fail& fail) {
  const int n = static_cast<int>(nodes);
  const std::uint64_t record_bytes = 16 + 48 * nodes;
  std::vector<StoredStep> steps;
  for (std::uint64_t record = 0;; ++record) {
    const std::uint64_t offset = first_offset + record * record_bytes;
    std::int32_t ids[2];
    StoredStep step;
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p(n, 3), t(n, 3);
    if (std::fread(ids, sizeof ids, 1, f) != 1 ||
        std::fread(&step.lambda, sizeof(double), 1, f) != 1 ||
        std::fread(p.data(), sizeof(double), p.size(), f) != static_cast<size_t>(p.size()) ||
        std::fread(t.data(), sizeof(double), t.size(), f) != static_cast<size_t>(t.size()))
      break;  // end of file, or a record cut off by a crash: keep the whole ones
    const std::string where = "record " + std::to_string(record) + " (stage " +
                              std::to_string(ids[0]) + ", step " + std::to_string(ids[1]) + ")";
    if (!std::isfinite(step.lambda))
      fail(where + ": the load factor is not a finite number" + At(offset + 8));
    for (int i = 0; i < n; ++i) {
      const std::uint64_t director_at = offset + 16 + 24 * (nodes + static_cast<std::uint64_t>(i));
      if (!p.row(i).allFinite())
        fail(where + ": node " + std::to_string(i) + "'s position is not a finite number" +
             At(offset + 16 + 24 * static_cast<std::uint64_t>(i)));
      if (!t.row(i).allFinite())
        fail(where + ": node " + std::to_string(i) + "'s director is not a finite number" +
             At(director_at));
      // Directors are unit vectors; a rotation rebuilt from anything else
      // (StateOf) is no rotation, and overflows for large ones.
      const double length = t.row(i).norm();
      if (std::abs(length - 1.0) > kDirectorTolerance)
        fail(where + ": node " + std::to_string(i) + "'s director is not a unit vector (length " +
             Number(length) + ")" + At(director_at));
    }
    step.stage = ids[0];
    step.step = ids[1];
    step.positions = p;
    step.directors = t;
    steps.push_back(std::move(step));
  }
  return steps;
}

}  // namespace

StateFile ReadStateFile(const std::filesystem::path& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot open state file '" + file.string() + "'");
  struct Closer {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{f};
  const Fail fail = [&](const std::string& what) {
    throw std::runtime_error("state file '" + file.string() + "': " + what);
  };
  char magic[8];
  std::uint32_t header[4];
  if (std::fread(magic, 1, 8, f) != 8 || std::memcmp(magic, kMagic, 8) != 0)
    fail("not a Drape state file");
  if (std::fread(header, sizeof header, 1, f) != 1) fail("truncated header");
  if (header[0] != kVersion) fail("unsupported version " + std::to_string(header[0]));
  // The counts size every allocation below: a damaged header must not ask for
  // more memory than the file could fill.
  std::error_code error;
  const std::uint64_t file_bytes = std::filesystem::file_size(file, error);
  if (error) fail("cannot tell its size (" + error.message() + ")");
  const std::uint64_t nodes = header[1], elements = header[2];
  const std::uint64_t mesh_bytes = 24 * nodes + 16 * elements + (elements % 2 ? 4 : 0);
  if (kHeaderBytes + mesh_bytes > file_bytes)
    fail("truncated mesh: the header gives " + std::to_string(nodes) + " nodes and " +
         std::to_string(elements) + " elements, " + std::to_string(mesh_bytes) +
         " bytes of mesh, but " + std::to_string(file_bytes - kHeaderBytes) +
         " bytes follow the header");
  if (nodes > static_cast<std::uint64_t>(std::numeric_limits<int>::max()) ||
      elements > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    fail("the header gives " + std::to_string(nodes) + " nodes and " + std::to_string(elements) +
         " elements, more than a mesh can have");
  StateFile out;
  out.mesh = ReadStoredMesh(f, nodes, elements, fail);
  out.steps = ReadStoredSteps(f, nodes, kHeaderBytes + mesh_bytes, fail);
  return out;
}

}  // namespace drape
