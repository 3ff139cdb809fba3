#include "core/solve/solver_options.h"

#include <cmath>
#include <sstream>

namespace drape {
namespace {

template <typename T>
bool Check(bool ok, const char* name, T value, const char* constraint, std::string* error) {
  if (!ok && error) {
    std::ostringstream s;
    s << "SolverOptions::" << name << " = " << value << ". Violated constraint: " << constraint;
    *error = s.str();
  }
  return ok;
}

}  // namespace

SolverOptions SolverOptions::FromScene(const SolverSettings& settings) {
  SolverOptions o;
  o.tolerance = settings.tolerance;
  o.displacement_tolerance = settings.displacement_tolerance;
  o.target_iterations = settings.target_iterations;
  o.acceleration = settings.acceleration;
  o.max_steps = settings.max_steps;
  o.max_iterations = settings.max_iterations;
  o.max_step_cuts = settings.max_step_cuts;
  o.max_turns = settings.max_turns;
  o.psi = settings.psi.value_or(0.0);
  o.branching = settings.branching;
  o.sequencing = settings.sequencing;
  o.max_wall_s = settings.max_wall_s.value_or(0.0);
  return o;
}

bool SolverOptions::IsValid(std::string* error) const {
  return Check(
             tolerance > 0 && tolerance < 1, "tolerance", tolerance, "0 < tolerance < 1", error) &&
         Check(displacement_tolerance > 0,
               "displacement_tolerance",
               displacement_tolerance,
               "displacement_tolerance > 0",
               error) &&
         Check(target_iterations >= 1,
               "target_iterations",
               target_iterations,
               "target_iterations >= 1",
               error) &&
         Check(min_step_growth > 0 && min_step_growth <= 1,
               "min_step_growth",
               min_step_growth,
               "0 < min_step_growth <= 1",
               error) &&
         Check(max_step_growth >= 1,
               "max_step_growth",
               max_step_growth,
               "max_step_growth >= 1",
               error) &&
         Check(max_increment > 0 && max_increment <= 1,
               "max_increment",
               max_increment,
               "0 < max_increment <= 1",
               error) &&
         Check(max_steps >= 1, "max_steps", max_steps, "max_steps >= 1", error) &&
         Check(
             max_iterations >= 1, "max_iterations", max_iterations, "max_iterations >= 1", error) &&
         Check(max_step_cuts >= 0, "max_step_cuts", max_step_cuts, "max_step_cuts >= 0", error) &&
         Check(max_turns >= 0, "max_turns", max_turns, "max_turns >= 0", error) &&
         Check(divergence_ratio > 1,
               "divergence_ratio",
               divergence_ratio,
               "divergence_ratio > 1",
               error) &&
         Check(psi >= 0, "psi", psi, "psi >= 0", error) &&
         Check(penetration_tolerance > 0,
               "penetration_tolerance",
               penetration_tolerance,
               "penetration_tolerance > 0",
               error) &&
         Check(max_augmentations >= 0,
               "max_augmentations",
               max_augmentations,
               "max_augmentations >= 0",
               error) &&
         Check(max_augmentation_iterations >= 0,
               "max_augmentation_iterations",
               max_augmentation_iterations,
               "max_augmentation_iterations >= 0",
               error) &&
         Check(sequencing >= 0,
               "sequencing",
               sequencing,
               "sequencing >= 1, or 0 (kAutoSequencing)",
               error) &&
         Check(threads >= 0, "threads", threads, "threads >= 0", error) &&
         Check(max_wall_s >= 0 && std::isfinite(max_wall_s),
               "max_wall_s",
               max_wall_s,
               "max_wall_s >= 0 (0: no limit)",
               error);
}

}  // namespace drape
