// Pattern pieces to a DXF in the AAMA layout (ASTM D6673), as the reader
// (dxf_pattern_reader.h) and apparel CAD read it: one block per piece,
// inserted at the origin, on the standard's numbered layers, in
// millimetres ($INSUNITS 4 and the AAMA text "UNITS = METRIC"). Written by
// dxflib.
#pragma once

#include <filesystem>
#include <vector>

#include "core/model/pattern_piece.h"

namespace drape {

// Writes `pieces` (coordinates in metres) to `file`; throws
// std::runtime_error naming the file when it cannot be written.
void WriteDxfPattern(const std::filesystem::path& file, const std::vector<PatternPiece>& pieces);

}  // namespace drape
