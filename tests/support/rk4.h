// One classical Runge–Kutta step, for the ODEs the verification tests solve
// as independent answers (the heavy and the nonlinear elastica).
#pragma once

#include <array>
#include <cstddef>

namespace drape::test {

// y(s + h) from y(s) for y' = rate(s, y).
template <std::size_t N, typename Rate>
std::array<double, N> Rk4Step(const Rate& rate,
                              double s,
                              const std::array<double, N>& y,
                              double h) {
  auto along = [](const std::array<double, N>& a, double c, const std::array<double, N>& d) {
    std::array<double, N> r;
    for (std::size_t j = 0; j < N; ++j) r[j] = a[j] + c * d[j];
    return r;
  };
  const std::array<double, N> k1 = rate(s, y);
  const std::array<double, N> k2 = rate(s + h / 2, along(y, h / 2, k1));
  const std::array<double, N> k3 = rate(s + h / 2, along(y, h / 2, k2));
  const std::array<double, N> k4 = rate(s + h, along(y, h, k3));
  std::array<double, N> next;
  for (std::size_t j = 0; j < N; ++j)
    next[j] = y[j] + h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  return next;
}

}  // namespace drape::test
