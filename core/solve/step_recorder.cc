#include "core/solve/step_recorder.h"

#include <algorithm>

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

StepRecorder::StepRecorder(SolveSummary& summary,
                           const std::vector<StepObserver>& observers,
                           Clock::time_point start)
    : summary_(summary), observers_(observers), start_(start) {}

StepDecision StepRecorder::Record(StepState& step, const StabilityEvent* classified) {
  step.step = ++summary_.steps;
  step.elapsed_s = SecondsSince(start_);
  RecordStabilityEvent(step, classified);
  UpdateSummary(step);
  const auto observe_start = Clock::now();
  StepDecision decision = StepDecision::kContinue;
  for (const auto& observer : observers_)
    if (observer(step) == StepDecision::kStop) decision = StepDecision::kStop;
  summary_.observer_s += SecondsSince(observe_start);
  return decision;
}

void StepRecorder::RecordStabilityEvent(StepState& step, const StabilityEvent* classified) {
  // Against the unloaded start (0 negative pivots), so that a first step that
  // already lands past a buckling point is reported too.
  if (step.negative_pivots != last_negative_pivots_ || classified) {
    StabilityEvent e;
    if (classified) {
      e = *classified;
    } else {
      e.kind = StabilityKind::kBifurcation;
      e.branch = Branch::kFundamental;
      e.lambda = step.lambda;
    }
    e.stage = step.stage;
    e.step = step.step;
    e.negative_pivots_before = last_negative_pivots_;
    e.negative_pivots_after = step.negative_pivots;
    if (e.branch != Branch::kStable && e.kind != StabilityKind::kSnap)
      e.negative_pivots_fundamental = step.negative_pivots;
    summary_.stability_events.push_back(e);
    step.stability_event = e;
  }
  last_negative_pivots_ = step.negative_pivots;
}

void StepRecorder::UpdateSummary(const StepState& step) {
  summary_.max_curvature = std::max(summary_.max_curvature, step.max_curvature);
  summary_.max_law_curvature = std::max(summary_.max_law_curvature, step.law_curvature);
  if (step.contact) {
    const ContactReport& c = *step.contact;
    const bool deep = c.penetration_target > 0 && c.max_penetration > c.penetration_target;
    if (!c.augmentation_shortfall.empty() && !deep) {
      if (summary_.friction_unsettled++ == 0) {
        summary_.first_unsettled_step = step.step;
        summary_.unsettled_reason = c.augmentation_shortfall;
      }
    } else if (!c.augmentation_shortfall.empty()) {
      ++summary_.penetration_target_missed;
      if (c.max_penetration > summary_.worst_missed_penetration) {
        summary_.worst_missed_penetration = c.max_penetration;
        summary_.worst_missed_step = step.step;
        summary_.worst_missed_reason = c.augmentation_shortfall;
      }
    }
    summary_.max_penetration = std::max(summary_.max_penetration, c.max_penetration);
    summary_.max_stabilization_force =
        std::max(summary_.max_stabilization_force, c.max_stabilization_force);
  }
  if (step.layer_distance && *step.layer_distance < summary_.min_layer_distance) {
    summary_.min_layer_distance = *step.layer_distance;
    summary_.min_layer_step = step.step;
  }
}

}  // namespace drape
