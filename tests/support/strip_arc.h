// The closed-form shape of a cantilever strip (support/strip_scene.h, root
// at x = 0) under an end moment about +y: a circular arc of radius R = EI/M
// curling toward −z, centred at (0, 0, −R), every director pointing away from
// the centre.
#pragma once

#include <Eigen/Core>

#include <cmath>

#include "core/fe/shell_model.h"
#include "core/mechanics/director.h"

namespace drape::test {

// Where the point at distance `s` along the strip from the root lies.
inline Eigen::Vector3d ArcPoint(double s, double radius) {
  return {radius * std::sin(s / radius), 0.0, -radius * (1 - std::cos(s / radius))};
}

// The reference state bent onto the arc: each node at arc length x keeps its
// y and turns by x/R about +y.
inline ShellState ArcState(const ShellModel& model, double radius) {
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = model.reference.positions(i, 0);
    const Eigen::Vector3d p = ArcPoint(x, radius);
    state.positions(i, 0) = p.x();
    state.positions(i, 2) = p.z();
    state.rotations[i] =
        ExpRotation(Eigen::Vector3d(0, x / radius, 0)) * model.reference.rotations[i];
  }
  return state;
}

}  // namespace drape::test
