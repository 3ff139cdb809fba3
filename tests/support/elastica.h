// Euler's elastica in closed form (complete elliptic integrals), for the
// post-buckled strips. With p² = P/EI and modulus k = sin(α/2) (α the slope
// at an inflection point), one quarter-wave between a point of zero slope
// and an inflection point has arc length K(k)/p, chord (2E(k) − K(k))/p and
// rise 2k/p.
//  - pinned–pinned, first mode: two quarter-waves, L = 2K/p;
//  - clamped–clamped, symmetric first mode: four quarter-waves, L = 4K/p.
// Both give the same end shortening and mid-span height over the ends:
//   Δ/L = 2 − 2E(k)/K(k),   δ/L = k/K(k),
// and P L²/EI = 4K² (pinned) or 16K² (clamped), P → P_E as k → 0.
// PostBuckling.ClosedFormMatchesShootingOnTheElasticaOde checks these against
// the ODE θ'' = −(PL²/EI) sin θ solved by shooting.
#pragma once

#include <cmath>

namespace drape::test {

struct Elastica {
  double k = 0;           // modulus sin(α/2)
  double force = 0;       // μ = P L² / EI of the clamped–clamped strip (¼ of it when pinned)
  double shortening = 0;  // Δ / L
  double height = 0;      // δ / L, mid-span over the ends
  double curvature = 0;   // θ'(0) L at the clamps
};

inline Elastica ClosedForm(double k) {
  const double kk = std::comp_ellint_1(k), ek = std::comp_ellint_2(k);
  return {k, 16 * kk * kk, 2 - 2 * ek / kk, k / kk, 8 * k * kk};
}

// Δ/L = 2 − 2E/K rises monotonically from 0 (k = 0) to 2 (k → 1): bisection on k.
inline Elastica ClosedFormAtShortening(double shortening) {
  double lo = 0, hi = 1 - 1e-12;
  for (int i = 0; i < 100; ++i) {
    const double mid = (lo + hi) / 2;
    (ClosedForm(mid).shortening < shortening ? lo : hi) = mid;
  }
  return ClosedForm((lo + hi) / 2);
}

}  // namespace drape::test
