// Newton's method for equilibrium at a fixed load: K Δq = −R, φ += Δu,
// Λ ← exp(ŵ)Λ, until ‖R‖/‖R₀‖ ≤ tolerance.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>
#include <vector>

#include "core/continuation/cancellation_token.h"
#include "core/continuation/convergence.h"
#include "core/continuation/equilibrium_system.h"

namespace drape {

struct NewtonSettings {
  double tolerance = 1e-5;  // on ‖R‖/‖R₀‖
  // R₀: the out-of-balance force the step introduced, ‖Δλ F₀‖ over the free
  // DOFs (F₀ = ∂F_ext/∂λ − ∂F_int/∂λ: the paper's R⁰ when the step starts
  // from the last equilibrium). Zero means "the first residual", for steps
  // that introduce no load.
  double residual_reference = 0;
  // Measure ‖R‖ against the force level (loads and reactions) instead: for
  // steps that add no load. Prescribed motion's ‖K_fp ∂u_p/∂λ‖ Δλ is a
  // membrane-stiffness force, often 1e6 times the reactions it produces, and
  // would accept steps whose reactions are still wrong.
  bool relative_to_force_level = false;
  // The round-off floor: ‖R‖ at most this many times the residual's
  // round-off level (EquilibriumSystem::RoundOffLevel: ‖K δ‖ for the state
  // rounded to double precision) counts as converged, reported as such.
  // Measured: 10 keeps every verification test at its tolerance; 100
  // accepts steps that the tests find inaccurate.
  double round_off_factor = 10;
  // A correction max|Δu| at or below this [m] while the residual is above
  // both the tolerance and the floor and no longer halves per iteration
  // is a stall: the step fails (and is cut back) at once.
  double stall_correction = 0;
  int max_iterations = 30;
  double divergence_ratio = 1e6;

  // `ratios`: every ‖R‖/‖R₀‖ of the iteration so far, the current one last;
  // `norm` = ‖R‖ [N]; `round_off` the residual's round-off level [N];
  // `last_correction` the last max|Δu| [m] (∞ before the first).
  Convergence Judge(const std::vector<double>& ratios,
                    double norm,
                    double round_off,
                    double last_correction) const {
    if (ratios.back() <= tolerance) return Convergence::kTolerance;
    if (norm <= round_off_factor * round_off) return Convergence::kRoundOff;
    if (last_correction > stall_correction) return Convergence::kNotYet;
    // A stiff penalty (contact) turns a residual of a few percent of a node's
    // weight into a correction below the floor, and friction makes Newton
    // converge linearly: while the residual still halves, that is progress,
    // not a stall.
    const bool falling = ratios.size() >= 2 && ratios.back() <= 0.5 * ratios[ratios.size() - 2];
    return falling ? Convergence::kNotYet : Convergence::kStalled;
  }
};

struct NewtonOutcome {
  enum class Status { kConverged, kDiverged, kIterationLimit, kStalled, kCancelled };
  Status status = Status::kDiverged;
  int iterations = 0;             // linear solves
  std::vector<double> residuals;  // ‖R‖/‖R₀‖, one per assembly (R₀: the load the step added)
  // How the last iteration was judged: kTolerance or kRoundOff when converged.
  Convergence convergence = Convergence::kNotYet;
  int negative_pivots = 0;  // of the converged state's tangent
  std::string reason;       // why it did not converge
};

// What a corrector makes of one iteration: Newton at a fixed λ, the
// arc-length corrector and the step onto a branch judge alike.
struct IterationVerdict {
  bool done = false;  // stop iterating: converged, or failed (`status` says which)
  NewtonOutcome::Status status = NewtonOutcome::Status::kConverged;
  std::string reason;  // why it failed
};

// Before an assembly: a pause holds the run here; a cancellation or a
// non-finite state ends the iteration.
IterationVerdict CheckBeforeAssembly(const ShellState& state, const CancellationToken* cancel);

// After an assembly: appends ‖R‖/`reference` to `ratios` (`reference` 0:
// the ratio is ‖R‖ itself), sets `convergence`, and says whether to stop —
// converged (tolerance or round-off floor), stalled, diverged (a non-finite
// residual or one above the divergence ratio) or out of iterations
// (`corrections` applied so far, against max_iterations).
IterationVerdict JudgeIteration(const NewtonSettings& settings,
                                double norm,
                                double reference,
                                double round_off,
                                double last_correction,
                                int corrections,
                                std::vector<double>& ratios,
                                Convergence& convergence);

// A ratio or tolerance for a message: "%.3g".
std::string Number(double value);

// Why a stalled iteration failed, for the step's message.
std::string StallReason(double ratio, double tolerance);

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
