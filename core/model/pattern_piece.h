// A pattern piece as apparel CAD draws it (ASTM D6673 / AAMA DXF): the cut
// line, the holes cut out of it, the named points a cutter or a sewer uses
// and the grain line, all in the piece's own plane coordinates [m].
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace drape {

using PiecePoint = std::array<double, 2>;
using PieceLine = std::vector<PiecePoint>;

struct PatternPiece {
  std::string name;
  PieceLine boundary;                     // the cut line, not closed (layer 1)
  std::vector<PieceLine> holes;           // internal cut-outs, each closed, not repeated (layer 11)
  std::vector<PiecePoint> notches;        // where each notch meets the cut line (layer 4)
  std::vector<PiecePoint> drills;         // drill holes (layer 13)
  std::vector<PieceLine> internal_lines;  // fold lines and placement marks (layer 8)
  // The grain line (layer 7), from its first point to its second: the warp.
  std::optional<std::array<PiecePoint, 2>> grain;

  friend bool operator==(const PatternPiece&, const PatternPiece&) = default;
};

// Where a piece lies on the part's plane: turned over (x → −x, the piece's
// other face up) when `flip`, then turned by `rotation_deg`
// counter-clockwise about the piece's origin, then moved by `at` [m].
struct PiecePlacement {
  PiecePoint at{0, 0};
  double rotation_deg = 0;
  bool flip = false;
  friend bool operator==(const PiecePlacement&, const PiecePlacement&) = default;
};

// `piece` with every point placed (its grain line turns with it).
PatternPiece Placed(PatternPiece piece, const PiecePlacement& placement);

// The grain line's direction from the piece's x axis [deg], in (−180, 180].
// Requires piece.grain.
double GrainAngleDeg(const PatternPiece& piece);

}  // namespace drape
