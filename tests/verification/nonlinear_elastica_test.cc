// Verification of the measured bending laws in the whole engine: a cantilever
// strip under its own weight with a nonlinear M(K) against the nonlinear
// heavy elastica solved here as a boundary-value problem with the same law:
//   θ' = K(m),  m' = −w (L − s) cos θ,  x' = cos θ,  z' = −sin θ,
//   θ(0) = 0 (clamp),  m(L) = 0 (free end),
// m the moment per unit width, w the weight per area, K(m) the inverse of the
// (monotone) law. We shoot on m(0) ∈ (0, wL²/2] with bisection and RK4.
// The law object is the engine's own (MakePolynomialLaw / MakeCurveLaw,
// checked against finite differences in tests/mechanics); the test checks
// that the shell, through its plate law K² = κᵀCκ (ν = 0), bends as that
// strip law says.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/mechanics/moment_curvature.h"
#include "core/solve/shell_solver.h"
#include "support/rk4.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

constexpr double kGf = 9.80665e-3;  // N
constexpr double kPerCm = 100.0;    // 1/m

// The paper's cotton twill: M = Σ cₖ Kᵏ gf·cm/cm with K in 1/cm, to 2.5 1/cm.
PolynomialBending Cotton() {
  const double paper[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  PolynomialBending law;
  for (int k = 0; k < 5; ++k)
    law.coefficients.push_back(paper[k] * kGf * std::pow(kPerCm, -(k + 1.0)));
  law.valid_to = 2.5 * kPerCm;
  return law;
}

// A measured-looking saturating curve, M = 0.02 tanh(K/150) N·m/m, 8 points.
CurveBending Saturating() {
  CurveBending law;
  for (int i = 1; i <= 8; ++i) {
    const double k = 40.0 * i;
    law.points.push_back({k, 0.02 * std::tanh(k / 150.0)});
  }
  return law;
}

// K with M(K) = m, for a law increasing in K (bisection to rounding).
double InverseLaw(const MomentCurvatureLaw& law, double m) {
  double lo = 0, hi = 1;
  while (law.Moment(hi) < m) hi *= 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (law.Moment(mid) < m ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct ElasticaEnd {
  double m_end = 0;     // m(L) [N·m/m]
  double x = 0, z = 0;  // tip [m]
  double max_k = 0;     // largest curvature on the way [1/m]
};

ElasticaEnd Shoot(const MomentCurvatureLaw& law, double w, double length, double m0, int steps) {
  using State = std::array<double, 4>;  // θ, m, x, z
  auto rate = [&](double s, const State& y) {
    return State{InverseLaw(law, std::max(y[1], 0.0)),
                 -w * (length - s) * std::cos(y[0]),
                 std::cos(y[0]),
                 -std::sin(y[0])};
  };
  State y{0.0, m0, 0.0, 0.0};
  const double h = length / steps;
  double max_k = 0;
  for (int i = 0; i < steps; ++i) {
    max_k = std::max(max_k, rate(i * h, y)[0]);
    y = test::Rk4Step(rate, i * h, y, h);
  }
  return {y[1], y[2], y[3], max_k};
}

// m(L) rises with m(0) (more moment at the root, more bending, less lever
// arm for the weight): bisection on its sign in (0, wL²/2].
ElasticaEnd SolveElastica(const MomentCurvatureLaw& law, double w, double length, int steps) {
  double lo = 0, hi = 0.5 * w * length * length;
  EXPECT_GT(Shoot(law, w, length, hi, steps).m_end, 0.0);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Shoot(law, w, length, mid, steps).m_end < 0 ? lo : hi) = mid;
  }
  return Shoot(law, w, length, 0.5 * (lo + hi), steps);
}

// ---- the FE strip -----------------------------------------------------------

struct StripRun {
  SolveSummary summary;
  Eigen::Vector3d tip = Eigen::Vector3d::Constant(NAN);
};

// The cotton twill strip (h = 0.0489 cm, w = 0.02665 gf/cm², E = 60 450
// gf/cm² for the membrane), L long, 1 cm wide, ν = 0, under its weight.
StripRun RunStrip(double length, int elements, const BendingLaw& law, double weight_factor) {
  test::StripSpec spec;
  spec.length = length;
  spec.width = 0.01;
  spec.thickness = 0.0489e-2;
  spec.youngs_modulus = 60450 * kGf / 1e-4;
  spec.elements = elements;
  Scene scene = test::HeavyStrip(spec, 1.0, 0.05);
  scene.material.areal_weight = weight_factor * 0.02665 * kGf / 1e-4;
  scene.material.bending.warp = law;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  StripRun run;
  run.summary = solver.Solve({[&](const StepState& s) {
    for (const auto& p : s.probes)
      if (p.name == "tip") run.tip = p.value;
    return StepDecision::kContinue;
  }});
  return run;
}

struct Case {
  std::string name;
  double length;  // [m]
  BendingLaw law;
  double weight_factor = 1;  // times the cotton's weight
};

TEST(NonlinearElastica, OdeSolutionIsConvergedInSteps) {
  const auto law = MakePolynomialLaw(Cotton().coefficients, Cotton().valid_to);
  const double w = 0.02665 * kGf / 1e-4;
  for (double length : {0.10, 0.15}) {
    const ElasticaEnd coarse = SolveElastica(*law, w, length, 1000);
    const ElasticaEnd fine = SolveElastica(*law, w, length, 4000);
    const double change = std::hypot(coarse.x - fine.x, coarse.z - fine.z) / length;
    std::printf("L = %.2f m: tip (%.6f, %.6f) m, |Δtip|/L 1000→4000 steps = %.1e\n",
                length,
                fine.x,
                fine.z,
                change);
    EXPECT_LT(change, 1e-7);
  }
}

TEST(NonlinearElastica, CantileverMatchesTheOdeWithTheSameLaw) {
  // Under its own weight a cotton strip hangs down before its root bends
  // past 1.1 1/cm; 30 times the weight (a heavily coated cotton) takes the
  // root past the fit's 2.5 1/cm, onto the end-tangent continuation.
  const std::vector<Case> cases = {
      {"cotton, 10 cm (inside the fitted range)", 0.10, Cotton(), 1},
      {"cotton, 15 cm", 0.15, Cotton(), 1},
      {"cotton x30 weight, 10 cm (past 2.5 1/cm)", 0.10, Cotton(), 30},
      {"measured curve, 12 cm", 0.12, Saturating(), 1},
  };
  std::printf("%-44s %9s %9s %9s %9s %9s %10s\n",
              "case",
              "FE x/L",
              "FE z/L",
              "ODE x/L",
              "ODE z/L",
              "error/L",
              "max K 1/cm");
  for (const Case& c : cases) {
    std::shared_ptr<const MomentCurvatureLaw> law;
    if (const auto* p = std::get_if<PolynomialBending>(&c.law))
      law = MakePolynomialLaw(p->coefficients, p->valid_to);
    else {
      std::vector<std::array<double, 2>> points;
      for (const auto& q : std::get<CurveBending>(c.law).points) points.push_back({q[0], q[1]});
      law = MakeCurveLaw(points);
    }
    const double w = c.weight_factor * 0.02665 * kGf / 1e-4;
    const ElasticaEnd ode = SolveElastica(*law, w, c.length, 2000);
    const StripRun fe = RunStrip(c.length, 40, c.law, c.weight_factor);
    ASSERT_TRUE(fe.summary.IsComplete()) << c.name << ": " << fe.summary.message;
    const double error = std::hypot(fe.tip.x() - ode.x, fe.tip.z() - ode.z) / c.length;
    std::printf("%-44s %9.5f %9.5f %9.5f %9.5f %9.2e %10.3f\n",
                c.name.c_str(),
                fe.tip.x() / c.length,
                fe.tip.z() / c.length,
                ode.x / c.length,
                ode.z / c.length,
                error,
                fe.summary.max_curvature / kPerCm);
    EXPECT_LT(error, 0.005) << c.name;  // the 0.5 % of L
    // The large-deflection regime each case is meant to test.
    EXPECT_LT(ode.z / c.length, -0.2) << c.name;
    if (c.weight_factor > 1) {
      EXPECT_GT(ode.max_k, 2.5 * kPerCm) << "this case must bend past the fitted range";
      EXPECT_GT(fe.summary.max_curvature, 2.5 * kPerCm);
    } else if (std::holds_alternative<PolynomialBending>(c.law)) {
      EXPECT_LT(ode.max_k, 2.5 * kPerCm);
    }
  }
}

}  // namespace
}  // namespace drape
