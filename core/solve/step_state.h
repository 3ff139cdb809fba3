// What the outside world sees of a run: one StepState per converged step
// (Ceres' IterationSummary), handed to observers that may stop the run.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/contact/contact_report.h"
#include "core/continuation/cancellation_token.h"
#include "core/continuation/convergence.h"
#include "core/continuation/stability_event.h"
#include "core/fe/shell_state.h"

namespace drape {

struct NamedVector {
  std::string name;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

struct StepState {
  int stage = -1;  // index in the scene's stages
  std::string stage_name;
  int step = 0;                   // 1-based over the whole run
  int stage_step = 0;             // 1-based within the stage
  double lambda = 0;              // the stage's load factor
  int iterations = 0;             // Newton iterations of this step
  std::vector<double> residuals;  // ‖R‖/‖R₀‖ after each assembly (R₀: the load the step added)
  // How the step's last iteration met the test: the tolerance, or the
  // round-off floor (NewtonSettings::round_off_factor).
  Convergence convergence = Convergence::kTolerance;
  double arc_length = 0;                 // the step's length along the path
  int negative_pivots = 0;               // of the converged tangent
  double max_curvature = 0;              // largest principal |κ| at a Gauss point [1/m]
  double law_curvature = 0;              // largest argument of the bending laws [1/m]
  std::vector<NamedVector> reactions;    // force each support and gripper exerts [N]
  std::vector<NamedVector> probes;       // probe positions [m]
  std::optional<ContactReport> contact;  // present when the scene has obstacles
  // The smallest distance between the mid-surfaces of two parts of the
  // fabric more than SolveSummary::layer_exclusion apart at rest, when two
  // such parts come within twice the thickness of each other [m]: below the
  // thickness, layers pass into each other.
  std::optional<double> layer_distance;
  // With self-contact, the force the layers exert on each other then
  // (SelfContactEvaluation::force) [N].
  std::optional<double> layer_force;
  ShellState state;  // the converged configuration
  // Set on the step where the path crossed a limit or bifurcation point
  // (also in SolveSummary::stability_events).
  std::optional<StabilityEvent> stability_event;
  double elapsed_s = 0;  // since the run started
};

enum class StepDecision { kContinue, kStop };

using StepObserver = std::function<StepDecision(const StepState&)>;

}  // namespace drape
