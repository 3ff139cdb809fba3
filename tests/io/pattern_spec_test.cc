// Pieces described in JSON (drape_pattern files): the shipped garments read
// with the coordinates they state, and each kind of mistake named at its
// key.
#include "core/io/pattern_spec.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/model/scene_error.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

std::string ErrorOf(const std::string& text) {
  test::TempDir dir("pattern-spec");
  std::ofstream(dir / "p.json") << text;
  try {
    ReadPatternSpec(dir / "p.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// One piece, `extra` members added to a 10 cm square.
std::string Piece(const std::string& extra, const std::string& name = "P") {
  return R"({"name": ")" + name +
         R"(", "cut": [[0, 0], ["10 cm", 0], ["10 cm", "10 cm"], [0, "10 cm"]])" + extra + "}";
}

std::string Spec(const std::string& pieces) {
  return R"({"drape_pattern": 1, "pieces": [)" + pieces + "]}";
}

TEST(PatternSpec, ReadsTheShippedGarmentsInMetres) {
  const auto pieces =
      ReadPatternSpec(test::SourceDir() / "resources" / "patterns" / "garments.json");
  ASSERT_EQ(pieces.size(), 2u);
  const PatternPiece& skirt = pieces[0];
  EXPECT_EQ(skirt.name, "SKIRT-FRONT");
  ASSERT_EQ(skirt.boundary.size(), 13u);
  EXPECT_NEAR(skirt.boundary[2][0], 0.245, 1e-15);
  EXPECT_NEAR(skirt.boundary[2][1], 0.35, 1e-15);
  EXPECT_EQ(skirt.notches.size(), 4u);
  EXPECT_EQ(skirt.drills.size(), 3u);
  ASSERT_EQ(skirt.internal_lines.size(), 3u);
  EXPECT_EQ(skirt.internal_lines[1].size(), 3u);  // a dart: two legs
  ASSERT_TRUE(skirt.grain.has_value());
  EXPECT_NEAR((*skirt.grain)[1][0], 0.05, 1e-15);
  EXPECT_NEAR((*skirt.grain)[1][1], 0.40, 1e-15);
  EXPECT_EQ(pieces[1].name, "TSHIRT-FRONT");
  EXPECT_EQ(pieces[1].boundary.size(), 21u);
}

TEST(PatternSpec, MistakesAreNamedAtTheirKey) {
  EXPECT_EQ(ErrorOf(Spec(Piece(R"(, "notches": [["5 cm", "1 cm"]])"))),
            "pieces[0].notches[0]: a notch lies on the cut line; this one is 10.000000 mm from it");
  EXPECT_EQ(ErrorOf(Spec(Piece(R"(, "drills": [["15 cm", "5 cm"]])"))),
            "pieces[0].drills[0]: must lie inside the cut line");
  EXPECT_EQ(ErrorOf(Spec(Piece(R"(, "internal_lines": [[["5 cm", "5 cm"], ["20 cm", "5 cm"]]])"))),
            "pieces[0].internal_lines[0]: must lie inside the cut line (or end on it)");
  EXPECT_EQ(ErrorOf(Spec(Piece(
                R"(, "cut_outs": [[["8 cm", "8 cm"], ["12 cm", "8 cm"], ["12 cm", "9 cm"]]])"))),
            "pieces[0].cut_outs[0]: must lie inside the cut line");
  EXPECT_EQ(ErrorOf(Spec(Piece(R"(, "grain": [["5 cm", "5 cm"], ["5 cm", "5 cm"]])"))),
            "pieces[0].grain: the grain line's two ends must differ");
  EXPECT_EQ(ErrorOf(Spec(Piece("") + ", " + Piece(""))),
            "pieces[1].name: two pieces are named 'P'");
  EXPECT_EQ(ErrorOf(Spec(R"({"name": "X", "cut": [[0, 0], [1, 1], [1, 0], [0, 1]]})")),
            "pieces[0].cut: crosses itself: its segments 1 and 3 (counted from its first point) "
            "meet");
  EXPECT_EQ(ErrorOf(Spec(R"({"name": "X", "cut": [[0, 0], [1, 1]]})")),
            "pieces[0].cut: expected at least 3 points, found 2");
  EXPECT_EQ(ErrorOf(Spec(Piece(R"(, "notches": [["5 cm", "1 kg"]])"))).substr(0, 22),
            "pieces[0].notches[0][1");
  EXPECT_EQ(ErrorOf(R"({"drape_pattern": 2, "pieces": []})"),
            "drape_pattern: this program reads pattern format 1");
  EXPECT_EQ(ErrorOf(Spec("")), "pieces: expected at least one piece");
  EXPECT_NE(ErrorOf("{").find("is not valid JSON"), std::string::npos);
}

}  // namespace
}  // namespace drape
