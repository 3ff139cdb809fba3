#include "core/mechanics/contact_barrier.h"

#include <cmath>
#include <limits>

namespace drape {

BarrierValue ClampedLogBarrier(double s, double s_hat) {
  BarrierValue b;
  if (s >= s_hat) return b;
  if (s <= 0) {
    b.value = b.first = std::numeric_limits<double>::infinity();
    b.first = -b.first;
    b.second = std::numeric_limits<double>::infinity();
    return b;
  }
  const double log = std::log(s / s_hat), gap = s - s_hat;
  b.value = -gap * gap * log;
  b.first = -2 * gap * log - gap * gap / s;
  b.second = -2 * log - 4 * gap / s + gap * gap / (s * s);
  return b;
}

PairPotential BarrierPotential(const DistanceDerivatives& d,
                               double offset,
                               double activation,
                               double stiffness) {
  PairPotential out;
  const double s_hat = 2 * offset * activation + activation * activation;
  const BarrierValue b = ClampedLogBarrier(d.squared - offset * offset, s_hat);
  if (b.value == 0) return out;
  out.energy = stiffness * b.value;
  out.gradient = stiffness * b.first * d.gradient;
  out.hessian = stiffness * (b.second * d.gradient * d.gradient.transpose() + b.first * d.hessian);
  return out;
}

}  // namespace drape
