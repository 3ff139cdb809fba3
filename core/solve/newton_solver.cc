#include "core/solve/newton_solver.h"

#include <algorithm>
#include <cmath>

namespace drape {

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
    if (settings.Converged(out.residuals, norm, last_correction)) {
      out.status = NewtonOutcome::Status::kConverged;
      // The stability indicator belongs to the converged state, whose tangent
      // was just assembled.
      out.negative_pivots = system.Factorize().negative_pivots;
      return out;
    }
    if (ratio > settings.divergence_ratio) {
      out.status = NewtonOutcome::Status::kDiverged;
      out.reason = "the residual grew by a factor " + std::to_string(ratio);
      return out;
    }
    if (it == settings.max_iterations) {
      out.status = NewtonOutcome::Status::kIterationLimit;
      out.reason = "no convergence in " + std::to_string(it) +
                   " iterations (‖R‖/‖R₀‖ = " + std::to_string(ratio) + ")";
      return out;
    }
    system.Factorize();
    const Eigen::VectorXd correction = system.dofs().Expand(system.Solve(-r));
    ApplyIncrement(correction, state);
    ++out.iterations;
    last_correction = 0;
    for (int i = 0; i < state.NodeCount(); ++i)
      last_correction =
          std::max(last_correction, correction.segment<3>(kDofsPerNode * i).cwiseAbs().maxCoeff());
  }
}

}  // namespace drape
