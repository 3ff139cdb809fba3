#include "core/io/pattern_spec.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/io/json_cursor.h"
#include "core/model/outline_geometry.h"
#include "core/model/polygon_checks.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

constexpr int kPatternFormatVersion = 1;
// A notch is on the cut line when it is this close [m]: well below what a
// cutter resolves, well above rounding.
constexpr double kOnCutLine = 1e-5;

std::vector<Eigen::Vector2d> Points(const PieceLine& line) {
  std::vector<Eigen::Vector2d> points;
  for (const PiecePoint& p : line) points.emplace_back(p[0], p[1]);
  return points;
}

PieceLine ReadLine(const JsonCursor& c, std::size_t at_least) {
  PieceLine line;
  for (const JsonCursor& item : c.Items()) line.push_back(item.QuantityVec2(dim::kLength));
  if (line.size() < at_least)
    c.Fail("expected at least " + std::to_string(at_least) + " points, found " +
           std::to_string(line.size()));
  return line;
}

// A closed polyline (not repeating its first point) that does not cross
// itself and encloses an area.
PieceLine ReadLoop(const JsonCursor& c) {
  const PieceLine loop = ReadLine(c, 3);
  const std::vector<Eigen::Vector2d> points = Points(loop);
  double extent = 0;
  for (const auto& p : points) extent = std::max(extent, (p - points.front()).norm());
  const double zero = 1e-12 * extent * extent;
  if (const auto crossing = FirstCrossing(points, zero))
    c.Fail("crosses itself: its segments " + std::to_string(crossing->first + 1) + " and " +
           std::to_string(crossing->second + 1) + " (counted from its first point) meet");
  if (!(std::abs(ShoelaceArea(points)) > zero)) c.Fail("encloses no area");
  return loop;
}

bool InsidePiece(const PatternPiece& piece, const PiecePoint& p) {
  return DistanceToOutline(PolygonOutline{piece.boundary}, p) == 0 &&
         DistanceToLoop(piece.boundary, p) > 0;
}

PatternPiece ReadPiece(const JsonCursor& c) {
  c.ExpectObject({"name", "cut", "cut_outs", "notches", "drills", "internal_lines", "grain"});
  PatternPiece piece;
  piece.name = c["name"].String();
  if (piece.name.empty()) c["name"].Fail("a piece needs a name");
  piece.boundary = ReadLoop(c["cut"]);
  if (auto holes = c.Find("cut_outs"))
    for (const JsonCursor& h : holes->Items()) {
      piece.holes.push_back(ReadLoop(h));
      for (const PiecePoint& p : piece.holes.back())
        if (!InsidePiece(piece, p)) h.Fail("must lie inside the cut line");
    }
  if (auto notches = c.Find("notches"))
    for (const JsonCursor& n : notches->Items()) {
      piece.notches.push_back(n.QuantityVec2(dim::kLength));
      if (const double d = DistanceToLoop(piece.boundary, piece.notches.back()); d > kOnCutLine)
        n.Fail("a notch lies on the cut line; this one is " + std::to_string(d * 1e3) +
               " mm from it");
    }
  if (auto drills = c.Find("drills"))
    for (const JsonCursor& d : drills->Items()) {
      piece.drills.push_back(d.QuantityVec2(dim::kLength));
      if (!InsidePiece(piece, piece.drills.back())) d.Fail("must lie inside the cut line");
    }
  if (auto lines = c.Find("internal_lines"))
    for (const JsonCursor& l : lines->Items()) {
      piece.internal_lines.push_back(ReadLine(l, 2));
      for (const PiecePoint& p : piece.internal_lines.back())
        if (DistanceToOutline(PolygonOutline{piece.boundary}, p) > kOnCutLine)
          l.Fail("must lie inside the cut line (or end on it)");
    }
  if (auto grain = c.Find("grain")) {
    const auto ends = grain->Items(2);
    const std::array<PiecePoint, 2> g{ends[0].QuantityVec2(dim::kLength),
                                      ends[1].QuantityVec2(dim::kLength)};
    if (g[0] == g[1]) grain->Fail("the grain line's two ends must differ");
    piece.grain = g;
  }
  return piece;
}

}  // namespace

std::vector<PatternPiece> ReadPatternSpec(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec))
    throw SceneError("", "cannot open pattern file '" + file.string() + "'");
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError("", file.string() + " is not valid JSON: " + e.what());
  }
  const JsonCursor root(document, "");
  root.ExpectObject({"drape_pattern", "name", "description", "pieces"});
  if (root["drape_pattern"].Integer() != kPatternFormatVersion)
    root["drape_pattern"].Fail("this program reads pattern format 1");
  std::vector<PatternPiece> pieces;
  std::set<std::string> names;
  const auto items = root["pieces"].Items();
  if (items.empty()) root["pieces"].Fail("expected at least one piece");
  for (const JsonCursor& item : items) {
    pieces.push_back(ReadPiece(item));
    if (!names.insert(pieces.back().name).second)
      item["name"].Fail("two pieces are named '" + pieces.back().name + "'");
  }
  return pieces;
}

}  // namespace drape
