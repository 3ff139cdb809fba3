// A strip hung over a round rod, held by nothing but contact (node_contact.h),
// checked against answers found without the code: the mirror symmetry and
// global equilibrium of the symmetric hang; the extensible string's hang
// depth, the tensioned beam's contact edge and the chord error of a polygon
// wrapped on a circle; and the capstan limit of a heavy belt.
//
// Every quantity is per strip: b the width, q = w b the weight per length,
// EA = E h b and EI = E b h³/12 (ν = 0), R' = R + h/2 the radius the
// midsurface wraps at, L_h = L/2 − πR'/2 the length hanging below each side
// of the rod, T_h = q L_h its weight. Two lengths measure the bending
// stiffness: the gravity bending length ℓ_b = (EI/q)^⅓, and the tension
// bending length λ_T = √(EI/T_h), over which a strip under the tension T_h
// leaves the rod; λ_T/R' is what decides how far the contact edge and the
// capstan limit are from their string values.

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/rod_hang_run.h"

namespace drape {
namespace {

using namespace test;
using std::numbers::pi;

// ---- tests ------------------------------------------------------------------

// Nothing in the scene tells left from right, so the two free ends must
// mirror each other; and at rest the rod alone carries the whole weight
// (the stabilisation springs have been drained by the settle steps).
TEST(RodHang, SymmetricHangIsSymmetricAndCarriesTheWeight) {
  const auto start = Clock::now();
  struct Case {
    const char* label;
    test::RodHangSpec spec;
  };
  for (const Case& c : {Case{"stiff strip, dropped free", StiffStrip(80, 0.0)},
                        Case{"soft strip, held then released", SoftStrip(80, 0.0)}}) {
    SCOPED_TRACE(c.label);
    const Hang run = RunHang(c.spec);
    ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
    const Eigen::Vector3d left = LeftEnd(run.last), right = RightEnd(run.last);
    const ContactReport& contact = *run.last.contact;
    std::printf(
        "%s: %d steps, %.2f s; ends (%.9f, %.9f) and (%.9f, %.9f) m; contact force "
        "(%.2e, %.2e, %.12f) N for a weight %.12f N; stabilisation %.1e N; penetration %.1e m\n",
        c.label,
        run.summary.steps,
        run.seconds,
        left.x(),
        left.z(),
        right.x(),
        right.z(),
        contact.force.x(),
        contact.force.y(),
        contact.force.z(),
        run.weight,
        contact.stabilization_force.norm(),
        contact.max_penetration);
    EXPECT_NEAR(left.x(), -right.x(), 1e-9 * std::abs(right.x()));
    EXPECT_NEAR(left.z(), right.z(), 1e-9 * std::abs(right.z()));
    EXPECT_NEAR(left.y(), right.y(), 1e-9 * std::abs(right.z()));
    EXPECT_NEAR(contact.force.z(), run.weight, 1e-6 * run.weight);
    EXPECT_LT(contact.force.head<2>().norm(), 1e-6 * run.weight);
    // The settle steps stop after five passes; what the springs still hold
    // then (7e-9 of the weight for the stiff strip) must not blur the check
    // above.
    EXPECT_LT(contact.stabilization_force.norm(), 1e-7 * run.weight);
    // It hangs on both sides (the free ends below the rod's axis).
    EXPECT_LT(right.z(), test::RodAxisZ(c.spec));
  }
  std::printf("RodHang.SymmetricHang: %.2f s\n", SecondsSince(start));
}

// The soft, frictionless strip on meshes of 20 … 160 elements.
//
// Free-end depth. The nodes lie on the circle of radius R', the elements are
// its chords: a chord of length ℓ spans ℓ³/(24R'²) less arc than the same
// length of strip would, so a quarter turn of chords leaves πℓ²/(48R') more
// strip hanging on each side. The depth converges as ℓ² (successive
// differences shrink by 4), by that much. Its limit is the extensible
// string's: R' + L_h, plus the stretch of the wrapped quarter turn, where
// T = T_h + qR' cos φ, (T_h πR'/2 + qR'²)/EA, and of the hanging part,
// q L_h²/(2 EA). Bending moves it by about λ_T²/R' (the hanging part's line
// is λ_T²/(2R') off the rod's side), 12 µm here.
//
// Contact edge. A string leaves the rod at φ = π/2. A strip under the
// tension T leaves with the rod's curvature 1/R', which decays over λ_T past
// the edge; the free part turns through λ_T/R' before it hangs straight
// down, so the edge is at φ_c = π/2 − λ_T/R' (1.546 rad). The last node the
// rod pushes on is within one node spacing ℓ/R' of the edge (0.125 rad on the
// finest mesh): the edge must lie between it and the next node.
TEST(RodHang, ContactAngleAndFreeEndsConvergeWithRefinement) {
  const auto start = Clock::now();
  const std::vector<int> meshes = {20, 40, 80, 160};
  const test::RodHangSpec base = SoftStrip(20, 0.0);
  const double r = WrapRadius(base), q = LineWeight(base), ea = AxialStiffness(base);
  const double hanging = HangingLength(base), tension = HangingWeight(base);
  const double lambda_t = TensionBendingLength(base);
  const double stretch = (tension * pi * r / 2 + q * r * r) / ea + q * hanging * hanging / (2 * ea);
  const double string_depth = r + hanging + stretch;
  const double edge = pi / 2 - lambda_t / r;
  std::printf(
      "soft strip: l_b = %.2f mm, lambda_T = %.3f mm; inextensible depth R' + L_h = %.6f m, "
      "stretch %.3f mm, extensible string depth %.6f m; contact edge pi/2 - lambda_T/R' = %.4f "
      "rad\n",
      1e3 * test::BendingLength(base),
      1e3 * lambda_t,
      r + hanging,
      1e3 * stretch,
      string_depth,
      edge);
  std::printf(
      "   n   depth [m]    d(depth)   chord pred.  ratio | end x [m]   d(x)      | last contact "
      "node [rad]  d(angle)  next node [rad] | steps    s\n");

  std::vector<double> depth, end_x, angle;
  for (int n : meshes) {
    SCOPED_TRACE(n);
    const test::RodHangSpec spec = SoftStrip(n, 0.0);
    const Hang run = RunHang(spec);
    ASSERT_TRUE(run.summary.IsComplete()) << run.summary.FullReport();
    const Eigen::Vector3d left = LeftEnd(run.last), right = RightEnd(run.last);
    ASSERT_NEAR(left.z(), right.z(), 1e-9);  // symmetric, as the first test checks
    depth.push_back(-right.z());
    end_x.push_back(right.x());
    const ContactSpan span = Span(run.last, spec);
    ASSERT_GT(span.last, n / 2);
    ASSERT_LT(span.last, n);
    angle.push_back(NodeAngle(run.last, spec, span.last));
    const double next = NodeAngle(run.last, spec, span.last + 1);
    EXPECT_LE(angle.back(), edge);
    EXPECT_GE(next, edge);

    const size_t k = depth.size() - 1;
    const double spacing = spec.length / n;
    if (k == 0) {
      std::printf("%4d  %.7f                                | %.7f            | %.5f",
                  n,
                  depth[k],
                  end_x[k],
                  angle[k]);
    } else {
      const double coarse = base.length / meshes[k - 1];
      const double predicted = pi * (coarse * coarse - spacing * spacing) / (48 * r);
      const double ratio = k >= 2 ? (depth[k - 2] - depth[k - 1]) / (depth[k - 1] - depth[k]) : 0;
      std::printf("%4d  %.7f  %.3e  %.3e  %5.2f | %.7f  %+.2e | %.5f  %+.2e",
                  n,
                  depth[k],
                  depth[k - 1] - depth[k],
                  predicted,
                  ratio,
                  end_x[k],
                  end_x[k] - end_x[k - 1],
                  angle[k],
                  angle[k] - angle[k - 1]);
      // From 40 elements on (ℓ ≤ R'/2) the chords' error is the whole change.
      if (k >= 2) {
        EXPECT_NEAR(depth[k - 1] - depth[k], predicted, 0.1 * predicted);
      }
    }
    std::printf("        %.5f       | %4d  %.2f\n", next, run.summary.steps, run.seconds);
  }

  const size_t f = depth.size() - 1;
  const double finest = base.length / meshes[f];
  // Second order: the last ratio of successive differences is near 4.
  const double ratio = (depth[f - 2] - depth[f - 1]) / (depth[f - 1] - depth[f]);
  EXPECT_GT(ratio, 3.5);
  EXPECT_LT(ratio, 4.5);
  // The finest two differ by what the chords predict (checked above); with
  // that error removed (Richardson, order 2) the depth is the string's to
  // within bending's λ_T²/R'.
  const double extrapolated = depth[f] - (depth[f - 1] - depth[f]) / 3;
  std::printf(
      "depth: extrapolated %.7f m, extensible string %.7f m (difference %.1e m; bending "
      "lambda_T^2/R' = %.1e m); above the inextensible R' + L_h by %.3f mm (%.2f %% of the "
      "depth)\n",
      extrapolated,
      string_depth,
      extrapolated - string_depth,
      lambda_t * lambda_t / r,
      1e3 * (extrapolated - r - hanging),
      100 * (extrapolated - r - hanging) / extrapolated);
  EXPECT_NEAR(extrapolated, string_depth, lambda_t * lambda_t / r);
  // The free end hangs at the rod's side, x = R', to within the sag of a
  // chord, R'(ℓ/R')²/8, where the last contact node leaves the rod.
  EXPECT_NEAR(end_x[f], r, finest * finest / (8 * r));
  // The last contact node is the same material node (30 mm from the
  // middle) on the three finest meshes, so its angle converges as the
  // depth does; in general the measure is good to a node spacing.
  EXPECT_NEAR(angle[f], angle[f - 1], finest / r);
  std::printf("RodHang.ContactAngleAndFreeEnds: %.2f s\n", SecondsSince(start));
}

}  // namespace
}  // namespace drape
