// The heavy elastica: a cantilever strip bending under its own weight,
// solved as a boundary-value problem (the independent answer for the heavy
// strip tests). With θ(s) the downward slope angle, s = arc length / L and
// α = wbL³/EI:
//   θ'' = −α (1 − s) cos θ,  θ(0) = 0 (clamp),  θ'(1) = 0 (free end),
//   x' = cos θ,  z' = −sin θ  (lengths over L).
// We shoot on k = θ'(0) = M(0) L/EI ∈ [0, α/2] (the root moment is at most
// that of the straight strip) with bisection, integrating by RK4.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "support/rk4.h"

namespace drape::test {

struct ElasticaEnd {
  double root_curvature = 0;  // k = θ'(0) [1/L]
  double theta = 0;           // θ(1), tip slope [rad]
  double x = 0, z = 0;        // tip position / L
};

// Integrates from s = 0 to 1 with θ'(0) = k. `bent_back` reports whether θ'
// fell below zero anywhere, i.e. the root curvature k was too small.
inline ElasticaEnd Shoot(double alpha, double k, int steps, bool* bent_back) {
  using State = std::array<double, 4>;  // θ, θ', x, z
  auto rate = [alpha](double s, const State& y) {
    return State{y[1], -alpha * (1 - s) * std::cos(y[0]), std::cos(y[0]), -std::sin(y[0])};
  };
  State y{0.0, k, 0.0, 0.0};
  const double h = 1.0 / steps;
  *bent_back = false;
  for (int i = 0; i < steps; ++i) {
    y = Rk4Step(rate, i * h, y, h);
    if (y[1] < 0) *bent_back = true;
  }
  return {k, y[0], y[2], y[3]};
}

// The heavy elastica by shooting on k = θ'(0) with bisection on [0, α/2].
//
// The sign test is "θ' < 0 somewhere on [0, 1]" rather than "θ'(1) < 0":
// the two agree near the root of θ'(1), but for α ≳ 30 the trial k = 0 sends
// θ up past −90°, where cos θ < 0 turns the curvature around and makes θ'(1)
// positive again (α = 50: θ'(1) = +1.01; α = 100: +7.87), so θ'(1) alone does
// not bracket the physical branch. k = α/2 gives θ' ≥ α(1 − s)²/2 ≥ 0.
inline ElasticaEnd SolveHeavyElastica(double alpha, int steps = 2000) {
  double lo = 0, hi = alpha / 2;
  bool bent_back = false;
  Shoot(alpha, lo, steps, &bent_back);
  EXPECT_TRUE(bent_back) << "k = 0 must be too small at α = " << alpha;
  Shoot(alpha, hi, steps, &bent_back);
  EXPECT_FALSE(bent_back) << "k = α/2 must be too large at α = " << alpha;
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    Shoot(alpha, mid, steps, &bent_back);
    (bent_back ? lo : hi) = mid;
  }
  return Shoot(alpha, (lo + hi) / 2, steps, &bent_back);
}

}  // namespace drape::test
