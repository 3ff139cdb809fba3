#include "core/model/pattern_piece.h"

#include <cmath>

namespace drape {

PatternPiece Placed(PatternPiece piece, const PiecePlacement& placement) {
  const double a = placement.rotation_deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
  auto place = [&](PiecePoint& p) {
    const double x = placement.flip ? -p[0] : p[0], y = p[1];
    p = {placement.at[0] + c * x - s * y, placement.at[1] + s * x + c * y};
  };
  auto place_line = [&](PieceLine& line) {
    for (PiecePoint& p : line) place(p);
  };
  place_line(piece.boundary);
  for (PieceLine& hole : piece.holes) place_line(hole);
  place_line(piece.notches);
  place_line(piece.drills);
  for (PieceLine& line : piece.internal_lines) place_line(line);
  if (piece.grain)
    for (PiecePoint& p : *piece.grain) place(p);
  return piece;
}

double GrainAngleDeg(const PatternPiece& piece) {
  const auto& [from, to] = *piece.grain;
  return std::atan2(to[1] - from[1], to[0] - from[0]) * 180.0 / M_PI;
}

}  // namespace drape
