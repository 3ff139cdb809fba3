// The colour maps by name, as the command line and the workbench offer them,
// and as the lookup table the fabric's field and its bar share.
#include "ui/render/colour_map.h"

#include <vtkLookupTable.h>

#include <algorithm>

namespace drape {
namespace {

// Viridis at nine evenly spaced points (matplotlib's data, CC0), in 0–255.
constexpr unsigned char kViridis[9][3] = {{68, 1, 84},
                                          {71, 44, 122},
                                          {59, 81, 139},
                                          {44, 113, 142},
                                          {33, 144, 141},
                                          {39, 173, 129},
                                          {92, 200, 99},
                                          {170, 220, 50},
                                          {253, 231, 37}};

}  // namespace

void FillColourMap(ColourMap map, vtkLookupTable* table) {
  constexpr int kEntries = 256;
  table->SetNumberOfTableValues(kEntries);
  if (map == ColourMap::kRainbow) {
    table->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
    table->ForceBuild();
    return;
  }
  for (int i = 0; i < kEntries; ++i) {
    const double t = 8.0 * i / (kEntries - 1);
    const int k = std::min(7, static_cast<int>(t));
    const double f = t - k;
    double rgb[3];
    for (int c = 0; c < 3; ++c)
      rgb[c] = ((1 - f) * kViridis[k][c] + f * kViridis[k + 1][c]) / 255.0;
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
}

const char* ToString(ColourMap map) {
  return map == ColourMap::kRainbow ? "rainbow" : "viridis";
}

std::optional<ColourMap> ColourMapNamed(std::string_view name) {
  for (ColourMap m : {ColourMap::kViridis, ColourMap::kRainbow})
    if (name == ToString(m)) return m;
  return std::nullopt;
}

}  // namespace drape
