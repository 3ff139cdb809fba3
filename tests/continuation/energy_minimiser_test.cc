// The energy minimiser (energy_minimiser.h) called directly on the straight
// clamped–free column (support/strip_scene.h: L = 0.2 m, b = 1 cm, h = 0.5
// mm, E = 1 MPa, ν = 0) under an axial tip force P = 2 P_E, P_E = π²EI/4L²
// its first Euler load (the second is 9 P_E, so one mode is unstable). The
// straight column is an equilibrium there, but a saddle of the energy; the
// stable rest state is the buckled elastica, whose closed form (Timoshenko &
// Gere, Theory of Elastic Stability, §2.7) gives P/P_E = (2K(k)/π)² and the
// tip's deflection δ/L = 2k/K(k), K the complete elliptic integral of the
// first kind.
#include "core/continuation/energy_minimiser.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

constexpr double kPi = std::numbers::pi;

// The elastica under P = `ratio` P_E: k from K(k) = (π/2)√ratio by bisection
// (K rises with k). With ω² = P/EI: L = K/ω, the tip's deflection 2k/ω, its
// projection on the axis (2E − K)/ω, and, from the first integral θ'² =
// 2ω²(cos θ − cos α), the strain energy P(x_tip − L cos α), so the total
// potential energy Π = U − P(L − x_tip) = (2P/ω)(2E − 2K + k²K).
struct Elastica {
  double deflection_over_length = 0;
  double energy_over_pl = 0;  // Π/(PL)
};

Elastica ElasticaAt(double ratio) {
  const double target = 0.5 * kPi * std::sqrt(ratio);
  double lo = 0, hi = 1 - 1e-15;
  for (int i = 0; i < 80; ++i) {
    const double k = (lo + hi) / 2;
    (std::comp_ellint_1(k) < target ? lo : hi) = k;
  }
  const double k = (lo + hi) / 2;
  const double kk = std::comp_ellint_1(k), ee = std::comp_ellint_2(k);
  return {2 * k / kk, 2 * (2 * ee - 2 * kk + k * k * kk) / kk};
}

MinimiserSettings Tight() {
  MinimiserSettings m;
  m.newton.tolerance = 1e-10;
  m.newton.max_iterations = 3000;
  return m;
}

struct Minimised {
  MinimiserOutcome outcome;
  double tip_z = 0;  // [m]
};

// The column on `elements` elements at P = 2 P_E, minimised from the straight
// reference state moved by `tip_push` [m] along z at every node in proportion
// to its distance from the root (0: exactly straight).
Minimised MinimiseColumn(int elements, double tip_push) {
  const test::StripSpec spec = test::StripOf(elements);
  test::SceneSystem s(
      test::TipLoadedStrip(spec, {-2 * test::CantileverEulerLoad(spec), 0, 0}, {0, 0, 0}));
  ShellState state = s.model.reference;
  for (int i = 0; i < s.model.NodeCount(); ++i)
    state.positions(i, 2) += tip_push * state.positions(i, 0) / spec.length;
  Minimised m;
  m.outcome = MinimiseEnergy(
      s.system,
      [&](const ShellState& at) { return s.loading.External(1.0, at); },
      Tight(),
      state,
      nullptr);
  m.tip_z = test::ProbeAt(s.model, "tip", state).z();
  return m;
}

// Started exactly straight, the corrector first reaches the straight
// equilibrium (the saddle: one negative pivot), leaves it along its mode and
// comes to rest on the elastica: 0 negative pivots, the tip's deflection and
// the energy released the closed form's to the mesh's h² error (measured
// +8.96e-4 and +2.75e-4 on 8 and 16 elements for the deflection, their
// Richardson extrapolation +6.9e-5; the energy's below). The straight start
// has Π = 0 (its axial strain energy, P²L/2EA ≈ 3e-12 J, is 4e-6 of Π).
TEST(EnergyMinimiser, FromTheStraightColumnPastEulersLoadItComesToRestOnTheElastica) {
  const Elastica exact = ElasticaAt(2.0);
  const test::StripSpec spec = test::StripOf(8);
  const double pl = 2 * test::CantileverEulerLoad(spec) * spec.length;
  std::vector<double> deflection, energy;
  for (int elements : {8, 16}) {
    const Minimised m = MinimiseColumn(elements, 0.0);
    ASSERT_EQ(m.outcome.newton.status, NewtonOutcome::Status::kConverged)
        << m.outcome.newton.reason;
    EXPECT_EQ(m.outcome.newton.negative_pivots, 0);
    deflection.push_back(std::abs(m.tip_z) / spec.length / exact.deflection_over_length - 1);
    energy.push_back(m.outcome.energy_change / pl / exact.energy_over_pl - 1);
    std::printf(
        "%d elements: δ/L %+.3e, Π %+.3e from the elastica's (%.6f, %.4e J); "
        "%d iterations, %d steps, %d refused\n",
        elements,
        deflection.back(),
        energy.back(),
        exact.deflection_over_length,
        exact.energy_over_pl * pl,
        m.outcome.newton.iterations,
        m.outcome.steps,
        m.outcome.refused_steps);
  }
  const double deflection_extrapolated = (4 * deflection[1] - deflection[0]) / 3;
  const double energy_extrapolated = (4 * energy[1] - energy[0]) / 3;
  std::printf("extrapolated: δ/L %+.3e, Π %+.3e\n", deflection_extrapolated, energy_extrapolated);
  EXPECT_NEAR(deflection[0], 0, 2e-3);
  EXPECT_NEAR(deflection[1], 0, 6e-4);
  EXPECT_NEAR(deflection_extrapolated, 0, 2e-4);
  // Measured +1.71e-2, +4.09e-3, extrapolated −2.6e-4.
  EXPECT_NEAR(energy[0], 0, 3.5e-2);
  EXPECT_NEAR(energy[1], 0, 8e-3);
  EXPECT_NEAR(energy_extrapolated, 0, 8e-4);
}

// Pushed a little to one side, it falls to that side: the minimiser goes
// down the energy from where it starts.
TEST(EnergyMinimiser, PushedToOneSideTheColumnBucklesToThatSide) {
  for (double side : {1.0, -1.0}) {
    const Minimised m = MinimiseColumn(8, side * 1e-4);
    ASSERT_EQ(m.outcome.newton.status, NewtonOutcome::Status::kConverged)
        << m.outcome.newton.reason;
    EXPECT_EQ(m.outcome.newton.negative_pivots, 0);
    EXPECT_GT(side * m.tip_z, 0);
  }
}

}  // namespace
}  // namespace drape
