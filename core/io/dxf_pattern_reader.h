// Pattern pieces from a DXF in the AAMA layout (ASTM D6673), as Gerber
// AccuMark, Lectra Modaris, Optitex, CLO and Valentina export them: one
// block per piece, named after it, with the standard's numbered layers —
// 1 the cut line, 4 notches, 7 the grain line, 8 internal lines, 11
// internal cut-outs, 13 drill holes (others are read past). Parsed by
// dxflib; lengths come out in metres.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/model/pattern_piece.h"

namespace drape {

// What is wrong with a pattern file, naming the file and the piece.
class DxfPatternError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DxfPattern {
  std::vector<PatternPiece> pieces;  // in the file's order
  // The drawing unit [m] and where it was stated: "$INSUNITS" or the
  // AAMA "UNITS" text.
  double unit = 1;
  std::string unit_source;
};

// Reads every piece of `file`. Throws DxfPatternError for a file that is
// not DXF, states no units, or has a piece whose cut line is open, crosses
// itself, is missing or bulges (AAMA draws curves as points); and for a
// file with no piece at all.
DxfPattern ReadDxfPattern(const std::filesystem::path& file);

// The piece called `name`; a DxfPatternError listing the pieces otherwise.
const PatternPiece& FindPiece(const DxfPattern& pattern,
                              const std::string& name,
                              const std::filesystem::path& file);

}  // namespace drape
