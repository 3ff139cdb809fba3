#include "core/io/dxf_pattern_reader.h"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <regex>

#include "core/model/outline_geometry.h"
#include "core/model/polygon_checks.h"

namespace drape {
namespace {

// ASTM D6673's layers, by number.
constexpr int kCutLine = 1;
constexpr int kNotches = 4;
constexpr int kGrainLine = 7;
constexpr int kInternalLines = 8;
constexpr int kCutOuts = 11;
constexpr int kDrillHoles = 13;

std::string Mm(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g mm", metres * 1e3);
  return text;
}

// A layer's number: "1", " 4 " → 1, 4; anything else → −1.
int LayerNumber(const std::string& layer) {
  const auto first = layer.find_first_not_of(' ');
  const auto last = layer.find_last_not_of(' ');
  if (first == std::string::npos) return -1;
  const std::string digits = layer.substr(first, last - first + 1);
  if (digits.size() > 3 ||
      !std::all_of(digits.begin(), digits.end(), [](unsigned char ch) { return std::isdigit(ch); }))
    return -1;
  return std::stoi(digits);
}

// $INSUNITS codes with a length [m].
std::optional<double> InsunitsLength(int code) {
  switch (code) {
    case 1:
      return 0.0254;  // inches
    case 2:
      return 0.3048;  // feet
    case 4:
      return 1e-3;  // millimetres
    case 5:
      return 1e-2;  // centimetres
    case 6:
      return 1.0;  // metres
    default:
      return std::nullopt;
  }
}

struct Polyline {
  int layer = -1;
  bool closed = false;
  bool bulged = false;
  PieceLine points;
};

// One block's entities as drawn, in drawing units.
struct RawPiece {
  std::string name;
  PiecePoint base{0, 0};
  std::vector<Polyline> polylines;
  std::vector<std::array<PiecePoint, 2>> lines[14];  // by layer, 1…13
  std::vector<PiecePoint> points[14];
};

// Collects what dxflib parses: the blocks (pieces), their polylines, lines
// and points by layer, and the units.
class AamaCollector : public DL_CreationAdapter {
 public:
  std::vector<RawPiece> pieces;
  std::optional<int> insunits;
  std::optional<double> units_text;  // [m] per unit from "UNITS = …"

  void addBlock(const DL_BlockData& data) override {
    Flush();
    in_block_ = !data.name.empty() && data.name[0] != '*';
    if (in_block_) pieces.push_back({data.name, {data.bpx, data.bpy}, {}, {}, {}});
  }
  void endBlock() override {
    Flush();
    in_block_ = false;
  }
  void addPolyline(const DL_PolylineData& data) override {
    Flush();
    if (!in_block_) return;
    pending_ = Polyline{Layer(), (data.flags & 1) != 0, false, {}};
  }
  void addVertex(const DL_VertexData& data) override {
    if (!pending_) return;
    pending_->points.push_back({data.x, data.y});
    if (std::abs(data.bulge) > 1e-12) pending_->bulged = true;
  }
  void endSequence() override { Flush(); }
  void addLine(const DL_LineData& data) override {
    Flush();
    if (const int layer = Layer(); in_block_ && layer >= 1 && layer <= 13)
      pieces.back().lines[layer].push_back({{{data.x1, data.y1}, {data.x2, data.y2}}});
  }
  void addPoint(const DL_PointData& data) override {
    Flush();
    if (const int layer = Layer(); in_block_ && layer >= 1 && layer <= 13)
      pieces.back().points[layer].push_back({data.x, data.y});
  }
  void addText(const DL_TextData& data) override {
    Flush();
    ReadUnitsText(data.text);
  }
  void addMText(const DL_MTextData& data) override {
    Flush();
    ReadUnitsText(data.text);
  }
  void addInsert(const DL_InsertData&) override { Flush(); }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") insunits = value;
  }

  void Flush() {
    if (pending_ && in_block_) pieces.back().polylines.push_back(std::move(*pending_));
    pending_.reset();
  }

 private:
  int Layer() { return LayerNumber(getAttributes().getLayer()); }

  // AAMA states units in a text: "UNITS = ENGLISH" (inches) or
  // "UNITS = METRIC" (millimetres).
  void ReadUnitsText(const std::string& text) {
    static const std::regex kUnits(R"(UNITS\s*[=:]\s*(ENGLISH|METRIC))", std::regex::icase);
    std::smatch m;
    if (!std::regex_search(text, m, kUnits)) return;
    const bool english = std::toupper(static_cast<unsigned char>(m[1].str()[0])) == 'E';
    units_text = english ? 0.0254 : 1e-3;
  }

  bool in_block_ = false;
  std::optional<Polyline> pending_;
};

// The first group of an ASCII DXF is "0 / SECTION" (after comments, 999).
void RequireAsciiDxf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw DxfPatternError(file.string() + ": cannot be opened");
  std::string code, value;
  auto next = [&](std::string& s) {
    if (!std::getline(in, s)) return false;
    s.erase(std::remove_if(s.begin(), s.end(), [](char ch) { return ch == '\r'; }), s.end());
    const auto a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    s = a == std::string::npos ? "" : s.substr(a, b - a + 1);
    return true;
  };
  while (next(code) && next(value)) {
    if (code == "999") continue;
    if (code == "0" && value == "SECTION") return;
    break;
  }
  std::ifstream again(file, std::ios::binary);
  char magic[18] = {};
  again.read(magic, sizeof magic);
  if (std::string(magic, sizeof magic) == "AutoCAD Binary DXF")
    throw DxfPatternError(file.string() + ": a binary DXF; save the pattern as ASCII DXF");
  throw DxfPatternError(file.string() +
                        ": not a DXF file (an ASCII DXF begins with the group 0 / SECTION)");
}

// In metres, rounded to the nanometre: a piece saved in inches and in
// millimetres then has the very same coordinates (the two conversions differ
// in the last bits, and Gmsh's mesh follows such bits), 10⁻⁶ of any cutting
// tolerance.
PiecePoint Scaled(const PiecePoint& p, const PiecePoint& base, double unit) {
  auto metres = [&](double x, double origin) {
    return std::round((x - origin) * unit * 1e9) / 1e9;
  };
  return {metres(p[0], base[0]), metres(p[1], base[1])};
}

PieceLine Scaled(const PieceLine& line, const PiecePoint& base, double unit) {
  PieceLine out;
  for (const auto& p : line) out.push_back(Scaled(p, base, unit));
  return out;
}

double Distance(const PiecePoint& a, const PiecePoint& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// A closed loop from a polyline (in metres): the closing vertex dropped when
// the file repeats the first; an error naming `what` when its ends do not
// meet.
PieceLine ClosedLoop(PieceLine points, bool closed, const std::string& what) {
  if (points.size() >= 2) {
    const double size = Distance(points.front(), points.back());
    double extent = 0;
    for (const auto& p : points) extent = std::max(extent, Distance(p, points.front()));
    if (size <= 1e-9 * std::max(extent, 1e-12)) {
      points.pop_back();
    } else if (!closed) {
      throw DxfPatternError(what + " is open: its ends are " + Mm(size) +
                            " apart (close the polyline)");
    }
  }
  if (points.size() < 3)
    throw DxfPatternError(what + " has " + std::to_string(points.size()) +
                          " distinct points; a closed line needs at least 3");
  return points;
}

// "" for a simple loop, else which of its segments cross.
std::string SelfCrossing(const PieceLine& loop) {
  std::vector<Eigen::Vector2d> points;
  double extent = 0;
  for (const auto& p : loop) {
    points.emplace_back(p[0], p[1]);
    extent = std::max(extent, (points.back() - points.front()).norm());
  }
  const auto crossing = FirstCrossing(points, 1e-12 * extent * extent);
  if (!crossing) return "";
  return "crosses itself: its segments " + std::to_string(crossing->first + 1) + " and " +
         std::to_string(crossing->second + 1) + " (counted from its first point) meet";
}

// Every number a reader computes with must be one: a DXF may hold
// "1e999", "nan" or 1e308 (finite, but not once in nanometres) where a
// coordinate belongs.
void RequireFinite(const RawPiece& raw, double unit, const std::string& where) {
  auto finite = [&](const PiecePoint& p) {
    return std::isfinite((p[0] - raw.base[0]) * unit * 1e9) &&
           std::isfinite((p[1] - raw.base[1]) * unit * 1e9);
  };
  bool ok = std::isfinite(raw.base[0]) && std::isfinite(raw.base[1]);
  for (const Polyline& p : raw.polylines)
    for (const PiecePoint& q : p.points) ok = ok && finite(q);
  for (int layer = 0; layer < 14; ++layer) {
    for (const auto& line : raw.lines[layer]) ok = ok && finite(line[0]) && finite(line[1]);
    for (const PiecePoint& q : raw.points[layer]) ok = ok && finite(q);
  }
  if (!ok) throw DxfPatternError(where + ": a coordinate is not a finite number");
}

PatternPiece MakePiece(const RawPiece& raw, double unit, const std::filesystem::path& file) {
  const std::string where = file.string() + ": piece '" + raw.name + "'";
  RequireFinite(raw, unit, where);
  PatternPiece piece;
  piece.name = raw.name;
  std::vector<const Polyline*> cut_lines;
  for (const Polyline& p : raw.polylines) {
    if (p.bulged && (p.layer == kCutLine || p.layer == kCutOuts))
      throw DxfPatternError(where + ": a polyline on layer " + std::to_string(p.layer) +
                            " has arc segments (bulges); AAMA draws curves as points");
    if (p.layer == kCutLine) cut_lines.push_back(&p);
  }
  if (cut_lines.empty())
    throw DxfPatternError(where + ": no cut line (a closed polyline on layer 1)");
  if (cut_lines.size() > 1)
    throw DxfPatternError(where + ": " + std::to_string(cut_lines.size()) +
                          " polylines on layer 1; a piece has one cut line");
  piece.boundary = ClosedLoop(Scaled(cut_lines[0]->points, raw.base, unit),
                              cut_lines[0]->closed,
                              where + ": the cut line (layer 1)");
  if (const std::string crossing = SelfCrossing(piece.boundary); !crossing.empty())
    throw DxfPatternError(where + ": the cut line (layer 1) " + crossing);
  int hole = 0;
  for (const Polyline& p : raw.polylines) {
    if (p.layer == kCutOuts) {
      const std::string what =
          where + ": internal cut-out " + std::to_string(++hole) + " (layer 11)";
      piece.holes.push_back(ClosedLoop(Scaled(p.points, raw.base, unit), p.closed, what));
      if (const std::string crossing = SelfCrossing(piece.holes.back()); !crossing.empty())
        throw DxfPatternError(what + " " + crossing);
    } else if (p.layer == kInternalLines) {
      piece.internal_lines.push_back(Scaled(p.points, raw.base, unit));
    }
  }
  for (const auto& line : raw.lines[kInternalLines])
    piece.internal_lines.push_back(
        {Scaled(line[0], raw.base, unit), Scaled(line[1], raw.base, unit)});
  // A notch is drawn as a short line into the piece from the cut line (or
  // as a point on it): the end on the cut line is the notch.
  for (const auto& line : raw.lines[kNotches]) {
    const PiecePoint a = Scaled(line[0], raw.base, unit), b = Scaled(line[1], raw.base, unit);
    piece.notches.push_back(
        DistanceToLoop(piece.boundary, a) <= DistanceToLoop(piece.boundary, b) ? a : b);
  }
  for (const auto& p : raw.points[kNotches]) piece.notches.push_back(Scaled(p, raw.base, unit));
  for (const auto& p : raw.points[kDrillHoles]) piece.drills.push_back(Scaled(p, raw.base, unit));
  const auto& grains = raw.lines[kGrainLine];
  if (grains.size() > 1)
    throw DxfPatternError(where + ": " + std::to_string(grains.size()) +
                          " grain lines on layer 7; a piece has one");
  if (!grains.empty()) {
    const PiecePoint a = Scaled(grains[0][0], raw.base, unit),
                     b = Scaled(grains[0][1], raw.base, unit);
    if (Distance(a, b) <= 0)
      throw DxfPatternError(where + ": the grain line (layer 7) has no length");
    piece.grain = std::array<PiecePoint, 2>{a, b};
  }
  return piece;
}

}  // namespace

DxfPattern ReadDxfPattern(const std::filesystem::path& file) {
  RequireAsciiDxf(file);
  AamaCollector collector;
  DL_Dxf dxf;
  if (!dxf.in(file.string(), &collector))
    throw DxfPatternError(file.string() + ": cannot be opened");
  collector.Flush();
  DxfPattern pattern;
  if (collector.insunits && InsunitsLength(*collector.insunits)) {
    pattern.unit = *InsunitsLength(*collector.insunits);
    pattern.unit_source = "$INSUNITS";
  } else if (collector.units_text) {
    pattern.unit = *collector.units_text;
    pattern.unit_source = "UNITS";
  } else {
    throw DxfPatternError(
        file.string() +
        ": the file states no length unit: give the header variable $INSUNITS (1 inches, 4 "
        "millimetres, 5 centimetres, 6 metres) or the AAMA text 'UNITS = ENGLISH' or "
        "'UNITS = METRIC'" +
        (collector.insunits ? " ($INSUNITS is " + std::to_string(*collector.insunits) + ")" : ""));
  }
  for (const RawPiece& raw : collector.pieces) {
    // Blocks that draw no cut line are not pieces (title blocks, symbols).
    const bool has_cut_line = std::any_of(raw.polylines.begin(),
                                          raw.polylines.end(),
                                          [](const Polyline& p) { return p.layer == kCutLine; });
    if (has_cut_line) pattern.pieces.push_back(MakePiece(raw, pattern.unit, file));
  }
  if (pattern.pieces.empty())
    throw DxfPatternError(file.string() +
                          ": no pattern piece (a block with a closed polyline on layer 1)");
  return pattern;
}

const PatternPiece& FindPiece(const DxfPattern& pattern,
                              const std::string& name,
                              const std::filesystem::path& file) {
  for (const PatternPiece& p : pattern.pieces)
    if (p.name == name) return p;
  std::string names;
  for (const PatternPiece& p : pattern.pieces)
    names += (names.empty() ? "'" : ", '") + p.name + "'";
  throw DxfPatternError(file.string() + ": no piece '" + name + "'; the file has " + names);
}

}  // namespace drape
