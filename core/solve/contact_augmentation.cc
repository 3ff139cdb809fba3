#include "core/solve/contact_augmentation.h"

#include <vector>

namespace drape {

Augmentation AugmentContact(SolveRun& run,
                            double lambda,
                            const StageLoading& loading,
                            ContinuationStep& step) {
  NodeContact& contact = *run.contact;
  const double allowed = run.options.penetration_tolerance * run.model.thickness;
  Augmentation out;
  for (; out.passes < run.options.max_augmentations; ++out.passes) {
    if (contact.Report(run.state).max_penetration <= allowed) return out;
    const ShellState saved = run.state;
    const std::vector<double> multipliers = contact.multipliers();
    contact.Augment(run.state);
    const NewtonOutcome newton =
        run.SolveAtFixedLambda(lambda, loading, run.options.max_augmentation_iterations);
    if (newton.status != NewtonOutcome::Status::kConverged) {
      run.state = saved;
      contact.SetMultipliers(multipliers);
      run.system->Assemble(run.state, /*with_tangent=*/false);
      out.shortfall = "augmented-Lagrangian pass " + std::to_string(out.passes + 1) +
                      " did not converge (" + newton.reason + ")";
      return out;
    }
    step.iterations += newton.iterations;
    step.residuals.insert(step.residuals.end(), newton.residuals.begin(), newton.residuals.end());
    step.convergence = newton.convergence;
    step.negative_pivots = newton.negative_pivots;
    ++run.summary.augmentations;
    run.summary.iterations += newton.iterations;
  }
  if (contact.Report(run.state).max_penetration > allowed)
    out.shortfall = "stopped after " + std::to_string(run.options.max_augmentations) +
                    " augmented-Lagrangian passes";
  return out;
}

}  // namespace drape
