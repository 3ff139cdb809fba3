// Pattern pieces described in JSON (a "drape_pattern" file, docs/format.md
// §9), for writing a DXF-AAMA file with `drape pattern write`: pieces made
// by a script or by hand, in any length unit, checked as a cutting room
// would need them.
#pragma once

#include <filesystem>
#include <vector>

#include "core/model/pattern_piece.h"

namespace drape {

// Reads and checks `file`: each piece's cut line a simple polygon, its
// cut-outs inside it, its notches on it, its drill holes and internal lines
// inside it. Throws SceneError naming the key.
std::vector<PatternPiece> ReadPatternSpec(const std::filesystem::path& file);

}  // namespace drape
