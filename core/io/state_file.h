// The binary state file of a run (`states.bin`, docs/format.md): the mesh,
// then one record per converged step with every node's position and director.
//
// Layout, little-endian:
//   header   char[8] "DRAPESTA", uint32 version (1), uint32 nodes N, uint32 elements E,
//            uint32 reserved (0)
//   mesh     float64[3N] reference positions, int32[4E] quads (+ int32 0 if E is odd)
//   records  int32 stage, int32 step, float64 λ, float64[3N] positions, float64[3N] directors
// A record is written whole and flushed; a file cut off mid-record ends at
// the last whole record.
#pragma once

#include <Eigen/Core>

#include <cstdio>
#include <filesystem>
#include <vector>

#include "core/model/mesh.h"

namespace drape {

struct StoredStep {
  int stage = 0;
  int step = 0;
  double lambda = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 3> positions;
  Eigen::Matrix<double, Eigen::Dynamic, 3> directors;
};

class StateFileWriter {
 public:
  // Throws std::runtime_error naming the file when it cannot be written.
  StateFileWriter(const std::filesystem::path& file, const Mesh& mesh);
  ~StateFileWriter();
  StateFileWriter(const StateFileWriter&) = delete;
  StateFileWriter& operator=(const StateFileWriter&) = delete;

  void Append(const StoredStep& step);

 private:
  std::FILE* file_ = nullptr;
  std::filesystem::path path_;
  int nodes_ = 0;
};

struct StateFile {
  Mesh mesh;
  std::vector<StoredStep> steps;
};

// Reads a whole state file. Throws std::runtime_error naming the file and
// the problem (not a state file, unsupported version, truncated header, a
// mesh larger than the file, a quad's node out of range, a number that is not
// finite, a director that is not a unit vector) and, past the header, its
// record and byte offset.
StateFile ReadStateFile(const std::filesystem::path& file);

}  // namespace drape
