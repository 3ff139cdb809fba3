// A fabric's lab figures (KES-FB, FAST units) and back: a summary made into
// a material gives SI values worked out by hand from the unit definitions
// (gf = 9.80665e-3 N), and its figures are the summary again; the library's
// cotton twill has the Kawabata B of the paper's polynomial, Σ cₖ(1.5ᵏ − 0.5ᵏ).
#include "core/fe/textile_figures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <variant>

#include "support/fabric_summaries.h"

namespace drape {
namespace {

using test::Shirting;

TEST(TextileFigures, ASummaryBecomesTheMaterialInSI) {
  const Material m = MaterialFromSummary(Shirting());
  EXPECT_DOUBLE_EQ(m.thickness, 0.5e-3);
  EXPECT_NEAR(m.areal_weight, 0.150 * 9.80665, 1e-12);  // 150 g/m² weighs 1.471 N/m²
  const auto& o = std::get<OrthotropicMembrane>(m.membrane);
  EXPECT_NEAR(o.e1, 400 * 0.980665 / 0.5e-3, 1e-6);  // 400 gf/cm over 0.5 mm: 784.5 kPa
  EXPECT_NEAR(o.e2, 250 * 0.980665 / 0.5e-3, 1e-6);
  EXPECT_NEAR(o.g12, 0.8 * 0.980665 / (0.5e-3 * std::numbers::pi / 180), 1e-6);
  EXPECT_DOUBLE_EQ(o.nu12, 0.3);
  EXPECT_NEAR(*std::get<LinearBending>(m.bending.warp).rigidity, 0.08 * 9.80665e-5, 1e-18);
  ASSERT_TRUE(m.bending.weft.has_value());
  EXPECT_NEAR(*std::get<LinearBending>(*m.bending.weft).rigidity, 0.05 * 9.80665e-5, 1e-18);
}

TEST(TextileFigures, TheMaterialsFiguresAreTheSummaryAgain) {
  const FabricSummary s = Shirting();
  const TextileFigures f = FiguresOf(MaterialFromSummary(s));
  EXPECT_NEAR(f.thickness_mm, s.thickness_mm, 1e-12);
  EXPECT_NEAR(f.weight_g_per_m2, s.weight_g_per_m2, 1e-9);
  EXPECT_NEAR(f.bending_warp, s.bending_warp, 1e-12);
  EXPECT_NEAR(f.bending_weft, s.bending_weft, 1e-12);
  EXPECT_NEAR(f.shear, s.shear, 1e-12);
  EXPECT_NEAR(f.tensile_warp, s.tensile_warp, 1e-9);
  EXPECT_NEAR(f.tensile_weft, s.tensile_weft, 1e-9);
  EXPECT_EQ(f.membrane, "orthotropic");
  EXPECT_NEAR(EmtPercent(f.tensile_warp), 500.0 / 400 * 100, 1e-9);  // 125 % at 500 gf/cm
  // Warp and weft alike: one law.
  FabricSummary same = s;
  same.bending_weft = same.bending_warp;
  EXPECT_FALSE(MaterialFromSummary(same).bending.weft.has_value());
}

// A figure a fabric always has, given as zero, is named rather than made
// into an infinite modulus.
TEST(TextileFigures, ASummaryWithAZeroFigureIsRefusedByName) {
  FabricSummary s = Shirting();
  s.shear = 0;
  try {
    MaterialFromSummary(s);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "the shear rigidity G must be greater than zero, found 0");
  }
}

// The paper's fit M = Σ cₖ Kᵏ (gf·cm/cm, K in 1/cm): B between 0.5 and 1.5 1/cm.
TEST(TextileFigures, KawabataBOfThePapersPolynomial) {
  const double c[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  double b = 0;
  for (int k = 1; k <= 5; ++k) b += c[k - 1] * (std::pow(1.5, k) - std::pow(0.5, k));
  Material m = MaterialFromSummary(Shirting());
  PolynomialBending law;
  // cₖ in gf·cm/cm · cmᵏ to N·m/m · mᵏ: × 9.80665e-3 / 100ᵏ.
  for (int k = 1; k <= 5; ++k)
    law.coefficients.push_back(c[k - 1] * 9.80665e-3 / std::pow(100.0, k));
  law.valid_to = 250;
  m.bending.warp = law;
  m.bending.weft.reset();
  EXPECT_NEAR(FiguresOf(m).bending_warp, b, 1e-9 * b);
}

}  // namespace
}  // namespace drape
