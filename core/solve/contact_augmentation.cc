#include "core/solve/contact_augmentation.h"

#include <cstdio>
#include <vector>

namespace drape {
namespace {

// Friction's lag has stopped changing when no node's normal force would
// move by more than this share of the largest.
constexpr double kLagTolerance = 1e-3;

std::string Shortfall(bool deep, double lag_change, int passes) {
  char text[200];
  if (deep)
    std::snprintf(text, sizeof text, "stopped after %d augmented-Lagrangian passes", passes);
  else
    std::snprintf(text,
                  sizeof text,
                  "friction's normal forces still moved by %.2g %% after %d passes",
                  100 * lag_change,
                  passes);
  return text;
}

}  // namespace

Augmentation AugmentContact(SolveRun& run,
                            double lambda,
                            const StageLoading& loading,
                            ContinuationStep& step) {
  NodeContact& contact = *run.contact;
  const double allowed = run.options.penetration_tolerance * run.model.thickness;
  auto deep = [&] {
    return run.augment_contact && contact.Report(run.state).max_penetration > allowed;
  };
  Augmentation out;
  for (; out.passes < run.options.max_augmentations; ++out.passes) {
    const bool penetrating = deep();
    if (!penetrating && contact.FrictionLagChange(run.state) <= kLagTolerance) return out;
    const ShellState saved = run.state;
    NodeContact::Memory memory = contact.memory();
    if (penetrating) contact.Augment(run.state);
    contact.Relag(run.state);
    const NewtonOutcome newton =
        run.SolveAtFixedLambda(lambda, loading, run.options.max_augmentation_iterations);
    if (newton.status != NewtonOutcome::Status::kConverged) {
      run.state = saved;
      contact.Restore(std::move(memory));
      run.system->Assemble(run.state, /*with_tangent=*/false);
      out.shortfall = "contact pass " + std::to_string(out.passes + 1) + " did not converge (" +
                      newton.reason + ")";
      return out;
    }
    step.iterations += newton.iterations;
    step.residuals.insert(step.residuals.end(), newton.residuals.begin(), newton.residuals.end());
    step.convergence = newton.convergence;
    step.negative_pivots = newton.negative_pivots;
    ++run.summary.augmentations;
    run.summary.iterations += newton.iterations;
  }
  const bool penetrating = deep();
  const double lag_change = contact.FrictionLagChange(run.state);
  if (penetrating || lag_change > kLagTolerance)
    out.shortfall = Shortfall(penetrating, lag_change, run.options.max_augmentations);
  return out;
}

}  // namespace drape
