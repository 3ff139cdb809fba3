// Fuzzing the DXF-AAMA pattern reader (dxflib underneath): mutated pattern
// files give pieces whose every number is finite, or one DxfPatternError;
// never a crash (the sanitized tier runs this too).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/io/dxf_pattern_reader.h"
#include "support/aama_patterns.h"
#include "support/drape_command.h"
#include "support/fuzz_files.h"
#include "support/fuzz_input.h"
#include "support/temp_dir.h"

namespace drape {
namespace {

using test::FuzzAlphabet;
using test::Mutator;

FuzzAlphabet DxfAlphabet() {
  return {"0123456789.-\n\r $ABCDEFGHIJKLMNOPQRSTUVWXYZ",
          {"\n0\n",           "\n8\n1\n",       "\n8\n4\n", "\n8\n7\n", "\n8\n11\n",
           "\n8\n13\n",       "\n10\n",         "\n20\n",   "\n42\n",   "\n70\n",
           "\n90\n",          "SECTION",        "ENDSEC",   "BLOCK",    "ENDBLK",
           "POLYLINE",        "LWPOLYLINE",     "VERTEX",   "SEQEND",   "LINE",
           "POINT",           "TEXT",           "INSERT",   "EOF",      "$INSUNITS",
           "UNITS = ENGLISH", "UNITS = METRIC", "\n2\n",    "\n1\n"}};
}

// Seeds written by ezdxf (tests/data/patterns/make_aama_dxf.py).
std::vector<std::string> DxfSeeds(const test::TempDir& dir) {
  std::vector<std::string> seeds;
  for (const char* units : {"mm", "text-english"})
    seeds.push_back(
        test::ReadBytes(test::MakeAamaPattern(dir / (std::string(units) + ".dxf"), units)));
  return seeds;
}

void ExpectFinite(const PieceLine& line, const std::string& what) {
  for (const PiecePoint& p : line) ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1])) << what;
}

void ExpectSoundPattern(const DxfPattern& pattern) {
  ASSERT_FALSE(pattern.pieces.empty());
  ASSERT_TRUE(std::isfinite(pattern.unit) && pattern.unit > 0);
  for (const PatternPiece& piece : pattern.pieces) {
    ASSERT_GE(piece.boundary.size(), 3u) << piece.name;
    ExpectFinite(piece.boundary, piece.name);
    for (const PieceLine& hole : piece.holes) ExpectFinite(hole, piece.name);
    for (const PieceLine& line : piece.internal_lines) ExpectFinite(line, piece.name);
    ExpectFinite(piece.notches, piece.name);
    ExpectFinite(piece.drills, piece.name);
    if (piece.grain) {
      ASSERT_TRUE(std::isfinite(GrainAngleDeg(piece))) << piece.name;
    }
  }
}

TEST(ReaderFuzzDxf, MutatedPatternsGivePiecesOrADxfPatternError) {
  test::TempDir dir("dxf-fuzz");
  const std::vector<std::string> seeds = DxfSeeds(dir);
  ASSERT_EQ(seeds.size(), 2u);
  Mutator mutator(20261205, DxfAlphabet());
  test::FuzzTally tally{"DXF-AAMA pattern"};
  // Each input goes through a file (the reader's only door): fewer than the
  // in-memory readers get.
  const int inputs = test::FuzzInputs(400);
  for (int i = 0; i < inputs; ++i) {
    const std::string bytes = mutator.Make(seeds);
    const test::TempFile file(".dxf", bytes);
    try {
      ExpectSoundPattern(ReadDxfPattern(file.path()));
      ++tally.accepted;
    } catch (const DxfPatternError& e) {
      ASSERT_NE(std::string(e.what()), "");
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

}  // namespace
}  // namespace drape
