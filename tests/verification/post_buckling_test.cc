// Verification: post-buckling of a clamped–clamped strip whose right end is
// pushed in by a gripper (end shortening Δ under arc-length control).
//
// The exact solution is the clamped–clamped elastica. With p² = P/EI, the
// first (symmetric) buckled shape is four quarter-waves of Euler's pinned
// elastica, each of arc length K(k)/p between a point of zero slope and
// maximum curvature (clamps, mid-span) and an inflection point of slope α,
// k = sin(α/2). Per quarter-wave the chord is (2E(k) − K(k))/p and the rise
// 2k/p, so
//   L = 4K/p           ⇒  P = 16 K(k)² EI / L²   (P → P_E = 4π²EI/L² as k → 0),
//   L − Δ = 4(2E − K)/p ⇒  Δ/L = 2 − 2E(k)/K(k),
//   δ = 4 · 2k/p / 2    ⇒  δ/L = k/K(k)           (mid-height over the clamps),
//   θ'(0) = 2pk         ⇒  θ'(0)·L = 8kK(k)        (curvature at the clamps),
// K, E the complete elliptic integrals of modulus k (std::comp_ellint_1/2).
// PostBuckling.ClosedFormMatchesShootingOnTheElasticaOde checks every one of
// these against the ODE θ'' = −(PL²/EI) sin θ solved by shooting, which is
// independent of them; they agree to ~1e-9, so the closed form is the
// reference below.
//
// The FE strip: L = 0.2 m, b = 0.01 m, h = 0.5 mm, E = 1 MPa, ν = 0, 80 × 1
// elements, no weight; EI = 1.04e-7 N·m², EA = 5 N, P_E = 1.028e-4 N. It is
// very slender (L/h = 400): it buckles at the membrane end shortening
// Δ_E = P_E L/EA = 2.06e-5 L, so almost the whole path is post-buckled.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/model/fabric_mesh.h"
#include "core/solve/shell_solver.h"
#include "support/elastica.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

// ---- the clamped–clamped elastica, closed form (support/elastica.h) --------

using test::ClosedForm;
using test::ClosedFormAtShortening;
using test::Elastica;

// ---- the same elastica by shooting on the ODE -----------------------------------
//
// Lengths over L, s ∈ [0, 1], μ = PL²/EI, θ the slope, z up:
//   θ'' = −μ sin θ,  x' = cos θ,  z' = sin θ,  θ(0) = 0, x(0) = z(0) = 0.
// For a given clamp curvature c = θ'(0) > 0, μ is found by bisection such that
// θ first returns to zero exactly at mid-span (the symmetric first mode:
// θ > 0 on (0, ½)); the clamp at s = 1 (θ(1) = 0, z(1) = 0) then follows by
// symmetry and is checked, not imposed. The first zero of θ moves towards
// s = 0 as μ grows, so "θ ≤ 0 somewhere on (0, ½]" brackets it.

struct OdeState {
  double theta = 0, dtheta = 0, x = 0, z = 0;
};

// RK4 from s = 0 to `end` in `steps` steps; `crossed` (if given) reports
// whether θ fell to ≤ 0 after the start.
OdeState IntegrateElastica(double mu, double c, double end, int steps, bool* crossed) {
  using Y = std::array<double, 4>;
  auto rate = [mu](const Y& y) {
    return Y{y[1], -mu * std::sin(y[0]), std::cos(y[0]), std::sin(y[0])};
  };
  auto add = [](const Y& y, double h, const Y& dy) {
    return Y{y[0] + h * dy[0], y[1] + h * dy[1], y[2] + h * dy[2], y[3] + h * dy[3]};
  };
  Y y{0.0, c, 0.0, 0.0};
  const double h = end / steps;
  if (crossed) *crossed = false;
  for (int i = 0; i < steps; ++i) {
    const Y k1 = rate(y), k2 = rate(add(y, h / 2, k1)), k3 = rate(add(y, h / 2, k2)),
            k4 = rate(add(y, h, k3));
    for (int j = 0; j < 4; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    if (crossed && y[0] <= 0) *crossed = true;
  }
  return {y[0], y[1], y[2], y[3]};
}

struct ShotElastica {
  double force = 0;       // μ
  double shortening = 0;  // 1 − x(1)
  double height = 0;      // z(½)
  double end_slope = 0;   // θ(1), 0 at a clamp
  double end_height = 0;  // z(1), 0 at a clamp
};

ShotElastica ShootElastica(double c, int steps = 2000) {
  bool crossed = false;
  double lo = 0, hi = 4 * kPi * kPi;  // μ ≤ lo: no zero on (0, ½]; μ ≥ hi: one
  for (IntegrateElastica(hi, c, 0.5, steps / 2, &crossed); !crossed;
       IntegrateElastica(hi, c, 0.5, steps / 2, &crossed)) {
    lo = hi;
    hi *= 2;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    IntegrateElastica(mid, c, 0.5, steps / 2, &crossed);
    (crossed ? hi : lo) = mid;
  }
  const double mu = (lo + hi) / 2;
  const OdeState half = IntegrateElastica(mu, c, 0.5, steps / 2, nullptr);
  const OdeState end = IntegrateElastica(mu, c, 1.0, steps, nullptr);
  return {mu, 1 - end.x, half.z, end.theta, end.z};
}

// ---- the FE strip -----------------------------------------------------------

Eigen::Vector3d Named(const std::vector<NamedVector>& values,
                      const std::string& name,
                      const StepState& step) {
  for (const auto& v : values)
    if (v.name == name) return v.value;
  ADD_FAILURE() << "nothing named '" << name << "' in step " << step.step;
  return Eigen::Vector3d::Constant(NAN);
}

struct StripRun {
  SolveSummary summary;
  std::vector<StepState> steps;
};

// The strip clamped at x = 0 and held clamped at x = L by the gripper "end",
// which a `move` stage pushes in by `shortening`·L along −x under arc-length
// control. `imperfection`·L is the amplitude of a stress-free out-of-plane
// offset z₀(x) = a (1 − cos 2πx/L)/2 of the reference surface, the first
// clamped–clamped buckling mode, rising towards +z.
//
// Why this imperfection: a perfectly flat strip under pure compression sits on
// a bifurcation and stays on the straight (unstable) branch. The first-mode
// shape couples the compression to that mode alone and picks its sign
// deterministically; fabric.imperfection's random patterns (smooth or nodal)
// would also excite higher modes, with a sign set by the seed, and a
// transverse point load would need its own `load` stage and would sit in the
// gripper reaction. It is applied to the reference mesh (BuildShellModel on a
// given mesh), which the scene's own imperfection also does.
StripRun RunStrip(const test::StripSpec& spec,
                  double shortening,
                  double imperfection,
                  double initial_increment,
                  bool acceleration,
                  Branching branching = Branching::kStable) {
  Scene scene = test::CantileverStrip(spec);  // support "root": left edge clamped
  scene.name = "clamped-clamped strip";
  scene.grippers.push_back({"end", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kClamp});
  scene.probes.push_back({"mid", {spec.length / 2, 0.0}});
  Stage stage;
  stage.name = "push";
  stage.kind = StageKind::kMove;
  stage.initial_increment = initial_increment;
  stage.control = StepControl::kArcLength;
  stage.moves.push_back({"end", LinePath{{-shortening * spec.length, 0.0, 0.0}}, {}});
  scene.stages.push_back(stage);
  scene.solver.acceleration = acceleration;
  scene.solver.branching = branching;
  // The default ‖R‖/‖R₀‖ ≤ 1e-5 is relative to the step's Δλ·‖F₀‖, and for a
  // moved gripper F₀ = −K_fp ∂u_p/∂λ is the membrane stiffness of the
  // elements next to the gripper times the path (EA/ℓₑ·Δ ~ 200 N), a million
  // times the end force P ~ 1e-4 N. Measured with this run at 1e-5: the end
  // force (the gripper's reaction) off by up to 19 % (Δ/L = 0.48: 1.079 P_E
  // against 1.327 P_E), the mid-height within 0.15 %. At 1e-8 the force is
  // within 0.11 %, but the negative pivots a step reports are those of the
  // last tangent it factorised, not of the converged state: the start of the
  // step when the predictor alone converges (iterations = 1: the perfect
  // strip's pivot changes then show one step late, at 1.012 and 2.068 P_E),
  // the predicted state when one correction suffices (iterations = 2: a spurious
  // 0 → 1 → 0 at P ≈ 0.93 P_E on this path, whose predictor overshoots the
  // knee). At 1e-10 every step takes at least one correction and the
  // imperfect path takes 86 iterations in all.
  scene.solver.tolerance = 1e-10;

  Mesh mesh = MeshFabric(scene.fabric);
  for (int i = 0; i < mesh.NodeCount(); ++i)
    mesh.positions(i, 2) += imperfection * spec.length * 0.5 *
                            (1 - std::cos(2 * kPi * mesh.positions(i, 0) / spec.length));
  ShellSolver solver(scene, BuildShellModel(scene, mesh), SolverOptions::FromScene(scene.solver));
  StripRun run;
  run.summary = solver.Solve({[&](const StepState& s) {
    run.steps.push_back(s);
    return StepDecision::kContinue;
  }});
  return run;
}

struct StripConstants {
  test::StripSpec spec;
  double ei = 0, ea = 0;
  double euler = 0;         // P_E [N]
  double euler_strain = 0;  // Δ_E / L = P_E / EA
};

StripConstants Constants() {
  StripConstants c;
  c.spec.elements = 80;
  c.ei = test::StripBendingStiffness(c.spec);
  c.ea = c.spec.youngs_modulus * c.spec.width * c.spec.thickness;
  c.euler = 4 * kPi * kPi * c.ei / (c.spec.length * c.spec.length);
  c.euler_strain = c.euler / c.ea;
  return c;
}

// The perfect column at end shortening Δ/L: straight (P = EA Δ/L, δ = 0) up
// to Δ_E, then the elastica. The elastica above is inextensible; the FE strip
// also shortens by membrane strain, P L/EA ≈ Δ_E = 2e-5 L, which we take off
// at its value at buckling (the rest, ≲ 1e-5 L, is ≤ 2e-4 of Δ where the FE
// is compared, far below the 1 % checked).
struct Reference {
  double force = 0;   // P / P_E
  double height = 0;  // δ / L
};

Reference PerfectColumn(const StripConstants& c, double shortening) {
  if (shortening <= c.euler_strain) return {shortening / c.euler_strain, 0.0};
  const Elastica e = ClosedFormAtShortening(shortening - c.euler_strain);
  return {e.force / (4 * kPi * kPi), e.height};
}

double EndForce(const StepState& s) {
  return -Named(s.reactions, "end", s).x();
}  // pushes −x

// ---- tests ------------------------------------------------------------------

TEST(PostBuckling, ClosedFormMatchesShootingOnTheElasticaOde) {
  std::printf("%6s %8s %12s %12s %10s %10s %10s %10s %9s %9s\n",
              "c",
              "k",
              "P/P_E ODE",
              "P/P_E exact",
              "D/L ODE",
              "d/L ODE",
              "d/L exact",
              "c exact",
              "theta(1)",
              "z(1)");
  // c = θ'(0)L from a barely buckled strip (k ≈ 0.04, Δ/L ≈ 0.0016) to
  // k ≈ 0.77, Δ/L ≈ 0.66, past the largest shortening the FE run reaches (0.5).
  for (double c : {0.5, 1.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0}) {
    const ShotElastica ode = ShootElastica(c);
    const Elastica exact = ClosedFormAtShortening(ode.shortening);
    std::printf("%6.2f %8.5f %12.9f %12.9f %10.7f %10.7f %10.7f %10.7f %9.1e %9.1e\n",
                c,
                exact.k,
                ode.force / (4 * kPi * kPi),
                exact.force / (4 * kPi * kPi),
                ode.shortening,
                ode.height,
                exact.height,
                exact.curvature,
                ode.end_slope,
                ode.end_height);
    EXPECT_NEAR(ode.force / exact.force, 1.0, 1e-8) << "c = " << c;
    EXPECT_NEAR(ode.height / exact.height, 1.0, 1e-8) << "c = " << c;
    EXPECT_NEAR(c / exact.curvature, 1.0, 1e-8) << "c = " << c;
    EXPECT_NEAR(ode.end_slope, 0.0, 1e-8) << "c = " << c;  // the right end is a clamp
    EXPECT_NEAR(ode.end_height, 0.0, 1e-8) << "c = " << c;
  }
  // The small-k limits: P → P_E, Δ/L ≈ k², δ/L ≈ 2k/π.
  const Elastica small = ClosedForm(1e-3);
  EXPECT_NEAR(small.force / (4 * kPi * kPi), 1.0, 1e-6);
  EXPECT_NEAR(small.shortening / 1e-6, 1.0, 1e-3);
  EXPECT_NEAR(small.height / (2e-3 / kPi), 1.0, 1e-3);
}

TEST(PostBuckling, PushedClampedStripFollowsTheElastica) {
  const StripConstants c = Constants();
  const double length = c.spec.length;
  const double shortening = 0.5;     // Δ/L at the end of the stage
  const double imperfection = 1e-5;  // a/L
  // The first step must not pass the Euler load: Δλ₀ = 8e-6 pushes in
  // 4e-6 L ≈ 0.2 Δ_E. With Δλ₀ = 1e-4 (first step 2 Δ_E) the first step lands
  // on the straight branch at P = 1.95 P_E (converged in the predictor) and
  // the path then buckles to −z, against the +z imperfection (measured).
  const StripRun run = RunStrip(c.spec, shortening, imperfection, 8e-6, /*acceleration=*/true);
  std::printf("%s", run.summary.FullReport().c_str());
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  ASSERT_FALSE(run.steps.empty());
  EXPECT_DOUBLE_EQ(run.steps.back().lambda, 1.0);

  std::printf("%4s %5s %10s %10s %10s %9s %9s %6s\n",
              "step",
              "iters",
              "D/L",
              "P_FE/P_E",
              "P_ex/P_E",
              "d_FE/L",
              "d_ex/L",
              "negpiv");
  int compared = 0;
  double worst_force = 0, worst_height = 0;
  for (const StepState& s : run.steps) {
    const double d = s.lambda * shortening;  // the gripper's own travel over L
    const double force = EndForce(s) / c.euler;
    const double height = Named(s.probes, "mid", s).z() / length;
    const Reference exact = PerfectColumn(c, d);
    std::printf("%4d %5d %10.3e %10.6f %10.6f %9.6f %9.6f %6d\n",
                s.step,
                s.iterations,
                d,
                force,
                exact.force,
                height,
                exact.height,
                s.negative_pivots);
    // Never above the perfect column (beyond discretisation): the path did
    // not climb the straight, unstable branch past P_E.
    EXPECT_LT(force, 1.01 * exact.force) << "step " << s.step;
    if (d > 2 * c.euler_strain) {
      EXPECT_GT(height, 0.0) << "step " << s.step << ": buckled against the imperfection";
    }
    if (d < 0.05) continue;
    // Post-buckled: against the elastica at the FE's own end shortening; the
    // buckled path is stable under end-shortening control.
    ++compared;
    worst_force = std::max(worst_force, std::abs(force / exact.force - 1));
    worst_height = std::max(worst_height, std::abs(height / exact.height - 1));
    EXPECT_NEAR(force / exact.force, 1.0, 0.01) << "step " << s.step << ", Δ/L = " << d;
    EXPECT_NEAR(height / exact.height, 1.0, 0.01) << "step " << s.step << ", Δ/L = " << d;
    EXPECT_EQ(s.negative_pivots, 0) << "step " << s.step;
  }
  std::printf("Δ/L ≥ 0.05: %d steps, worst |P_FE/P_ex − 1| = %.2e, |δ_FE/δ_ex − 1| = %.2e\n",
              compared,
              worst_force,
              worst_height);
  EXPECT_GE(compared, 4);
}

TEST(PostBuckling, PerfectStripTangentTurnsIndefiniteAtTheEulerLoad) {
  // The imperfect path is stable throughout (no negative pivot at converged
  // steps), so the bifurcation is seen on the perfect flat strip: the
  // continuation stays on the straight branch (z ≡ 0) past P_E, and the
  // tangent gains a negative pivot as P crosses each clamped–clamped
  // critical load: P_E (symmetric mode) and, for the antisymmetric mode,
  // 4u²EI/L² with tan u = u, u = 4.493409: P₂ = (u/π)² P_E = 2.04575 P_E.
  // Fixed steps (acceleration off) of 1.1 % of P_E resolve both. The
  // straight branch is exact here: P = EA Δ/L.
  const StripConstants c = Constants();
  const double first = 1.0, second = std::pow(4.493409457909064 / kPi, 2);
  const double shortening = 2.2 * c.euler_strain;
  // `fundamental`: the straight branch is followed through the bifurcations
  // (`stable` would switch to the buckled branch at the first one).
  const StripRun run =
      RunStrip(c.spec, shortening, 0.0, 0.005, /*acceleration=*/false, Branching::kFundamental);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();

  double max_height = 0;
  for (const StepState& s : run.steps)
    max_height = std::max(max_height, std::abs(Named(s.probes, "mid", s).z()));
  EXPECT_LT(max_height, 1e-9 * c.spec.length) << "left the straight branch";

  const auto& events = run.summary.stability_events;
  std::printf("%4s %5s %10s %10s %10s %s\n",
              "step",
              "iters",
              "D/L",
              "P_FE/P_E",
              "EA D/L/P_E",
              "negative pivots");
  for (const auto& e : events) {
    for (const StepState& s : run.steps) {
      if (s.step != e.step - 1 && s.step != e.step) continue;
      std::printf("%4d %5d %10.4e %10.6f %10.6f %d%s\n",
                  s.step,
                  s.iterations,
                  s.lambda * shortening,
                  EndForce(s) / c.euler,
                  s.lambda * shortening / c.euler_strain,
                  s.negative_pivots,
                  s.step == e.step ? "  <- stability event" : "");
    }
  }
  ASSERT_EQ(events.size(), 2u) << run.summary.FullReport();
  const double expected[2] = {first, second};
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(events[i].negative_pivots_before, i);
    EXPECT_EQ(events[i].negative_pivots_after, i + 1);
    // The critical load lies between the last definite and the first
    // indefinite step: both within 2 % of it.
    const StepState& before = run.steps[events[i].step - 2];
    const StepState& after = run.steps[events[i].step - 1];
    ASSERT_EQ(after.step, events[i].step);
    const double p_before = EndForce(before) / c.euler, p_after = EndForce(after) / c.euler;
    std::printf("negative pivots %d -> %d between P = %.4f and %.4f P_E (exact %.5f P_E)\n",
                i,
                i + 1,
                p_before,
                p_after,
                expected[i]);
    EXPECT_LT(p_before, expected[i] * 1.005);
    EXPECT_GT(p_after, expected[i] * 0.995);
    EXPECT_NEAR(p_after / expected[i], 1.0, 0.02);
    EXPECT_NEAR(p_before / expected[i], 1.0, 0.02);
  }
}

}  // namespace
}  // namespace drape
