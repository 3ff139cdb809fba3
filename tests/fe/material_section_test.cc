// From a scene's material to the section the elements evaluate.
#include "core/fe/material_section.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <limits>

#include "core/model/scene_error.h"

namespace drape {
namespace {

// A curve law of points [K, M] (SI).
CurveBending CurveOf(std::vector<Vec2> points) {
  CurveBending c;
  c.points = std::move(points);
  return c;
}

constexpr double kH = 5e-4;  // m

Material Isotropic(BendingLaw law) {
  Material m;
  m.thickness = kH;
  m.areal_weight = 1.0;
  m.membrane = IsotropicMembrane{1e6, 0.3};
  m.bending.warp = std::move(law);
  return m;
}

TEST(MaterialSection, LinearIsotropicIsThePlateOfTheStripRigidity) {
  const MaterialSection s = MakeMaterialSection(Isotropic(LinearBending{2e-4}));
  const ShellSection expected = IsotropicSection(1e6, 0.3, kH, 2e-4);
  EXPECT_LT((s.section.bending - expected.bending).norm(), 1e-15 * expected.bending.norm());
  EXPECT_LT((s.section.membrane - expected.membrane).norm(), 1e-15 * expected.membrane.norm());
  EXPECT_FALSE(s.section.bending_law);  // the constant-matrix path
  EXPECT_EQ(s.bending_valid_to, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(s.warnings.empty());
  // The default is the strip rigidity E h³/12.
  const MaterialSection d = MakeMaterialSection(Isotropic(LinearBending{}));
  EXPECT_NEAR(d.section.bending(0, 0), 1e6 * kH * kH * kH / 12 / (1 - 0.09), 1e-18);
}

TEST(MaterialSection, PolynomialLawStartsFromItsFirstCoefficient) {
  const MaterialSection s =
      MakeMaterialSection(Isotropic(PolynomialBending{{1.3e-4, -2e-7, 1e-9}, 250.0}));
  ASSERT_TRUE(s.section.bending_law);
  EXPECT_NEAR(s.section.bending(0, 0), 1.3e-4 / (1 - 0.09), 1e-17);
  EXPECT_EQ(s.bending_valid_to, 250.0);
}

TEST(MaterialSection, SofteningLawIsWarnedOfWithItsCurvatures) {
  // M = c₁K − c₃K³ with c₃ = c₁/(3 K₀²): dM/dK < 0 beyond K₀ = 150 1/m
  // = 1.5 1/cm, inside the fit's 2.5 1/cm.
  const double c1 = 1e-4;
  const MaterialSection s = MakeMaterialSection(
      Isotropic(PolynomialBending{{c1, 0.0, -c1 / (3 * 150.0 * 150.0)}, 250.0}));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].rfind("material.bending: the moment falls with curvature (dM/dK < 0) "
                                "for K from 1.5 to 2.5 1/cm",
                                0),
            0u)
      << s.warnings[0];
}

TEST(MaterialSection, LawWithoutInitialStiffnessIsAnErrorAtItsKey) {
  Material m = Isotropic(LinearBending{});
  m.bending.weft = CurveOf({{50.0, 0.0}, {100.0, 1e-4}});
  try {
    MakeMaterialSection(m);
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "material.bending.weft");
  }
}

TEST(MaterialSection, OrthotropicMembraneIsTheInverseOfItsCompliance) {
  Material m;
  m.thickness = kH;
  m.membrane = OrthotropicMembrane{2e6, 0.8e6, 0.25, 0.04e6};
  m.bending.warp = LinearBending{};
  m.bending.weft = LinearBending{};
  const MaterialSection s = MakeMaterialSection(m);
  // Independent: the engineering compliance S (ε = S σ), inverted.
  Eigen::Matrix3d compliance;
  compliance << 1 / 2e6, -0.25 / 2e6, 0, -0.25 / 2e6, 1 / 0.8e6, 0, 0, 0, 1 / 0.04e6;
  const Eigen::Matrix3d expected = kH * compliance.inverse();
  EXPECT_LT((s.section.membrane - expected).norm(), 1e-12 * expected.norm());
  // Warp and weft default to E₁h³/12 and E₂h³/12; the twist to their mean / 2.
  const double b1 = 2e6 * kH * kH * kH / 12, b2 = 0.8e6 * kH * kH * kH / 12;
  EXPECT_NEAR(s.section.bending(0, 0), b1, 1e-15 * b1);
  EXPECT_NEAR(s.section.bending(1, 1), b2, 1e-15 * b2);
  EXPECT_NEAR(s.section.bending(2, 2), (b1 + b2) / 4, 1e-15 * b1);
  EXPECT_EQ(s.section.bending(0, 1), 0.0);
}

TEST(MaterialSection, ValidRangeIsTheSmallestOfTheLaws) {
  Material m = Isotropic(PolynomialBending{{1e-4}, 250.0});
  m.bending.weft = CurveOf({{100.0, 1e-2}, {180.0, 1.5e-2}});
  const MaterialSection s = MakeMaterialSection(m);
  EXPECT_EQ(s.bending_valid_to, 180.0);
}

}  // namespace
}  // namespace drape
