// Verification: no transverse shear locking. A cantilever strip under a small
// tip force P (deflection ~1e-4 L: the linear regime) must match Timoshenko
// beam theory,
//   δ = P L³ / (3 E I) + P L / (κ G A),  κ = 5/6, G = E/2 (ν = 0), A = b h,
// for thicknesses from h = L/10 (shear adds 0.6 (h/L)² = 0.6 % to δ) down to
// h = L/10000 (shear negligible), same E. An element that locks in shear gets
// stiffer as h/L falls (FE/theory dropping with h); the MITC4 assumed shear
// strain must keep the ratio at 1 for every h.
//
// Measured: FE/theory = 1 − 1/(4n²) for n × 1 elements at every h (n = 40:
// 0.999844; 10: 0.9975; 5: 0.9900; 1: 0.7500), the error of piecewise-constant
// curvature under a linear moment, with no trend in h. Six elements would
// pass; forty leave the 1 % band almost wholly to detect stiffening.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

Eigen::Vector3d Probe(const StepState& step, const std::string& name) {
  for (const auto& p : step.probes)
    if (p.name == name) return p.value;
  ADD_FAILURE() << "no probe '" << name << "' in step " << step.step;
  return Eigen::Vector3d::Constant(NAN);
}

double TimoshenkoTipDeflection(const test::StripSpec& s, double force) {
  const double ei = test::StripBendingStiffness(s);
  const double kga = 5.0 / 6.0 * (s.youngs_modulus / 2) * s.width * s.thickness;
  return force * std::pow(s.length, 3) / (3 * ei) + force * s.length / kga;
}

// FE tip deflection (downward positive) under a tip force P toward −z.
double FeTipDeflection(const test::StripSpec& s, double force, SolveSummary* summary) {
  Scene scene = test::TipLoadedStrip(s, {0, 0, -force}, {0, 0, 0});
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  double deflection = NAN;
  *summary = solver.Solve({[&](const StepState& step) {
    deflection = -Probe(step, "tip").z();
    return StepDecision::kContinue;
  }});
  return deflection;
}

void CheckAgainstTimoshenko(int elements) {
  std::printf("%d x 1 elements\n%8s %10s %12s %12s %12s %10s %10s %6s\n",
              elements,
              "L/h",
              "h [m]",
              "P [N]",
              "FE delta/L",
              "theory/L",
              "FE/theory",
              "shear part",
              "iters");
  for (double slenderness : {10.0, 100.0, 1000.0, 10000.0}) {
    test::StripSpec spec;  // L = 0.2 m, b = 0.01 m, E = 1 MPa, ν = 0
    spec.elements = elements;
    spec.thickness = spec.length / slenderness;
    // P for a bending deflection of 1e-4 L.
    const double force = 1e-4 * 3 * test::StripBendingStiffness(spec) / std::pow(spec.length, 2);
    const double theory = TimoshenkoTipDeflection(spec, force);
    const double shear_part =
        1 - force * std::pow(spec.length, 3) / (3 * test::StripBendingStiffness(spec)) / theory;
    SolveSummary summary;
    const double fe = FeTipDeflection(spec, force, &summary);
    EXPECT_TRUE(summary.IsComplete()) << "L/h = " << slenderness << "\n" << summary.FullReport();
    const double ratio = fe / theory;
    std::printf("%8.0f %10.2e %12.4e %12.6e %12.6e %10.6f %10.2e %6d\n",
                slenderness,
                spec.thickness,
                force,
                fe / spec.length,
                theory / spec.length,
                ratio,
                shear_part,
                summary.iterations);
    EXPECT_NEAR(ratio, 1.0, 0.01) << "L/h = " << slenderness << ", " << elements << " elements";
  }
}

TEST(ShearLocking, ThinCantileverMatchesTimoshenkoBeamFrom10To10000) {
  CheckAgainstTimoshenko(40);
}

}  // namespace
}  // namespace drape
