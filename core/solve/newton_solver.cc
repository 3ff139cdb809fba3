#include "core/solve/newton_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace drape {

const char* ToString(Convergence c) {
  switch (c) {
    case Convergence::kNotYet:
      return "not_converged";
    case Convergence::kTolerance:
      return "tolerance";
    case Convergence::kRoundOff:
      return "round_off";
    case Convergence::kStalled:
      return "stalled";
  }
  return "?";
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string StallReason(double ratio, double tolerance) {
  return "Newton stalled at ‖R‖/‖R₀‖ = " + Number(ratio) + " (tolerance " + Number(tolerance) +
         "): the corrections stopped while the residual stays above the tolerance and the "
         "round-off floor";
}

NewtonOutcome SolveEquilibrium(EquilibriumSystem& system,
                               const ExternalForce& external,
                               const NewtonSettings& settings,
                               ShellState& state,
                               const CancellationToken* cancel) {
  NewtonOutcome out;
  double r0 = 0;
  double last_correction = INFINITY;
  for (int it = 0;; ++it) {
    if (cancel) cancel->WaitWhilePaused();  // a pause holds the run here
    if (cancel && cancel->IsCancelled()) {
      out.status = NewtonOutcome::Status::kCancelled;
      out.reason = "cancelled";
      return out;
    }
    if (!IsFinite(state)) {
      out.status = NewtonOutcome::Status::kDiverged;
      out.reason = "the state is not finite";
      return out;
    }
    system.Assemble(state, /*with_tangent=*/true);
    const Eigen::VectorXd f_ext = external(state);
    const Eigen::VectorXd r = system.Residual(f_ext);
    const double norm = r.norm();
    if (!std::isfinite(norm)) {
      out.status = NewtonOutcome::Status::kDiverged;
      out.reason = "the residual is not finite";
      return out;
    }
    // A predictor may start far from or close to equilibrium; the test stays
    // relative to the load the step added, not to where the predictor landed.
    if (it == 0) r0 = settings.residual_reference > 0 ? settings.residual_reference : norm;
    const double reference = settings.relative_to_force_level ? system.ForceLevel(f_ext) : r0;
    const double ratio = reference > 0 ? norm / reference : 0.0;
    out.residuals.push_back(ratio);
    out.convergence =
        settings.Judge(out.residuals, norm, system.RoundOffLevel(state), last_correction);
    if (out.convergence == Convergence::kTolerance || out.convergence == Convergence::kRoundOff) {
      out.status = NewtonOutcome::Status::kConverged;
      // The stability indicator belongs to the converged state, whose tangent
      // was just assembled.
      out.negative_pivots = system.Factorize().negative_pivots;
      return out;
    }
    if (out.convergence == Convergence::kStalled) {
      out.status = NewtonOutcome::Status::kStalled;
      out.reason = StallReason(ratio, settings.tolerance);
      return out;
    }
    if (ratio > settings.divergence_ratio) {
      out.status = NewtonOutcome::Status::kDiverged;
      out.reason = "the residual grew by a factor " + Number(ratio);
      return out;
    }
    if (it == settings.max_iterations) {
      out.status = NewtonOutcome::Status::kIterationLimit;
      out.reason = "no convergence in " + std::to_string(it) +
                   " iterations (‖R‖/‖R₀‖ = " + Number(ratio) + ")";
      return out;
    }
    system.Factorize();
    const Eigen::VectorXd correction = system.dofs().Expand(system.Solve(-r));
    ApplyIncrement(correction, state);
    ++out.iterations;
    last_correction = MaxTranslation(correction);
  }
}

}  // namespace drape
