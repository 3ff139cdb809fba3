// Where the ends of the dress-form scarf (resources/scenes/dress-form-drape.json
// and scarf-on-form.json, probes left_end and right_end) must hang, from the
// form's shape alone: its mesh is mirror-symmetric about x = 0 (a surface of
// revolution squashed in y), so both ends hang alike; they fall past the
// shoulders (z ≈ 0.5 m) and hang along the body, outside it (its half-width
// is at most 0.16 m). Their y is free: the strip may turn a little.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>

namespace drape::test {

inline void ExpectScarfEndsHangAlongTheBody(const Eigen::Vector3d& left,
                                            const Eigen::Vector3d& right) {
  EXPECT_NEAR(left.x(), -right.x(), 1e-6);
  EXPECT_NEAR(left.z(), right.z(), 1e-6);
  EXPECT_LT(left.z(), 0.45);
  EXPECT_GT(std::abs(left.x()), 0.11);
  EXPECT_LT(std::abs(left.x()), 0.2);
}

}  // namespace drape::test
