// What one evaluation of a plan came to (docs/plan.md): read from its
// result folder, the objective at the final state and each constraint's
// margin over every converged step — a fold that is stable at its end but
// passed through an unstable state on the way is not feasible.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/plan/plan_file.h"

namespace drape {

// One constraint over the whole path. `margin` ≥ 0 where it holds, in its
// own unit: negative pivots (−count), metres (layers, grippers), newtons
// (force), sliding nodes (−count); +∞ where nothing came near (no layers
// met). `scale` makes it a pure number for the search (the thickness, the
// force limit, one pivot or node).
struct ConstraintMargin {
  std::string name;  // "stable", "layers", "grippers_outside", "max_gripper_force", "no_slip"
  double margin = 0;
  std::string unit;  // of margin: "pivots", "m", "N", "nodes"
  double scale = 1;
  int worst_step = 0;  // where the margin was smallest (0: none)

  // The shortfall as a pure number, 0 where it holds.
  double Violation() const;
  // −margin / scale, ≤ 0 where it holds (COBYLA's c(x) ≤ 0), −1 for +∞.
  double Value() const;
};

struct EvaluationOutcome {
  // result.json's status; "missing" without one, "unreadable" when it
  // cannot be read.
  std::string status = "missing";
  std::string message;
  // Objective terms at the final state, present when the run converged.
  std::vector<double> probe_distances;  // per objective probe [m]
  std::optional<double> flat_gap;       // [m]
  std::optional<double> path_length;    // the grippers' summed path [m]
  std::optional<double> objective;      // their weighted sum [m]
  std::vector<ConstraintMargin> constraints;
  std::optional<double> wall_s;
  // How far the run got: the stages' λ reached, summed, over the scene's
  // stage count (1: every stage completed). A failed run that got further
  // is penalised less, so the search can tell which way failures recede.
  double progress = 0;

  bool Converged() const { return status == "converged" && objective.has_value(); }
  bool Feasible() const;
};

// Reads the evaluation's result folder. Never throws: a result that cannot
// be read is an outcome saying so.
EvaluationOutcome MeasureEvaluation(const Plan& plan, const std::filesystem::path& result_dir);

// The value the search minimises [m]: the objective where feasible. An
// infeasible or failed point is put just above the worst feasible point the
// search has seen (`worst_feasible`), by a tenth of `scale` [m] per unit of
// violation plus one (a failure counts two): a model-based search then
// sees a step, not a cliff that spoils its model. Before any feasible
// point, the converged objective plus `scale` per unit of violation plus
// one, and `scale` × 10 for a run with no objective (failed, missing).
double PenalisedValue(const EvaluationOutcome& outcome,
                      double scale,
                      std::optional<double> worst_feasible = std::nullopt);

// A plan's natural length scale [m]: the diagonal of the part's outline,
// what a penalty is measured in.
double PlanScale(const Plan& plan);

}  // namespace drape
