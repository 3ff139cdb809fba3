// Random element states for derivative and invariance tests.
#pragma once

#include <Eigen/Core>

#include "core/mechanics/director.h"
#include "core/mechanics/shell_element.h"
#include "core/model/imperfection.h"

namespace drape::test {

// Uniform in [lo, hi) from the project's own generator (reproducible).
inline double Uniform(SplitMix64& rng, double lo, double hi) {
  return lo + (hi - lo) * rng.NextUniform();
}

inline Eigen::Vector3d RandomVector(SplitMix64& rng, double scale) {
  return {Uniform(rng, -scale, scale), Uniform(rng, -scale, scale), Uniform(rng, -scale, scale)};
}

// A distorted flat quad of size about `size` in the xy plane, counter-clockwise.
inline NodeColumns RandomFlatQuad(SplitMix64& rng, double size, double distortion) {
  NodeColumns x;
  const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i)
    x.col(i) << size * (corner[i][0] + Uniform(rng, -distortion, distortion)),
        size * (corner[i][1] + Uniform(rng, -distortion, distortion)), 0.0;
  return x;
}

// Nodal state: positions and rotations; the element state follows from them.
struct NodalState {
  NodeColumns positions;
  std::array<Eigen::Matrix3d, 4> rotations;

  ShellElementState Element() const {
    ShellElementState s;
    s.positions = positions;
    for (int i = 0; i < 4; ++i) {
      s.directors.col(i) = rotations[i].col(2);
      s.director_tangents[i] = DirectorTangent(rotations[i]);
    }
    return s;
  }

  // The state after the 20-DOF increment q (Δu, then Λ ← exp(ŵ)Λ).
  NodalState Incremented(const ElementVector& q) const {
    NodalState next = *this;
    for (int i = 0; i < 4; ++i) {
      next.positions.col(i) += q.segment<3>(5 * i);
      UpdateRotation(q.segment<2>(5 * i + 3), next.rotations[i]);
    }
    return next;
  }
};

// A large-deformation state of a reference quad: a big rigid rotation, a
// stretch and shear of a few tens of percent, and nodal rotations of up to
// `max_rotation` radians.
inline NodalState RandomDeformedState(SplitMix64& rng,
                                      const NodeColumns& reference,
                                      double size,
                                      double max_rotation) {
  NodalState s;
  const Eigen::Matrix3d rigid = ExpRotation(RandomVector(rng, 2.0));
  for (int i = 0; i < 4; ++i) {
    s.positions.col(i) = rigid * (reference.col(i) + RandomVector(rng, 0.2 * size));
    s.rotations[i] = ExpRotation(RandomVector(rng, max_rotation)) * rigid;
  }
  return s;
}

}  // namespace drape::test
