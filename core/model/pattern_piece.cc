#include "core/model/pattern_piece.h"

#include <cmath>

namespace drape {

double GrainAngleDeg(const PatternPiece& piece) {
  const auto& [from, to] = *piece.grain;
  return std::atan2(to[1] - from[1], to[0] - from[0]) * 180.0 / M_PI;
}

}  // namespace drape
