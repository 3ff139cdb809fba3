#include "core/continuation/branch_switch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/linalg/critical_modes.h"

namespace drape {
namespace {

bool Cancelled(const ContinuationStep& step) {
  return step.status == NewtonOutcome::Status::kCancelled;
}

double LargestTranslation(const ShellState& from, const ShellState& to) {
  return (to.positions - from.positions).rowwise().norm().maxCoeff();
}

// What trying the critical modes' branches found.
struct BranchSearch {
  std::optional<PathPoint> best;  // the stable branch point taken
  int unstable = 0;               // branches found whose tangent is not definite either
  std::string last_failure = "no mode to switch along";
  int iterations = 0;
  bool cancelled = false;
};

// Steps from `at` along each mode in turn, both signs, until one gives a
// stable branch. An imperfection in the scene decides the sign; without one
// both are tried and the stable branch that goes on furthest in λ is taken
// (the other may bend back, towards where the part came from).
BranchSearch SearchBranches(ArcLengthStepper& stepper,
                            const PathPoint& at,
                            const std::vector<CriticalMode>& modes,
                            int pivots_before,
                            const BifurcationSettings& settings,
                            const CancellationToken* cancel) {
  BranchSearch out;
  for (const CriticalMode& mode : modes) {
    const bool imperfect = settings.imperfection.size() == mode.shape.size() &&
                           mode.shape.dot(settings.imperfection) != 0;
    const double first_sign = imperfect && mode.shape.dot(settings.imperfection) < 0 ? -1 : 1;
    for (double sign : {first_sign, -first_sign}) {
      PathPoint trial{at.state, at.lambda, {}};
      trial.step = stepper.StepAlong(trial.state,
                                     at.lambda,
                                     mode.shape,
                                     sign * settings.amplitude,
                                     settings.rotation_length,
                                     cancel);
      out.iterations += trial.step.iterations;
      if (Cancelled(trial.step)) {
        out.cancelled = true;
        return out;
      }
      if (trial.step.status != NewtonOutcome::Status::kConverged) {
        out.last_failure = trial.step.reason;
        continue;
      }
      trial.lambda = trial.step.lambda;
      if (trial.step.negative_pivots > pivots_before) {
        ++out.unstable;
        out.last_failure = "the branch along it has " + std::to_string(trial.step.negative_pivots) +
                           " negative pivot(s) too";
        continue;
      }
      if (!out.best || trial.lambda > out.best->lambda) out.best = std::move(trial);
      if (imperfect) break;
    }
    if (out.best) break;  // the mode nearest zero that has a stable branch
  }
  return out;
}

}  // namespace

CrossingBracket LocateCrossing(ArcLengthStepper& stepper,
                               const PathPoint& start,
                               const PathDirection* previous,
                               const PathPoint& crossing,
                               int pivots_before,
                               const BifurcationSettings& settings,
                               const CancellationToken* cancel) {
  CrossingBracket b{start, crossing, 0.0, crossing.step.arc_length};
  auto located = [&] {
    return b.hi_s - b.lo_s <= settings.locate_fraction * (settings.path_before + b.lo_s);
  };
  for (int k = 0; k < settings.max_bisections && !located(); ++k) {
    const double mid = 0.5 * (b.lo_s + b.hi_s);
    PathPoint trial{start.state, start.lambda, {}};
    trial.step = stepper.Step(
        trial.state, {.lambda = start.lambda, .arc_length = mid, .previous = previous}, cancel);
    b.iterations += trial.step.iterations;
    if (Cancelled(trial.step)) {
      b.cancelled = true;
      return b;
    }
    if (trial.step.status != NewtonOutcome::Status::kConverged) break;  // keep what we have
    trial.lambda = trial.step.landed ? 1.0 : trial.step.lambda;
    if (trial.step.negative_pivots > pivots_before) {
      b.hi = std::move(trial);
      b.hi_s = mid;
    } else {
      b.lo = std::move(trial);
      b.lo_s = mid;
    }
  }
  return b;
}

BranchSwitch SwitchBranch(ArcLengthStepper& stepper,
                          EquilibriumSystem& system,
                          const PathPoint& start,
                          const PathDirection* previous,
                          const PathPoint& crossing,
                          int pivots_before,
                          const BifurcationSettings& settings,
                          const CancellationToken* cancel) {
  const auto clock_start = std::chrono::steady_clock::now();
  BranchSwitch out;
  auto finish = [&](BranchSwitch& o) -> BranchSwitch& {
    o.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return o;
  };

  const CrossingBracket b =
      LocateCrossing(stepper, start, previous, crossing, pivots_before, settings, cancel);
  out.iterations += b.iterations;
  if (b.cancelled) {
    out.cancelled = true;
    out.failure = "cancelled";
    return finish(out);
  }
  out.lambda = 0.5 * (b.lo.lambda + b.hi.lambda);
  out.negative_pivots_fundamental = b.hi.step.negative_pivots;
  if (b.lo_s > 0) out.bifurcation = b.lo;
  out.past = b.hi;

  // The critical modes from the tangent just past the point.
  system.Assemble(b.hi.state, /*with_tangent=*/true);
  const int past = system.Factorize().negative_pivots;
  const int count = std::clamp(past - pivots_before, 1, 4);
  std::vector<CriticalMode> modes;
  try {
    modes = CriticalModes(LastFactorizedTangent(system), count);
  } catch (const std::exception& e) {
    out.failure = e.what();
    return finish(out);
  }
  out.modes = static_cast<int>(modes.size());
  if (!modes.empty()) out.mode = modes.front().shape;

  BranchSearch search = SearchBranches(stepper, b.lo, modes, pivots_before, settings, cancel);
  out.iterations += search.iterations;
  if (search.cancelled) {
    out.cancelled = true;
    out.failure = "cancelled";
    return finish(out);
  }
  std::optional<PathPoint>& best = search.best;
  const int unstable = search.unstable;
  const std::string& last_failure = search.last_failure;
  if (best) {
    out.switched = true;
    out.kind = Branch::kStable;
    out.max_displacement = LargestTranslation(b.lo.state, best->state);
    out.branch = std::move(*best);
    return finish(out);
  }
  // A subcritical bifurcation: every branch from the point is unstable; a
  // real part leaves it dynamically (it snaps), which a static path cannot
  // follow.
  out.failure = unstable > 0 ? "no stable branch along " + std::to_string(modes.size()) +
                                   " critical mode(s), either sign (" + std::to_string(unstable) +
                                   " unstable ones found: the part would snap)"
                             : "no secondary branch along " + std::to_string(modes.size()) +
                                   " critical mode(s), either sign: " + last_failure;
  return finish(out);
}

}  // namespace drape
