// The colour fields against states whose strains are known in closed form.
#include "core/fe/element_fields.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/mechanics/director.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

// A 20 × 2 cm sheet, 20 × 4 elements, E = 1 MPa, ν = 0.3, h = 0.5 mm.
ShellModel Sheet() {
  test::StripSpec spec;
  spec.width = 0.02;
  spec.elements = 20;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 4};
  scene.material.membrane = IsotropicMembrane{1e6, 0.3};
  return BuildShellModel(scene);
}

TEST(ElementFields, UniformStretchGivesItsGreenStrainAndEnergy) {
  const ShellModel model = Sheet();
  ShellState state = model.reference;
  const double s = 0.01;  // 1 % along x, none across
  state.positions.col(0) *= 1 + s;
  const double green = ((1 + s) * (1 + s) - 1) / 2;
  const Eigen::VectorXd strain = EvaluateField(FieldKind::kMembraneStrain, model, state);
  EXPECT_NEAR(strain.minCoeff(), green, 1e-12 * green);
  EXPECT_NEAR(strain.maxCoeff(), green, 1e-12 * green);
  // ½ εᵀ D_m ε with ε = (green, 0, 0): ½ E h/(1 − ν²) green².
  const double energy = 0.5 * 1e6 * 5e-4 / (1 - 0.09) * green * green;
  const Eigen::VectorXd density = EvaluateField(FieldKind::kElementEnergy, model, state);
  EXPECT_NEAR(density.minCoeff(), energy, 1e-9 * energy);
  EXPECT_NEAR(density.maxCoeff(), energy, 1e-9 * energy);
  // Node displacement: s x.
  const Eigen::VectorXd u = EvaluateField(FieldKind::kDisplacement, model, state);
  for (int i = 0; i < model.NodeCount(); ++i)
    EXPECT_NEAR(u(i), s * std::abs(model.reference.positions(i, 0)), 1e-15);
}

TEST(ElementFields, RolledSheetHasTheCylindersCurvatureAndMoment) {
  // Rolled onto a cylinder of radius R about the y axis without stretching
  // its midsurface: κ₁₁ = 1/R at the nodes; the bilinear element sees the
  // chord, so its curvature is 1/R to O((a/R)²) with a = 1 cm element length.
  const ShellModel model = Sheet();
  ShellState state = model.reference;
  const double r = 0.1;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = model.reference.positions(i, 0), y = model.reference.positions(i, 1);
    const double angle = x / r;
    state.positions.row(i) << r * std::sin(angle), y, r * (1 - std::cos(angle));
    const Eigen::Vector3d normal(-std::sin(angle), 0, std::cos(angle));
    state.rotations[i] = RotationFromDirector(normal);
  }
  const Eigen::VectorXd k = EvaluateField(FieldKind::kCurvature, model, state);
  const double a = 0.01;
  EXPECT_NEAR(k.minCoeff(), 1 / r, 0.5 * (a / r) * (a / r) / r);
  EXPECT_NEAR(k.maxCoeff(), 1 / r, 0.5 * (a / r) * (a / r) / r);
  EXPECT_NEAR(MaxPrincipalCurvature(model, state), k.maxCoeff(), 0.0);
  // Linear plate: m₁₁ = D κ₁₁ with D = E h³/12(1 − ν²) (κ₂₂ = 0).
  const double d = 1e6 * std::pow(5e-4, 3) / 12 / (1 - 0.09);
  const Eigen::VectorXd m = EvaluateField(FieldKind::kBendingMoment, model, state);
  for (int e = 0; e < m.size(); ++e) EXPECT_NEAR(m(e), d * k(e), 1e-3 * d * k(e));
}

// The bending law is evaluated at K = √(κᵀCκ), C the plane-stress matrix
// over (1 − ν²): for a cylinder (κ₁₁ = 1/R, κ₂₂ = 0) K = κ/√(1 − ν²), 4.8 %
// above the principal curvature at ν = 0.3; for a sphere (κ₁₁ = κ₂₂ = 1/R)
// K = κ √(2/(1 − ν)), 69 % above. The range check must use K.
TEST(ElementFields, LawCurvatureIsTheArgumentTheLawIsEvaluatedAt) {
  test::StripSpec spec;
  spec.width = 0.02;
  spec.elements = 20;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 4};
  scene.material.membrane = IsotropicMembrane{1e6, 0.3};
  // A gently stiffening law: M = B K + B K³ / (100 1/m)².
  const double b = 1e6 * std::pow(5e-4, 3) / 12;
  scene.material.bending.warp = PolynomialBending{{b, 0.0, b / 1e4}, 200.0};
  const ShellModel model = BuildShellModel(scene);
  ASSERT_TRUE(model.section.bending_law);
  // Rolled onto a cylinder of radius R about the y axis: κ₁₁ = 1/R.
  const double r = 0.1;
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = model.reference.positions(i, 0), y = model.reference.positions(i, 1);
    state.positions.row(i) << r * std::sin(x / r), y, r * (1 - std::cos(x / r));
    state.rotations[i] = RotationFromDirector({-std::sin(x / r), 0, std::cos(x / r)});
  }
  const double principal = MaxPrincipalCurvature(model, state);
  const double law = MaxLawCurvature(model, state);
  std::printf("cylinder: principal %.5f 1/m, law %.5f 1/m, ratio %.5f (closed form %.5f)\n",
              principal,
              law,
              law / principal,
              1 / std::sqrt(1 - 0.09));
  EXPECT_NEAR(principal, 1 / r, 0.01 / r);
  EXPECT_NEAR(law / principal, 1 / std::sqrt(1 - 0.09), 1e-9);
  // Equal two-way bending and pure twist, on the law itself (Voigt, 2κ₁₂).
  const PlateBendingLaw& plate = *model.section.bending_law;
  EXPECT_NEAR(plate.LawCurvature({1.0, 1.0, 0.0}), std::sqrt(2 / (1 - 0.3)), 1e-12);
  EXPECT_NEAR(plate.LawCurvature({0.0, 0.0, 2.0}), std::sqrt(2 / (1 + 0.3)), 1e-12);
  // Warp and weft: each yarn's K_α = |κ e_α|, the larger one checked.
  Scene woven = scene;
  woven.material.bending.weft = woven.material.bending.warp;
  const ShellModel two = BuildShellModel(woven);
  EXPECT_NEAR(two.section.bending_law->LawCurvature({3.0, 1.0, 2.0 * 4.0}), 5.0, 1e-12);
}

TEST(ElementFields, NamesAreFoundAndContactPressureIsNotAnElementField) {
  ASSERT_TRUE(FindField("curvature"));
  EXPECT_EQ(FindField("curvature")->kind, FieldKind::kCurvature);
  EXPECT_FALSE(FindField("curvatur"));
  const ShellModel model = Sheet();
  EXPECT_THROW(EvaluateField(FieldKind::kContactPressure, model, model.reference),
               std::invalid_argument);
}

}  // namespace
}  // namespace drape
