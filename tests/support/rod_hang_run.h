// The rod-hang and capstan checks' strips, closed forms and measures
// (rod_hang_test.cc, capstan_slow_test.cc); the quantities are defined at
// the top of rod_hang_test.cc.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/solve/shell_solver.h"
#include "support/rod_hang_scene.h"

namespace drape::test {

using Clock = std::chrono::steady_clock;
using std::numbers::pi;

inline double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---- the strips ---------------------------------------------------------------

// The scene exactly as the Python generator wrote it (E = 2 MPa, h = 0.5 mm:
// ℓ_b = 22 mm, λ_T = 7.9 mm, not small against R = 20 mm), dropped freely.
inline test::RodHangSpec StiffStrip(int elements, double friction) {
  test::RodHangSpec s;
  s.elements = elements;
  s.friction = friction;
  return s;
}

// A heavy flexible strip: E = 1 MPa, h = 0.1 mm gives ℓ_b = 3.5 mm, λ_T =
// 0.5 mm (λ_T/R' = 0.025) and at most w L/(2 E h) = 0.4 % membrane strain.
// It flops from flat to hanging by λ ~ 1e-4, so the gravity stage's first
// increment is 1e-5, and it is held at the middle while it wraps
// (rod_hang_scene.h).
inline test::RodHangSpec SoftStrip(int elements, double friction, double thickness = 1e-4) {
  test::RodHangSpec s;
  s.youngs_modulus = 1e6;
  s.thickness = thickness;
  s.elements = elements;
  s.friction = friction;
  s.hold_middle = true;
  s.gravity_increment = 1e-5;
  return s;
}

inline double WrapRadius(const test::RodHangSpec& s) {  // R'
  return s.radius + s.thickness / 2;
}
inline double LineWeight(const test::RodHangSpec& s) {  // q [N/m]
  return s.areal_weight * s.width;
}
inline double AxialStiffness(const test::RodHangSpec& s) {  // EA [N]
  return s.youngs_modulus * s.thickness * s.width;
}
inline double FlexuralRigidity(const test::RodHangSpec& s) {  // EI [N·m²]
  return s.youngs_modulus * s.width * std::pow(s.thickness, 3) / 12;
}
inline double HangingLength(const test::RodHangSpec& s) {  // L_h, inextensible, full wrap
  return s.length / 2 - pi * WrapRadius(s) / 2;
}
inline double HangingWeight(const test::RodHangSpec& s) {  // T_h
  return LineWeight(s) * HangingLength(s);
}
inline double TensionBendingLength(const test::RodHangSpec& s) {  // λ_T
  return std::sqrt(FlexuralRigidity(s) / HangingWeight(s));
}

// The capstan limit of a heavy belt over a half turn. On the rod, at the
// angle φ from its top, the tension obeys dT/dφ = μT + qR'(μ cos φ − sin φ)
// when the belt is about to slide towards φ > 0: the weight on the rod
// presses it on (μ q R' cos φ) and pulls it along (q R' sin φ). With
// T(−π/2) = T_h the solution gives the largest pull
//   F = (e^{μπ} − 1) T_h + (e^{μπ} + 1) 2μqR'/(1 + μ²).
// The textbook T₂ = T₁ e^{μθ} is the first term alone: it leaves out the
// weight of the wrapped half turn, here qπR' = 37 % of T_h.
inline double HeavyBeltLimit(const test::RodHangSpec& s) {
  const double mu = s.friction, q = LineWeight(s), r = WrapRadius(s);
  const double e = std::exp(mu * pi);
  return (e - 1) * HangingWeight(s) + (e + 1) * 2 * mu * q * r / (1 + mu * mu);
}

// ---- a run and what it measures ---------------------------------------------

struct Hang {
  SolveSummary summary;
  StepState hung;  // the last step before the pull: the settled hang
  StepState last;
  StepState peak;  // the pull step of largest λ
  double weight = 0;
  double seconds = 0;
};

// Past its limit the pulled strip slides on at an almost constant λ (each
// step a few µm of slide); once λ has fallen below its peak this many steps
// in a row the path has turned, and the run is stopped there.
inline constexpr int kStepsPastThePeak = 10;

inline Hang RunHang(const test::RodHangSpec& spec) {
  const Scene scene = test::RodHang(spec);
  SolverOptions options = SolverOptions::FromScene(scene.solver);
  options.threads = 1;  // 162–322 nodes: threads cost more than they save
  ShellSolver solver(scene, options);
  Hang run;
  int falling = 0;
  const auto start = Clock::now();
  run.summary = solver.Solve({[&](const StepState& step) {
    run.last = step;
    if (step.stage_name != "pull") {
      run.hung = step;
      return StepDecision::kContinue;
    }
    if (step.lambda > run.peak.lambda) {
      run.peak = step;
      falling = 0;
    } else if (++falling == kStepsPastThePeak) {
      return StepDecision::kStop;
    }
    return StepDecision::kContinue;
  }});
  run.seconds = SecondsSince(start);
  run.weight = solver.model().total_weight.norm();
  return run;
}

inline Eigen::Vector3d LeftEnd(const StepState& step) {
  return step.probes.at(0).value;
}
inline Eigen::Vector3d RightEnd(const StepState& step) {
  return step.probes.at(1).value;
}

// Angle of node i from the rod's top, seen from its axis (x = 0): positive
// on the right, beyond ±π/2 below the axis.
inline double NodeAngle(const StepState& step, const test::RodHangSpec& s, int i) {
  const auto x = step.state.positions.row(i);
  return std::atan2(x(0), x(2) - test::RodAxisZ(s));
}

// The first and last node along the strip (row y = −b/2; the row y = +b/2
// is its mirror) that the rod pushes on.
struct ContactSpan {
  int first = -1, last = -1;
};

inline ContactSpan Span(const StepState& step, const test::RodHangSpec& s) {
  ContactSpan span;
  const auto& p = step.contact->pressure;
  for (int i = 0; i <= s.elements; ++i)
    if (p[i] > 0 || p[i + s.elements + 1] > 0) {
      if (span.first < 0) span.first = i;
      span.last = i;
    }
  return span;
}

// The membrane force of element i (between nodes i and i + 1) from its
// stretch, both rows averaged: EA (|Δx|/ℓ − 1) [N].
inline double ElementTension(const StepState& step, const test::RodHangSpec& s, int i) {
  const double length = s.length / s.elements;
  double strain = 0;
  for (int row = 0; row < 2; ++row) {
    const int a = row * (s.elements + 1) + i;
    strain += (step.state.positions.row(a + 1) - step.state.positions.row(a)).norm() / length - 1;
  }
  return AxialStiffness(s) * strain / 2;
}

}  // namespace drape::test
