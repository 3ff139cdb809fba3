// The branch switch called directly (branch_switch.h) on a perfectly
// straight clamped–free column: the cantilever strip (support/
// strip_scene.h: L = 0.2 m, b = 1 cm, h = 0.5 mm, E = 1 MPa, ν = 0) under an
// axial tip force ramped to 2 P_E, P_E = π²EI/4L² its first Euler load (the
// second is 9 P_E). The straight path bifurcates at λ = 1/2; past it the
// straight column has one negative pivot, and the buckled branch (the
// elastica, supercritical) is stable. The switch is handed the stage's
// start (λ = 0) and a converged step to λ = 0.75 on the straight path.
#include "core/continuation/branch_switch.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

// The column of `elements` elements under 2 P_E, its stepper, and the two
// points the switch starts from.
struct Column {
  explicit Column(int elements, NewtonSettings newton = Tight())
      : spec(test::StripOf(elements)),
        s(test::TipLoadedStrip(spec, {-2 * test::CantileverEulerLoad(spec), 0, 0}, {0, 0, 0})),
        stepper(s.system, s.loading, newton, s.model.characteristic_length) {
    start = {s.model.reference, 0.0, {}};
    crossing = {s.model.reference, 0.0, {}};
    crossing.step = stepper.Step(crossing.state, {.lambda = 0, .first_increment = 0.75}, nullptr);
    crossing.lambda = crossing.step.lambda;
  }
  static NewtonSettings Tight() {
    NewtonSettings n;
    n.tolerance = 1e-10;
    return n;
  }
  // As the solver sets them (bifurcation_passage.cc), the bracket to 1e-5.
  BifurcationSettings Settings() const {
    BifurcationSettings b;
    b.locate_fraction = 1e-5;
    b.amplitude = 1e-3 * s.model.characteristic_length;
    b.rotation_length = spec.length / spec.elements;
    return b;
  }
  // +1 on every free z-translation: an imperfection toward +z.
  Eigen::VectorXd UpwardImperfection() const {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(s.model.DofCount());
    for (int i = 0; i < s.model.NodeCount(); ++i) full(kDofsPerNode * i + 2) = 1;
    return s.dofs.Restrict(full);
  }
  BranchSwitch Switch(const BifurcationSettings& settings, const CancellationToken* cancel) {
    return SwitchBranch(stepper, s.system, start, nullptr, crossing, 0, settings, cancel);
  }
  double TipZ(const ShellState& state) const { return test::ProbeAt(s.model, "tip", state).z(); }

  test::StripSpec spec;
  test::SceneSystem s;
  ArcLengthStepper stepper;
  PathPoint start, crossing;
};

// λ on the elastica of the clamped–free column at a tip deflection δ: δ/L =
// 2k/K(k) and P = (2K(k)/π)² P_E, so λ = P/(2 P_E).
double ElasticaLambda(double deflection_over_length) {
  double lo = 0, hi = 0.99;  // δ/L rises with k: bisection
  for (int i = 0; i < 60; ++i) {
    const double k = (lo + hi) / 2;
    (2 * k / std::comp_ellint_1(k) < deflection_over_length ? lo : hi) = k;
  }
  const double kk = std::comp_ellint_1((lo + hi) / 2);
  return 4 * kk * kk / (kPi * kPi) / 2;
}

// Located at Euler's load, λ = 1/2, to the mesh's error on the critical
// load (h²: measured 6.45e-3 above on 8 elements, 1.61e-3 on 16, their
// Richardson extrapolation 8.6e-6 below); the branch point stable, on the
// elastica at its own deflection to the same error (measured 6.46e-3,
// 1.60e-3, extrapolated 1.3e-5 below: at δ/L ≈ 4e-4 the elastica's λ is
// Euler's to 1e-7, so this holds the step along the mode at the critical
// load); the last point before the bifurcation straight, stable and below
// it.
TEST(BranchSwitch, LocatesEulersLoadAndStepsOntoTheStableElastica) {
  std::vector<double> located, branch;
  for (int elements : {8, 16}) {
    Column c(elements);
    ASSERT_EQ(c.crossing.step.status, NewtonOutcome::Status::kConverged);
    ASSERT_EQ(c.crossing.step.negative_pivots, 1);  // P = 1.5 P_E: one Euler load passed
    const BranchSwitch sw = c.Switch(c.Settings(), nullptr);
    ASSERT_TRUE(sw.switched) << sw.failure;
    EXPECT_FALSE(sw.cancelled);
    EXPECT_EQ(sw.kind, Branch::kStable);
    EXPECT_EQ(sw.negative_pivots_fundamental, 1);
    EXPECT_EQ(sw.modes, 1);
    ASSERT_TRUE(sw.bifurcation.has_value());
    EXPECT_LT(sw.bifurcation->lambda, sw.lambda);
    EXPECT_EQ(sw.bifurcation->step.negative_pivots, 0);
    EXPECT_EQ(sw.bifurcation->state.positions.col(2).cwiseAbs().maxCoeff(), 0.0);  // straight
    EXPECT_EQ(sw.branch.step.negative_pivots, 0);
    // The bracket: at most locate_fraction (1e-5) of the path to its near
    // end, and the located λ its middle. On the straight path Δs = ψΔλ to
    // 3e-12 (the shortening, 5e-7 m per unit λ, against ψ = 0.2 m), so in λ
    // the half-bracket is at most 0.5e-5 λ (measured 2.85e-6 λ).
    EXPECT_LE(sw.lambda - sw.bifurcation->lambda, 0.5e-5 * sw.lambda);
    // The largest nodal translation onto the branch: the tip's, recomputed.
    const double moved =
        (sw.branch.state.positions - sw.bifurcation->state.positions).rowwise().norm().maxCoeff();
    EXPECT_NEAR(sw.max_displacement, moved, 1e-15 * moved);
    const double delta = std::abs(c.TipZ(sw.branch.state)) / c.spec.length;
    located.push_back(sw.lambda / 0.5);
    branch.push_back(sw.branch.lambda / ElasticaLambda(delta));
    std::printf(
        "%d elements: located λ/λ_E − 1 = %.3e; branch δ/L = %.3e, λ/elastica − 1 = %.3e"
        " (%d iterations, %.3f s)\n",
        elements,
        located.back() - 1,
        delta,
        branch.back() - 1,
        sw.iterations,
        sw.seconds);
  }
  const double located_extrapolated = (4 * located[1] - located[0]) / 3;
  const double branch_extrapolated = (4 * branch[1] - branch[0]) / 3;
  std::printf("extrapolated: located − 1 = %.3e, branch − 1 = %.3e\n",
              located_extrapolated - 1,
              branch_extrapolated - 1);
  EXPECT_NEAR(located[0], 1.0, 2e-2);
  EXPECT_NEAR(located[1], 1.0, 5e-3);
  EXPECT_NEAR(located_extrapolated, 1.0, 3e-5);
  EXPECT_NEAR(branch[0], 1.0, 2e-2);
  EXPECT_NEAR(branch[1], 1.0, 5e-3);
  EXPECT_NEAR(branch_extrapolated, 1.0, 4e-5);
}

// "The mode's sign that agrees with [the imperfection] is tried first", and
// the first stable branch found is taken: the column buckles toward the
// imperfection, whichever side it is on.
TEST(BranchSwitch, TheImperfectionDecidesTheSideTheColumnBucklesTo) {
  for (double side : {1.0, -1.0}) {
    Column c(8);
    BifurcationSettings settings = c.Settings();
    settings.imperfection = side * c.UpwardImperfection();
    const BranchSwitch sw = c.Switch(settings, nullptr);
    ASSERT_TRUE(sw.switched) << sw.failure;
    const double tip = c.TipZ(sw.branch.state);
    std::printf("imperfection %+g: tip z %.3e m\n", side, tip);
    EXPECT_GT(side * tip, 0);
  }
}

TEST(BranchSwitch, ACancelledSwitchStopsAndSaysSo) {
  Column c(8);
  CancellationToken cancel;
  cancel.Cancel();
  const BranchSwitch sw = c.Switch(c.Settings(), &cancel);
  EXPECT_TRUE(sw.cancelled);
  EXPECT_FALSE(sw.switched);
  EXPECT_EQ(sw.failure, "cancelled");
}

// With no Newton correction allowed, no bisection step converges (so no
// point before the bifurcation is found: the bracket stays the step) and no
// step along the mode either: no branch, and the failure names the mode
// count and the last step's reason. (One correction is enough for all of
// them: the straight path is linear, the switch's step tiny.)
TEST(BranchSwitch, WhenNoStepAlongTheModeConvergesTheSwitchFailsAndSaysWhy) {
  NewtonSettings none;
  none.tolerance = 1e-10;
  none.max_iterations = 0;
  Column c(8, none);
  // The crossing from a stepper that can converge.
  Column able(8);
  c.crossing = able.crossing;
  ASSERT_EQ(c.crossing.step.status, NewtonOutcome::Status::kConverged);
  const BranchSwitch sw = c.Switch(c.Settings(), nullptr);
  std::printf("%s\n", sw.failure.c_str());
  EXPECT_FALSE(sw.switched);
  EXPECT_FALSE(sw.cancelled);
  EXPECT_EQ(sw.kind, Branch::kNone);
  EXPECT_FALSE(sw.bifurcation.has_value());
  EXPECT_EQ(sw.modes, 1);
  EXPECT_NE(sw.failure.find("no secondary branch along 1 critical mode(s), either sign"),
            std::string::npos);
  EXPECT_NE(sw.failure.find("no convergence in 0 iterations"), std::string::npos);
  // The bracket never shrank: the located λ is the middle of the step's.
  EXPECT_DOUBLE_EQ(sw.lambda, 0.5 * (0 + c.crossing.lambda));
}

}  // namespace
}  // namespace drape
