#include "core/fe/fabric_plausibility.h"

#include <cmath>
#include <exception>
#include <variant>

#include "core/fe/material_section.h"
#include "core/model/string_format.h"

namespace drape {
namespace {

constexpr double kStandardGravity = 9.80665;  // m/s²: g/m² = N/m² · 1000 / g

// The warp's bending rigidity at small curvature [N·m²/m] (linear laws by
// default E h³/12, as the engine builds them).
double InitialRigidity(const Material& m) {
  const double e = std::holds_alternative<IsotropicMembrane>(m.membrane)
                       ? std::get<IsotropicMembrane>(m.membrane).youngs_modulus
                       : std::get<OrthotropicMembrane>(m.membrane).e1;
  const double h = m.thickness;
  return MakeStripLaw(m.bending.warp, e * h * h * h / 12, "material.bending")->Stiffness(0.0);
}

}  // namespace

std::vector<Implausible> ImplausibleFabric(const Material& m) {
  std::vector<Implausible> out;
  const double h = m.thickness;
  if (h > 5e-3) {
    // The number typed, read in metres, meant millimetres when that is a fabric's.
    const bool mm = h * 1e-3 >= 0.05e-3 && h * 1e-3 <= 5e-3;
    out.push_back({"material.thickness",
                   "thickness",
                   Format("%g m", h),
                   "thicker than any fabric (0.05–5 mm)",
                   mm ? Format("%g mm", h) : ""});
  }
  const double gsm = m.areal_weight * 1000.0 / kStandardGravity;
  if (m.areal_weight > 0 && (gsm < 20 || gsm > 1000)) {
    // A bare number is N/m²: one meant as g/m² reads 102 times too heavy.
    const bool meant_gsm = m.areal_weight >= 20 && m.areal_weight <= 1000;
    out.push_back({"material.areal_weight",
                   "weight",
                   Format("%.4g g/m² (%g N/m²)", gsm, m.areal_weight),
                   gsm < 20 ? "lighter than any fabric (20–1 000 g/m²)"
                            : "heavier than any fabric (20–1 000 g/m²)",
                   meant_gsm ? Format("%g g/m²", m.areal_weight) : ""});
  }
  if (m.areal_weight > 0 && h > 0) {
    double rigidity = 0;
    try {
      rigidity = InitialRigidity(m);
    } catch (const std::exception&) {
      return out;  // the reader or the engine says what is wrong with the law
    }
    const double c = std::cbrt(rigidity / m.areal_weight);
    if (std::isfinite(c) && (c < 0.3e-2 || c > 15e-2))
      out.push_back({"material.bending",
                     "bending length",
                     Format("%.3g cm", c * 100),
                     c < 0.3e-2 ? "limper than any fabric (bending length 0.3–15 cm)"
                                : "stiffer than any fabric (bending length 0.3–15 cm)",
                     ""});
  }
  return out;
}

std::string Describe(const Implausible& i) {
  std::string text = i.key + ": " + i.read_as + " is " + i.why;
  if (!i.did_you_mean.empty()) text += "; did you mean " + i.did_you_mean + "?";
  return text;
}

}  // namespace drape
