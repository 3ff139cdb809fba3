// Physical states only (element_orientation.h): the unloaded cantilever
// strip reflected through its clamped edge (x ↦ −x, directors kept) has every
// length, angle and curvature of the flat strip — zero strain, zero residual —
// but every element inside out. The corrector must refuse it; the strip
// itself it accepts.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <string>

#include "core/continuation/newton_corrector.h"
#include "core/fe/element_orientation.h"
#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

struct UnloadedStrip {
  UnloadedStrip() : s(test::TipLoadedStrip(test::StripOf(8), {0, 0, 0}, {0, 0, 0})) {}
  ShellState Mirrored() const {
    ShellState state = s.model.reference;
    state.positions.col(0) *= -1;
    return state;
  }
  NewtonOutcome Solve(ShellState& state) {
    NewtonSettings settings;
    settings.tolerance = 1e-8;
    const test::SceneSystem& ss = s;
    const ExternalForce none = [&ss](const ShellState& at) { return ss.loading.External(1.0, at); };
    return SolveEquilibrium(s.system, none, settings, state, nullptr);
  }
  test::SceneSystem s;
};

TEST(InvertedState, TheFlatStripHasNoInvertedElement) {
  const UnloadedStrip strip;
  EXPECT_FALSE(FindInvertedElement(strip.s.model, strip.s.model.reference));
}

TEST(InvertedState, TheMirroredStripIsFoundInsideOutAtItsFirstElement) {
  const UnloadedStrip strip;
  const auto inverted = FindInvertedElement(strip.s.model, strip.Mirrored());
  ASSERT_TRUE(inverted);
  EXPECT_EQ(inverted->element, 0);
  EXPECT_EQ(inverted->gauss_point, 0);
  EXPECT_NEAR(inverted->ratio, -1, 1e-12);  // a reflection: the area, reversed
  const std::string said = Describe(*inverted, strip.s.model);
  EXPECT_NE(said.find("element 0 (nodes "), std::string::npos) << said;
  EXPECT_NE(said.find("turned inside out"), std::string::npos) << said;
}

TEST(InvertedState, TheCorrectorRefusesTheMirroredStripThatItsResidualCannotTellApart) {
  UnloadedStrip strip;
  ShellState mirrored = strip.Mirrored();
  // Zero to round-off: nothing in the force says the state is wrong.
  EXPECT_LT(strip.s.ResidualNorm(mirrored, 1.0), 1e-12);
  const NewtonOutcome refused = strip.Solve(mirrored);
  EXPECT_EQ(refused.status, NewtonOutcome::Status::kDiverged);
  EXPECT_NE(refused.reason.find("turned inside out"), std::string::npos) << refused.reason;

  ShellState flat = strip.s.model.reference;
  const NewtonOutcome accepted = strip.Solve(flat);
  EXPECT_EQ(accepted.status, NewtonOutcome::Status::kConverged) << accepted.reason;
  EXPECT_EQ(accepted.iterations, 0);
}

}  // namespace
}  // namespace drape
