// The AAMA DXF writer, read back two ways: by ezdxf, an independent reader
// (tests/data/patterns/describe_dxf.py), and by the project's own reader.
#include "core/io/dxf_pattern_writer.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/io/dxf_pattern_reader.h"
#include "support/aama_patterns.h"
#include "support/drape_command.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::TempDir;

// A 30 × 20 cm panel with a 4 × 2 cm cut-out, two notches, a drill hole,
// a fold line and a grain line at 45°.
PatternPiece Panel() {
  PatternPiece p;
  p.name = "PANEL";
  p.boundary = {{0, 0}, {0.30, 0}, {0.30, 0.20}, {0, 0.20}};
  p.holes = {{{0.10, 0.05}, {0.14, 0.05}, {0.14, 0.07}, {0.10, 0.07}}};
  p.notches = {{0.15, 0}, {0.30, 0.10}};
  p.drills = {{0.20, 0.15}};
  p.internal_lines = {{{0.15, 0}, {0.15, 0.20}}};
  p.grain = std::array<PiecePoint, 2>{PiecePoint{0.05, 0.05}, PiecePoint{0.10, 0.10}};
  return p;
}

TEST(DxfPatternWriter, EzdxfReadsThePieceInMillimetres) {
  TempDir dir("dxf-writer");
  WriteDxfPattern(dir / "out.dxf", {Panel()});
  const nlohmann::json d = test::DescribedByEzdxf(dir / "out.dxf");
  EXPECT_EQ(d["insunits"], 4);
  const nlohmann::json& panel = d["pieces"]["PANEL"];
  EXPECT_EQ(panel["cut_points"], 4);
  EXPECT_NEAR(panel["cut_area"].get<double>(), 300.0 * 200.0, 1e-6);
  ASSERT_EQ(panel["holes"].size(), 1u);
  EXPECT_NEAR(panel["holes"][0].get<double>(), 40.0 * 20.0, 1e-6);
  ASSERT_EQ(panel["notches"].size(), 2u);
  EXPECT_NEAR(panel["notches"][1][0].get<double>(), 300.0, 1e-9);
  EXPECT_NEAR(panel["notches"][1][1].get<double>(), 100.0, 1e-9);
  EXPECT_EQ(panel["drills"], 1);
  EXPECT_NEAR(panel["grain_deg"].get<double>(), 45.0, 1e-9);
}

TEST(DxfPatternWriter, TheReaderGetsBackWhatWasWritten) {
  TempDir dir("dxf-roundtrip");
  WriteDxfPattern(dir / "out.dxf", {Panel()});
  const DxfPattern pattern = ReadDxfPattern(dir / "out.dxf");
  ASSERT_EQ(pattern.pieces.size(), 1u);
  EXPECT_EQ(pattern.pieces[0], Panel());
}

TEST(DxfPatternWriter, AFolderThatCannotBeWrittenIsAnError) {
  TempDir dir("dxf-writer-bad");
  EXPECT_THROW(WriteDxfPattern(dir / "no" / "such" / "out.dxf", {Panel()}), std::runtime_error);
}

}  // namespace
}  // namespace drape
