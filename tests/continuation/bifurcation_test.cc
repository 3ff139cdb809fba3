// Verification: perfect strips pushed by a gripper take the buckled branch at
// Euler's load (solver.branching: stable) and follow the elastica.
//
// A perfect flat strip under end shortening sits on a bifurcation: the
// straight branch beyond Euler's load is unstable (a negative pivot per
// crossed mode) and no real strip stays on it. The continuation must locate
// the bifurcation, switch to the buckled branch and stay there with a
// positive definite tangent.
//
// Strip: L = 0.2 m, b = 0.01 m, h = 0.5 mm, E = 100 MPa, ν = 0 (plate and
// beam theory agree), weightless: EI = E b h³/12 = 1.042e-5 N·m²,
// EA = 500 N. Euler's load P_E = c π² EI/L², c = 1 pinned–pinned, 4
// clamped–clamped; the straight strip reaches it at the end shortening
// Δ_E = P_E L/EA (5.1e-6 L pinned, 2.1e-5 L clamped). Past it the midspan
// rises as the elastica's δ/L = k/K(k) at Δ/L = 2 − 2E(k)/K(k)
// (support/elastica.h, checked there against the ODE), taken at the
// elastica's own end shortening: the gripper's travel less the membrane
// shortening at buckling, Δ_E (the rest, P L/EA − Δ_E, is ≤ 4e-4 L here).
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/linalg/critical_modes.h"
#include "core/model/fabric_mesh.h"
#include "core/model/scene.h"
#include "core/solve/shell_solver.h"
#include "support/elastica.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 0.2, kWidth = 0.01, kThickness = 5e-4, kModulus = 1e8;

struct PushedStrip {
  bool clamped = false;
  double angle_deg = 0;  // the strip's axis, turned in the xy plane
  int nx = 80, ny = 1;
  double shortening = 0.6;  // the gripper's travel over L
  StepControl control = StepControl::kArcLength;
  std::string Label() const {
    char s[128];
    std::snprintf(s,
                  sizeof s,
                  "%s strip %dx%d at %g deg%s",
                  clamped ? "clamped-clamped" : "pinned-pinned",
                  nx,
                  ny,
                  angle_deg,
                  control == StepControl::kLoad ? ", load control" : "");
    return s;
  }
};

struct Run {
  SolveSummary summary;
  std::vector<StepState> steps;
  std::vector<int> midspan;  // the nodes across the strip at x = L/2
};

// The strip from (0, 0) to (L, 0), turned by `angle_deg` about z: supports
// and gripper pick their edges by node number, so they turn with it.
Run Push(const PushedStrip& p) {
  Scene scene;
  scene.name = p.Label();
  scene.fabric.outline = RectangleOutline{{kLength, kWidth}, {kLength / 2, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{p.nx, p.ny};
  scene.material.thickness = kThickness;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{kModulus, 0.0};
  scene.material.bending.warp = LinearBending{};
  Mesh mesh = MeshFabric(scene.fabric);
  const double a = p.angle_deg * kPi / 180;
  const Eigen::Vector3d axis(std::cos(a), std::sin(a), 0);
  NodesSelection left, right;
  Run run;
  for (int i = 0; i < mesh.NodeCount(); ++i) {
    const double x = mesh.positions(i, 0), y = mesh.positions(i, 1);
    if (std::abs(x) < 1e-9) left.nodes.push_back(i);
    if (std::abs(x - kLength) < 1e-9) right.nodes.push_back(i);
    if (std::abs(x - kLength / 2) < 1e-9) run.midspan.push_back(i);
    mesh.positions(i, 0) = x * std::cos(a) - y * std::sin(a);
    mesh.positions(i, 1) = x * std::sin(a) + y * std::cos(a);
  }
  const Fixity fixity = p.clamped ? Fixity::kClamp : Fixity::kPosition;
  scene.supports.push_back({"left", Selection{left, {}}, fixity});
  scene.grippers.push_back({"end", Selection{right, {}}, fixity});
  Stage push;
  push.name = "push";
  push.kind = StageKind::kMove;
  push.initial_increment = 0.01;  // a first step far past Euler's load
  push.control = p.control;
  const Eigen::Vector3d by = -p.shortening * kLength * axis;
  push.moves.push_back({"end", LinePath{{by.x(), by.y(), by.z()}}, {}});
  scene.stages.push_back(push);
  scene.solver.tolerance = 1e-8;

  ShellSolver solver(scene, BuildShellModel(scene, mesh), SolverOptions::FromScene(scene.solver));
  run.summary = solver.Solve({[&](const StepState& s) {
    run.steps.push_back(s);
    return StepDecision::kContinue;
  }});
  return run;
}

// The midspan's rise: the mean |z| of the nodes across the strip there.
double MidspanHeight(const Run& run, const StepState& s) {
  double sum = 0;
  for (int node : run.midspan) sum += std::abs(s.state.positions(node, 2));
  return sum / run.midspan.size();
}

// How close a run must come to the closed forms: about three times what was
// measured (the measurement in a comment at each call).
struct Within {
  double lambda;  // of the located bifurcation to Euler's, relative (the mesh's
                  // own discretisation error included)
  double height;  // of the midspan's rise to the elastica's at every step [L]
};

// Checks the run against the elastica; returns the located λ over Euler's.
double ExpectElastica(const PushedStrip& p, const Within& within) {
  SCOPED_TRACE(p.Label());
  const double ei = kModulus * kWidth * std::pow(kThickness, 3) / 12;
  const double ea = kModulus * kWidth * kThickness;
  const double euler = (p.clamped ? 4 : 1) * kPi * kPi * ei / (kLength * kLength);
  const double euler_shortening = euler / ea;  // Δ_E / L
  const double euler_lambda = euler_shortening / p.shortening;

  const Run run = Push(p);
  if (run.midspan.empty()) {
    ADD_FAILURE() << "no node at midspan";
    return NAN;
  }
  std::printf("%s: %s\n", p.Label().c_str(), run.summary.BriefReport().c_str());
  EXPECT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  if (run.summary.stability_events.empty() || run.steps.empty()) {
    ADD_FAILURE() << "no bifurcation passed: " << run.summary.FullReport();
    return NAN;
  }

  // One bifurcation, located near Euler's, switched to a stable branch.
  const StabilityEvent& e = run.summary.stability_events.front();
  std::printf("  %s\n  Euler: lambda %.6g (Δ_E/L = %.4g)\n",
              Describe(e).c_str(),
              euler_lambda,
              euler_shortening);
  EXPECT_EQ(e.kind, StabilityKind::kBifurcation);
  EXPECT_EQ(e.branch, Branch::kStable);
  EXPECT_EQ(e.negative_pivots_before, 0);
  EXPECT_GE(e.negative_pivots_fundamental, 1);
  std::printf("  located lambda / Euler's - 1 = %.3g\n", e.lambda / euler_lambda - 1);
  EXPECT_NEAR(e.lambda / euler_lambda, 1.0, within.lambda);

  std::printf("  %4s %10s %9s %9s %6s\n", "step", "D/L", "d_FE/L", "d_ex/L", "negpiv");
  int compared = 0;
  double worst = 0;
  for (const StepState& s : run.steps) {
    if (s.step < e.step) continue;  // after the switch
    EXPECT_EQ(s.negative_pivots, 0) << "step " << s.step;
    const double travel = s.lambda * p.shortening;
    if (travel < 1e-3) continue;
    const double exact = test::ClosedFormAtShortening(travel - euler_shortening).height;
    const double fe = MidspanHeight(run, s) / kLength;
    std::printf("  %4d %10.4e %9.6f %9.6f %6d\n", s.step, travel, fe, exact, s.negative_pivots);
    worst = std::max(worst, std::abs(fe - exact));
    EXPECT_NEAR(fe, exact, within.height) << "step " << s.step << ", Δ/L = " << travel;
    ++compared;
  }
  std::printf("  %d steps from Δ/L = 1e-3 to %.2f, worst |δ_FE − δ_ex| = %.2e L\n",
              compared,
              p.shortening,
              worst);
  EXPECT_GE(compared, 5);
  EXPECT_DOUBLE_EQ(run.steps.back().lambda, 1.0);
  return e.lambda / euler_lambda;
}

// 80 × 1 elements. Measured: the pinned strip's bifurcation 0.044 % above
// Euler's, its rise within 4.3e-5 L of the elastica's; the clamped strip's
// 0.100 % and 1.73e-4 L (the same at 30° and under load control).
constexpr Within kPinned80{.lambda = 1.3e-3, .height = 1.3e-4};
constexpr Within kClamped80{.lambda = 3e-3, .height = 5e-4};

TEST(Bifurcation, PerfectPinnedStripTakesTheElastica) {
  ExpectElastica({.clamped = false}, kPinned80);
}

TEST(Bifurcation, PerfectClampedStripTakesTheElastica) {
  ExpectElastica({.clamped = true}, kClamped80);
}

// Under load (displacement) control the bifurcation is located and switched
// the same way; the steps then go on under load control from the branch.
TEST(Bifurcation, StripUnderLoadControlTakesTheElastica) {
  ExpectElastica({.clamped = true, .control = StepControl::kLoad}, kClamped80);
}

TEST(Bifurcation, StripAtThirtyDegreesInThePlaneTakesTheElastica) {
  ExpectElastica({.clamped = false, .angle_deg = 30}, kPinned80);
  ExpectElastica({.clamped = true, .angle_deg = 30}, kClamped80);
}

// Twenty elements along resolve the pinned strip's half-wave well, but the
// clamped strip's four quarter-waves less so: its located bifurcation lies
// 1.7 % above Euler's, and on 40 × 3 0.4 % (80 × 1: 0.1 %) — the h²
// convergence of the FE critical load. So the clamped 3 × 20 strip is held
// to Euler's within 2 %, and its Richardson extrapolation from 20 and 40
// elements (order 2) within 0.08 %: the locator itself is as exact as the
// finer runs show.
//
// Measured (λ over Euler's − 1, largest rise error): pinned 20 × 3 0.43 %,
// 7.2e-4 L; clamped 20 × 3 1.66 %, 2.9e-3 L (held to 2 % and 5e-3 L, less
// than three times that); clamped 40 × 3 0.43 % (held to 1 %), 7.2e-4 L;
// extrapolated 0.026 %.
TEST(Bifurcation, ThreeByTwentyMeshTakesTheElastica) {
  ExpectElastica({.clamped = false, .nx = 20, .ny = 3}, {.lambda = 1.3e-2, .height = 2.2e-3});
  const double coarse =
      ExpectElastica({.clamped = true, .nx = 20, .ny = 3}, {.lambda = 0.02, .height = 5e-3});
  const double fine =
      ExpectElastica({.clamped = true, .nx = 40, .ny = 3}, {.lambda = 0.01, .height = 2.2e-3});
  const double extrapolated = fine + (fine - coarse) / 3;
  std::printf("clamped: lambda/lambda_E %.5f (20 x 3), %.5f (40 x 3), extrapolated %.5f\n",
              coarse,
              fine,
              extrapolated);
  EXPECT_NEAR(extrapolated, 1.0, 8e-4);
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// A 20 × 20 cm sheet (20 × 20 elements, h = 0.5 mm, E = 5 MPa, ν = 0.3,
// weightless), its left edge pinned, its right edge gripped and pushed in
// its own plane by 2 cm. The flat sheet is a wide column with free sides: it
// buckles between the beam's strain π²h²/(12L²) (ν plays no part: a narrow
// strip) and the cylindrical plate's π²h²/(12(1 − ν²)L²) (Timoshenko &
// Gere, Theory of Elastic Stability, 2nd ed., §9.2: the free sides relieve
// the anticlastic restraint), and past it bends cylindrically, its midline
// on the pinned elastica (the elastica's shape does not depend on the
// bending stiffness).
// The centre's rise against the pinned elastica's: measured within
// 2.04e-4 L at every step past the switch.
constexpr double kSheetHeight = 6e-4;

TEST(Bifurcation, SheetPushedInPlaneBucklesOutOfPlaneOntoAStableBranch) {
  const double l = 0.2, h = 5e-4, nu = 0.3, push = 0.1;  // push: travel over L
  Scene scene;
  scene.name = "sheet pushed in its plane";
  scene.fabric.outline = RectangleOutline{{l, l}, {0.0, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{20, 20};
  scene.material.thickness = h;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{5e6, nu};
  scene.material.bending.warp = LinearBending{};
  scene.supports.push_back({"left", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kPosition});
  scene.grippers.push_back(
      {"right", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kPosition});
  scene.probes.push_back({"centre", {0.0, 0.0}});
  Stage stage;
  stage.name = "push";
  stage.kind = StageKind::kMove;
  stage.moves.push_back({"right", LinePath{{-push * l, 0.0, 0.0}}, {}});
  scene.stages.push_back(stage);

  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  std::vector<StepState> steps;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    steps.push_back(s);
    return StepDecision::kContinue;
  }});
  std::printf("%s\n", summary.BriefReport().c_str());
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  ASSERT_FALSE(summary.stability_events.empty());
  const StabilityEvent& e = summary.stability_events.front();
  std::printf("  %s\n", Describe(e).c_str());
  EXPECT_EQ(e.kind, StabilityKind::kBifurcation);
  EXPECT_EQ(e.branch, Branch::kStable);

  const double beam = kPi * kPi * h * h / (12 * l * l);  // Δ/L at buckling
  const double plate = beam / (1 - nu * nu);
  const double critical = e.lambda * push;
  std::printf("  buckles at Δ/L = %.4g: beam %.4g, plate %.4g\n", critical, beam, plate);
  EXPECT_GT(critical, beam * 0.99);
  EXPECT_LT(critical, plate * 1.01);

  int compared = 0;
  double worst = 0;
  for (const StepState& s : steps) {
    if (s.step < e.step) continue;
    EXPECT_EQ(s.negative_pivots, 0) << "step " << s.step;
    const double travel = s.lambda * push;
    if (travel < 1e-3) continue;
    const double exact = test::ClosedFormAtShortening(travel - critical).height;
    const double fe = std::abs(s.probes.front().value.z()) / l;
    worst = std::max(worst, std::abs(fe - exact));
    EXPECT_NEAR(fe, exact, kSheetHeight) << "step " << s.step;
    ++compared;
  }
  std::printf("  %d steps, worst |δ_FE − δ_ex| = %.2e L\n", compared, worst);
  EXPECT_GE(compared, 5);
  EXPECT_GT(std::abs(steps.back().probes.front().value.z()), 0.15 * l);  // well out of plane
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// A shallow sinusoidal arch, w₀ = a sin(πx/L), pinned at both ends (L =
// 0.2 m, b = 1 cm, h = 0.5 mm, E = 100 MPa, ν = 0; rise a = 10 r, r = h/√12
// the radius of gyration: 1.44 mm), pressed at its crown by a frictionless
// rod of radius 5 mm that moves down by 0.6 a.
//
// Shallow-arch theory (Fung & Kaplan, "Buckling of low arches or curved
// beams of small curvature", NACA TN 2840, 1952): an antisymmetric
// perturbation leaves the thrust N unchanged (its integral against the
// symmetric shape vanishes) and vanishes at the crown, so it is resisted by
// EI w'''' + N w'' alone: the symmetric path bifurcates where the thrust
// reaches the second Euler load N₂ = 4π²EI/L², and on the antisymmetric
// branch the thrust stays N₂. For a rise of 10 r the bifurcation comes
// before the symmetric path's limit point (the largest rod force), so under
// a load the arch would snap there; the rod holds the crown's height, and
// the antisymmetric branch is stable under it.
struct ArchPoint {
  double lambda, thrust, force, left, right;  // H/N₂, rod force [N], quarter-point rises [m]
  int negative_pivots;
};

std::vector<ArchPoint> PressArch(Branching branching, SolveSummary* summary) {
  const double l = 0.2, b = 0.01, h = 5e-4, e = 1e8, rod = 0.005;
  const double a = 10 * h / std::sqrt(12.0);
  Scene scene;
  scene.name = "shallow arch pressed by a rod";
  scene.fabric.outline = RectangleOutline{{l, b}, {l / 2, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{80, 2};
  scene.material.thickness = h;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{e, 0.0};
  scene.material.bending.warp = LinearBending{};
  Mesh mesh = MeshFabric(scene.fabric);
  NodesSelection left, right;
  for (int i = 0; i < mesh.NodeCount(); ++i) {
    const double x = mesh.positions(i, 0);
    if (std::abs(x) < 1e-9) left.nodes.push_back(i);
    if (std::abs(x - l) < 1e-9) right.nodes.push_back(i);
    mesh.positions(i, 2) = a * std::sin(kPi * x / l);
  }
  scene.supports.push_back({"left", Selection{left, {}}, Fixity::kPosition});
  scene.supports.push_back({"right", Selection{right, {}}, Fixity::kPosition});
  // The rod's underside 1 µm above the crown's upper surface.
  scene.obstacles.push_back(
      {"rod", CylinderShape{{l / 2, 0.0, a + h / 2 + rod + 1e-6}, {0, 1, 0}, rod, {}}});
  scene.probes.push_back({"left", {l / 4, 0.0}});
  scene.probes.push_back({"right", {3 * l / 4, 0.0}});
  Stage press;
  press.name = "press";
  press.kind = StageKind::kMove;
  press.moves.push_back({"", LinePath{{0, 0, -0.6 * a}}, "rod"});
  scene.stages.push_back(press);
  scene.solver.tolerance = 1e-8;
  scene.solver.branching = branching;

  const double n2 = 4 * kPi * kPi * e * b * h * h * h / 12 / (l * l);
  ShellSolver solver(scene, BuildShellModel(scene, mesh), SolverOptions::FromScene(scene.solver));
  std::vector<ArchPoint> path;
  *summary = solver.Solve({[&](const StepState& s) {
    ArchPoint p{s.lambda, 0, -s.contact->force.z(), 0, 0, s.negative_pivots};
    for (const auto& r : s.reactions)
      if (r.name == "left") p.thrust = r.value.x() / n2;
    p.left = s.probes[0].value.z();
    p.right = s.probes[1].value.z();
    path.push_back(p);
    return StepDecision::kContinue;
  }});
  return path;
}

TEST(Bifurcation, ShallowArchTakesTheAntisymmetricBranchAtTheSecondEulerThrust) {
  SolveSummary primary_summary, summary;
  const std::vector<ArchPoint> primary = PressArch(Branching::kFundamental, &primary_summary);
  const std::vector<ArchPoint> path = PressArch(Branching::kStable, &summary);
  ASSERT_TRUE(primary_summary.IsComplete()) << primary_summary.FullReport();
  ASSERT_TRUE(summary.IsComplete()) << summary.FullReport();
  double limit_force = 0;  // the symmetric path's largest rod force
  for (const ArchPoint& p : primary) limit_force = std::max(limit_force, p.force);

  std::printf("%5s %9s %9s %10s %10s %10s %s\n",
              "step",
              "lambda",
              "H/N2",
              "force",
              "w(L/4)",
              "w(3L/4)",
              "negpiv");
  for (size_t i = 0; i < path.size(); ++i)
    std::printf("%5zu %9.5f %9.5f %10.4e %10.4e %10.4e %d\n",
                i + 1,
                path[i].lambda,
                path[i].thrust,
                path[i].force,
                path[i].left,
                path[i].right,
                path[i].negative_pivots);
  ASSERT_EQ(summary.stability_events.size(), 1u) << summary.FullReport();
  const StabilityEvent& e = summary.stability_events.front();
  std::printf("%s\n", Describe(e).c_str());
  EXPECT_EQ(e.kind, StabilityKind::kBifurcation);
  EXPECT_EQ(e.branch, Branch::kStable);
  ASSERT_GE(e.step, 2);
  // The located point (the step before the switch) carries the thrust N₂.
  // Measured: H/N₂ = 1.00062 there and at most 1.00072 along the branch.
  const ArchPoint& at = path[e.step - 2];
  EXPECT_NEAR(at.thrust, 1.0, 2e-3);
  EXPECT_NEAR(at.left, at.right, 1e-9);  // still symmetric there
  EXPECT_LT(at.force, 0.9 * limit_force) << "the bifurcation comes before the limit point";
  // On the branch: the thrust stays N₂, the arch leans over, nothing unstable.
  for (size_t i = e.step - 1; i < path.size(); ++i) {
    EXPECT_NEAR(path[i].thrust, 1.0, 2e-3) << "step " << i + 1;
    EXPECT_EQ(path[i].negative_pivots, 0) << "step " << i + 1;
  }
  const double a = 10 * 5e-4 / std::sqrt(12.0);
  EXPECT_GT(std::abs(path.back().left - path.back().right), 0.5 * a);
  EXPECT_LT(path.back().force, at.force);  // the rod force falls along the branch
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// The critical mode from the factorised tangent: a straight clamped–clamped
// strip held compressed just past its first critical load (1.05 P_E; the
// second is 2.05 P_E) has one negative pivot, and the negative eigenvector
// nearest zero is the first buckling mode, w ∝ 1 − cos(2πx/L) (Euler; past
// the critical load the eigenvector drifts from it: 0.99963 at 1.5 P_E).
TEST(CriticalModes, CompressedClampedStripGivesEulersFirstMode) {
  Scene scene;
  scene.fabric.outline = RectangleOutline{{kLength, kWidth}, {kLength / 2, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{80, 1};
  scene.material.thickness = kThickness;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{kModulus, 0.0};
  scene.material.bending.warp = LinearBending{};
  scene.supports.push_back({"left", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kClamp});
  scene.supports.push_back({"right", Selection{EdgeSelection{Side::kRight}, {}}, Fixity::kClamp});
  const ShellModel model = BuildShellModel(scene);
  DofMap dofs(model.NodeCount());
  for (const auto& s : model.supports)
    for (int node : s.nodes) dofs.FixNode(node, s.fixity);
  const double ei = kModulus * kWidth * std::pow(kThickness, 3) / 12;
  const double strain =
      1.05 * 4 * kPi * kPi * ei / (kLength * kLength) / (kModulus * kWidth * kThickness);
  ShellState state = model.reference;
  state.positions.col(0) *= 1 - strain;
  EquilibriumSystem system(model, dofs);
  system.Assemble(state, true);
  ASSERT_EQ(system.Factorize().negative_pivots, 1);
  const std::vector<CriticalMode> modes = CriticalModes(LastFactorizedTangent(system), 1);
  ASSERT_EQ(modes.size(), 1u);
  EXPECT_LT(modes[0].eigenvalue, 0);
  // The mode's z-translations along one edge against 1 − cos(2πx/L).
  Eigen::VectorXd fe(0), exact(0);
  for (int i = 0; i < model.NodeCount(); ++i) {
    const int f = dofs.Free(kDofsPerNode * i + 2);
    if (f < 0 || model.reference.positions(i, 1) > 0) continue;
    fe.conservativeResize(fe.size() + 1);
    exact.conservativeResize(exact.size() + 1);
    fe(fe.size() - 1) = modes[0].shape(f);
    exact(exact.size() - 1) = 1 - std::cos(2 * kPi * model.reference.positions(i, 0) / kLength);
  }
  const double correlation = std::abs(fe.dot(exact)) / (fe.norm() * exact.norm());
  std::printf("eigenvalue %.3e, correlation with 1 - cos(2 pi x/L): %.6f\n",
              modes[0].eigenvalue,
              correlation);
  EXPECT_GT(correlation, 0.99999);  // measured 0.999997
}

}  // namespace
}  // namespace drape
