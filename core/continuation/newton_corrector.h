// The Newton corrector: K Δq = −R, φ += Δu, Λ ← exp(ŵ)Λ, until ‖R‖/‖R₀‖
// meets the tolerance or the round-off floor. One loop serves every caller —
// equilibrium at a fixed load, the arc-length corrector, the step onto a
// branch — each saying through a CorrectorRequest how it assembles, how it
// turns a factorised tangent into a correction and what else a converged
// iterate must satisfy.
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

// What a caller asks of the corrector.
struct CorrectorRequest {
  // How iterations are judged (tolerance, floor, stall, divergence, limit).
  NewtonSettings settings;
  // The residual at an iterate and the ‖R₀‖ its ratio is taken against (0:
  // the ratio is ‖R‖ itself).
  struct Residual {
    Eigen::VectorXd free;  // R over the free DOFs
    double reference = 0;
    // The residual's round-off level [N] when the caller knows it better
    // than the system's last assembled tangent does (a shifted tangent);
    // negative: EquilibriumSystem::RoundOffLevel.
    double round_off = -1;
  };
  // Assembles the system (tangent included) at `state`; `iteration` counts
  // from 0.
  std::function<Residual(const ShellState& state, int iteration)> assemble;
  // With the tangent factorised at `state` (unless `correct_factorizes`):
  // computes the correction from the residual, applies it to `state`, and
  // returns max|Δu| [m]; a negative value when it found none, which ends the
  // iteration as diverged.
  std::function<double(const Eigen::VectorXd& residual, ShellState& state)> correct;
  // `correct` factorises what it solves with itself (a shifted tangent), so
  // the corrector does not factorise the assembled one first.
  bool correct_factorizes = false;
  // Optional: a converged iterate the caller still refuses, and why ("" to
  // accept). A refused one ends the iteration as diverged, without the
  // factorisation that would count its negative pivots. An iterate with an
  // element turned inside out (element_orientation.h) is always refused.
  std::function<std::string(const ShellState& state)> refuse;
};

// Iterates from `state` (updated in place) until the request's settings
// judge it done. `iterations` counts the corrections applied; a converged
// outcome carries the negative pivots of its tangent. On return the system
// holds the assembly at the final state.
NewtonOutcome RunCorrector(EquilibriumSystem& system,
                           ShellState& state,
                           const CorrectorRequest& request,
                           const CancellationToken* cancel);

// The correction K Δq = −R on the system's factorised tangent, cut to the
// part that keeps the fabric's layers apart, applied to `state`; returns
// max|Δu| [m]. The corrector's `correct` at a fixed λ.
double ApplyNewtonCorrection(EquilibriumSystem& system,
                             const Eigen::VectorXd& residual,
                             ShellState& state);

// External force (full, 5 per node) for a state: moments depend on the
// nodal bases, so this is a function, not a vector.
using ExternalForce = std::function<Eigen::VectorXd(const ShellState&)>;

// Equilibrium at a fixed load: the corrector with `external` as the load,
// the ratio taken against the first residual (or settings.residual_reference,
// or the force level).
NewtonOutcome SolveEquilibrium(EquilibriumSystem& system,
                               const ExternalForce& external,
                               const NewtonSettings& settings,
                               ShellState& state,
                               const CancellationToken* cancel);

}  // namespace drape
