// Physical quantities in scene files: "number unit" strings or SI numbers.
//
// A unit expression is built from the named units below with `*` (or `·`),
// `/`, `^` (integer powers; `²` and `³` are accepted) and parentheses, e.g.
// "gf*cm^2/cm", "oz/in^2", "1/cm". In this product `oz` and `lb` are forces,
// as in the textile literature; `kg` and `g` are masses.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace drape {

// Exponents of the base dimensions. Angle is kept as its own dimension so that
// "3 cm" cannot be given where an angle is asked.
struct Dimension {
  int length = 0;
  int mass = 0;
  int time = 0;
  int angle = 0;

  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
  friend constexpr Dimension operator*(Dimension a, Dimension b) {
    return {a.length + b.length, a.mass + b.mass, a.time + b.time, a.angle + b.angle};
  }
  friend constexpr Dimension operator/(Dimension a, Dimension b) {
    return {a.length - b.length, a.mass - b.mass, a.time - b.time, a.angle - b.angle};
  }
};

namespace dim {
inline constexpr Dimension kNone{};
inline constexpr Dimension kLength{1, 0, 0, 0};
inline constexpr Dimension kMass{0, 1, 0, 0};
inline constexpr Dimension kAngle{0, 0, 0, 1};
inline constexpr Dimension kForce{1, 1, -2, 0};
inline constexpr Dimension kArea{2, 0, 0, 0};
inline constexpr Dimension kPressure = kForce / kArea;             // also weight per area
inline constexpr Dimension kArealDensity = kMass / kArea;          // kg/m²
inline constexpr Dimension kCurvature = kNone / kLength;           // 1/m
inline constexpr Dimension kMoment = kForce * kLength;             // N·m
inline constexpr Dimension kMomentPerWidth = kForce;               // N·m/m
inline constexpr Dimension kBendingRigidity = kForce * kLength;    // N·m²/m
inline constexpr Dimension kForcePerLength = kForce / kLength;     // N/m
inline constexpr Dimension kPenaltyPerArea = kPressure / kLength;  // N/m³
}  // namespace dim

// Human name of a dimension with typical units, e.g. "force/area (Pa, gf/cm^2, oz/in^2)".
// Unnamed dimensions are spelled out as "m^-1 kg s^-2".
std::string DimensionName(Dimension d);

// Thrown for text that is not a quantity or a unit of the expected dimension.
// The message says what is wrong with the text; callers add the key path.
class UnitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Unit {
  double si_factor = 1.0;  // value in SI = value in this unit × si_factor
  Dimension dimension;
};

struct Quantity {
  double value_si = 0.0;
  Dimension dimension;
};

// Parses a unit expression such as "gf*cm^2/cm" or "1/cm". Throws UnitError
// naming the token it does not know.
Unit ParseUnit(std::string_view expression);

// Parses "number unit" ("0.489 mm", "1.5 1/cm", "2e-3 m"). A string that is a
// bare number is dimensionless. Throws UnitError.
Quantity ParseQuantity(std::string_view text);

// Parses text and checks its dimension; returns the SI value. Throws UnitError
// whose message names the expected dimension and the dimension found.
double ParseQuantityAs(std::string_view text, Dimension expected);

}  // namespace drape
