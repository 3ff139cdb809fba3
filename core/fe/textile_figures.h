// A fabric in the figures a textile lab reports (KES-FB, FAST): thickness,
// weight, bending rigidity of warp and weft, shear rigidity and tensile
// stiffness per width — read from a material as the engine builds it, and a
// material made from such a summary.
#pragma once

#include <string>

#include "core/mechanics/moment_curvature.h"
#include "core/model/scene.h"

namespace drape {

struct TextileFigures {
  double thickness_mm = 0, weight_g_per_m2 = 0;
  double bending_warp = 0, bending_weft = 0;        // Kawabata B [gf·cm²/cm]
  double hysteresis_warp = 0, hysteresis_weft = 0;  // 2HB [gf·cm/cm]
  double shear = 0;                                 // G [gf/(cm·deg)]
  double tensile_warp = 0, tensile_weft = 0;        // membrane per width E·h [gf/cm]
  double poisson_ratio = 0;
  std::string membrane, bending_warp_law, bending_weft_law;
};

// The figures of `material`, its bending laws built as the engine builds
// them (without a weft law the warp's bends every direction). Throws
// SceneError for a law that cannot be built.
TextileFigures FiguresOf(const Material& material);

// Kawabata's B of a strip law: its mean slope between K = 0.5 and 1.5 1/cm
// (a linear law's rigidity) [gf·cm²/cm].
double KawabataB(const MomentCurvatureLaw& strip);

// The extension at the KES-FB1 load (500 gf/cm) of a linear membrane of
// `tensile` gf/cm per width [%].
double EmtPercent(double tensile_gf_per_cm);

// A fabric as a lab summary gives it, in its units.
struct FabricSummary {
  double thickness_mm = 0;                    // T (KES-FB3 at 0.5 gf/cm², FAST T2)
  double weight_g_per_m2 = 0;                 // W
  double bending_warp = 0, bending_weft = 0;  // B [gf·cm²/cm] (FAST: µN·m / 98.0665)
  double shear = 0;                           // G [gf/(cm·deg)]
  double tensile_warp = 0, tensile_weft = 0;  // per width [gf/cm] (KES: 500 / EMT %·100)
  double poisson_ratio = 0.3;                 // ν₁₂: summaries give none
};

// The material of a summary: linear bending with B for warp and weft (one
// law when they agree), an orthotropic membrane E = tensile / h, G₁₂ =
// G / h (per radian). FiguresOf gives the summary back. Throws
// std::invalid_argument naming the first figure that is not greater than
// zero (ν₁₂ may be zero).
Material MaterialFromSummary(const FabricSummary& summary);

}  // namespace drape
