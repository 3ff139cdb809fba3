// A cantilever strip's state bent to a known curvature, for the tests that
// colour or export it (field_units_test.cc, frame_renderer_test.cc).
#pragma once

#include <cmath>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/mechanics/director.h"
#include "support/strip_scene.h"

namespace drape::test {

// The cantilever strip bent to θ(s) = 15 s²/L: curvature from 0 at the
// root to 30 1/m at the tip.
inline ShellState BentStrip(const StripSpec& spec, const ShellModel& model) {
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double s_end = model.reference.positions(i, 0);
    double x = 0, z = 0;
    const int n = 400;
    for (int j = 0; j < n; ++j) {
      const double s = (j + 0.5) * s_end / n;
      const double th = 15.0 * s * s / spec.length;
      x += std::cos(th) * s_end / n;
      z += std::sin(th) * s_end / n;
    }
    state.positions(i, 0) = x;
    state.positions(i, 2) = z;
    const double th = 15.0 * s_end * s_end / spec.length;
    state.rotations[i] = RotationFromDirector({-std::sin(th), 0, std::cos(th)});
  }
  return state;
}

}  // namespace drape::test
