#include "core/model/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

namespace drape {
namespace {

// Exact definitions, spelled out independently of units.cc.
constexpr double kG = 9.80665;          // standard gravity [m/s²]
constexpr double kLb = 0.45359237;      // pound [kg]
constexpr double kOz = 0.028349523125;  // ounce [kg]
constexpr double kIn = 0.0254;          // inch [m]
constexpr Dimension kTime{0, 0, 1, 0};

double SiValue(std::string_view text) {
  return ParseQuantity(text).value_si;
}

// Checks value (to 1e-12 relative) and dimension (by name, for readable failures).
void ExpectQuantity(std::string_view text, double expected_value, Dimension expected_dimension) {
  SCOPED_TRACE(std::string(text));
  const auto [value, dimension] = ParseQuantity(text);
  EXPECT_NEAR(value, expected_value, 1e-12 * std::abs(expected_value));
  EXPECT_EQ(DimensionName(dimension), DimensionName(expected_dimension));
}

// Message of the UnitError thrown by ParseQuantity(text), or "" (and a failure) if none.
std::string QuantityError(std::string_view text) {
  try {
    ParseQuantity(text);
  } catch (const UnitError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no UnitError for \"" << text << "\"";
  return "";
}

std::string QuantityAsError(std::string_view text, Dimension expected) {
  try {
    ParseQuantityAs(text, expected);
  } catch (const UnitError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no UnitError for \"" << text << "\"";
  return "";
}

::testing::AssertionResult Contains(const std::string& message, std::string_view part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "\"" << message << "\" does not contain \"" << part << "\"";
}

TEST(Units, LengthUnits) {
  ExpectQuantity("2 m", 2.0, dim::kLength);
  ExpectQuantity("2 cm", 0.02, dim::kLength);
  ExpectQuantity("0.489 mm", 0.489e-3, dim::kLength);
  ExpectQuantity("250 um", 250e-6, dim::kLength);
  ExpectQuantity("3 in", 3 * 0.0254, dim::kLength);
  ExpectQuantity("2 ft", 2 * 12 * 0.0254, dim::kLength);
}

TEST(Units, ForceUnits) {
  ExpectQuantity("2 N", 2.0, dim::kForce);
  ExpectQuantity("2 kN", 2000.0, dim::kForce);
  ExpectQuantity("2 mN", 2e-3, dim::kForce);
  ExpectQuantity("2 gf", 2 * 1e-3 * 9.80665, dim::kForce);
  ExpectQuantity("2 gmf", 2 * 1e-3 * 9.80665, dim::kForce);
  ExpectQuantity("2 kgf", 2 * 9.80665, dim::kForce);
  ExpectQuantity("2 ozf", 2 * 0.028349523125 * 9.80665, dim::kForce);
  ExpectQuantity("2 lbf", 2 * 0.45359237 * 9.80665, dim::kForce);
}

TEST(Units, OunceAndPoundAreForces) {
  ExpectQuantity("2 oz", 2 * 0.028349523125 * 9.80665, dim::kForce);
  ExpectQuantity("2 lb", 2 * 0.45359237 * 9.80665, dim::kForce);
  EXPECT_EQ(SiValue("1 oz"), SiValue("1 ozf"));
  EXPECT_EQ(SiValue("1 lb"), SiValue("1 lbf"));
  EXPECT_THROW(ParseQuantityAs("1 oz", dim::kMass), UnitError);
  // 16 oz = 1 lb.
  EXPECT_NEAR(SiValue("16 oz"), SiValue("1 lb"), 1e-12);
}

TEST(Units, MassUnits) {
  ExpectQuantity("2 kg", 2.0, dim::kMass);
  ExpectQuantity("2 g", 2e-3, dim::kMass);
  ExpectQuantity("150 g/m^2", 150e-3, dim::kArealDensity);
}

TEST(Units, PressureUnits) {
  ExpectQuantity("2 Pa", 2.0, dim::kPressure);
  ExpectQuantity("2 kPa", 2e3, dim::kPressure);
  ExpectQuantity("2 MPa", 2e6, dim::kPressure);
  ExpectQuantity("2 GPa", 2e9, dim::kPressure);
  ExpectQuantity("2 psi", 2 * 0.45359237 * 9.80665 / (0.0254 * 0.0254), dim::kPressure);
  EXPECT_NEAR(SiValue("1 psi"), 6894.757293168361, 1e-9);
  EXPECT_NEAR(SiValue("1 psi"), SiValue("1 lbf/in^2"), 1e-9);
}

TEST(Units, AngleAndTimeUnits) {
  ExpectQuantity("30 deg", std::numbers::pi / 6, dim::kAngle);
  ExpectQuantity("0.5 rad", 0.5, dim::kAngle);
  ExpectQuantity("2 s", 2.0, kTime);
}

TEST(Units, TextileAreaWeightInGramForcePerSquareCentimetre) {
  ExpectQuantity("0.02665 gf/cm^2", 0.02665 * 9.80665e-3 / 1e-4, dim::kPressure);
  EXPECT_NEAR(SiValue("0.02665 gf/cm^2"), 2.61347, 1e-5);
}

TEST(Units, PaperValues) {
  // Polyester: E = 4196 oz/in², w = 4.019e-3 oz/in².
  ExpectQuantity("4196 oz/in^2", 4196 * kOz * kG / (kIn * kIn), dim::kPressure);
  ExpectQuantity("4.019e-3 oz/in^2", 4.019e-3 * kOz * kG / (kIn * kIn), dim::kPressure);
  ExpectQuantity("60450 gf/cm^2", 60450 * 1e-3 * kG / (1e-2 * 1e-2), dim::kPressure);
  // Bending rigidity per width: gf·cm²/cm.
  ExpectQuantity("0.589 gf*cm^2/cm", 0.589 * 1e-3 * kG * 1e-4 / 1e-2, dim::kBendingRigidity);
  ExpectQuantity("2688 oz/in^2", 2688 * kOz * kG / (kIn * kIn), dim::kPressure);
}

TEST(Units, PrecedenceIsPowerThenLeftToRight) {
  // gf*cm^2/cm = (gf*(cm^2))/cm = gf·cm.
  ExpectQuantity("1 gf*cm^2/cm", 1e-3 * kG * 1e-2, dim::kMoment);
  ExpectQuantity("1 N/m/m", 1.0, dim::kPressure);
  ExpectQuantity("1 N/m*m", 1.0, dim::kForce);
  ExpectQuantity("1 N/(m*m)", 1.0, dim::kPressure);
  ExpectQuantity("1 N/(m/m)", 1.0, dim::kForce);
  ExpectQuantity("1 m/cm^2", 1.0 / (1e-2 * 1e-2), dim::kCurvature);
  ExpectQuantity("1 (cm)^2", 1e-4, dim::kArea);
  ExpectQuantity("1 (gf/cm)^2",
                 (1e-3 * kG / 1e-2) * (1e-3 * kG / 1e-2),
                 dim::kForcePerLength * dim::kForcePerLength);
  ExpectQuantity("1 gf/(cm*cm)", 1e-3 * kG / 1e-4, dim::kPressure);
}

TEST(Units, IntegerExponentsIncludingNegative) {
  ExpectQuantity("2 m^-1", 2.0, dim::kCurvature);
  ExpectQuantity("2 cm^-1", 200.0, dim::kCurvature);
  ExpectQuantity("1 N*m^-3", 1.0, dim::kPenaltyPerArea);
  ExpectQuantity("1 cm^3", 1e-6, Dimension{3, 0, 0, 0});
  ExpectQuantity("1 m^0", 1.0, dim::kNone);
  ExpectQuantity("1 cm^+2", 1e-4, dim::kArea);
}

TEST(Units, OneOverUnit) {
  ExpectQuantity("1.5 1/cm", 150.0, dim::kCurvature);
  ExpectQuantity("0.2 1/in", 0.2 / 0.0254, dim::kCurvature);
  ExpectQuantity("4 1/(cm*cm)", 4 / 1e-4, Dimension{-2, 0, 0, 0});
}

TEST(Units, UnicodeSuperscripts) {
  ExpectQuantity("0.02665 gf/cm²", 0.02665 * 1e-3 * kG / 1e-4, dim::kPressure);
  ExpectQuantity("1 cm³", 1e-6, Dimension{3, 0, 0, 0});
  ExpectQuantity("2 cm⁻¹", 200.0, dim::kCurvature);
  ExpectQuantity("1 N/m³", 1.0, dim::kPenaltyPerArea);
  EXPECT_EQ(ParseUnit("oz/in²").si_factor, ParseUnit("oz/in^2").si_factor);
}

TEST(Units, MiddleDotMultiplies) {
  ExpectQuantity("0.589 gf·cm²/cm", 0.589 * 1e-3 * kG * 1e-4 / 1e-2, dim::kBendingRigidity);
  ExpectQuantity("2 N⋅m", 2.0, dim::kMoment);  // U+22C5 dot operator
  ExpectQuantity("2 N · m", 2.0, dim::kMoment);
}

TEST(Units, WhitespaceAroundOperators) {
  ExpectQuantity("  0.02665  gf / cm ^ 2  ", 0.02665 * 1e-3 * kG / 1e-4, dim::kPressure);
  ExpectQuantity("1 ( N * m ) / m", 1.0, dim::kMomentPerWidth);
  ExpectQuantity("3mm", 3e-3, dim::kLength);
}

TEST(Units, NumberLiterals) {
  ExpectQuantity("0.3", 0.3, dim::kNone);
  ExpectQuantity("-2.5e-3", -2.5e-3, dim::kNone);
  ExpectQuantity("+4", 4.0, dim::kNone);
  ExpectQuantity(".5 m", 0.5, dim::kLength);
  ExpectQuantity("2E3 Pa", 2000.0, dim::kPressure);
  ExpectQuantity("-1e-2 m", -0.01, dim::kLength);
}

TEST(Units, ParseUnitGivesFactorAndDimension) {
  const Unit oz_per_in2 = ParseUnit("oz/in^2");
  EXPECT_NEAR(oz_per_in2.si_factor, kOz * kG / (kIn * kIn), 1e-12);
  EXPECT_EQ(oz_per_in2.dimension, dim::kPressure);
  const Unit per_cm = ParseUnit(" 1/cm ");
  EXPECT_NEAR(per_cm.si_factor, 100.0, 1e-12);
  EXPECT_EQ(per_cm.dimension, dim::kCurvature);
  EXPECT_EQ(ParseUnit("lbf").si_factor, kLb * kG);
  EXPECT_THROW(ParseUnit(""), UnitError);
  EXPECT_THROW(ParseUnit("furlongs"), UnitError);
}

TEST(Units, DimensionNames) {
  EXPECT_EQ(DimensionName(dim::kNone), "dimensionless");
  EXPECT_EQ(DimensionName(dim::kLength), "length (m, cm, mm, in, ft)");
  EXPECT_EQ(DimensionName(dim::kMass), "mass (kg, g)");
  EXPECT_EQ(DimensionName(dim::kAngle), "angle (deg, rad)");
  EXPECT_EQ(DimensionName(dim::kForce), "force (N, gf, oz, lbf)");
  EXPECT_EQ(DimensionName(dim::kArea), "area (m^2, cm^2, in^2)");
  EXPECT_EQ(DimensionName(dim::kPressure), "force/area (Pa, kPa, MPa, GPa, psi, gf/cm^2, oz/in^2)");
  EXPECT_EQ(DimensionName(dim::kArealDensity), "mass/area (kg/m^2, g/m^2, g/cm^2)");
  EXPECT_EQ(DimensionName(dim::kCurvature), "curvature (1/m, 1/cm, 1/in)");
  EXPECT_EQ(DimensionName(dim::kMoment), "force·length (N*m, gf*cm^2/cm)");
  EXPECT_EQ(DimensionName(dim::kBendingRigidity), DimensionName(dim::kMoment));
  EXPECT_EQ(DimensionName(dim::kMomentPerWidth), DimensionName(dim::kForce));
  EXPECT_EQ(DimensionName(dim::kForcePerLength), "force/length (N/m, gf/cm, lbf/in)");
  EXPECT_EQ(DimensionName(dim::kPenaltyPerArea), "force/length^3 (N/m^3, gf/cm^3)");
  EXPECT_EQ(DimensionName(Dimension{-1, 1, -2, 1}), "m^-1 kg^1 s^-2 rad^1");
  EXPECT_EQ(DimensionName(Dimension{1, 0, -1, 0}), "m^1 s^-1");
}

TEST(Units, ParseQuantityAsReturnsSiValue) {
  EXPECT_NEAR(ParseQuantityAs("0.489 mm", dim::kLength), 0.489e-3, 1e-15);
  EXPECT_NEAR(ParseQuantityAs("30 deg", dim::kAngle), std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(ParseQuantityAs("1.5 1/cm", dim::kCurvature), 150.0, 1e-12);
  EXPECT_NEAR(ParseQuantityAs("0.3", dim::kNone), 0.3, 1e-15);
  EXPECT_NEAR(ParseQuantityAs("50 cm/m", dim::kNone), 0.5, 1e-15);
}

TEST(Units, DimensionMismatchNamesExpectedAndFound) {
  EXPECT_EQ(QuantityAsError("3 cm", dim::kPressure),
            "\"3 cm\" is a length, expected a force/area "
            "(Pa, kPa, MPa, GPa, psi, gf/cm^2, oz/in^2)");
  EXPECT_EQ(QuantityAsError("5 g", dim::kForce),
            "\"5 g\" is a mass, expected a force (N, gf, oz, lbf)");
  EXPECT_EQ(QuantityAsError("0.3", dim::kLength),
            "\"0.3\" is dimensionless, expected a length (m, cm, mm, in, ft)");
  EXPECT_EQ(QuantityAsError("3 cm", dim::kAngle),
            "\"3 cm\" is a length, expected an angle (deg, rad)");
  EXPECT_EQ(QuantityAsError("3 deg", dim::kNone),
            "\"3 deg\" is an angle, expected a dimensionless number");
  EXPECT_EQ(QuantityAsError("1 m/s", dim::kLength),
            "\"1 m/s\" is of dimension m^1 s^-1, expected a length (m, cm, mm, in, ft)");
  EXPECT_TRUE(Contains(QuantityAsError("1 gf*cm", dim::kForcePerLength),
                       "is a force·length, expected a force/length (N/m"));
}

TEST(Units, MalformedNumbers) {
  EXPECT_TRUE(Contains(QuantityError(""), "empty quantity"));
  EXPECT_TRUE(Contains(QuantityError("   "), "empty quantity"));
  EXPECT_TRUE(Contains(QuantityError("abc"), "expected a number at the start of \"abc\""));
  EXPECT_TRUE(Contains(QuantityError("inf"), "expected a number"));
  EXPECT_TRUE(Contains(QuantityError("nan m"), "expected a number"));
  EXPECT_TRUE(Contains(QuantityError("1.2.3 m"),
                       "malformed number '1.2.3' (expected a number such as 0.5 or 2e-3) in "
                       "\"1.2.3 m\""));
  EXPECT_TRUE(Contains(QuantityError("+-3 m"), "malformed number '+-3'"));
  EXPECT_TRUE(Contains(QuantityError("3-4 m"), "malformed number '3-4'"));
  EXPECT_TRUE(Contains(QuantityError("- m"), "malformed number '-'"));
  EXPECT_TRUE(Contains(QuantityError("1e400 m"), "number '1e400' is out of range"));
  EXPECT_TRUE(Contains(QuantityError("1e300 GPa"), "\"1e300 GPa\" is out of range in SI units"));
}

TEST(Units, UnknownUnitIsQuotedWithKnownOnes) {
  const std::string message = QuantityError("5 furlongs");
  EXPECT_TRUE(Contains(message, "unknown unit 'furlongs'"));
  EXPECT_TRUE(Contains(message, "in \"5 furlongs\""));
  EXPECT_TRUE(Contains(message, "(known: m, cm, mm, um, in, ft, N, "));
  EXPECT_TRUE(Contains(QuantityError("3 Cm"), "unknown unit 'Cm'"));
  EXPECT_TRUE(Contains(QuantityError("3 gf/furlong^2"), "unknown unit 'furlong'"));
}

TEST(Units, MalformedUnitExpressions) {
  EXPECT_TRUE(
      Contains(QuantityError("3 cm^x"), "expected an integer exponent after '^', found 'x'"));
  EXPECT_TRUE(Contains(QuantityError("3 cm^1.5"), "found '1.5'"));
  EXPECT_TRUE(Contains(QuantityError("3 cm^"), "found end of text"));
  EXPECT_TRUE(Contains(QuantityError("3 m^-"), "found end of text"));
  EXPECT_TRUE(Contains(QuantityError("3 m^999"), "exponent '999' is too large"));
  EXPECT_TRUE(Contains(QuantityError("3 m^99999999999"), "exponent '99999999999' is too large"));
  EXPECT_TRUE(Contains(QuantityError("3 (m^50)^50"), "exponent too large"));
  EXPECT_TRUE(Contains(QuantityError("3 m¹²³⁴⁵⁶⁷⁸⁹"), "exponent too large"));
  EXPECT_TRUE(Contains(QuantityError("3 (cm"), "missing ')' in \"3 (cm\""));
  EXPECT_TRUE(Contains(QuantityError("3 cm)"), "unexpected ')'"));
  EXPECT_TRUE(Contains(QuantityError("3 ()"), "expected a unit, found ')'"));
  EXPECT_TRUE(Contains(QuantityError("3 cm/"), "expected a unit, found end of text"));
  EXPECT_TRUE(Contains(QuantityError("3 /cm"), "expected a unit, found '/'"));
  EXPECT_TRUE(Contains(QuantityError("3 gf cm"), "expected '*' or '/' before 'cm'"));
  EXPECT_TRUE(Contains(QuantityError("3 (gf cm)"), "expected '*' or '/' before 'cm'"));
  EXPECT_TRUE(Contains(QuantityError("3 cm 4"), "expected '*' or '/' before '4'"));
  EXPECT_TRUE(Contains(QuantityError("3 2/cm"), "unexpected number '2'"));
  EXPECT_TRUE(Contains(QuantityError("3 m#"), "unexpected '#'"));
  EXPECT_TRUE(Contains(QuantityError("3 m⁻"), "unexpected '⁻'"));
  EXPECT_TRUE(Contains(QuantityError("3 um^-60"), "unit 'um^-60' is out of range"));
  EXPECT_TRUE(Contains(QuantityError("3 um^60"), "unit 'um^60' is out of range"));
}

}  // namespace
}  // namespace drape
