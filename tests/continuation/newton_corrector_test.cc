// The Newton corrector called directly (newton_corrector.h): JudgeIteration's
// verdicts against the rules its header states, SolveEquilibrium on a
// cantilever strip against beam theory (the end moment's circle of radius
// EI/M, the tip force's PL³/3EI, Euler's loads in the pivot count) and
// against Newton's quadratic convergence, and RunCorrector's loop (what it
// counts, records, refuses and stops on).
//
// The strip (support/strip_scene.h): L = 0.2 m, b = 1 cm, h = 0.5 mm, E =
// 1 MPa, ν = 0, clamped at x = 0; EI = E b h³/12 = 1.04e-7 N·m².
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "core/continuation/newton_corrector.h"
#include "support/strip_arc.h"
#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

// The stage's full load (λ = 1) as SolveEquilibrium takes it.
ExternalForce FullLoad(const test::SceneSystem& s) {
  return [&s](const ShellState& state) { return s.loading.External(1.0, state); };
}

// ---- JudgeIteration: each verdict from the rules in the header ---------------

NewtonSettings JudgeSettings() {
  NewtonSettings s;
  s.tolerance = 1e-6;
  s.round_off_factor = 10;
  s.stall_correction = 1e-9;
  s.max_iterations = 5;
  s.divergence_ratio = 1e6;
  return s;
}

struct Judged {
  IterationVerdict verdict;
  std::vector<double> ratios;
  Convergence convergence = Convergence::kNotYet;
};

Judged Judge(double norm,
             double reference,
             double round_off = 0,
             double last_correction = INFINITY,
             int corrections = 0,
             std::vector<double> before = {}) {
  Judged j;
  j.ratios = std::move(before);
  j.verdict = JudgeIteration(JudgeSettings(),
                             norm,
                             reference,
                             round_off,
                             last_correction,
                             corrections,
                             j.ratios,
                             j.convergence);
  return j;
}

TEST(NewtonCorrectorJudge, AppendsTheNormOverTheReferenceOrTheNormItselfWithoutOne) {
  // 3/4 and 0.5 are exact in binary: the ratio must be exactly that.
  Judged j = Judge(3.0, 4.0, 0, INFINITY, 0, {1.0});
  ASSERT_EQ(j.ratios.size(), 2u);
  EXPECT_EQ(j.ratios[0], 1.0);  // earlier ratios kept
  EXPECT_EQ(j.ratios[1], 0.75);
  EXPECT_FALSE(j.verdict.done);
  j = Judge(0.5, 0.0);
  ASSERT_EQ(j.ratios.size(), 1u);
  EXPECT_EQ(j.ratios[0], 0.5);
  EXPECT_EQ(j.convergence, Convergence::kNotYet);
}

TEST(NewtonCorrectorJudge, ConvergesAtTheToleranceOrAtTheRoundOffFloor) {
  // ‖R‖/‖R₀‖ = 1e-6 = the tolerance ("≤ tolerance").
  Judged j = Judge(1e-6, 1.0);
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kConverged);
  EXPECT_EQ(j.convergence, Convergence::kTolerance);
  // Twice the tolerance: not converged, and nothing else stops it.
  j = Judge(2e-6, 1.0);
  EXPECT_FALSE(j.verdict.done);
  EXPECT_EQ(j.convergence, Convergence::kNotYet);
  // ‖R‖ = 1e-9 N (ratio 1e3 to ‖R₀‖ = 1e-12 N) at a round-off level of
  // 1e-10 N: 10 × the level, at the floor.
  j = Judge(1e-9, 1e-12, 1e-10);
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kConverged);
  EXPECT_EQ(j.convergence, Convergence::kRoundOff);
  // 20 × the level: above the floor.
  j = Judge(2e-9, 1e-12, 1e-10);
  EXPECT_FALSE(j.verdict.done);
  // Converged on the last allowed iteration is converged, not out of iterations.
  j = Judge(1e-7, 1.0, 0, 1.0, /*corrections=*/5);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kConverged);
}

TEST(NewtonCorrectorJudge, TinyCorrectionsWithAResidualThatNoLongerHalvesStall) {
  // Correction 1e-12 m ≤ stall_correction (1e-9 m), ratio 8e-4 after 1e-3.
  Judged j = Judge(8e-4, 1.0, 0, 1e-12, 2, {1.0, 1e-3});
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kStalled);
  EXPECT_EQ(j.convergence, Convergence::kStalled);
  EXPECT_NE(j.verdict.reason.find("stalled"), std::string::npos) << j.verdict.reason;
  // The same correction while the residual halves (4e-4 after 1e-3): progress.
  j = Judge(4e-4, 1.0, 0, 1e-12, 2, {1.0, 1e-3});
  EXPECT_FALSE(j.verdict.done);
}

TEST(NewtonCorrectorJudge, DivergesOnANonFiniteResidualOrOneAboveTheDivergenceRatio) {
  Judged j = Judge(NAN, 1.0);
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kDiverged);
  ASSERT_EQ(j.ratios.size(), 1u);  // recorded all the same
  EXPECT_TRUE(std::isnan(j.ratios[0]));
  j = Judge(INFINITY, 1.0);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kDiverged);
  // 2e6 > divergence_ratio (1e6); exactly 1e6 is not above it.
  j = Judge(2e6, 1.0);
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kDiverged);
  EXPECT_NE(j.verdict.reason.find("2e+06"), std::string::npos) << j.verdict.reason;
  j = Judge(1e6, 1.0);
  EXPECT_FALSE(j.verdict.done);
}

TEST(NewtonCorrectorJudge, RunsOutOfIterationsAfterMaxIterationsCorrections) {
  Judged j = Judge(0.1, 1.0, 0, 1.0, /*corrections=*/4);  // max_iterations 5
  EXPECT_FALSE(j.verdict.done);
  j = Judge(0.1, 1.0, 0, 1.0, /*corrections=*/5);
  EXPECT_TRUE(j.verdict.done);
  EXPECT_EQ(j.verdict.status, NewtonOutcome::Status::kIterationLimit);
  EXPECT_NE(j.verdict.reason.find("5 iterations"), std::string::npos) << j.verdict.reason;
}

// ---- SolveEquilibrium on the cantilever strip ---------------------------------

// A pure end moment M bends the strip into a circle of radius EI/M (ν = 0:
// no anticlastic curvature). Newton from the flat strip diverges under a
// moment (its first, linear step stretches the strip by the tip's whole
// deflection), so it starts on the closed-form arc: the FE equilibrium near
// it differs by the mesh's discretisation error, O(h²).
//
// Measured (8 / 16 elements): nodes off the circle by 9.06e-4 / 2.26e-4 L,
// directors off its radius by 1.66e-3 / 4.13e-4, the tip off the arc's by
// 1.32e-3 / 3.30e-4 L, and the tip of the Richardson extrapolation from the
// two by 2.0e-6 L; every node's y kept to 1.7e-15 L.
TEST(NewtonCorrector, EndMomentBendsTheStripIntoACircleOfRadiusEIOverM) {
  struct Within {
    int elements;
    double radial, director, tip;  // [L], [1], [L]
  };
  std::vector<Eigen::Vector3d> tips;
  for (const Within& w : {Within{8, 3e-3, 5e-3, 4e-3}, Within{16, 7e-4, 1.2e-3, 1e-3}}) {
    const test::StripSpec spec = test::StripOf(w.elements);
    const double ei = test::StripBendingStiffness(spec);
    const double radius = spec.length;  // one radian of bend: M = EI/L
    test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, 0}, {0, ei / radius, 0}));
    ShellState state = test::ArcState(s.model, radius);
    s.loading.Place(1.0, state);  // the load factor the edge moment's work scales with
    NewtonSettings settings;
    settings.tolerance = 1e-12;
    const NewtonOutcome out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
    ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;
    // Every node on the circle, its director along the radius, its y kept.
    const Eigen::Vector3d centre(0, 0, -radius);
    double radial = 0, director = 0, width = 0;
    for (int i = 0; i < s.model.NodeCount(); ++i) {
      const Eigen::Vector3d x = state.positions.row(i).transpose() - centre;
      const Eigen::Vector3d in_plane(x.x(), 0, x.z());
      radial = std::max(radial, std::abs(in_plane.norm() - radius));
      director = std::max(director, (state.Director(i) - in_plane.normalized()).norm());
      width = std::max(width, std::abs(x.y() - s.model.reference.positions(i, 1)));
    }
    tips.push_back(test::ProbeAt(s.model, "tip", state));
    const double tip_error = (tips.back() - test::ArcPoint(spec.length, radius)).norm();
    std::printf("%d elements: radial %.3e L, director %.3e, width %.3e L, tip %.3e L (%d its)\n",
                w.elements,
                radial / spec.length,
                director,
                width / spec.length,
                tip_error / spec.length,
                out.iterations);
    EXPECT_LT(radial, w.radial * spec.length);
    EXPECT_LT(director, w.director);
    EXPECT_LT(width, 1e-13 * spec.length);
    EXPECT_LT(tip_error, w.tip * spec.length);
  }
  const double length = test::StripOf(8).length;
  const Eigen::Vector3d extrapolated = (4 * tips[1] - tips[0]) / 3;
  const double error = (extrapolated - test::ArcPoint(length, length)).norm() / length;
  std::printf("extrapolated tip: %.3e L\n", error);
  EXPECT_LT(error, 6e-6);
}

// Near the solution Newton converges quadratically: e₁ = C e₀². From the
// equilibrium under M, the strip is solved again under M(1 + δ): e₀ is the
// distance between the two equilibria (∝ δ) and e₁ what is left after the
// first correction. C = e₁/e₀² must not depend on δ; for a linearly
// converging iteration it would grow as 1/δ (a factor 100 here).
//
// Distances are the largest nodal distance to the final iterate (converged
// to the round-off floor). Residuals do not show the rate on this thin
// strip: after the first correction ‖R‖/‖R₀‖ rises to 4.7e3 (δ = 1e-3) while
// the error falls 3000-fold, the residual then being membrane force, which
// per unit of error is EA/EI = 4.8e7 m⁻² times the bending residual it
// replaced.
TEST(NewtonCorrector, ConvergesQuadraticallyOnACantileverUnderAnEndMoment) {
  const test::StripSpec spec = test::StripOf(8);
  const double ei = test::StripBendingStiffness(spec);
  const double radius = spec.length;
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, 0}, {0, ei / radius, 0}));
  ShellState converged = test::ArcState(s.model, radius);
  s.loading.Place(1.0, converged);
  NewtonSettings settings;
  settings.tolerance = 1e-15;  // on to the round-off floor
  ASSERT_EQ(SolveEquilibrium(s.system, FullLoad(s), settings, converged, nullptr).status,
            NewtonOutcome::Status::kConverged);
  auto distance = [&](const ShellState& a, const ShellState& b) {
    return (a.positions - b.positions).rowwise().norm().maxCoeff();
  };
  std::vector<double> constants;
  for (double delta : {1e-1, 1e-2, 1e-3}) {
    std::vector<ShellState> iterates;  // the state at each assembly
    ShellState state = converged;
    // The moment about the tip edge is a potential scaled by the state's
    // load factor; the rest of the load scales here.
    state.load_factor = 1 + delta;
    const NewtonOutcome out = SolveEquilibrium(
        s.system,
        [&](const ShellState& x) {
          iterates.push_back(x);
          return Eigen::VectorXd((1 + delta) * s.loading.External(1.0, x));
        },
        settings,
        state,
        nullptr);
    ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;
    ASSERT_GE(iterates.size(), 3u);
    const double e0 = distance(iterates[0], state), e1 = distance(iterates[1], state);
    constants.push_back(e1 / (e0 * e0));
    std::printf("δ = %g: e0 = %.4e m, e1 = %.4e m, e1/e0² = %.5g /m, %d iterations\n",
                delta,
                e0,
                e1,
                constants.back(),
                out.iterations);
  }
  // Measured: C = 3.4547, 3.4419, 3.4418 /m for δ = 0.1, 0.01, 0.001: a
  // spread of 0.37 %.
  for (double c : constants) EXPECT_NEAR(c / constants.front(), 1.0, 1.2e-2);
}

// Small deflection: the tip moves by PL³/3EI (Euler–Bernoulli; the shell's
// shear adds (h/L)² ≈ 6e-6 relative, the geometric nonlinearity at δ/L = 1e-3
// about as little). The 4-node mesh converges as h²: measured 3.90e-3 low on
// 8 elements, 9.74e-4 on 16, and their Richardson extrapolation within
// 3e-6 of beam theory.
TEST(NewtonCorrector, SmallTipForceDeflectsTheTipByPLCubedOver3EI) {
  std::vector<double> ratios;
  for (int elements : {8, 16}) {
    const test::StripSpec spec = test::StripOf(elements);
    const double ei = test::StripBendingStiffness(spec);
    const double exact = 1e-3 * spec.length;
    const double force = 3 * ei * exact / std::pow(spec.length, 3);
    test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -force}, {0, 0, 0}));
    ShellState state = s.model.reference;
    NewtonSettings settings;
    settings.tolerance = 1e-10;
    const NewtonOutcome out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
    ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;
    ratios.push_back(-test::ProbeAt(s.model, "tip", state).z() / exact);
    std::printf("%d elements: tip / (PL³/3EI) − 1 = %.4e\n", elements, ratios.back() - 1);
  }
  EXPECT_NEAR(ratios[0], 1.0, 1.2e-2);
  EXPECT_NEAR(ratios[1], 1.0, 3e-3);
  const double extrapolated = (4 * ratios[1] - ratios[0]) / 3;
  std::printf("extrapolated − 1 = %.3e\n", extrapolated - 1);
  EXPECT_NEAR(extrapolated, 1.0, 1e-5);
}

// The converged outcome carries the inertia of its tangent: a straight
// clamped–free column under an axial tip force P has one negative pivot per
// Euler load below P, P_n = (2n − 1)² π²EI/4L² (1, 9, 25 × P_E). The
// straight state is the exact equilibrium (the corrections stay axial).
TEST(NewtonCorrector, ConvergedTangentHasOneNegativePivotPerEulerLoadPassed) {
  const test::StripSpec spec = test::StripOf(8);
  const double euler =
      kPi * kPi * test::StripBendingStiffness(spec) / (4 * spec.length * spec.length);
  const struct {
    double load;  // over P_E
    int pivots;
  } cases[] = {{0.5, 0}, {2.0, 1}, {15.0, 2}};
  for (const auto& c : cases) {
    test::SceneSystem s(test::TipLoadedStrip(spec, {-c.load * euler, 0, 0}, {0, 0, 0}));
    ShellState state = s.model.reference;
    NewtonSettings settings;
    settings.tolerance = 1e-10;
    const NewtonOutcome out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
    ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;
    EXPECT_EQ(out.negative_pivots, c.pivots) << "P = " << c.load << " P_E";
    EXPECT_EQ(state.positions.col(2).cwiseAbs().maxCoeff(), 0.0) << "the column stays straight";
  }
}

// ‖R₀‖ at the flat strip under a tip force P (F_int = 0 there) is the load
// itself over the free DOFs: P/2 on each of the tip's two nodes, P/√2.
TEST(NewtonCorrector, RatiosAreTakenAgainstTheFirstResidualTheGivenOneOrTheForceLevel) {
  const test::StripSpec spec = test::StripOf(8);
  const double force = 3 * test::StripBendingStiffness(spec) * 0.01 / std::pow(spec.length, 2);
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -force}, {0, 0, 0}));
  NewtonSettings settings;
  settings.tolerance = 1e-8;

  ShellState state = s.model.reference;
  NewtonOutcome out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
  ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged);
  EXPECT_EQ(out.residuals.front(), 1.0);
  const double first = force / std::sqrt(2.0);  // ‖R₀‖
  // The last ratio is ‖R‖ at the returned state over P/√2 (to round-off:
  // the same residual, and P/√2 summed differently; measured 2e-16).
  EXPECT_NEAR(out.residuals.back() / (s.ResidualNorm(state, 1.0) / first), 1.0, 1e-12);

  settings.residual_reference = force;
  state = s.model.reference;
  out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
  EXPECT_NEAR(out.residuals.front(), 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(out.residuals.back() / (s.ResidualNorm(state, 1.0) / force), 1.0, 1e-12);

  // The force level: ‖F_ext‖ over the free DOFs plus the reactions' norm,
  // ‖F_int‖ over the fixed DOFs (no load there); no reactions at the start.
  settings.residual_reference = 0;
  settings.relative_to_force_level = true;
  state = s.model.reference;
  out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
  ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged);
  EXPECT_NEAR(out.residuals.front(), 1.0, 1e-15);
  s.system.Assemble(state, false);
  double reactions = 0;
  for (int d = 0; d < s.dofs.DofCount(); ++d)
    if (s.dofs.IsFixed(d)) reactions += std::pow(s.system.InternalForce()(d), 2);
  reactions = std::sqrt(reactions);
  // Statics: each of the two clamped root nodes carries half the force P and
  // half the moment PL (to O((δ/L)²) = 1e-4 at δ/L = 0.01). Measured 2.3e-6
  // relative.
  const double statics = std::sqrt((force * force + std::pow(force * spec.length, 2)) / 2);
  std::printf("reactions %.6e N, statics %.6e N\n", reactions, statics);
  EXPECT_NEAR(reactions / statics, 1.0, 1e-5);
  EXPECT_NEAR(
      out.residuals.back() / (s.ResidualNorm(state, 1.0) / (first + reactions)), 1.0, 1e-12);
}

TEST(NewtonCorrector, StopsAtTheIterationLimitWithThatManyCorrections) {
  // δ/L ≈ 0.3 under the tip force: Newton from the flat strip needs 10
  // corrections (measured), more than the 2 allowed.
  const test::StripSpec spec = test::StripOf(8);
  const double force = 3 * test::StripBendingStiffness(spec) * 0.3 / std::pow(spec.length, 2);
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -force}, {0, 0, 0}));
  NewtonSettings settings;
  settings.max_iterations = 2;
  ShellState state = s.model.reference;
  const NewtonOutcome out = SolveEquilibrium(s.system, FullLoad(s), settings, state, nullptr);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kIterationLimit);
  EXPECT_EQ(out.iterations, 2);
  EXPECT_EQ(out.residuals.size(), 3u);  // one per assembly: before, and after each correction
  EXPECT_NE(out.reason.find("2 iterations"), std::string::npos) << out.reason;
}

// ---- RunCorrector's loop ----------------------------------------------------------

// An axial tip pull on the strip is linear to 1e-6 (the Green strain's
// u'²/2 at ε = 1e-6): a correction of half the Newton step halves the
// residual, so the ratios are 2⁻ᵏ and the tolerance 1.5e-3 is first met
// after k = 10 corrections (2⁻⁹ = 1.95e-3, 2⁻¹⁰ = 9.8e-4).
TEST(NewtonCorrectorLoop, CountsEachCorrectionAndRecordsOneRatioPerAssembly) {
  const test::StripSpec spec = test::StripOf(8);
  const double ea = spec.youngs_modulus * spec.width * spec.thickness;
  test::SceneSystem s(test::TipLoadedStrip(spec, {1e-6 * ea, 0, 0}, {0, 0, 0}));
  CorrectorRequest request;
  request.settings.tolerance = 1.5e-3;
  std::vector<int> assembled;
  double r0 = 0;
  request.assemble = [&](const ShellState& state, int iteration) {
    assembled.push_back(iteration);
    s.system.Assemble(state, true);
    CorrectorRequest::Residual r{s.system.Residual(s.loading.External(1.0, state)), 0.0};
    if (iteration == 0) r0 = r.free.norm();
    r.reference = r0;
    return r;
  };
  int corrections = 0;
  request.correct = [&](const Eigen::VectorXd& residual, ShellState& state) {
    ++corrections;
    const Eigen::VectorXd step = s.dofs.Expand(s.system.Solve(-0.5 * residual));
    ApplyIncrement(step, state);
    return MaxTranslation(step);
  };
  ShellState state = s.model.reference;
  const NewtonOutcome out = RunCorrector(s.system, state, request, nullptr);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kConverged);
  EXPECT_EQ(out.convergence, Convergence::kTolerance);
  EXPECT_EQ(out.iterations, 10);
  EXPECT_EQ(corrections, 10);
  ASSERT_EQ(out.residuals.size(), 11u);
  for (int k = 0; k <= 10; ++k) EXPECT_EQ(assembled[k], k);
  double worst = 0;
  for (int k = 1; k <= 10; ++k)
    worst = std::max(worst, std::abs(out.residuals[k] / out.residuals[k - 1] - 0.5));
  std::printf("largest |r_k/r_(k-1) − 1/2| = %.3e\n", worst);
  EXPECT_LT(worst, 1.5e-6);  // measured 3.75e-7
  // On return the system holds the assembly at the final state: the same
  // arithmetic on the same state, so bit for bit what a fresh system gives.
  EquilibriumSystem fresh(s.model, s.dofs);
  fresh.Assemble(state, true);
  EXPECT_EQ((fresh.InternalForce() - s.system.InternalForce()).cwiseAbs().maxCoeff(), 0.0);
}

// A refused converged iterate ends as diverged with the caller's reason, and
// its tangent is not factorised for the pivot count: the column at 2 P_E,
// whose converged tangent has one negative pivot when accepted.
TEST(NewtonCorrectorLoop, ARefusedConvergedIterateEndsDivergedWithoutItsPivotCount) {
  const test::StripSpec spec = test::StripOf(8);
  const double euler =
      kPi * kPi * test::StripBendingStiffness(spec) / (4 * spec.length * spec.length);
  test::SceneSystem s(test::TipLoadedStrip(spec, {-2 * euler, 0, 0}, {0, 0, 0}));
  CorrectorRequest request;
  request.settings.tolerance = 1e-10;
  request.assemble = [&](const ShellState& state, int) {
    s.system.Assemble(state, true);
    return CorrectorRequest::Residual{s.system.Residual(s.loading.External(1.0, state)), 0.0};
  };
  request.correct = [&](const Eigen::VectorXd& r, ShellState& state) {
    return ApplyNewtonCorrection(s.system, r, state);
  };
  ShellState accepted = s.model.reference;
  const NewtonOutcome ok = RunCorrector(s.system, accepted, request, nullptr);
  ASSERT_EQ(ok.status, NewtonOutcome::Status::kConverged);
  EXPECT_EQ(ok.negative_pivots, 1);

  int asked = 0;
  request.refuse = [&](const ShellState&) {
    ++asked;
    return std::string("not this one");
  };
  ShellState refused = s.model.reference;
  const NewtonOutcome out = RunCorrector(s.system, refused, request, nullptr);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kDiverged);
  EXPECT_EQ(out.reason, "not this one");
  EXPECT_EQ(out.negative_pivots, 0);
  EXPECT_EQ(asked, 1);  // asked once: of the converged iterate only
  EXPECT_EQ(out.iterations, ok.iterations);
}

TEST(NewtonCorrectorLoop, ACancelledRunOrANonFiniteStateStopsBeforeAssembling) {
  const test::StripSpec spec = test::StripOf(2);
  test::SceneSystem s(test::TipLoadedStrip(spec, {0, 0, -1e-6}, {0, 0, 0}));
  int assemblies = 0;
  CorrectorRequest request;
  request.assemble = [&](const ShellState& state, int) {
    ++assemblies;
    s.system.Assemble(state, true);
    return CorrectorRequest::Residual{s.system.Residual(s.loading.External(1.0, state)), 0.0};
  };
  request.correct = [&](const Eigen::VectorXd& r, ShellState& state) {
    return ApplyNewtonCorrection(s.system, r, state);
  };
  CancellationToken cancel;
  cancel.Cancel();
  ShellState state = s.model.reference;
  NewtonOutcome out = RunCorrector(s.system, state, request, &cancel);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kCancelled);
  EXPECT_EQ(assemblies, 0);
  EXPECT_TRUE(out.residuals.empty());

  state.positions(3, 1) = std::numeric_limits<double>::quiet_NaN();
  out = RunCorrector(s.system, state, request, nullptr);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kDiverged);
  EXPECT_NE(out.reason.find("not finite"), std::string::npos) << out.reason;
  EXPECT_EQ(assemblies, 0);
}

}  // namespace
}  // namespace drape
