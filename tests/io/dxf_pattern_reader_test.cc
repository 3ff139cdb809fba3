// The AAMA DXF reader against files written by ezdxf, an independent DXF
// writer (tests/data/patterns/make_aama_dxf.py): the geometry the script
// draws, in centimetres, must come back in metres from every unit.
#include "core/io/dxf_pattern_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "support/aama_patterns.h"
#include "support/drape_command.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::TempDir;

// Writes the script's file for `units` and `variant` into `dir`.
std::filesystem::path MakePattern(const TempDir& dir,
                                  const std::string& units,
                                  const std::string& variant = "good") {
  return test::MakeAamaPattern(dir / (units + "-" + variant + ".dxf"), units, variant);
}

std::string ErrorOf(const std::filesystem::path& file) {
  try {
    ReadDxfPattern(file);
  } catch (const DxfPatternError& e) {
    return e.what();
  }
  return "";
}

void ExpectPoint(const PiecePoint& p, double x_cm, double y_cm) {
  EXPECT_NEAR(p[0], x_cm * 1e-2, 1e-12);
  EXPECT_NEAR(p[1], y_cm * 1e-2, 1e-12);
}

TEST(DxfPatternReader, ReadsTheScriptsPiecesInMetres) {
  TempDir dir("dxf-pieces");
  const DxfPattern pattern = ReadDxfPattern(MakePattern(dir, "mm"));
  EXPECT_EQ(pattern.unit, 1e-3);
  EXPECT_EQ(pattern.unit_source, "$INSUNITS");
  ASSERT_EQ(pattern.pieces.size(), 2u);
  const PatternPiece& front = FindPiece(pattern, "FRONT", "p.dxf");
  ASSERT_EQ(front.boundary.size(), 5u);
  ExpectPoint(front.boundary[1], 40, 0);
  ExpectPoint(front.boundary[3], 20, 32);
  ASSERT_EQ(front.holes.size(), 1u);
  ASSERT_EQ(front.holes[0].size(), 4u);
  ExpectPoint(front.holes[0][2], 15, 14);
  // Each notch is the end of its line that lies on the cut line.
  ASSERT_EQ(front.notches.size(), 4u);
  ExpectPoint(front.notches[0], 10, 0);
  ExpectPoint(front.notches[1], 40, 15);
  ExpectPoint(front.notches[3], 0, 20);
  ASSERT_EQ(front.drills.size(), 2u);
  ExpectPoint(front.drills[1], 30, 8);
  ASSERT_EQ(front.internal_lines.size(), 1u);
  ASSERT_TRUE(front.grain.has_value());
  // Ends rounded to the nanometre on a 12 cm line: within 1e-6°.
  EXPECT_NEAR(GrainAngleDeg(front), 30.0, 1e-6);

  const PatternPiece& back = FindPiece(pattern, "BACK", "p.dxf");
  ASSERT_EQ(back.boundary.size(), 4u);  // a closed 2-D POLYLINE
  ExpectPoint(back.boundary[2], 32, 28);
  EXPECT_NEAR(GrainAngleDeg(back), 90.0, 1e-9);
  EXPECT_TRUE(back.holes.empty());
}

TEST(DxfPatternReader, EveryUnitGivesTheSameMetres) {
  TempDir dir("dxf-units");
  const PatternPiece mm = ReadDxfPattern(MakePattern(dir, "mm")).pieces[0];
  for (const std::string units : {"in", "cm", "text-metric", "text-english"}) {
    SCOPED_TRACE(units);
    const PatternPiece other = ReadDxfPattern(MakePattern(dir, units)).pieces[0];
    ASSERT_EQ(other.boundary.size(), mm.boundary.size());
    for (std::size_t i = 0; i < mm.boundary.size(); ++i)
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(other.boundary[i][k], mm.boundary[i][k], 1e-12);
    ASSERT_EQ(other.notches.size(), 4u);
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(other.notches[2][k], mm.notches[2][k], 1e-12);
  }
}

TEST(DxfPatternReader, BadFilesSayWhatIsWrong) {
  TempDir dir("dxf-bad");
  EXPECT_NE(ErrorOf(MakePattern(dir, "mm", "open"))
                .find("piece 'FRONT': the cut line (layer 1) is open: its ends are 300 mm apart"),
            std::string::npos)
      << ErrorOf(MakePattern(dir, "mm", "open"));
  EXPECT_NE(ErrorOf(MakePattern(dir, "mm", "crossing"))
                .find("piece 'FRONT': the cut line (layer 1) crosses itself"),
            std::string::npos)
      << ErrorOf(MakePattern(dir, "mm", "crossing"));
  EXPECT_NE(ErrorOf(MakePattern(dir, "mm", "bulge")).find("arc segments (bulges)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(MakePattern(dir, "none")).find("states no length unit"), std::string::npos);

  // A coordinate beyond any double.
  std::string bytes;
  {
    std::ifstream in(MakePattern(dir, "mm"));
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto at = bytes.find("\n400.0\n");
  ASSERT_NE(at, std::string::npos);
  bytes.replace(at, 7, "\n1e999\n");
  std::ofstream(dir / "huge.dxf") << bytes;
  EXPECT_NE(ErrorOf(dir / "huge.dxf").find("piece 'FRONT': a coordinate is not a finite number"),
            std::string::npos)
      << ErrorOf(dir / "huge.dxf");

  const std::filesystem::path text = dir / "notes.dxf";
  std::ofstream(text) << "a pattern, but not a DXF\n";
  EXPECT_NE(ErrorOf(text).find("not a DXF file"), std::string::npos) << ErrorOf(text);
  EXPECT_NE(ErrorOf(dir / "missing.dxf").find("cannot be opened"), std::string::npos);

  const DxfPattern pattern = ReadDxfPattern(MakePattern(dir, "mm"));
  try {
    FindPiece(pattern, "SLEEVE", "p.dxf");
    ADD_FAILURE() << "no error for an unknown piece";
  } catch (const DxfPatternError& e) {
    EXPECT_STREQ(e.what(), "p.dxf: no piece 'SLEEVE'; the file has 'FRONT', 'BACK'");
  }
}

}  // namespace
}  // namespace drape
