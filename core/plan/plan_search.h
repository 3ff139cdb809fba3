// The search of a plan (docs/plan.md): NLopt's BOBYQA or COBYLA over the
// parameters scaled to [0, 1], each point evaluated by a caller-given
// function (in `drape plan` a `drape run` process). A failed or infeasible
// evaluation is a penalised point (PenalisedValue), never the end of the
// search; `--jobs N` runs N searches from N starting points side by side,
// sharing the budget of evaluations.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/plan/plan_file.h"
#include "core/plan/plan_outcome.h"

namespace drape {

struct PlanEvaluation {
  int start = 0;  // which search (0: from the plan's start)
  int index = 0;  // 1-based within its search
  std::vector<double> x;
  EvaluationOutcome outcome;
  double value = 0;  // what the search saw (PenalisedValue)
};

// Evaluates the plan at `x` (SI, the parameters' order). `start` and
// `index` name the evaluation (its folder). Called from several threads
// when there are several starts.
using PlanEvaluator =
    std::function<EvaluationOutcome(int start, int index, const std::vector<double>& x)>;
// Called after each evaluation (under a lock), in the order they end.
using PlanProgress = std::function<void(const PlanEvaluation&)>;

struct PlanSearchOptions {
  int starts = 1;
  const std::atomic<bool>* stop = nullptr;  // set: every search stops after its evaluation
};

struct PlanSearchSummary {
  std::vector<PlanEvaluation> evaluations;  // in the order they ended
  std::optional<size_t> best;               // the feasible one with the least objective
  std::optional<size_t> closest;            // without a feasible one: the least penalised
  std::string stop_reason;                  // why the searches ended, in words
  bool interrupted = false;
};

PlanSearchSummary RunPlanSearch(const Plan& plan,
                                const PlanEvaluator& evaluate,
                                const PlanProgress& progress,
                                const PlanSearchOptions& options);

// The starting points of `starts` searches: the plan's start, then points
// spread over the bounds (a Halton sequence, the same on every run so that
// a rerun resumes).
std::vector<std::vector<double>> StartingPoints(const Plan& plan, int starts);

// "no evaluation met 'stable' (every one ended with negative pivots); the
// closest: …". Empty when some evaluation was feasible.
std::string InfeasibilityReport(const Plan& plan, const PlanSearchSummary& summary);

}  // namespace drape
