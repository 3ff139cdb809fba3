// The units a user reads and types quantities in: SI, textile (cm, mm, gf,
// g/m², as in the KES and FAST literature) or imperial (in, oz/in², as in
// Eischen, Deng & Clapp 1996). Values stay SI everywhere else; these only
// turn an SI value into text and say which unit a label names.
//
// Units per system and measure (value shown = SI value / si_factor):
//
//   measure           SI          textile      imperial
//   length            m           cm           in
//   thickness         m           mm           in
//   force             N           gf           oz
//   pressure/modulus  Pa          gf/cm²       oz/in²
//   areal weight      N/m²        g/m²         oz/in²
//   areal density     kg/m²       g/m²         g/m²  (no mass unit of its own)
//   curvature         1/m         1/cm         1/in
//   moment            N·m         gf·cm        oz·in
//   moment per width  N·m/m       gf·cm/cm     oz·in/in
//   bending rigidity  N·m²/m      gf·cm²/cm    oz·in²/in
//   force per length  N/m         gf/cm        oz/in
//   energy per area   N·m/m²      gf·cm/cm²    oz·in/in²
//   penalty per area  N/m³        gf/cm³       oz/in³
//   area              m²          cm²          in²
//   mass              kg          g            g     (no mass unit of its own)
//   angle             deg         deg          deg
//
// Thickness is in mm for textiles because fabric gauges (KES-FB3) read mm;
// areal weight (a weight per area, the scene's material.areal_weight) is in
// g/m² there because fabrics are sold by mass per area: 1 g/m² of mass
// weighs 9.80665e-3 N/m². In this product `oz` is a force (units.h), so the
// imperial labels say "oz". Every label is a unit the scene reader parses.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/model/units.h"

namespace drape {

enum class UnitSystem { kSI, kTextile, kImperial };

// "si", "textile", "imperial".
const char* ToString(UnitSystem system);
// The system named so (as ToString spells it), or nullopt.
std::optional<UnitSystem> UnitSystemNamed(std::string_view name);

// What a quantity is, where the dimension alone does not pick its unit
// (a thickness is a length; a moment per width is a force).
enum class Measure {
  kNone,
  kLength,
  kThickness,
  kForce,
  kPressure,
  kArealWeight,
  kArealDensity,
  kCurvature,
  kMoment,
  kMomentPerWidth,
  kBendingRigidity,
  kForcePerLength,
  kEnergyPerArea,
  kPenaltyPerArea,
  kArea,
  kMass,
  kAngle,
};

// The dimension a measure's SI values have.
Dimension DimensionOf(Measure measure);

// A unit to show values in: value shown = SI value / si_factor.
struct DisplayUnit {
  std::string label;  // "gf·cm²/cm"; "" for a dimensionless number
  double si_factor = 1.0;
};

DisplayUnit UnitFor(Measure measure, UnitSystem system);
// The unit of a dimension's usual measure (a force is a force, a length a
// length); a dimension without one is shown in SI base units, factor 1.
DisplayUnit UnitFor(Dimension dimension, UnitSystem system);

// "20 cm": `si` in the system's unit with `significant` digits (printf %g).
std::string FormatQuantity(double si, Measure measure, UnitSystem system, int significant = 4);
std::string FormatQuantity(double si, Dimension dimension, UnitSystem system, int significant = 4);
// Only the number of FormatQuantity: "20" for 0.2 m in textile units.
std::string FormatNumber(double si, const DisplayUnit& unit, int significant = 4);

// Text typed for a measure, in any unit the scene reader takes for it, to
// its SI value: ParseQuantityAs, and for an areal weight also a mass per
// area ("180 g/m^2"), weighed at standard gravity as the reader's
// material.areal_density is. Throws UnitError.
double ParseMeasure(std::string_view text, Measure measure);

// The system a scene is written in: each quantity string of the JSON text
// votes by its units (cm, mm, gf, g: textile; in, ft, oz, lb, psi:
// imperial; m, N, Pa, kg: SI; a string with units of two systems votes for
// the one not SI). The most votes win, a tie the first of SI, textile,
// imperial; nothing voting (plain numbers only) or text that is not JSON:
// SI.
UnitSystem GuessUnitSystem(std::string_view scene_json);

}  // namespace drape
