#include "core/continuation/step_policy.h"

#include <algorithm>

namespace drape {

double StepPolicy::Next(double length, int iterations) const {
  if (!acceleration) return length;
  const double gamma = static_cast<double>(target_iterations) / std::max(1, iterations);
  return length * std::clamp(gamma, min_step_growth, max_step_growth);
}

}  // namespace drape
