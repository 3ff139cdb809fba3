// The arc-length stepper called directly (arc_length_stepper.h), on the
// cantilever strip (support/strip_scene.h: L = 0.2 m, b = 1 cm, h = 0.5 mm,
// E = 1 MPa, ν = 0, clamped at x = 0; EI = 1.04e-7 N·m², EA = 5 N):
//  - a converged step lies on its sphere ‖Δu‖² + ψ²Δλ² = Δs² (round-off);
//  - under an axial pull the response is linear, u = λPx/EA at every node
//    (uniform stress: the 4-node mesh is exact), so the predictor's tangent
//    K⁻¹F₀ is known by hand, and with it Δs, the step's Δλ, StepTo's
//    direction and LambdaDirection's sign;
//  - under an end moment each step lands on the circle of radius EI/(λM);
//  - a step past the target lands on it, PL³/3EI at the tip;
//  - StepAlong ends on its hyperplane, on the elastica of the column.
#include "core/continuation/arc_length_stepper.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include "core/continuation/step_policy.h"
#include "support/strip_arc.h"
#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

NewtonSettings Tight() {
  NewtonSettings n;
  n.tolerance = 1e-10;
  return n;
}

// The free translations of `to − from` (the sphere's Δu), over the free DOFs.
Eigen::VectorXd FreeTranslation(const test::SceneSystem& s,
                                const ShellState& from,
                                const ShellState& to) {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(s.model.DofCount());
  for (int i = 0; i < s.model.NodeCount(); ++i)
    full.segment<3>(kDofsPerNode * i) = (to.positions.row(i) - from.positions.row(i)).transpose();
  return s.dofs.Restrict(full);
}

// Under a pull P along x, K⁻¹F₀ at the flat strip by hand: u_x = P x/EA on
// every free node, nothing else, over the free DOFs.
Eigen::VectorXd PullTangent(const test::SceneSystem& s, double force, const test::StripSpec& spec) {
  const double ea = spec.youngs_modulus * spec.width * spec.thickness;
  Eigen::VectorXd full = Eigen::VectorXd::Zero(s.model.DofCount());
  for (int i = 0; i < s.model.NodeCount(); ++i)
    full(kDofsPerNode * i) = force * s.model.reference.positions(i, 0) / ea;
  return s.dofs.Restrict(full);
}

// ---- the sphere ---------------------------------------------------------------

// The end moment M = EI/L (one radian at λ = 1): Δu is nonlinear in Δλ, so
// the corrector has to move off the predictor to get back onto the sphere.
TEST(ArcLengthStepper, ConvergedStepsLieOnTheirSphereToRoundOff) {
  const test::StripSpec spec = test::StripOf(8);
  const double ei = test::StripBendingStiffness(spec);
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, 0}, {0, ei / spec.length, 0}));
  const double psi = 0.05;
  ArcLengthStepper stepper(s.system, s.loading, Tight(), psi);
  ShellState state = s.model.reference;
  double lambda = 0;
  std::optional<PathDirection> previous;
  double worst = 0;
  for (int k = 0; k < 3; ++k) {
    const ShellState start = state;
    // The first step sized from Δλ₀ = 0.2, the others 0.02 m long.
    const ContinuationStep step = stepper.Step(state,
                                               {.lambda = lambda,
                                                .arc_length = k == 0 ? 0.0 : 0.02,
                                                .first_increment = 0.2,
                                                .previous = previous ? &*previous : nullptr},
                                               nullptr);
    ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
    ASSERT_FALSE(step.landed);
    const Eigen::VectorXd du = FreeTranslation(s, start, state);
    const double dl = step.lambda - lambda;
    const double sphere = du.squaredNorm() + psi * psi * dl * dl;
    const double error = std::abs(sphere / (step.arc_length * step.arc_length) - 1);
    worst = std::max(worst, error);
    std::printf("step %d: λ %.6f, Δs %.5f m, %d iterations, |sphere/Δs² − 1| = %.2e\n",
                k + 1,
                step.lambda,
                step.arc_length,
                step.iterations,
                error);
    if (k > 0) {
      EXPECT_EQ(step.arc_length, 0.02);
    }
    EXPECT_GT(dl, 0);
    // The direction reported is that same secant.
    EXPECT_LT((step.direction.translation - du).norm(), 1e-12 * du.norm());
    EXPECT_NEAR(step.direction.lambda, dl, 1e-14);
    lambda = step.lambda;
    previous = step.direction;
  }
  EXPECT_LT(worst, 1e-15);  // measured 2.2e-16: one rounding
}

// ---- the axial pull: a linear response known by hand ----------------------------

// The pull's stretch u' = λP/EA = λ·1e-6 is linear to 1.5u' (Green strain:
// the force is EA(u' + 1.5u'² + …)), so at the linear predictor ‖R‖/R₀ =
// 1.5u' ≤ 6e-7, within a tolerance of 1e-6: these steps end on their
// predictor, whose translations are λ K⁻¹F₀ to the linear solve's round-off.
NewtonSettings Linear() {
  NewtonSettings n;
  n.tolerance = 1e-6;
  return n;
}

// Δs from Δλ₀ = 0.3: Δs = Δλ₀ √(‖K⁻¹F₀‖² + ψ²), and the step is the
// predictor: Δλ = Δλ₀, Δu = Δλ₀ K⁻¹F₀. Measured: Δs 2.2e-15 off, Δλ exactly
// 0.3, Δu 1.5e-10 off.
TEST(ArcLengthStepper, OnALinearPathTheFirstStepTakesTheRequestedIncrement) {
  const test::StripSpec spec = test::StripOf(8);
  const double ea = spec.youngs_modulus * spec.width * spec.thickness;
  const double force = 1e-6 * ea;
  test::SceneSystem s(test::TipLoadedStrip(spec, {force, 0, 0}, {0, 0, 0}));
  const double psi = 1e-6;  // on the scale of the displacements (‖t_i‖ = 9e-7 m)
  ArcLengthStepper stepper(s.system, s.loading, Linear(), psi);
  ShellState state = s.model.reference;
  const ContinuationStep step =
      stepper.Step(state, {.lambda = 0, .arc_length = 0, .first_increment = 0.3}, nullptr);
  ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
  EXPECT_EQ(step.convergence, Convergence::kTolerance);
  EXPECT_EQ(step.iterations, 1);  // the predictor's solve
  const Eigen::VectorXd t = PullTangent(s, force, spec);
  const double ds = 0.3 * std::sqrt(t.squaredNorm() + psi * psi);
  const double u_error =
      (FreeTranslation(s, s.model.reference, state) - 0.3 * t).norm() / (0.3 * t.norm());
  std::printf("Δs/hand − 1 = %.2e, Δλ − 0.3 = %.2e, Δu %.2e off\n",
              step.arc_length / ds - 1,
              step.lambda - 0.3,
              u_error);
  EXPECT_NEAR(step.arc_length / ds, 1.0, 1e-14);
  EXPECT_NEAR(step.lambda, 0.3, 1e-15);
  EXPECT_LT(u_error, 5e-10);
}

// StepTo: λ → target under load control; the direction is (Δλ K⁻¹F₀
// translations, Δλ), the length |Δλ|, and the state Δλ K⁻¹F₀ (the
// predictor). Measured: direction 9.4e-14 (Release, -O3) and 4.5e-13 (the
// sanitized build, -O2: the factorisation's round-off follows the order of
// its sums), state 1.3e-10 off.
TEST(ArcLengthStepper, StepToLandsOnTheTargetAlongTheLinearResponse) {
  const test::StripSpec spec = test::StripOf(8);
  const double ea = spec.youngs_modulus * spec.width * spec.thickness;
  const double force = 1e-6 * ea;
  test::SceneSystem s(test::TipLoadedStrip(spec, {force, 0, 0}, {0, 0, 0}));
  ArcLengthStepper stepper(s.system, s.loading, Linear(), 1e-6);
  ShellState state = s.model.reference;
  const ContinuationStep step = stepper.StepTo(state, 0.0, 0.4, nullptr);
  ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
  EXPECT_EQ(step.convergence, Convergence::kTolerance);
  EXPECT_TRUE(step.landed);
  EXPECT_EQ(step.lambda, 0.4);
  EXPECT_EQ(step.direction.lambda, 0.4);
  EXPECT_EQ(step.arc_length, 0.4);
  EXPECT_EQ(step.iterations, 1);  // the predictor's solve, no correction
  const Eigen::VectorXd t = PullTangent(s, force, spec);
  const double direction_error = (step.direction.translation - 0.4 * t).norm() / (0.4 * t.norm());
  const double state_error =
      (FreeTranslation(s, s.model.reference, state) - 0.4 * t).norm() / (0.4 * t.norm());
  std::printf("direction %.2e, state %.2e off 0.4 P x/EA\n", direction_error, state_error);
  EXPECT_LT(direction_error, 2e-12);
  EXPECT_LT(state_error, 5e-10);
}

// Forward is the side of the secant: sign(Δu·t + ψ²Δλ) with t the
// translations of K⁻¹F₀ (here by hand). Secants just either side of the
// plane Δu·t + ψ²Δλ = 0, 1 % off it.
TEST(ArcLengthStepper, LambdaDirectionIsTheSideOfTheSecantAlongTheTangent) {
  const test::StripSpec spec = test::StripOf(8);
  const double ea = spec.youngs_modulus * spec.width * spec.thickness;
  const double force = 1e-6 * ea;
  test::SceneSystem s(test::TipLoadedStrip(spec, {force, 0, 0}, {0, 0, 0}));
  const double psi = 1e-6;
  ArcLengthStepper stepper(s.system, s.loading, Tight(), psi);
  ShellState state = s.model.reference;
  ASSERT_EQ(stepper.StepTo(state, 0.0, 0.5, nullptr).status, NewtonOutcome::Status::kConverged);
  const Eigen::VectorXd t = PullTangent(s, force, spec);
  const double balance = t.squaredNorm() / (psi * psi);  // Δλ on the plane for Δu = t
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {t, 1.0}), 1);
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {-t, -1.0}), -1);
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {t, -0.99 * balance}), 1);
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {t, -1.01 * balance}), -1);
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {-t, 0.99 * balance}), -1);
  EXPECT_EQ(stepper.LambdaDirection(state, 0.5, {-t, 1.01 * balance}), 1);
}

// Length: √(‖Δu‖² + ψ_e²Δλ²), ψ_e² = ψ² + ‖∂u_p/∂λ‖². A 3-4-5 secant with
// ψΔλ = 12 is 13 long under a load; with the tip's two clamped nodes moved
// by 0.2 m along x over the stage, ‖∂u_p/∂λ‖² = 2 · 0.2² = 0.08 m².
TEST(ArcLengthStepper, LengthIsTheSecantInTheMetricWithThePrescribedSpeedFoldedIntoPsi) {
  const test::StripSpec spec = test::StripOf(2);
  {
    test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -1e-6}, {0, 0, 0}));
    ArcLengthStepper stepper(s.system, s.loading, Tight(), 2.0);
    Eigen::VectorXd du = Eigen::VectorXd::Zero(s.dofs.FreeCount());
    du(0) = 3;
    du(7) = 4;
    EXPECT_DOUBLE_EQ(stepper.Length({du, 6.0}, 0.5, s.model.reference), 13.0);
  }
  Scene scene = test::CantileverStrip(spec);
  scene.grippers.push_back({"tip", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kClamp});
  Stage move;
  move.name = "pull";
  move.kind = StageKind::kMove;
  move.moves.push_back({"tip", LinePath{{0.2, 0, 0}}, {}});
  scene.stages.push_back(move);
  test::SceneSystem s(scene);
  ASSERT_EQ(s.model.grippers.at(0).nodes.size(), 2u);
  ArcLengthStepper stepper(s.system, s.loading, Tight(), 0.3);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(s.dofs.FreeCount());
  EXPECT_DOUBLE_EQ(stepper.Length({none, 1.0}, 0.5, s.model.reference),
                   std::sqrt(0.3 * 0.3 + 0.08));
}

// ---- along the end moment's circle -------------------------------------------------

// Steps sized by the paper's acceleration from Δλ₀ = 0.1 to λ = 1 under the
// end moment M = EI/L: every converged point on the circle of radius
// EI/(λM) to the discretisation error (8 elements: measured at most 1.32e-3 L
// at λ = 1, in NewtonCorrector.EndMomentBendsTheStripIntoACircleOfRadiusEIOverM),
// the last landing on λ = 1 exactly.
TEST(ArcLengthStepper, StepsFollowTheEndMomentsCircleAndLandOnTheTarget) {
  const test::StripSpec spec = test::StripOf(8);
  const double ei = test::StripBendingStiffness(spec);
  const double moment = ei / spec.length;
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, 0}, {0, moment, 0}));
  ArcLengthStepper stepper(s.system, s.loading, Tight(), s.model.characteristic_length);
  const StepPolicy policy;
  ShellState state = s.model.reference;
  double lambda = 0, arc_length = 0, worst = 0;
  std::optional<PathDirection> previous;
  int steps = 0;
  while (lambda < 1 && steps < 30) {
    const ContinuationStep step = stepper.Step(state,
                                               {.lambda = lambda,
                                                .arc_length = arc_length,
                                                .first_increment = 0.1,
                                                .previous = previous ? &*previous : nullptr},
                                               nullptr);
    ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
    ++steps;
    lambda = step.landed ? 1.0 : step.lambda;
    if (step.landed) {
      EXPECT_EQ(step.lambda, 1.0);
    }
    const Eigen::Vector3d tip = test::ProbeAt(s.model, "tip", state);
    const double error = (tip - test::ArcPoint(spec.length, ei / (lambda * moment))).norm();
    worst = std::max(worst, error / spec.length);
    std::printf("λ %.5f (%d its%s): tip off the arc by %.2e L\n",
                lambda,
                step.iterations,
                step.landed ? ", landed" : "",
                error / spec.length);
    previous = step.direction;
    arc_length = policy.Next(step.arc_length, step.iterations);
  }
  EXPECT_EQ(lambda, 1.0);
  EXPECT_LT(worst, 4e-3);  // measured 1.32e-3 L, at λ = 1 (the error grows with the bend)
}

// A step whose predictor passes the target lands on it under load control:
// the tip force's small deflection PL³/3EI at λ = 1 (16 elements: 9.74e-4
// low, NewtonCorrector.SmallTipForceDeflectsTheTipByPLCubedOver3EI), its
// residual within the tolerance of R₀ = |Δλ| ‖F₀‖ = P/√2 (P/2 on each of
// the two tip nodes).
TEST(ArcLengthStepper, AStepPastTheTargetLandsOnItAtPLCubedOver3EI) {
  const test::StripSpec spec = test::StripOf(16);
  const double ei = test::StripBendingStiffness(spec);
  const double exact = 1e-3 * spec.length;
  const double force = 3 * ei * exact / std::pow(spec.length, 3);
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -force}, {0, 0, 0}));
  NewtonSettings newton;
  newton.tolerance = 1e-4;
  ArcLengthStepper stepper(s.system, s.loading, newton, s.model.characteristic_length);
  ShellState state = s.model.reference;
  const ContinuationStep step =
      stepper.Step(state, {.lambda = 0, .arc_length = 0, .first_increment = 2.0}, nullptr);
  ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
  EXPECT_TRUE(step.landed);
  EXPECT_EQ(step.lambda, 1.0);
  const double deflection = -test::ProbeAt(s.model, "tip", state).z();
  std::printf("tip / (PL³/3EI) − 1 = %.4e\n", deflection / exact - 1);
  EXPECT_NEAR(deflection / exact, 1.0, 3e-3);
  // The ratio is ‖R‖ over R₀ = |Δλ| ‖F₀‖ with Δλ = 1, the landing's (not
  // the predictor's 2): to round-off (measured 2.2e-16).
  const double ratio = s.ResidualNorm(state, 1.0) / (force / std::sqrt(2.0));
  std::printf("last ratio / (‖R‖/R₀) − 1 = %.2e\n", step.residuals.back() / ratio - 1);
  EXPECT_NEAR(step.residuals.back() / ratio, 1.0, 1e-15);
  EXPECT_LE(step.residuals.back(), newton.tolerance);
}

// ---- StepAlong --------------------------------------------------------------------------

// A straight clamped–free column under 2 P_E (P_E = π²EI/4L², its first
// Euler load), stepped along w = 1 − cos(πx/2L) (Euler's mode; rotations left
// out, rotation_length 0) by an amplitude A = 0.02 L: the converged point
// lies on the hyperplane n·Δu = A (n the unit mode; translations add
// exactly), and on the elastica: a tip deflection δ = 2kL/K(k) carries P =
// (2K(k)/π)² P_E, i.e. λ = P/(2 P_E). The mesh's critical load converges as
// h²: measured λ 0.646 % above the elastica's on 8 elements, 0.160 % on 16,
// and their Richardson extrapolation 1.3e-5 below.
TEST(ArcLengthStepper, StepAlongEndsOnItsHyperplaneOnTheElastica) {
  std::vector<double> ratios;  // λ over the elastica's
  for (int elements : {8, 16}) {
    const test::StripSpec spec = test::StripOf(elements);
    const double euler =
        kPi * kPi * test::StripBendingStiffness(spec) / (4 * spec.length * spec.length);
    test::SceneSystem s(test::TipLoadedStrip(spec, {-2 * euler, 0, 0}, {0, 0, 0}));
    ArcLengthStepper stepper(s.system, s.loading, Tight(), s.model.characteristic_length);
    ShellState state = s.model.reference;
    ASSERT_EQ(stepper.StepTo(state, 0.0, 1.0, nullptr).status, NewtonOutcome::Status::kConverged);
    const ShellState straight = state;
    Eigen::VectorXd full = Eigen::VectorXd::Zero(s.model.DofCount());
    for (int i = 0; i < s.model.NodeCount(); ++i)
      full(kDofsPerNode * i + 2) =
          1 - std::cos(kPi * s.model.reference.positions(i, 0) / (2 * spec.length));
    const Eigen::VectorXd mode = s.dofs.Restrict(full);
    const double amplitude = 0.02 * spec.length;
    const ContinuationStep step = stepper.StepAlong(state, 1.0, mode, amplitude, 0.0, nullptr);
    ASSERT_EQ(step.status, NewtonOutcome::Status::kConverged) << step.reason;
    EXPECT_EQ(step.negative_pivots, 0);  // the buckled column is stable
    const double plane = mode.normalized().dot(FreeTranslation(s, straight, state));
    std::printf("%d elements: n·Δu/A − 1 = %.2e\n", elements, plane / amplitude - 1);
    EXPECT_NEAR(plane / amplitude, 1.0, 1e-14);  // measured 0 (8 and 16 elements)

    const double delta = std::abs(test::ProbeAt(s.model, "tip", state).z()) / spec.length;
    double lo = 0, hi = 0.99;  // δ/L = 2k/K(k) rises with k: bisection
    for (int i = 0; i < 60; ++i) {
      const double k = (lo + hi) / 2;
      (2 * k / std::comp_ellint_1(k) < delta ? lo : hi) = k;
    }
    const double kk = std::comp_ellint_1((lo + hi) / 2);
    const double elastica = 4 * kk * kk / (kPi * kPi) / 2;  // λ = P/(2 P_E)
    ratios.push_back(step.lambda / elastica);
    std::printf("  δ/L = %.4e: λ %.6f, elastica %.6f, ratio − 1 = %.3e\n",
                delta,
                step.lambda,
                elastica,
                ratios.back() - 1);
  }
  EXPECT_NEAR(ratios[0], 1.0, 2e-2);
  EXPECT_NEAR(ratios[1], 1.0, 5e-3);
  const double extrapolated = (4 * ratios[1] - ratios[0]) / 3;
  std::printf("extrapolated − 1 = %.3e\n", extrapolated - 1);
  EXPECT_NEAR(extrapolated, 1.0, 4e-5);
}

}  // namespace
}  // namespace drape
