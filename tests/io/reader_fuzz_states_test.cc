// The states.bin reader under seeded mutations of small state files, its
// binary words included (reader_fuzz_test.cc says what is asked of every
// reader), then the regressions the fuzzing left.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/state_file.h"
#include "core/mechanics/director.h"
#include "core/model/mesh.h"
#include "support/fuzz_files.h"
#include "support/fuzz_input.h"

namespace drape {
namespace {

using test::AllFinite;
using test::Contains;
using test::FuzzInputs;
using test::FuzzTally;
using test::Mutator;
using test::ReadBytes;
using test::TempFile;

// ---- states.bin ---------------------------------------------------------------

// A state file of `steps` records on an nx × ny mesh, with unit directors.
std::string StateFileBytes(int nx, int ny, int steps) {
  const Mesh mesh = MeshRectangle(0.2, 0.1, {0, 0}, nx, ny, 0.0);
  const TempFile file(".bin", "");
  {
    StateFileWriter writer(file.path(), mesh);
    for (int s = 0; s < steps; ++s) {
      StoredStep step;
      step.stage = s / 2;
      step.step = s + 1;
      step.lambda = 0.25 * (s + 1);
      step.positions = mesh.positions;
      step.positions.col(2).array() -= 0.01 * s;
      step.directors.resize(mesh.NodeCount(), 3);
      for (int n = 0; n < mesh.NodeCount(); ++n)
        step.directors.row(n) = Eigen::Vector3d(0.1 * s, -0.05 * n, 1.0).normalized();
      writer.Append(step);
    }
  }
  return ReadBytes(file.path());
}

// Every number finite, every quad's nodes in the mesh, every record the
// mesh's size; and the rotations a result rebuilds from the directors
// (StateOf) finite too.
void ExpectSoundStates(const StateFile& states, const std::string& what) {
  const Mesh& mesh = states.mesh;
  ASSERT_TRUE(AllFinite(mesh.positions)) << what;
  if (mesh.ElementCount() > 0) {
    ASSERT_GE(mesh.quads.minCoeff(), 0) << what;
    ASSERT_LT(mesh.quads.maxCoeff(), mesh.NodeCount()) << what;
  }
  for (const StoredStep& s : states.steps) {
    ASSERT_TRUE(std::isfinite(s.lambda)) << what;
    ASSERT_EQ(s.positions.rows(), mesh.NodeCount()) << what;
    ASSERT_EQ(s.directors.rows(), mesh.NodeCount()) << what;
    ASSERT_TRUE(AllFinite(s.positions) && AllFinite(s.directors)) << what;
    for (int n = 0; n < s.directors.rows(); ++n)
      ASSERT_TRUE(AllFinite(RotationFromDirector(s.directors.row(n).transpose())))
          << what << ", node " << n << " director " << s.directors.row(n);
  }
}

std::string Hex(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string text;
  for (std::size_t i = 0; i < std::min<std::size_t>(bytes.size(), 256); ++i) {
    text += digits[static_cast<unsigned char>(bytes[i]) >> 4];
    text += digits[static_cast<unsigned char>(bytes[i]) & 15];
    text += i % 32 == 31 ? '\n' : ' ';
  }
  return text + (bytes.size() > 256 ? "..." : "") + " (" + std::to_string(bytes.size()) + " bytes)";
}

TEST(ReaderFuzzStates, MutatedStateFilesGiveStatesOrANamedError) {
  // 2 × 2 (even quad count) and 3 × 1 (odd: a padding word), with and without records.
  const std::vector<std::string> seeds = {
      StateFileBytes(2, 2, 3), StateFileBytes(3, 1, 2), StateFileBytes(1, 1, 0)};
  Mutator mutator(424242,
                  {test::Bytes("\x00\x01\xff\x7f\x80"), {"DRAPESTA", std::string(8, '\0')}, true});
  FuzzTally tally{"states.bin"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const std::string bytes = mutator.Make(seeds);
    const TempFile file(".bin", bytes);
    try {
      ExpectSoundStates(ReadStateFile(file.path()), Hex(bytes));
      ++tally.accepted;
    } catch (const std::runtime_error& e) {
      ASSERT_NE(std::string(e.what()).find(file.path().string()), std::string::npos) << e.what();
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

std::string StateMessage(const std::string& bytes) {
  const TempFile file(".bin", bytes);
  try {
    ReadStateFile(file.path());
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(Contains(e.what(), "state file '" + file.path().string() + "': "));
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << Hex(bytes);
  return "";
}

template <class T>
std::string Patched(std::string bytes, std::size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof value);
  return bytes;
}

// 2 × 2 quads: 9 nodes (bytes 24-239), 4 quads (240-303), records of
// 16 + 48 · 9 = 448 bytes from byte 304.
TEST(ReaderFuzzRegression, StateFileRefusesWhatItCannotHold) {
  const std::string good = StateFileBytes(2, 2, 3);
  ASSERT_EQ(good.size(), 304u + 3 * 448);
  // A node count of 2^31 or more was a negative matrix size; a large one an
  // allocation of gigabytes the file cannot fill.
  EXPECT_TRUE(Contains(StateMessage(Patched<std::uint32_t>(good, 12, 0xffffffffu)),
                       "truncated mesh: the header gives 4294967295 nodes and 4 elements"));
  EXPECT_TRUE(Contains(StateMessage(Patched<std::uint32_t>(good, 16, 100000000u)),
                       "truncated mesh: the header gives 9 nodes and 100000000 elements"));
  // Quads whose nodes are not in the mesh were passed on to index with.
  EXPECT_TRUE(Contains(StateMessage(Patched<std::int32_t>(good, 240 + 16 * 2 + 4, 9)),
                       "quad 2 has node 9, outside the mesh's 9 nodes (byte 276)"));
  EXPECT_TRUE(Contains(StateMessage(Patched<std::int32_t>(good, 240, -1)),
                       "quad 0 has node -1, outside the mesh's 9 nodes (byte 240)"));
  // Numbers that are not finite, and directors that are not unit vectors
  // (the rotation rebuilt from one overflowed).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 24 + 24 * 5 + 8, nan)),
                       "node 5 of the mesh: its position is not a finite number (byte 144)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 448 + 8, nan)),
                       "record 1 (stage 0, step 2): the load factor is not a finite number "
                       "(byte 760)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 16 + 24 * 3, -HUGE_VAL)),
                       "record 0 (stage 0, step 1): node 3's position is not a finite number "
                       "(byte 392)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 2 * 448 + 16 + 24 * 9 + 24 * 8, nan)),
                       "record 2 (stage 1, step 3): node 8's director is not a finite number "
                       "(byte 1624)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 16 + 24 * 9 + 16, 3.0)),
                       "record 0 (stage 0, step 1): node 0's director is not a unit vector "
                       "(length 3) (byte 536)"));
  // A record cut off is still no error: the whole ones before it are kept.
  const TempFile cut(".bin", good.substr(0, good.size() - 7));
  EXPECT_EQ(ReadStateFile(cut.path()).steps.size(), 2u);
}

// A run killed while the header and mesh are written leaves no state file
// (they go to states.bin.part first); once the writer exists, the file reads
// with its mesh and no step, and no side file is left.
TEST(StateFileWriter, TheFileTakesItsNameOnlyWhenHeaderAndMeshAreWhole) {
  const Mesh mesh = MeshRectangle(0.2, 0.1, {0, 0}, 3, 2, 0.0);
  const TempFile file(".bin", "");
  std::filesystem::remove(file.path());
  StateFileWriter writer(file.path(), mesh);
  std::filesystem::path part = file.path();
  part += ".part";
  EXPECT_FALSE(std::filesystem::exists(part));
  const StateFile states = ReadStateFile(file.path());
  EXPECT_EQ(states.mesh.NodeCount(), 12);
  EXPECT_EQ(states.mesh.ElementCount(), 6);
  EXPECT_TRUE(states.steps.empty());
}

}  // namespace
}  // namespace drape
