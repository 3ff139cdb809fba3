// Bending hysteresis (KES 2HB) through the whole shell, against independent
// answers:
//  - a strip bent and released by KES-FB2's cycle, its curvature imposed as
//    the tester does (every node on the arc of uniform curvature K) and its
//    moment read, as the tester reads it, from the clamp's reaction (the
//    assembled internal moment at the moving end), each state accepted by
//    the engine's own CommitBendingSlip: the loop is 2HB wide at |K| = 1 1/cm;
//  - a cantilever under its own weight with a Coulomb moment, solved by the
//    engine, against the closed-form small-deflection droop and against the
//    heavy elastica with the same monotone law (RK4 shooting in the test).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/fe/bending_slip.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_assembler.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/mechanics/director.h"
#include "core/solve/shell_solver.h"
#include "support/rk4.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

constexpr double kPerCm = 100.0;           // 1/m per 1/cm
constexpr double kGfCmPerCm = 9.80665e-3;  // N·m/m per gf·cm/cm

// A KES-FB2 specimen: 1 cm long (the tester's gap), 1 cm wide here, ν = 0
// so that the strip's moment is the law's, B and 2HB of Matsudaira et al.'s
// cotton broadcloth (0.118 gf·cm²/cm, 0.124 gf·cm/cm).
constexpr double kB = 0.118 * kGfCmPerCm / kPerCm;  // [N·m]
constexpr double kTwoHb = 0.124 * kGfCmPerCm;       // [N·m/m]

ShellModel KesSpecimen(bool hysteresis) {
  char text[1024];
  std::snprintf(text,
                sizeof text,
                R"({"drape_scene": 1, "name": "KES-FB2 specimen",
  "fabric": {"outline": {"rectangle": {"size": ["1 cm", "1 cm"], "center": ["0.5 cm", 0]}},
             "mesh": {"elements": [20, 2]}},
  "material": {"thickness": "0.5 mm", "areal_weight": 0, "youngs_modulus": "10 MPa",
               "poisson_ratio": 0,
               "bending": {"model": "linear", "rigidity": "0.118 gf*cm^2/cm" %s}},
  "supports": [{"name": "fixed chuck", "select": {"edge": "left"}, "fix": "clamp"}],
  "stages": [{"name": "none", "kind": "hold"}]})",
                hysteresis ? R"(, "hysteresis": "0.124 gf*cm/cm")" : "");
  return BuildShellModel(ParseScene(text));
}

// Every node on the arc of curvature K from the fixed chuck (x = 0).
void BendTo(double k, const ShellModel& model, ShellState& state) {
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = model.reference.positions(i, 0);
    const double phi = k * x;
    const double sx = std::abs(k) > 0 ? std::sin(phi) / k : x;
    const double sz = std::abs(k) > 0 ? (1 - std::cos(phi)) / k : 0.0;
    state.positions(i, 0) = sx;
    state.positions(i, 2) = sz;
    state.rotations[i] = RotationFromDirector({-std::sin(phi), 0, std::cos(phi)});
  }
}

// The moment per width the moving chuck (x = L) must apply: the internal
// moment about y at its nodes (rotation DOF b is about Λe₂ = y for a director
// in the xz plane), over the width.
double ChuckMoment(const ShellModel& model, const ShellAssembler& assembler, const ShellState& s) {
  Eigen::VectorXd internal;
  assembler.Assemble(s, internal, nullptr);
  double moment = 0;
  for (int i = 0; i < model.NodeCount(); ++i)
    if (std::abs(model.reference.positions(i, 0) - 0.01) < 1e-9) moment += internal(5 * i + 4);
  return -moment / 0.01;
}

struct Loop {
  std::vector<double> k, m;  // the cycle's curvatures [1/m] and moments [N·m/m]
};

Loop KesCycle(const ShellModel& model) {
  const DofMap dofs(model.NodeCount());
  const ShellAssembler assembler(model, dofs);
  ShellState state = model.reference;
  Loop loop;
  std::vector<int> path;  // in 0.02 1/cm: 0 → 2.5 → −2.5 → 0
  for (int i = 0; i <= 125; ++i) path.push_back(i);
  for (int i = 124; i >= -125; --i) path.push_back(i);
  for (int i = -124; i <= 0; ++i) path.push_back(i);
  for (int step : path) {
    const double k = step * 0.02 * kPerCm;
    BendTo(k, model, state);
    loop.k.push_back(k);
    loop.m.push_back(ChuckMoment(model, assembler, state));
    CommitBendingSlip(model, state);  // the step is accepted
  }
  return loop;
}

TEST(BendingHysteresis, AStripBentThroughTheKesCycleTracesALoopTwoHbWide) {
  const Loop elastic = KesCycle(KesSpecimen(false));
  const Loop loop = KesCycle(KesSpecimen(true));
  // Indices of K = +1 and −1 1/cm on the loading (|K| rising) and the
  // unloading branches: steps 50 and 200 (+1), 300 and 450 (−1).
  const double at_plus_1_loading = loop.m[50], at_plus_1_unloading = loop.m[200];
  const double at_minus_1_loading = loop.m[300], at_minus_1_unloading = loop.m[450];
  ASSERT_NEAR(loop.k[50], kPerCm, 1e-9);
  ASSERT_NEAR(loop.k[200], kPerCm, 1e-9);
  ASSERT_NEAR(loop.k[300], -kPerCm, 1e-9);
  ASSERT_NEAR(loop.k[450], -kPerCm, 1e-9);
  const double width_plus = at_plus_1_loading - at_plus_1_unloading;
  const double width_minus = at_minus_1_unloading - at_minus_1_loading;
  // Kawabata's B: the slope between 0.5 and 1.5 1/cm of the elastic strip.
  const double b = (elastic.m[75] - elastic.m[25]) / (loop.k[75] - loop.k[25]);
  std::printf(
      "B = %.4f gf cm^2/cm (given 0.118); 2HB at +1 1/cm %.4f, at -1 1/cm %.4f "
      "gf cm/cm (given 0.124)\n",
      b / kGfCmPerCm * kPerCm,
      width_plus / kGfCmPerCm,
      width_minus / kGfCmPerCm);
  EXPECT_NEAR(b, kB, 0.01 * kB);
  EXPECT_NEAR(width_plus, kTwoHb, 0.02 * kTwoHb);
  EXPECT_NEAR(width_minus, kTwoHb, 0.02 * kTwoHb);
  // The loop's middle is the elastic law: the branches straddle B K.
  EXPECT_NEAR(0.5 * (at_plus_1_loading + at_plus_1_unloading), elastic.m[50], 0.01 * kTwoHb);
  // Released to K = 0, the strip still needs −HB to hold it flat: friction
  // keeps the bend it was given (a flat strip at rest would be curved HB/B).
  EXPECT_NEAR(loop.m.back(), 0.5 * kTwoHb, 0.02 * kTwoHb);
}

// ---- the cantilever with a Coulomb moment --------------------------------------

// The monotone law a section follows when bent one way from flat: the
// elastic B K plus the Jenkins element's min(k K, HB), k = 2HB/ΔK with the
// engine's stated reversal range ΔK (written here from its definition, not
// taken from the engine's law).
struct CoulombLaw {
  double b, hb, k;
  double Moment(double kappa) const { return b * kappa + std::min(k * kappa, hb); }
  double Curvature(double m) const {  // the inverse, M ≥ 0
    const double transition = hb / k * (b + k);
    return m <= transition ? m / (b + k) : (m - hb) / b;
  }
};

CoulombLaw LawOf(double b, double two_hb) {
  return {b, 0.5 * two_hb, two_hb / kHysteresisReversalCurvature};
}

// Small-deflection droop δ = ∫₀ᴸ K(M(s)) s ds, M(s) = w s²/2 (s from the
// free end), in closed form: K = M/(B + k) up to the transition moment
// M_t = HB (B + k)/k at s_t, then (M − HB)/B.
double SmallDeflectionDroop(const CoulombLaw& law, double w, double length) {
  const double m_t = law.hb * (law.b + law.k) / law.k;
  const double s_t = std::min(length, std::sqrt(2 * m_t / w));
  auto slipping = [&](double s) { return (w * std::pow(s, 4) / 8 - law.hb * s * s / 2) / law.b; };
  return w * std::pow(s_t, 4) / (8 * (law.b + law.k)) + slipping(length) - slipping(s_t);
}

// The heavy elastica with the law: θ' = K(m), m' = −w (L − s) cos θ from the
// clamp, shot on m(0) until m(L) = 0 (as in nonlinear_elastica_test.cc).
std::array<double, 2> ElasticaTip(const CoulombLaw& law, double w, double length) {
  using State = std::array<double, 4>;  // θ, m, x, z
  auto shoot = [&](double m0) {
    auto rate = [&](double s, const State& y) {
      return State{law.Curvature(std::max(y[1], 0.0)),
                   -w * (length - s) * std::cos(y[0]),
                   std::cos(y[0]),
                   -std::sin(y[0])};
    };
    State y{0.0, m0, 0.0, 0.0};
    const int steps = 4000;
    const double h = length / steps;
    for (int i = 0; i < steps; ++i) y = test::Rk4Step(rate, i * h, y, h);
    return y;
  };
  double lo = 0, hi = 0.5 * w * length * length;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (shoot(mid)[1] < 0 ? lo : hi) = mid;
  }
  const State tip = shoot(0.5 * (lo + hi));
  return {tip[2], tip[3]};
}

struct EngineRun {
  Eigen::Vector3d tip = Eigen::Vector3d::Constant(NAN);
  // Over the final state's Gauss points, |κ − s| (ν = 0: the norm of
  // (κ₁₁ − s₁₁, κ₂₂ − s₂₂, (2κ₁₂ − 2s₁₂)/√2)) against the slip range HB/k,
  // the largest and the smallest at the root element.
  double largest_over_stick = NAN, root_over_stick = NAN;
};

EngineRun RunEngine(double w, double b, double two_hb, double length, int elements) {
  test::StripSpec spec;
  spec.length = length;
  spec.width = 0.002;
  spec.thickness = 2e-4;
  spec.youngs_modulus = 2e8;  // a stiff membrane: the droop is bending's
  spec.elements = elements;
  Scene scene = test::HeavyStrip(spec, 1.0, 0.05);
  scene.material.areal_weight = w;
  scene.material.bending.warp = LinearBending{b};
  scene.material.bending.warp_hysteresis.width = two_hb;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  EngineRun run;
  ShellState last;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    for (const auto& p : s.probes)
      if (p.name == "tip") run.tip = p.value;
    last = s.state;
    return StepDecision::kContinue;
  }});
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  // The history the steps committed: at the last step every Gauss point is
  // within the slip range of its slip, and the root's are at its edge.
  const ShellModel model = BuildShellModel(scene);
  if (last.bending_slip.size() != static_cast<size_t>(model.mesh.ElementCount())) {
    ADD_FAILURE() << "the converged states carry no committed slip";
    return run;
  }
  const double stick = 0.5 * kHysteresisReversalCurvature;
  run.largest_over_stick = 0;
  run.root_over_stick = INFINITY;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const auto kappa = ElementBendingStrains(model, last, e);
    for (int p = 0; p < 4; ++p) {
      const Eigen::Vector3d d = kappa[p] - last.bending_slip[e].col(2 * p);
      const double r = std::sqrt(d(0) * d(0) + d(1) * d(1) + 0.5 * d(2) * d(2)) / stick;
      run.largest_over_stick = std::max(run.largest_over_stick, r);
      const bool at_root = model.reference.positions(model.mesh.quads(e, 0), 0) < 1e-12;
      if (at_root) run.root_over_stick = std::min(run.root_over_stick, r);
    }
  }
  return run;
}

TEST(BendingHysteresis, ACantileverWithACoulombMomentDroopsAsTheClosedFormSays) {
  // 1 cm long, B = 1e-5 N·m, HB = 1e-4 N·m/m, w = 10 N/m²: the root moment
  // wL²/2 = 5e-4 slips over the strip's inner 83 %, and the tip turns by
  // 0.07 rad (small deflection). Without friction it would droop 1.25 mm.
  const double length = 0.01, b = 1e-5, two_hb = 2e-4, w = 10;
  const CoulombLaw law = LawOf(b, two_hb);
  const double closed_form = SmallDeflectionDroop(law, w, length);
  const auto [ode_x, ode_z] = ElasticaTip(law, w, length);
  const Eigen::Vector3d tip = RunEngine(w, b, two_hb, length, 40).tip;
  const double elastic = w * std::pow(length, 4) / (8 * b);
  std::printf(
      "droop: engine %.5f mm, small-deflection closed form %.5f mm, elastica %.5f mm "
      "(no friction: %.4f mm)\n",
      -tip.z() * 1e3,
      closed_form * 1e3,
      -ode_z * 1e3,
      elastic * 1e3);
  EXPECT_NEAR(-tip.z(), closed_form, 0.01 * closed_form);
  EXPECT_NEAR(-tip.z(), -ode_z, 0.002 * closed_form);
  EXPECT_NEAR(tip.x(), ode_x, 0.002 * closed_form);
  EXPECT_LT(closed_form, 0.7 * elastic);  // the friction is what this tests
}

TEST(BendingHysteresis, AHeavyCantileverWithACoulombMomentMatchesTheElastica) {
  // Large deflection: 6 cm of Matsudaira et al.'s cotton broadcloth
  // (B = 0.118 gf·cm²/cm, 2HB = 0.124 gf·cm/cm, w = 12.38 mg/cm²): the tip
  // falls to 68 % of L below the clamp. Every section is bent one way only
  // as the weight comes on, so the monotone law is the answer. (A 10 cm
  // strip hangs so far that its outer sections' moments rise and then fall
  // while the weight comes on: they unload along the loop, and the droop is
  // no longer the monotone elastica's — 0.5 % of L apart.)
  const double length = 0.06, b = kB, two_hb = kTwoHb, w = 12.38e-6 / 1e-4 * 9.80665;
  const CoulombLaw law = LawOf(b, two_hb);
  const auto [ode_x, ode_z] = ElasticaTip(law, w, length);
  const EngineRun run = RunEngine(w, b, two_hb, length, 40);
  const Eigen::Vector3d& tip = run.tip;
  std::printf("tip/L: engine (%.5f, %.5f), elastica (%.5f, %.5f)\n",
              tip.x() / length,
              tip.z() / length,
              ode_x / length,
              ode_z / length);
  EXPECT_LT(ode_z / length, -0.2);
  EXPECT_LT(std::hypot(tip.x() - ode_x, tip.z() - ode_z) / length, 0.002);
  std::printf("|κ − s| over HB/k: largest %.9f, at the root %.9f\n",
              run.largest_over_stick,
              run.root_over_stick);
  EXPECT_LT(run.largest_over_stick, 1 + 1e-9);
  EXPECT_GT(run.root_over_stick, 1 - 1e-9);
}

}  // namespace
}  // namespace drape
