// The hinged cylindrical roof of Sze et al. (2004) §3.8 as the tests build,
// run and compare it: the scene, its mesh, the reference curves and the
// comparisons. tests/verification/hinged_roof_test.cc says what the problem
// is, where the reference comes from and what the measured errors are.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/mesh.h"
#include "core/solve/shell_solver.h"

namespace drape::test {

constexpr double kRadius = 2540.0;  // R
constexpr double kHalfAngle = 0.1;  // θ [rad]
constexpr double kLength = 508.0;   // along the axis (y)
constexpr double kYoungsModulus = 3102.75;
constexpr double kPoissonRatio = 0.3;
constexpr double kPmax = 3000.0;  // the tables' load scale
constexpr int kElements = 20;     // per side

// One point of a load–deflection curve: P/Pmax against the central deflection
// W_C (downward positive).
struct CurvePoint {
  double w = 0;
  double p = 0;
};

// Sze et al. (2004) §3.8, isotropic roof, h = 12.7 (via MBDyn sze38_ref_a.dat).
inline const std::vector<CurvePoint> kReferenceThick = {
    {0.000, 0.0000},  {0.693, 0.0877},  {1.638, 0.1980},  {3.087, 0.3473},  {4.477, 0.4686},
    {5.802, 0.5647},  {7.057, 0.6381},  {8.237, 0.6908},  {9.339, 0.7246},  {10.358, 0.7412},
    {11.293, 0.7421}, {12.141, 0.7286}, {12.903, 0.7023}, {13.583, 0.6649}, {14.188, 0.6182},
    {14.728, 0.5643}, {15.217, 0.5055}, {15.676, 0.4442}, {16.125, 0.3830}, {16.590, 0.3245},
    {17.094, 0.2717}, {17.657, 0.2272}, {18.299, 0.1940}, {19.028, 0.1750}, {19.852, 0.1729},
    {20.771, 0.1905}, {21.780, 0.2303}, {22.875, 0.2950}, {24.049, 0.3871}, {24.663, 0.4443},
    {25.293, 0.5093}, {25.940, 0.5826}, {26.601, 0.6644}, {27.276, 0.7551}, {27.964, 0.8549},
    {28.663, 0.9643}, {29.374, 1.0835}};

// Sze et al. (2004) §3.8, isotropic roof, h = 6.35 (via MBDyn sze38_ref_d.dat).
inline const std::vector<CurvePoint> kReferenceThin = {
    {0.000, 0.0000},   {1.846, 0.0517},   {5.271, 0.1182},   {8.257, 0.1583},   {10.799, 0.1837},
    {11.904, 0.1914},  {12.892, 0.1953},  {13.752, 0.1950},  {14.472, 0.1901},  {15.050, 0.1806},
    {15.501, 0.1671},  {16.145, 0.1323},  {16.602, 0.0923},  {16.915, 0.0504},  {17.008, 0.0083},
    {16.697, -0.0312}, {15.780, -0.0622}, {15.206, -0.0739}, {14.767, -0.0861}, {14.520, -0.1001},
    {14.451, -0.1142}, {14.862, -0.1247}, {15.778, -0.1288}, {16.961, -0.1271}, {18.320, -0.1196},
    {19.817, -0.1055}, {21.420, -0.0825}, {23.100, -0.0484}, {24.824, -0.0006}, {26.565, 0.0626},
    {28.302, 0.1427},  {30.023, 0.2403},  {31.720, 0.3559},  {33.388, 0.4898},  {35.024, 0.6417},
    {36.626, 0.8114},  {38.450, 1.0313}};

// The roof's reference surface: x = R sin φ, z = R cos φ − R cos θ (edges at
// z = 0), φ ∈ [−θ, θ] in nx equal steps and y ∈ [−L/2, L/2] in ny; quads
// numbered counter-clockwise seen from +z, so the directors point up
// (outward).
inline Mesh RoofMesh(int nx, int ny, double length) {
  Mesh mesh;
  mesh.positions.resize((nx + 1) * (ny + 1), 3);
  const double base = kRadius * std::cos(kHalfAngle);
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double phi = -kHalfAngle + 2 * kHalfAngle * i / nx;
      mesh.positions.row(j * (nx + 1) + i) << kRadius * std::sin(phi),
          -length / 2 + length * j / ny, kRadius * std::cos(phi) - base;
    }
  }
  mesh.quads.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      mesh.quads.row(j * nx + i) << a, a + 1, a + nx + 2, a + nx + 1;
    }
  }
  return mesh;
}

inline Mesh RoofMesh(int n) {
  return RoofMesh(n, n, kLength);
}

// Rise of the roof: the centre's height above the hinged edges.
inline double Rise() {
  return kRadius * (1 - std::cos(kHalfAngle));
}

enum class Drive { kPointLoad, kCentralDeflection };

struct RoofSpec {
  double thickness = 12.7;
  Drive drive = Drive::kPointLoad;
  double load = 1.1 * kPmax;  // the point load at λ = 1 (kPointLoad)
  double push = 40.0;         // the centre's downward travel at λ = 1 (kCentralDeflection)
  double increment = 0.03;    // Δλ of the first step; later steps keep its arc length
  Branching branching = Branching::kStable;
  double tolerance = 0;  // solver.tolerance on ‖R‖/‖R₀‖ (0: the default)
  int max_turns = 20;    // solver.max_turns
  // A clamped shallow arch instead: a slice `arch_width` wide along the axis
  // (one element), both straight edges clamped, the load a line across the
  // slice's middle (0: the roof).
  double arch_width = 0;
};

// The mesh the spec's scene is solved on.
inline Mesh RoofMeshOf(const RoofSpec& spec) {
  return spec.arch_width > 0 ? RoofMesh(kElements, 1, spec.arch_width) : RoofMesh(kElements);
}

// The roof with both straight edges (x = ±R sin θ) hinged, the curved edges
// free, and one arc-length stage driving the centre.
inline Scene RoofScene(const RoofSpec& spec) {
  Scene scene;
  scene.name = "hinged cylindrical roof";
  // The outline is the roof's projection, so that the hinged edges' nodes lie
  // exactly on the left and right sides of its bounding box.
  const double half_width = kRadius * std::sin(kHalfAngle);
  const bool arch = spec.arch_width > 0;
  scene.fabric.outline =
      RectangleOutline{{2 * half_width, arch ? spec.arch_width : kLength}, {0.0, 0.0}};
  scene.material.thickness = spec.thickness;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{kYoungsModulus, kPoissonRatio};
  scene.material.bending.warp = LinearBending{};
  const Fixity edges = arch ? Fixity::kClamp : Fixity::kPosition;
  scene.supports.push_back({"left", Selection{EdgeSelection{Side::kLeft}, {}}, edges});
  scene.supports.push_back({"right", Selection{EdgeSelection{Side::kRight}, {}}, edges});
  const Selection centre =
      arch ? Selection{LineSelection{{0.0, -spec.arch_width / 2}, {0.0, spec.arch_width / 2}}, {}}
           : Selection{PointSelection{{0.0, 0.0}}, {}};
  Stage stage;
  stage.name = "load";
  stage.initial_increment = spec.increment;
  stage.control = StepControl::kArcLength;
  if (spec.drive == Drive::kPointLoad) {
    scene.loads.push_back({"P", centre, {0.0, 0.0, -spec.load}, {0.0, 0.0, 0.0}});
    stage.kind = StageKind::kLoad;
  } else {
    scene.grippers.push_back({"centre", centre, Fixity::kPosition});
    stage.kind = StageKind::kMove;
    stage.moves.push_back({"centre", LinePath{{0.0, 0.0, -spec.push}}, {}});
  }
  scene.stages.push_back(stage);
  scene.probes.push_back({"C", {0.0, 0.0}});
  scene.solver.branching = spec.branching;
  if (spec.tolerance > 0) scene.solver.tolerance = spec.tolerance;
  scene.solver.max_turns = spec.max_turns;
  return scene;
}

struct PathPoint {
  CurvePoint at;            // W_C, P/Pmax
  int step = 0;             // 0: the unloaded start
  double lambda = 0;        // the stage's load factor
  int negative_pivots = 0;  // of the converged tangent
};

struct RoofRun {
  SolveSummary summary;
  std::vector<PathPoint> path;     // starts at the unloaded roof
  std::vector<ShellState> states;  // of the steps in `path` (none for the start)
};

inline RoofRun RunRoof(const RoofSpec& spec) {
  const Scene scene = RoofScene(spec);
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  // Every step as long as the first (a fine, even sampling of the path: the
  // steps converge in 2–4 iterations and would otherwise grow to 0.25).
  options.max_increment = spec.increment;
  // 2 k DOFs: one assembly thread is enough and keeps the time steady when
  // tests run in parallel.
  options.threads = 1;
  ShellSolver solver(scene, BuildShellModel(scene, RoofMeshOf(spec)), options);
  RoofRun run;
  run.path.push_back({});
  run.summary = solver.Solve({[&](const StepState& s) {
    PathPoint q;
    q.step = s.step;
    q.lambda = s.lambda;
    q.negative_pivots = s.negative_pivots;
    q.at.p = s.lambda * spec.load / kPmax;
    if (spec.drive == Drive::kCentralDeflection) {
      q.at.p = NAN;
      for (const auto& r : s.reactions)
        if (r.name == "centre") q.at.p = -r.value.z() / kPmax;  // the push the gripper exerts
    }
    q.at.w = NAN;
    for (const auto& p : s.probes)
      if (p.name == "C") q.at.w = Rise() - p.value.z();
    run.path.push_back(q);
    run.states.push_back(s.state);
    return StepDecision::kContinue;
  }});
  std::printf("h = %g: %s\n", spec.thickness, run.summary.BriefReport().c_str());
  std::printf("%5s %9s %8s %9s %5s\n", "step", "lambda", "W_C", "P/Pmax", "neg");
  for (const auto& q : run.path)
    std::printf("%5d %9.5f %8.3f %9.4f %5d\n", q.step, q.lambda, q.at.w, q.at.p, q.negative_pivots);
  for (const auto& e : run.summary.stability_events) std::printf("  %s\n", Describe(e).c_str());
  return run;
}

inline std::vector<CurvePoint> Curve(const std::vector<PathPoint>& path) {
  std::vector<CurvePoint> curve;
  for (const auto& q : path) curve.push_back(q.at);
  return curve;
}

// Index ranges [first, last] of the maximal runs along which w is monotone;
// neighbouring runs share their turning point.
using Run = std::pair<int, int>;
inline std::vector<Run> MonotoneRuns(const std::vector<CurvePoint>& curve) {
  std::vector<Run> runs;
  int first = 0, direction = 0;
  for (int i = 1; i < static_cast<int>(curve.size()); ++i) {
    const double dw = curve[i].w - curve[i - 1].w;
    const int d = dw > 0 ? 1 : (dw < 0 ? -1 : 0);
    if (d == 0) continue;
    if (direction != 0 && d != direction) {
      runs.push_back({first, i - 1});
      first = i - 1;
    }
    direction = d;
  }
  runs.push_back({first, static_cast<int>(curve.size()) - 1});
  return runs;
}

// P on the run of `curve` at deflection w, linear between the points; clamped
// to the run's nearer end when w lies outside it (`*clamped` then set).
inline double LoadAt(const std::vector<CurvePoint>& curve,
                     const Run& run,
                     double w,
                     bool* clamped) {
  *clamped = false;
  for (int i = run.first; i < run.second; ++i) {
    const double a = curve[i].w, b = curve[i + 1].w;
    if (a != b && (w - a) * (w - b) <= 0)
      return curve[i].p + (w - a) / (b - a) * (curve[i + 1].p - curve[i].p);
  }
  *clamped = true;
  const CurvePoint& f = curve[run.first];
  const CurvePoint& l = curve[run.second];
  return std::abs(w - f.w) <= std::abs(w - l.w) ? f.p : l.p;
}

// Compares every reference point with the FE curve on the matching run
// (see the file comment) and expects |P_FE − P_ref| ≤ tolerance [Pmax].
// Returns the worst error.
inline double CompareWithReference(const std::vector<CurvePoint>& reference,
                                   const std::vector<CurvePoint>& fe,
                                   double tolerance) {
  const auto ref_runs = MonotoneRuns(reference);
  const auto fe_runs = MonotoneRuns(fe);
  EXPECT_EQ(fe_runs.size(), ref_runs.size())
      << "the FE path's deflection turns back a different number of times";
  if (fe_runs.size() != ref_runs.size()) return INFINITY;
  std::printf("%4s %8s %9s %9s %9s\n", "run", "W_C", "P_ref", "P_FE", "error");
  double worst = 0;
  for (size_t r = 0; r < ref_runs.size(); ++r) {
    for (int k = ref_runs[r].first; k <= ref_runs[r].second; ++k) {
      if (k == ref_runs[r].second && r + 1 < ref_runs.size()) continue;  // next run's first
      const CurvePoint& point = reference[k];
      bool clamped = false;
      double p = LoadAt(fe, fe_runs[r], point.w, &clamped);
      if (k == ref_runs[r].first && r > 0) {  // a turning point: on the run it ends too
        bool clamped_before = false;
        const double before = LoadAt(fe, fe_runs[r - 1], point.w, &clamped_before);
        if (std::abs(before - point.p) < std::abs(p - point.p)) {
          p = before;
          clamped = clamped_before;
        }
      }
      const double error = p - point.p;
      worst = std::max(worst, std::abs(error));
      std::printf("%4zu %8.3f %9.4f %9.4f %+9.4f%s\n",
                  r,
                  point.w,
                  point.p,
                  p,
                  error,
                  clamped ? "  (FE run ends before this W_C)" : "");
      EXPECT_LE(std::abs(error), tolerance)
          << "reference point W_C = " << point.w << ", P/Pmax = " << point.p;
    }
  }
  std::printf("worst |P_FE − P_ref| = %.4f Pmax (tolerance %.4f)\n", worst, tolerance);
  return worst;
}

// The vertex of the parabola y(x) through points i − 1, i, i + 1 of (x, y):
// an extremum of y sampled at i, refined.
inline double RefinedExtremum(const std::vector<double>& x, const std::vector<double>& y, int i) {
  const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
  const double y0 = y[i - 1], y1 = y[i], y2 = y[i + 1];
  // Newton form: y = y0 + a (x − x0) + b (x − x0)(x − x1).
  const double a = (y1 - y0) / (x1 - x0);
  const double b = ((y2 - y1) / (x2 - x1) - a) / (x2 - x0);
  if (b == 0) return y1;
  const double xv =
      std::clamp(0.5 * (x0 + x1 - a / b), std::min({x0, x1, x2}), std::max({x0, x1, x2}));
  return y0 + a * (xv - x0) + b * (xv - x0) * (xv - x1);
}

// Interior indices where the sequence v has a local maximum or minimum.
inline std::vector<int> Extrema(const std::vector<double>& v) {
  std::vector<int> out;
  for (int i = 1; i + 1 < static_cast<int>(v.size()); ++i)
    if ((v[i] - v[i - 1]) * (v[i + 1] - v[i]) < 0) out.push_back(i);
  return out;
}

// The curve's limit loads (extrema of P, refined as P(w)) and, when `of_w`,
// its turning deflections (extrema of w, refined as w(P)).
inline std::vector<double> Turns(const std::vector<CurvePoint>& curve, bool of_w) {
  std::vector<double> w, p;
  for (const auto& c : curve) {
    w.push_back(c.w);
    p.push_back(c.p);
  }
  std::vector<double> out;
  for (int i : Extrema(of_w ? w : p))
    out.push_back(of_w ? RefinedExtremum(p, w, i) : RefinedExtremum(w, p, i));
  return out;
}

}  // namespace drape::test
