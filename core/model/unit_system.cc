#include "core/model/unit_system.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cctype>
#include <cstdio>
#include <numbers>

namespace drape {
namespace {

// Exact definitions (NIST SP 811, appendix B): standard gravity, the inch,
// the avoirdupois ounce; gram-force and ounce-force are those masses' weights.
constexpr double kGravity = 9.80665;                       // [m/s²]
constexpr double kGramForce = 1e-3 * kGravity;             // [N]
constexpr double kOunceForce = 0.028349523125 * kGravity;  // [N]
constexpr double kCm = 1e-2, kMm = 1e-3, kInch = 0.0254;   // [m]
constexpr double kDegree = std::numbers::pi / 180;         // [rad]

struct Row {
  Measure measure;
  Dimension dimension;
  DisplayUnit si, textile, imperial;
};

// One row per measure; the header's table, with each factor worked out.
const std::array<Row, 17>& Rows() {
  static const std::array<Row, 17> rows{{
      {Measure::kNone, dim::kNone, {"", 1}, {"", 1}, {"", 1}},
      {Measure::kLength, dim::kLength, {"m", 1}, {"cm", kCm}, {"in", kInch}},
      {Measure::kThickness, dim::kLength, {"m", 1}, {"mm", kMm}, {"in", kInch}},
      {Measure::kForce, dim::kForce, {"N", 1}, {"gf", kGramForce}, {"oz", kOunceForce}},
      {Measure::kPressure,
       dim::kPressure,
       {"Pa", 1},
       {"gf/cm²", kGramForce / (kCm * kCm)},
       {"oz/in²", kOunceForce / (kInch * kInch)}},
      {Measure::kArealWeight,
       dim::kPressure,
       {"N/m²", 1},
       {"g/m²", 1e-3 * kGravity},
       {"oz/in²", kOunceForce / (kInch * kInch)}},
      {Measure::kArealDensity, dim::kArealDensity, {"kg/m²", 1}, {"g/m²", 1e-3}, {"g/m²", 1e-3}},
      {Measure::kCurvature, dim::kCurvature, {"1/m", 1}, {"1/cm", 1 / kCm}, {"1/in", 1 / kInch}},
      {Measure::kMoment,
       dim::kMoment,
       {"N·m", 1},
       {"gf·cm", kGramForce * kCm},
       {"oz·in", kOunceForce * kInch}},
      {Measure::kMomentPerWidth,
       dim::kMomentPerWidth,
       {"N·m/m", 1},
       {"gf·cm/cm", kGramForce},
       {"oz·in/in", kOunceForce}},
      {Measure::kBendingRigidity,
       dim::kBendingRigidity,
       {"N·m²/m", 1},
       {"gf·cm²/cm", kGramForce * kCm},
       {"oz·in²/in", kOunceForce * kInch}},
      {Measure::kForcePerLength,
       dim::kForcePerLength,
       {"N/m", 1},
       {"gf/cm", kGramForce / kCm},
       {"oz/in", kOunceForce / kInch}},
      {Measure::kEnergyPerArea,
       dim::kForcePerLength,
       {"N·m/m²", 1},
       {"gf·cm/cm²", kGramForce / kCm},
       {"oz·in/in²", kOunceForce / kInch}},
      {Measure::kPenaltyPerArea,
       dim::kPenaltyPerArea,
       {"N/m³", 1},
       {"gf/cm³", kGramForce / (kCm * kCm * kCm)},
       {"oz/in³", kOunceForce / (kInch * kInch * kInch)}},
      {Measure::kArea, dim::kArea, {"m²", 1}, {"cm²", kCm * kCm}, {"in²", kInch * kInch}},
      {Measure::kMass, dim::kMass, {"kg", 1}, {"g", 1e-3}, {"g", 1e-3}},
      {Measure::kAngle, dim::kAngle, {"deg", kDegree}, {"deg", kDegree}, {"deg", kDegree}},
  }};
  return rows;
}

const Row& RowOf(Measure measure) {
  for (const Row& row : Rows())
    if (row.measure == measure) return row;
  return Rows()[0];
}

// The measure a bare dimension stands for: the first row with it, so a
// force is a force (not a moment per width) and a length not a thickness.
const Row* RowOf(Dimension dimension) {
  for (const Row& row : Rows())
    if (row.dimension == dimension) return &row;
  return nullptr;
}

const DisplayUnit& In(const Row& row, UnitSystem system) {
  switch (system) {
    case UnitSystem::kTextile:
      return row.textile;
    case UnitSystem::kImperial:
      return row.imperial;
    default:
      return row.si;
  }
}

std::string WithUnit(std::string number, const DisplayUnit& unit) {
  return unit.label.empty() ? number : number + " " + unit.label;
}

// Which system the units of one quantity string belong to, if any.
std::optional<UnitSystem> SystemOfUnits(std::string_view units) {
  static constexpr std::string_view kTextile[] = {"cm", "mm", "gf", "gmf", "g", "kgf"};
  static constexpr std::string_view kImperial[] = {"in", "ft", "oz", "ozf", "lb", "lbf", "psi"};
  static constexpr std::string_view kSi[] = {
      "m", "um", "N", "kN", "mN", "kg", "Pa", "kPa", "MPa", "GPa"};
  bool textile = false, imperial = false, si = false;
  for (size_t i = 0; i < units.size();) {
    size_t j = i;
    while (j < units.size() && std::isalpha(static_cast<unsigned char>(units[j]))) ++j;
    if (j == i) {
      ++i;
      continue;
    }
    const std::string_view name = units.substr(i, j - i);
    for (auto n : kTextile) textile |= n == name;
    for (auto n : kImperial) imperial |= n == name;
    for (auto n : kSi) si |= n == name;
    i = j;
  }
  if (imperial) return UnitSystem::kImperial;
  if (textile) return UnitSystem::kTextile;
  if (si) return UnitSystem::kSI;
  return std::nullopt;
}

void CountVotes(const nlohmann::json& value, std::array<int, 3>& votes) {
  if (value.is_structured()) {
    for (const auto& item : value) CountVotes(item, votes);
    return;
  }
  if (!value.is_string()) return;
  const std::string& text = value.get_ref<const std::string&>();
  try {
    if (ParseQuantity(text).dimension == dim::kNone) return;
  } catch (const UnitError&) {
    return;  // a name, a file, a description: not a quantity
  }
  // The number's letters (an exponent's 'e') name no unit.
  if (const auto system = SystemOfUnits(text)) ++votes[static_cast<int>(*system)];
}

}  // namespace

const char* ToString(UnitSystem system) {
  switch (system) {
    case UnitSystem::kTextile:
      return "textile";
    case UnitSystem::kImperial:
      return "imperial";
    default:
      return "si";
  }
}

std::optional<UnitSystem> UnitSystemNamed(std::string_view name) {
  for (UnitSystem s : {UnitSystem::kSI, UnitSystem::kTextile, UnitSystem::kImperial})
    if (name == ToString(s)) return s;
  return std::nullopt;
}

Dimension DimensionOf(Measure measure) {
  return RowOf(measure).dimension;
}

DisplayUnit UnitFor(Measure measure, UnitSystem system) {
  return In(RowOf(measure), system);
}

DisplayUnit UnitFor(Dimension dimension, UnitSystem system) {
  if (const Row* row = RowOf(dimension)) return In(*row, system);
  return {DimensionName(dimension), 1.0};
}

std::string FormatNumber(double si, const DisplayUnit& unit, int significant) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significant, si / unit.si_factor);
  return text;
}

std::string FormatQuantity(double si, Measure measure, UnitSystem system, int significant) {
  const DisplayUnit unit = UnitFor(measure, system);
  return WithUnit(FormatNumber(si, unit, significant), unit);
}

std::string FormatQuantity(double si, Dimension dimension, UnitSystem system, int significant) {
  const DisplayUnit unit = UnitFor(dimension, system);
  return WithUnit(FormatNumber(si, unit, significant), unit);
}

double ParseMeasure(std::string_view text, Measure measure) {
  if (measure == Measure::kArealWeight) {
    // As the scene reader's areal_density: a mass per area, weighed.
    const Quantity q = ParseQuantity(text);
    if (q.dimension == dim::kArealDensity) return q.value_si * kGravity;
  }
  return ParseQuantityAs(text, DimensionOf(measure));
}

UnitSystem GuessUnitSystem(std::string_view scene_json) {
  const nlohmann::json scene = nlohmann::json::parse(scene_json, nullptr, false);
  if (scene.is_discarded()) return UnitSystem::kSI;
  std::array<int, 3> votes{};
  CountVotes(scene, votes);
  int best = 0;  // SI, kept on a tie
  for (int s = 1; s < 3; ++s)
    if (votes[s] > votes[best]) best = s;
  return static_cast<UnitSystem>(best);
}

}  // namespace drape
