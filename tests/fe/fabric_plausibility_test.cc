// Values no fabric has, said with their key and the slip that likely made
// them: the library's measured fabrics pass; a thickness typed "0.5" (read
// as 0.5 m), a weight typed as a bare number meant in g/m², and a bending
// length c = (B/w)^⅓ outside 0.3–15 cm are each named, the bending length
// worked out by hand.
#include "core/fe/fabric_plausibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/io/library_fabric.h"
#include "support/test_paths.h"

namespace drape {
namespace {

Material Plain(double thickness, double weight, double modulus) {
  Material m;
  m.thickness = thickness;
  m.areal_weight = weight;
  m.membrane = IsotropicMembrane{modulus, 0.3};
  return m;
}

TEST(FabricPlausibility, TheLibrarysFabricsPass) {
  for (const char* name : {"cotton-twill", "cotton-twill-linear", "polyester-plain-weave"})
    EXPECT_TRUE(ImplausibleFabric(LibraryFabric(name, test::ScenesDir())).empty()) << name;
}

TEST(FabricPlausibility, AThicknessReadInMetresIsNamedWithTheMillimetresMeant) {
  const auto found = ImplausibleFabric(Plain(0.5, 2.0, 1e6));
  ASSERT_GE(found.size(), 1u);
  EXPECT_EQ(found[0].key, "material.thickness");
  EXPECT_EQ(found[0].read_as, "0.5 m");
  EXPECT_EQ(Describe(found[0]),
            "material.thickness: 0.5 m is thicker than any fabric (0.05–5 mm); did you mean "
            "0.5 mm?");
  // 5 mm is a fabric's (a thick felt; E = 10 kPa keeps its bending length
  // (E h³/12w)^⅓ at 3.7 cm); 30 mm is not, and 30 read as mm (0.03 mm) is
  // thinner than any fabric: no slip explains it.
  EXPECT_TRUE(ImplausibleFabric(Plain(5e-3, 2.0, 1e4)).empty());
  const auto thick = ImplausibleFabric(Plain(0.03, 2.0, 1e3));
  ASSERT_FALSE(thick.empty());
  EXPECT_EQ(thick[0].did_you_mean, "");
}

// 200 N/m² is 200 · 1000 / 9.80665 = 20 394 g/m²: a bare 200 meant g/m².
TEST(FabricPlausibility, AWeightOutsideFabricsNamesGramsPerSquareMetre) {
  const auto heavy = ImplausibleFabric(Plain(0.5e-3, 200, 1e6));
  ASSERT_FALSE(heavy.empty());
  EXPECT_EQ(heavy[0].key, "material.areal_weight");
  EXPECT_EQ(heavy[0].read_as, "2.039e+04 g/m² (200 N/m²)");
  EXPECT_EQ(heavy[0].did_you_mean, "200 g/m²");
  const auto light = ImplausibleFabric(Plain(0.5e-3, 0.1, 1e6));
  ASSERT_FALSE(light.empty());
  EXPECT_EQ(light[0].why, "lighter than any fabric (20–1 000 g/m²)");
  EXPECT_EQ(light[0].did_you_mean, "");
}

// A linear law's B = 0.016 N·m over w = 2 N/m²: c = (0.008)^⅓ = 0.2 m.
TEST(FabricPlausibility, ABendingLengthOutsideFabricsIsNamed) {
  Material m = Plain(0.5e-3, 2.0, 1e6);
  m.bending.warp = LinearBending{0.016};
  const auto found = ImplausibleFabric(m);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].key, "material.bending");
  EXPECT_EQ(found[0].read_as, "20 cm");
  EXPECT_EQ(found[0].why, "stiffer than any fabric (bending length 0.3–15 cm)");
  // B = 2 · 0.002³ gives c = 2 mm: limper than any fabric.
  m.bending.warp = LinearBending{2.0 * std::pow(0.002, 3)};
  const auto limp = ImplausibleFabric(m);
  ASSERT_EQ(limp.size(), 1u);
  EXPECT_EQ(limp[0].read_as, "0.2 cm");
}

}  // namespace
}  // namespace drape
