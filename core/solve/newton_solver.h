// Newton's method for equilibrium at a fixed load: K Δq = −R, φ += Δu,
// Λ ← exp(ŵ)Λ, until ‖R‖/‖R₀‖ ≤ tolerance.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "core/solve/equilibrium_system.h"
#include "core/solve/step_state.h"

namespace drape {

struct NewtonSettings {
  double tolerance = 1e-5;  // on ‖R‖/‖R₀‖
  // R₀: the out-of-balance force the step introduced, ‖Δλ F_ref‖ over the
  // free DOFs (the paper's R⁰ when the step starts from the last equilibrium).
  // Zero means "the first residual", for steps that introduce no load.
  double residual_reference = 0;
  // Measure ‖R‖ against the force level (loads and reactions) instead: for
  // steps that add no load. Prescribed motion's ‖K_fp ∂u_p/∂λ‖ Δλ is a
  // membrane-stiffness force, often 1e6 times the reactions it produces, and
  // would accept steps whose reactions are still wrong.
  bool relative_to_force_level = false;
  double residual_floor = 0;      // ‖R‖ at or below this is converged [N]: round-off level
  double displacement_floor = 0;  // a correction max|Δu| at or below this is converged [m]
  int max_iterations = 30;
  double divergence_ratio = 1e6;

  // Converged: the residual is small, or at round-off, or the corrections
  // have stopped and so has the residual (`ratios`: every ‖R‖/‖R₀‖ so far,
  // the current one last). A stiff penalty (contact) turns a residual of a
  // few percent of a node's weight into a correction below the displacement
  // floor, so a small correction while the residual still falls fast is not
  // equilibrium yet.
  bool Converged(const std::vector<double>& ratios, double norm, double last_correction) const {
    const double ratio = ratios.back();
    if (ratio <= tolerance || norm <= residual_floor) return true;
    if (last_correction > displacement_floor) return false;
    const bool stalled = ratios.size() < 2 || ratio > 0.1 * ratios[ratios.size() - 2];
    return stalled || ratio * ratio <= tolerance;
  }
};

struct NewtonOutcome {
  enum class Status { kConverged, kDiverged, kIterationLimit, kCancelled };
  Status status = Status::kDiverged;
  int iterations = 0;             // linear solves
  std::vector<double> residuals;  // ‖R‖/‖R₀‖, one per assembly (R₀: the load the step added)
  int negative_pivots = 0;        // of the last factorised tangent
  std::string reason;             // why it did not converge
};

// External force (full, 5 per node) for a state: moments depend on the
// nodal bases, so this is a function, not a vector.
using ExternalForce = std::function<Eigen::VectorXd(const ShellState&)>;

// Iterates from `state` (updated in place). On return the system holds the
// assembly at the final state.
NewtonOutcome SolveEquilibrium(EquilibriumSystem& system,
                               const ExternalForce& external,
                               const NewtonSettings& settings,
                               ShellState& state,
                               const CancellationToken* cancel);

}  // namespace drape
