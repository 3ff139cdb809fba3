// The lookup table each ColourMap fills, for the fabric's colour field and
// its bar. Internal to ui/render.
#pragma once

#include "ui/render/frame_renderer.h"

class vtkLookupTable;

namespace drape {

void FillColourMap(ColourMap map, vtkLookupTable* table);

}  // namespace drape
