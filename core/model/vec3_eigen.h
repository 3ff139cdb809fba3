// A scene's Vec3 (plain std::array, so scene.h needs no Eigen) as an Eigen
// vector, for the code that computes with it.
#pragma once

#include <Eigen/Core>

#include "core/model/scene.h"

namespace drape {

inline Eigen::Vector3d ToEigen(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

inline Vec3 ToVec3(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

}  // namespace drape
