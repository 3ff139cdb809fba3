// The record of a run's converged steps, apart from the stepping: numbers
// each step, keeps the summary's running figures (curvature, penetration,
// layers, stability events), and hands the step to the observers.
#pragma once

#include <chrono>
#include <vector>

#include "core/solve/solve_summary.h"
#include "core/solve/step_state.h"

namespace drape {

class StepRecorder {
 public:
  // `summary` and `observers` must outlive the recorder.
  StepRecorder(SolveSummary& summary,
               const std::vector<StepObserver>& observers,
               std::chrono::steady_clock::time_point start);

  // The number the next recorded step will have (1-based over the run).
  int NextStep() const { return summary_.steps + 1; }
  // Negative pivots of the last recorded step's tangent (0 before the first:
  // the unloaded start is stable).
  int last_negative_pivots() const { return last_negative_pivots_; }

  // Numbers `step`, records in it and in the summary a change of the
  // negative pivots (`classified` says what it was; null: a change at fixed
  // λ or under load control, kept as a bifurcation followed on the primary
  // path; non-null is recorded even without a change, as a switch onto a
  // stable branch keeps the count), updates the summary and calls every
  // observer. kStop when an observer asked for it.
  StepDecision Record(StepState& step, const StabilityEvent* classified);

 private:
  void RecordStabilityEvent(StepState& step, const StabilityEvent* classified);
  void UpdateSummary(const StepState& step);

  SolveSummary& summary_;
  const std::vector<StepObserver>& observers_;
  std::chrono::steady_clock::time_point start_;
  int last_negative_pivots_ = 0;
};

}  // namespace drape
