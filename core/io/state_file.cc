#include "core/io/state_file.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace drape {
namespace {

constexpr char kMagic[8] = {'D', 'R', 'A', 'P', 'E', 'S', 'T', 'A'};
constexpr std::uint32_t kVersion = 1;

// The format is little-endian; so is every platform this builds on (x86-64,
// arm64), and the static_assert keeps it that way.
static_assert(std::endian::native == std::endian::little, "state files are little-endian");

void WriteOrThrow(std::FILE* f, const void* data, size_t bytes, const std::filesystem::path& path) {
  if (bytes && std::fwrite(data, 1, bytes, f) != bytes)
    throw std::runtime_error("cannot write '" + path.string() + "' (disk full?)");
}

}  // namespace

StateFileWriter::StateFileWriter(const std::filesystem::path& file, const Mesh& mesh)
    : path_(file), nodes_(mesh.NodeCount()) {
  file_ = std::fopen(file.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot create '" + file.string() + "'");
  const std::uint32_t header[4] = {kVersion,
                                   static_cast<std::uint32_t>(mesh.NodeCount()),
                                   static_cast<std::uint32_t>(mesh.ElementCount()),
                                   0};
  WriteOrThrow(file_, kMagic, sizeof kMagic, path_);
  WriteOrThrow(file_, header, sizeof header, path_);
  // Eigen stores column-major: write row by row so the file is node-major.
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x = mesh.positions;
  WriteOrThrow(file_, x.data(), sizeof(double) * x.size(), path_);
  Eigen::Matrix<std::int32_t, Eigen::Dynamic, 4, Eigen::RowMajor> q =
      mesh.quads.cast<std::int32_t>();
  WriteOrThrow(file_, q.data(), sizeof(std::int32_t) * q.size(), path_);
  if (mesh.ElementCount() % 2) {
    const std::int32_t pad = 0;
    WriteOrThrow(file_, &pad, sizeof pad, path_);
  }
  std::fflush(file_);
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

StateFile ReadStateFile(const std::filesystem::path& file) {
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot open state file '" + file.string() + "'");
  struct Closer {
    std::FILE* f;
    ~Closer() { std::fclose(f); }
  } closer{f};
  auto fail = [&](const std::string& what) {
    throw std::runtime_error("state file '" + file.string() + "': " + what);
  };
  char magic[8];
  std::uint32_t header[4];
  if (std::fread(magic, 1, 8, f) != 8 || std::memcmp(magic, kMagic, 8) != 0)
    fail("not a Drape state file");
  if (std::fread(header, sizeof header, 1, f) != 1) fail("truncated header");
  if (header[0] != kVersion) fail("unsupported version " + std::to_string(header[0]));
  const int n = static_cast<int>(header[1]), e = static_cast<int>(header[2]);
  StateFile out;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> x(n, 3);
  Eigen::Matrix<std::int32_t, Eigen::Dynamic, 4, Eigen::RowMajor> q(e, 4);
  if (std::fread(x.data(), sizeof(double), x.size(), f) != static_cast<size_t>(x.size()) ||
      std::fread(q.data(), sizeof(std::int32_t), q.size(), f) != static_cast<size_t>(q.size()))
    fail("truncated mesh");
  if (e % 2) {
    std::int32_t pad;
    if (std::fread(&pad, sizeof pad, 1, f) != 1) fail("truncated mesh");
  }
  out.mesh.positions = x;
  out.mesh.quads = q.cast<int>();
  for (;;) {
    std::int32_t ids[2];
    StoredStep step;
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p(n, 3), t(n, 3);
    if (std::fread(ids, sizeof ids, 1, f) != 1 ||
        std::fread(&step.lambda, sizeof(double), 1, f) != 1 ||
        std::fread(p.data(), sizeof(double), p.size(), f) != static_cast<size_t>(p.size()) ||
        std::fread(t.data(), sizeof(double), t.size(), f) != static_cast<size_t>(t.size()))
      break;  // end of file, or a record cut off by a crash: keep the whole ones
    step.stage = ids[0];
    step.step = ids[1];
    step.positions = p;
    step.directors = t;
    out.steps.push_back(std::move(step));
  }
  return out;
}

}  // namespace drape
