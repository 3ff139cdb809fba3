// Verification: snap-through and snap-back of the hinged cylindrical roof
// under a central point load, benchmark 3.8 ("Hinged cylindrical isotropic
// and laminated roofs") of
//
//   K.Y. Sze, X.H. Liu, S.H. Lo, "Popular benchmark problems for geometric
//   nonlinear analysis of shells", Finite Elements in Analysis and Design
//   40(11) (2004) 1551–1569, doi:10.1016/j.finel.2003.11.001.
//
// Problem: a shallow cylindrical panel, radius R = 2540, half-angle θ = 0.1
// rad (rise R(1 − cos θ) = 12.7), length 508 along the axis. The two straight
// edges along the axis are hinged (positions fixed, rotations free), the two
// curved edges are free. E = 3102.75, ν = 0.3, thickness h = 12.7 or 6.35.
// A downward point load P acts at the centre C; the result is P against the
// central deflection W_C. Units are the paper's (consistent, unnamed).
//
// Reference: the isotropic columns of the paper's tabulated reference curves
// for §3.8, given as P/Pmax against −W_C with Pmax = 3000. The numbers are
// transcribed from MBDyn's copy of those tables, tests/plates/sze2004/sze38/
// sze38_ref_a.dat (h = 12.7) and sze38_ref_d.dat (h = 6.35) in
// github.com/zanoni-mbdyn/MBDyn (a secondary source: we could not read the
// paper's table itself). Pmax = 3000 and the first h = 12.7 points also appear
// in the PENGoLINS hinged-roof example (force_ratio 0.0877 ↔ w 0.693, …).
//
// What happens: for h = 12.7 the load passes a maximum (≈ 0.74 Pmax), falls
// to a minimum (≈ 0.17 Pmax) while the roof snaps through and then rises
// again on the inverted roof; W_C grows all along (snap-through only). For
// h = 6.35 the load falls below zero after its maximum (≈ 0.195 Pmax) and W_C
// itself turns back (17.0 → 14.45) before growing again: a snap-back.
//
// Model: the full roof, 20 × 20 bilinear shells with equal angular spacing,
// the reference surface exactly on the cylinder (so the reference directors
// are the cylinder's normals up to the nodal averaging). The symmetric mesh
// and load keep the path on the symmetric branch, which is the reference's.
//
// h = 12.7 is loaded by the point load under arc-length control. h = 6.35
// is run both ways: by the point load (its path needs P < 0 between
// W_C ≈ 17 and W_C ≈ 24.8, i.e. λ < 0 for a while, which the stepper allows
// down to λ = −1), and with its centre pushed down by a gripper (a `move`
// stage): λ is then W_C/40, which stays positive, and the gripper's reaction
// is the point load. The equilibrium path is the same set of (W_C, P); under
// displacement control the snap-back shows up as λ turning back, which the
// arc-length stepper must pass.
//
// Comparison: both curves are split into runs along which W_C is monotone
// (the reference has 1 for h = 12.7 and 3 for h = 6.35; the FE path must have
// as many). Each reference point is compared with the FE polyline of the same
// run interpolated at its W_C (clamped to the run's ends when the FE run
// stops short of it, which happens only at the snap-back's tip); a point at a
// turning point is compared on both runs it ends and the better kept. The
// error |P_FE − P_ref| is measured in units of Pmax = 3000, the tables' load
// scale and (near enough) the largest load of both curves.
//
// Measured worst errors at 20 × 20 (they are discretisation errors: they fall
// with the mesh, 16 × 16 / 20 × 20 / 32 × 32):
//   h = 12.7: 0.0166 / 0.0145 / 0.0070 Pmax, at the last point (P ≈ 1.08 Pmax);
//             around the limit point ≤ 0.008.
//   h = 6.35: 0.047 / 0.039 / 0.027 Pmax, at the last point of the steep
//             inverted branch (dP/dW_C ≈ 0.12 Pmax per unit, so 0.039 Pmax is
//             a deflection offset of 0.3, 0.8 %); in the snap-back ≤ 0.018.
// Tolerances: 3 % of Pmax for h = 12.7 and 5 % for h = 6.35 (about twice and
// 1.3 times the measured worst; the latter is set by the steep branch, where
// the comparison at equal W_C is harsh). Because 5 % of Pmax is large next to
// the thin roof's own loads (0.195 Pmax at the limit point), the test also
// checks the features that are well conditioned, with tighter bounds: the
// load at each limit point (extremum of P, refined by a parabola in W_C) to
// 2 % of that load's magnitude and the deflections where the snap-back turns
// (extrema of W_C, refined by a parabola in P) to 1.5 %. Measured: limit loads
// within 0.9 % (12.7: 0.46 %, 0.12 %; 6.35: 0.72 %, 0.84 %), turning
// deflections within 0.6 % (0.51 %, 0.17 %).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "support/hinged_roof.h"

namespace drape {
namespace {

using namespace test;  // the roof, its runs and its reference curves

// Expects the FE curve's limit loads and (when `turning_w`) turning
// deflections to match the reference's one for one.
void CompareTurns(const std::vector<CurvePoint>& reference,
                  const std::vector<CurvePoint>& fe,
                  bool turning_w,
                  double load_tolerance,
                  double deflection_tolerance) {
  for (bool of_w : {false, true}) {
    if (of_w && !turning_w) continue;
    const auto ref = Turns(reference, of_w);
    const auto got = Turns(fe, of_w);
    const char* what = of_w ? "turning deflection W_C" : "limit load P/Pmax";
    ASSERT_EQ(got.size(), ref.size()) << "number of extrema of " << what;
    for (size_t k = 0; k < ref.size(); ++k) {
      const double relative = std::abs(got[k] - ref[k]) / std::abs(ref[k]);
      std::printf("%s %zu: FE %.4f, reference %.4f, relative difference %.2f %%\n",
                  what,
                  k + 1,
                  got[k],
                  ref[k],
                  100 * relative);
      EXPECT_LE(relative, of_w ? deflection_tolerance : load_tolerance) << what << " " << k + 1;
    }
  }
}

// The reference is the mathematical path through both limit points, which
// `fundamental` branching follows (under `stable` the roof snaps: below).
TEST(HingedRoof, ThickRoofSnapsThroughUnderPointLoad) {
  RoofSpec spec;
  spec.thickness = 12.7;
  spec.drive = Drive::kPointLoad;
  spec.load = 1.1 * kPmax;  // past the last reference point, 1.0835 Pmax
  spec.increment = 0.03;
  spec.branching = Branching::kFundamental;
  const RoofRun run = RunRoof(spec);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  ASSERT_DOUBLE_EQ(run.path.back().lambda, 1.0);
  const auto fe = Curve(run.path);

  // Both limit points passed: P rises to a maximum, falls to a minimum and
  // rises again.
  const auto limits = Turns(fe, false);
  ASSERT_EQ(limits.size(), 2u) << "P should have one maximum and one minimum";
  EXPECT_LT(limits[1], limits[0]);
  EXPECT_GT(run.path.back().at.p, limits[0]);

  // The falling branch is unstable under load control: every step strictly
  // inside it has a negative pivot, and the solver reported the change.
  int falling = 0;
  for (size_t i = 1; i + 1 < run.path.size(); ++i) {
    const auto& q = run.path[i];
    if (q.at.p < run.path[i - 1].at.p && run.path[i + 1].at.p < q.at.p) {
      ++falling;
      EXPECT_GT(q.negative_pivots, 0) << "step " << q.step << " on the falling branch";
    }
  }
  EXPECT_GE(falling, 5);
  // Both limit points are reported as such: the first makes the tangent
  // indefinite, the second definite again (between them a bifurcation on the
  // unstable part is passed on the primary path, which leads on to them).
  const auto& events = run.summary.stability_events;
  ASSERT_GE(events.size(), 2u);
  EXPECT_EQ(events.front().kind, StabilityKind::kLimit);
  EXPECT_EQ(events.front().negative_pivots_before, 0);
  EXPECT_GT(events.front().negative_pivots_after, 0);
  EXPECT_EQ(events.back().kind, StabilityKind::kLimit);
  EXPECT_GT(events.back().negative_pivots_before, 0);
  EXPECT_EQ(events.back().negative_pivots_after, 0);
  for (const auto& e : events) EXPECT_NE(e.branch, Branch::kStable) << Describe(e);

  CompareWithReference(kReferenceThick, fe, 0.03);
  CompareTurns(kReferenceThick, fe, /*turning_w=*/false, 0.02, 0.015);
}

TEST(HingedRoof, ThinRoofSnapsBackUnderCentralDeflection) {
  RoofSpec spec;
  spec.thickness = 6.35;
  spec.drive = Drive::kCentralDeflection;
  spec.push = 40.0;  // past the last reference point, W_C = 38.45
  spec.increment = 0.015;
  spec.branching = Branching::kFundamental;  // the reference is the symmetric path
  const RoofRun run = RunRoof(spec);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  ASSERT_DOUBLE_EQ(run.path.back().lambda, 1.0);
  ASSERT_NEAR(run.path.back().at.w, spec.push, 1e-6 * spec.push);
  const auto fe = Curve(run.path);

  // The snap-back: W_C rises, turns back, and rises again, so λ = W_C/40
  // passed two limit points of its own; and the load has a maximum and a
  // (negative) minimum.
  const auto runs = MonotoneRuns(fe);
  ASSERT_EQ(runs.size(), 3u) << "W_C should turn back exactly twice";
  const auto limits = Turns(fe, false);
  ASSERT_EQ(limits.size(), 2u) << "P should have one maximum and one minimum";
  EXPECT_GT(limits[0], 0);
  EXPECT_LT(limits[1], 0);

  // Where W_C falls the roof is unstable even with its centre held: every step
  // strictly inside that run has a negative pivot.
  for (int i = runs[1].first + 1; i < runs[1].second; ++i)
    EXPECT_GT(run.path[i].negative_pivots, 0) << "step " << run.path[i].step << " where W_C falls";
  EXPECT_GE(runs[1].second - runs[1].first - 1, 3);
  ASSERT_FALSE(run.summary.stability_events.empty());

  CompareWithReference(kReferenceThin, fe, 0.05);
  CompareTurns(kReferenceThin, fe, /*turning_w=*/true, 0.02, 0.015);
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

TEST(HingedRoof, ThinRoofSnapsBackUnderPointLoad) {
  // The same snap-back driven by the force itself: λ rises to the first
  // limit, falls through zero (the load must pull up to hold the roof on its
  // path) to the second, and rises again.
  RoofSpec spec;
  spec.thickness = 6.35;
  spec.drive = Drive::kPointLoad;
  spec.load = 1.1 * kPmax;
  spec.increment = 0.01;
  spec.branching = Branching::kFundamental;  // the reference is the symmetric path
  const RoofRun run = RunRoof(spec);
  ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
  const auto fe = Curve(run.path);
  const auto limits = Turns(fe, false);
  ASSERT_EQ(limits.size(), 2u) << "P should have one maximum and one minimum";
  EXPECT_GT(limits[0], 0);
  EXPECT_LT(limits[1], 0);
  ASSERT_FALSE(run.summary.stability_events.empty());
  // Its end is reached only through a reversed load (P < 0), where a real
  // roof jumps: the run warns of it.
  bool warned = false;
  for (const auto& w : run.summary.warnings)
    warned |= w.find("only after its path ran back to λ = ") != std::string::npos;
  EXPECT_TRUE(warned);
  CompareWithReference(kReferenceThin, fe, 0.05);
  CompareTurns(kReferenceThin, fe, /*turning_w=*/true, 0.02, 0.015);
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

// `solver.max_turns` bounds the limit points a path may pass: the thick
// roof's fundamental path passes two (P's maximum and minimum), so with one
// allowed it fails at the step past the second, naming the key. The steps
// kept pass the first and end on the falling branch, the last of them one
// step (measured 8.6 % of the load) above the reference's minimum.
TEST(HingedRoof, APathThatTurnsMoreOftenThanAllowedFailsNamingTheKey) {
  RoofSpec spec;
  spec.thickness = 12.7;
  spec.load = 1.1 * kPmax;
  spec.increment = 0.03;
  spec.branching = Branching::kFundamental;
  spec.max_turns = 1;
  const RoofRun run = RunRoof(spec);
  EXPECT_EQ(run.summary.termination, Termination::kStepTooSmall);
  EXPECT_NE(run.summary.message.find("turned back 2 times (solver.max_turns)"), std::string::npos)
      << run.summary.message;
  EXPECT_NE(run.summary.message.find("stages[0]"), std::string::npos) << run.summary.message;
  const double minimum = Turns(kReferenceThick, false).back();
  const double p = run.path.back().at.p;
  std::printf("stopped after P = %.4f Pmax (reference minimum %.4f)\n", p, minimum);
  EXPECT_EQ(Turns(Curve(run.path), false).size(), 1u);
  EXPECT_GT(p, minimum);
  EXPECT_LT(p, 1.15 * minimum);
}

}  // namespace
}  // namespace drape
