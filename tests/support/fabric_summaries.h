// A lab summary of a shirting, in KES units: T 0.5 mm, W 150 g/m², B 0.08
// (warp) and 0.05 (weft) gf·cm²/cm, G 0.8 gf/(cm·deg), 400 and 250 gf/cm per
// width, ν₁₂ 0.3 — what the textile-figures tests turn into SI by hand.
#pragma once

#include "core/fe/textile_figures.h"

namespace drape::test {

inline FabricSummary Shirting() {
  FabricSummary s;
  s.thickness_mm = 0.5;
  s.weight_g_per_m2 = 150;
  s.bending_warp = 0.08;
  s.bending_weft = 0.05;
  s.shear = 0.8;
  s.tensile_warp = 400;
  s.tensile_weft = 250;
  s.poisson_ratio = 0.3;
  return s;
}

}  // namespace drape::test
