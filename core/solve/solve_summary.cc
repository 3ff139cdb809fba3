#include "core/solve/solve_summary.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace drape {
namespace {

const char* SnapPlace(SnapTrigger trigger) {
  switch (trigger) {
    case SnapTrigger::kStart:
      return "stage's start";
    case SnapTrigger::kLimit:
      return "limit point";
    case SnapTrigger::kBifurcation:
      return "bifurcation";
    case SnapTrigger::kSliding:
      return "state where every node in contact slid, held only by the stabilisation springs";
    case SnapTrigger::kRelease:
      return "release";
    case SnapTrigger::kStalled:
      return "point where its path stalled";
  }
  return "?";
}

}  // namespace

const char* ToString(Termination t) {
  switch (t) {
    case Termination::kNotRun:
      return "not run";
    case Termination::kCompleted:
      return "converged";
    case Termination::kStepTooSmall:
      return "step too small";
    case Termination::kMaxStepsReached:
      return "maximum steps reached";
    case Termination::kCancelled:
      return "cancelled";
    case Termination::kStoppedByObserver:
      return "stopped by observer";
    case Termination::kInvalidInput:
      return "invalid input";
    case Termination::kIllPosed:
      return "ill-posed stage";
    case Termination::kNumericalFailure:
      return "numerical failure";
    case Termination::kNoStableBranch:
      return "no branch past a bifurcation";
    case Termination::kUnheld:
      return "nothing holds the part";
    case Termination::kTimeLimit:
      return "time limit";
  }
  return "?";
}

std::string Describe(const StabilityEvent& e) {
  char line[320];
  if (e.kind == StabilityKind::kSnap) {
    std::snprintf(line,
                  sizeof line,
                  "snap at stage %d step %d, lambda %.6g: at a %s (negative pivots %d -> %d) the "
                  "part jumped to a stable rest state, releasing %.3g J, largest displacement "
                  "%.3g m; %d iterations, %.3f s",
                  e.stage,
                  e.step,
                  e.lambda,
                  SnapPlace(e.trigger),
                  e.negative_pivots_before,
                  e.negative_pivots_fundamental,
                  e.energy_released,
                  e.mode_max_displacement,
                  e.switch_iterations,
                  e.switch_s);
  } else if (e.kind == StabilityKind::kLimit || e.branch == Branch::kNone) {
    std::snprintf(line,
                  sizeof line,
                  "%s point at stage %d step %d, lambda %.6g: negative pivots %d -> %d",
                  ToString(e.kind),
                  e.stage,
                  e.step,
                  e.lambda,
                  e.negative_pivots_before,
                  e.negative_pivots_after);
  } else if (e.branch == Branch::kFundamental) {
    std::snprintf(line,
                  sizeof line,
                  "bifurcation at stage %d step %d, lambda %.6g: negative pivots %d -> %d, "
                  "followed the fundamental path%s",
                  e.stage,
                  e.step,
                  e.lambda,
                  e.negative_pivots_before,
                  e.negative_pivots_after,
                  e.negative_pivots_after > e.negative_pivots_before ? " (unstable past it)" : "");
  } else {
    std::snprintf(line,
                  sizeof line,
                  "bifurcation at stage %d, lambda %.6g: negative pivots %d -> %d on the primary "
                  "path; switched to the %s branch (%d negative, step %d) along %d mode%s, "
                  "largest displacement %.3g m; %d iterations, %.3f s",
                  e.stage,
                  e.lambda,
                  e.negative_pivots_before,
                  e.negative_pivots_fundamental,
                  ToString(e.branch),
                  e.negative_pivots_after,
                  e.step,
                  e.modes,
                  e.modes == 1 ? "" : "s",
                  e.mode_max_displacement,
                  e.switch_iterations,
                  e.switch_s);
  }
  return line;
}

std::string SolveSummary::BriefReport() const {
  char line[256];
  // "Converged" alone is a state a real part can rest in.
  std::string headline = ToString(termination);
  if (IsComplete() && final_negative_pivots > 0)
    headline += " to an unstable equilibrium (" + std::to_string(final_negative_pivots) +
                " negative pivot" + (final_negative_pivots == 1 ? ")" : "s)");
  std::snprintf(line,
                sizeof line,
                "%s: %d steps, %d iterations, %d cut-backs, %.3f s",
                headline.c_str(),
                steps,
                iterations,
                step_cuts,
                total_s);
  std::string out = line;
  int limits = 0, switched = 0, followed = 0, snaps = 0;
  for (const auto& e : stability_events) {
    if (e.kind == StabilityKind::kLimit) ++limits;
    if (e.kind == StabilityKind::kSnap) ++snaps;
    if (e.kind == StabilityKind::kBifurcation && e.branch == Branch::kStable) ++switched;
    if (e.kind == StabilityKind::kBifurcation && e.branch == Branch::kFundamental &&
        e.negative_pivots_after > e.negative_pivots_before)
      ++followed;
  }
  auto count = [&](int n, const char* one, const char* many) {
    if (n == 0) return;
    std::snprintf(line, sizeof line, ", %d %s", n, n == 1 ? one : many);
    out += line;
  };
  count(limits, "limit point", "limit points");
  count(snaps, "snap", "snaps");
  count(switched, "bifurcation onto a stable branch", "bifurcations onto stable branches");
  count(followed,
        "bifurcation followed on the unstable primary path",
        "bifurcations followed on the unstable primary path");
  if (std::isfinite(bending_valid_to)) {
    std::snprintf(line,
                  sizeof line,
                  ", largest curvature %.3g 1/cm (law valid to %.3g 1/cm)",
                  max_law_curvature / 100,
                  bending_valid_to / 100);
    out += line;
  }
  if (!IsComplete()) out += " — " + message;
  return out;
}

std::string SolveSummary::FullReport() const {
  std::ostringstream s;
  char row[256];
  s << "Drape solve report\n";
  std::snprintf(row,
                sizeof row,
                "  nodes %d, elements %d, DOFs %d (free %d), threads %d\n",
                nodes,
                elements,
                dofs,
                free_dofs,
                threads_used);
  s << row;
  s << "  stage            kind     control     steps  iters  cuts   final λ   time [s]\n";
  for (const auto& st : stages) {
    std::snprintf(row,
                  sizeof row,
                  "  %-16s %-8s %-11s %5d %6d %5d %9.6f %10.3f\n",
                  st.name.c_str(),
                  ToString(st.kind),
                  ToString(st.control_used),
                  st.steps,
                  st.iterations,
                  st.step_cuts,
                  st.final_lambda,
                  st.time_s);
    s << row;
  }
  for (const auto& e : stability_events) s << "  " << Describe(e) << "\n";
  std::snprintf(row,
                sizeof row,
                "  time: total %.3f s, assembly %.3f s, factorisation %.3f s (%d, %d indefinite, "
                "%d reused), solve %.3f s, observers %.3f s\n",
                total_s,
                assembly_s,
                factorization_s,
                factorizations,
                indefinite_factorizations,
                reused_factorizations,
                solve_s,
                observer_s);
  s << row;
  if (contact_penalty > 0) {
    std::snprintf(row,
                  sizeof row,
                  "  contact: penalty %.4g N/m^3, largest penetration %.4g m",
                  contact_penalty,
                  max_penetration);
    s << row;
    if (max_stabilization_force > 0) {
      std::snprintf(
          row, sizeof row, ", largest stabilisation force %.3g N", max_stabilization_force);
      s << row;
    }
    s << "\n";
  }
  if (std::isfinite(bending_valid_to)) {
    std::snprintf(
        row,
        sizeof row,
        "  bending: largest curvature the laws were evaluated at %.4g 1/cm (largest "
        "principal %.4g 1/cm), their valid range to %.4g 1/cm%s\n",
        max_law_curvature / 100,
        max_curvature / 100,
        bending_valid_to / 100,
        max_law_curvature > bending_valid_to ? " (exceeded: the law was extrapolated)" : "");
    s << row;
  }
  for (const auto& warning : warnings) s << "  warning: " << warning << "\n";
  for (const auto& note : notes) s << "  note: " << note << "\n";
  s << "  termination: " << ToString(termination) << " — " << message << "\n";
  return s.str();
}

}  // namespace drape
