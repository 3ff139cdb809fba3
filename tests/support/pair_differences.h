// Central differences for functions of a contact pair's twelve coordinates
// (four points): the value's against a gradient, the gradient's against a
// Hessian. For the tests of distances, barriers and their derivatives.
#pragma once

#include <Eigen/Core>

#include <utility>

namespace drape::test {

using PairCoordinates = Eigen::Matrix<double, 12, 1>;

struct PairDifferences {
  PairCoordinates gradient;               // of the value
  Eigen::Matrix<double, 12, 12> hessian;  // of the gradient, by columns
};

// `f(x)` returns {value, gradient}; step `h` in every coordinate.
template <typename F>
PairDifferences CentralDifferences(F f, const PairCoordinates& x, double h) {
  PairDifferences d;
  for (int k = 0; k < 12; ++k) {
    PairCoordinates plus = x, minus = x;
    plus(k) += h;
    minus(k) -= h;
    const auto [value_plus, gradient_plus] = f(plus);
    const auto [value_minus, gradient_minus] = f(minus);
    d.gradient(k) = (value_plus - value_minus) / (2 * h);
    d.hessian.col(k) = (gradient_plus - gradient_minus) / (2 * h);
  }
  return d;
}

}  // namespace drape::test
