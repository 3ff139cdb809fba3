#include "core/model/unit_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "support/test_paths.h"

namespace drape {
namespace {

// Independent numbers, not taken from unit_system.cc:
// 1 gf = 9.80665e-3 N exactly (CGPM 1901, standard gravity 9.80665 m/s²);
// 1 in = 0.0254 m exactly (international yard and pound, 1959);
// 1 oz (force) = 0.028349523125 kg × 9.80665 m/s² = 0.27801385 N (NIST SP 811 B.9),
// so 1 oz/in² = 0.27801385 / 0.0254² = 430.9223 Pa.
constexpr double kGf = 9.80665e-3;
constexpr double kIn = 0.0254;
constexpr double kOzf = 0.27801385;
constexpr double kOzPerIn2 = 430.9223;

void ExpectUnit(Measure measure, UnitSystem system, const std::string& label, double factor) {
  SCOPED_TRACE(std::string(ToString(system)) + " " + label);
  const DisplayUnit unit = UnitFor(measure, system);
  EXPECT_EQ(unit.label, label);
  EXPECT_NEAR(unit.si_factor, factor, 1e-7 * factor);
}

TEST(UnitSystem, NamesReadBack) {
  for (UnitSystem s : {UnitSystem::kSI, UnitSystem::kTextile, UnitSystem::kImperial})
    EXPECT_EQ(UnitSystemNamed(ToString(s)), s);
  EXPECT_EQ(std::string(ToString(UnitSystem::kTextile)), "textile");
  EXPECT_FALSE(UnitSystemNamed("metric").has_value());
}

TEST(UnitSystem, TextileFactorsAreTheDefinitions) {
  ExpectUnit(Measure::kLength, UnitSystem::kTextile, "cm", 0.01);
  ExpectUnit(Measure::kThickness, UnitSystem::kTextile, "mm", 0.001);
  ExpectUnit(Measure::kForce, UnitSystem::kTextile, "gf", kGf);
  ExpectUnit(Measure::kPressure, UnitSystem::kTextile, "gf/cm²", kGf / 1e-4);  // 98.0665 Pa
  ExpectUnit(Measure::kArealWeight, UnitSystem::kTextile, "g/m²", kGf);  // 1 g/m² weighs 1 gf/m²
  ExpectUnit(Measure::kCurvature, UnitSystem::kTextile, "1/cm", 100);
  ExpectUnit(Measure::kMomentPerWidth, UnitSystem::kTextile, "gf·cm/cm", kGf);
  ExpectUnit(Measure::kBendingRigidity, UnitSystem::kTextile, "gf·cm²/cm", kGf * 0.01);
}

TEST(UnitSystem, ImperialFactorsAreTheDefinitions) {
  ExpectUnit(Measure::kLength, UnitSystem::kImperial, "in", kIn);
  ExpectUnit(Measure::kForce, UnitSystem::kImperial, "oz", kOzf);
  ExpectUnit(Measure::kPressure, UnitSystem::kImperial, "oz/in²", kOzPerIn2);
  ExpectUnit(Measure::kArealWeight, UnitSystem::kImperial, "oz/in²", kOzPerIn2);
  ExpectUnit(Measure::kCurvature, UnitSystem::kImperial, "1/in", 1 / kIn);
  ExpectUnit(Measure::kBendingRigidity, UnitSystem::kImperial, "oz·in²/in", kOzf * kIn);
}

TEST(UnitSystem, SiIsFactorOne) {
  for (Measure m : {Measure::kLength, Measure::kForce, Measure::kPressure, Measure::kCurvature})
    EXPECT_EQ(UnitFor(m, UnitSystem::kSI).si_factor, 1.0);
  EXPECT_EQ(UnitFor(Measure::kPressure, UnitSystem::kSI).label, "Pa");
  EXPECT_EQ(UnitFor(dim::kCurvature, UnitSystem::kSI).label, "1/m");
}

// The strip fold's numbers (resources/scenes/strip-fold.json).
TEST(UnitSystem, FormatsTheStripFold) {
  EXPECT_EQ(FormatQuantity(0.2, dim::kLength, UnitSystem::kTextile), "20 cm");
  EXPECT_EQ(FormatQuantity(0.2, dim::kLength, UnitSystem::kImperial), "7.874 in");
  EXPECT_EQ(FormatQuantity(0.2, dim::kLength, UnitSystem::kSI), "0.2 m");
  EXPECT_EQ(FormatQuantity(0.000469, Measure::kThickness, UnitSystem::kTextile), "0.469 mm");
  // 4196 oz/in² = 1.80815e6 Pa = 18438 gf/cm².
  const double modulus = 4196 * kOzPerIn2;
  EXPECT_EQ(FormatQuantity(modulus, Measure::kPressure, UnitSystem::kImperial), "4196 oz/in²");
  EXPECT_EQ(FormatQuantity(modulus, Measure::kPressure, UnitSystem::kTextile, 5), "18438 gf/cm²");
  // 4.019e-3 oz/in² = 1.73188 Pa: 176.6 g/m² of fabric.
  EXPECT_EQ(FormatQuantity(4.019e-3 * kOzPerIn2, Measure::kArealWeight, UnitSystem::kTextile),
            "176.6 g/m²");
  EXPECT_EQ(FormatQuantity(30, dim::kCurvature, UnitSystem::kTextile), "0.3 1/cm");
  EXPECT_EQ(FormatQuantity(0.3, dim::kNone, UnitSystem::kTextile), "0.3");
}

// Every label is one the scene reader parses, to the same factor, and
// formatted text reads back to its value.
TEST(UnitSystem, FormattedTextReadsBack) {
  for (int m = 0; m <= static_cast<int>(Measure::kAngle); ++m)
    for (UnitSystem s : {UnitSystem::kSI, UnitSystem::kTextile, UnitSystem::kImperial}) {
      const Measure measure = static_cast<Measure>(m);
      const double si = 0.123456789 * UnitFor(measure, s).si_factor;
      const std::string text = FormatQuantity(si, measure, s, 17);
      SCOPED_TRACE(text);
      EXPECT_NEAR(ParseMeasure(text, measure), si, 1e-12 * std::abs(si));
      if (measure != Measure::kArealWeight || s != UnitSystem::kTextile) {
        EXPECT_NEAR(ParseQuantityAs(text, DimensionOf(measure)), si, 1e-12 * std::abs(si));
      }
      const std::string short_text = FormatQuantity(si, measure, s);
      // Four digits: within half a unit of the fourth.
      EXPECT_NEAR(ParseMeasure(short_text, measure), si, 5e-4 * std::abs(si));
    }
}

TEST(UnitSystem, ArealWeightTakesAMassPerArea) {
  EXPECT_NEAR(ParseMeasure("180 g/m^2", Measure::kArealWeight), 180 * kGf, 1e-12);
  EXPECT_NEAR(ParseMeasure("1 oz/in^2", Measure::kArealWeight), kOzPerIn2, 1e-3);
  EXPECT_THROW(ParseMeasure("180 g/m^2", Measure::kPressure), UnitError);
}

std::string Slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(UnitSystem, GuessedFromTheScenesOwnUnits) {
  EXPECT_EQ(GuessUnitSystem(R"({"a": "2 cm", "b": ["1 m", "3 mm"], "c": "0.5 gf*cm^2/cm"})"),
            UnitSystem::kTextile);
  EXPECT_EQ(GuessUnitSystem(R"({"a": "10 in", "b": "4196 oz/in^2", "c": 0.2})"),
            UnitSystem::kImperial);
  EXPECT_EQ(GuessUnitSystem(R"({"a": 0.2, "b": "1 MPa", "name": "20 cm wide"})"), UnitSystem::kSI);
  EXPECT_EQ(GuessUnitSystem(R"({"a": 0.2})"), UnitSystem::kSI);
  EXPECT_EQ(GuessUnitSystem("not json"), UnitSystem::kSI);
  // The strip fold: seven lengths in cm, two stiffnesses in oz/in².
  EXPECT_EQ(GuessUnitSystem(Slurp(test::ScenesDir() / "strip-fold.json")), UnitSystem::kTextile);
}

}  // namespace
}  // namespace drape
