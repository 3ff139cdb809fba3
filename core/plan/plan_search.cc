#include "core/plan/plan_search.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>

#include "core/model/string_format.h"

namespace drape {
namespace {

// BOBYQA's first trust region, as a share of each parameter's range: wide
// enough to leave a poor start, narrow enough to stay on its branch.
constexpr double kInitialStep = 0.2;

double Halton(int index, int base) {
  double f = 1, r = 0;
  for (int i = index; i > 0; i /= base) {
    f /= base;
    r += f * (i % base);
  }
  return r;
}

struct SharedSearch {
  const Plan& plan;
  const PlanEvaluator& evaluate;
  const PlanProgress& progress;
  const PlanSearchOptions& options;
  double scale;
  std::mutex lock;
  PlanSearchSummary summary;
};

struct OneSearch {
  SharedSearch* shared = nullptr;
  int start = 0;
  int count = 0;
  std::optional<double> worst_feasible;  // this search's own, so a rerun sees the same
  nlopt::opt* opt = nullptr;
  // COBYLA asks for the objective and each constraint at the same point;
  // the last evaluation answers all of them.
  std::vector<double> last_x;
  EvaluationOutcome last;
  double last_value = 0;
  std::string error;  // why an evaluation could not be made (the search stops)
};

std::vector<double> Physical(const Plan& plan, const std::vector<double>& u) {
  std::vector<double> x(u.size());
  for (size_t i = 0; i < u.size(); ++i) {
    const PlanParameter& p = plan.parameters[i];
    x[i] = p.min + std::clamp(u[i], 0.0, 1.0) * (p.max - p.min);
  }
  return x;
}

const EvaluationOutcome& OutcomeAt(OneSearch& s, const std::vector<double>& u) {
  if (!s.last_x.empty() && s.last_x == u) return s.last;
  SharedSearch& shared = *s.shared;
  if (shared.options.stop && shared.options.stop->load()) throw nlopt::forced_stop();
  const std::vector<double> x = Physical(shared.plan, u);
  ++s.count;
  try {
    s.last = shared.evaluate(s.start, s.count, x);
  } catch (const std::exception& e) {
    // Not a failed run but no run at all (the program cannot be started):
    // every further point would be the same.
    s.error = e.what();
    throw nlopt::forced_stop();
  }
  s.last_x = u;
  PlanEvaluation e{
      s.start, s.count, x, s.last, PenalisedValue(s.last, shared.scale, s.worst_feasible)};
  s.last_value = e.value;
  if (s.last.Feasible())
    s.worst_feasible = std::max(s.worst_feasible.value_or(0.0), *s.last.objective);
  {
    std::lock_guard<std::mutex> guard(shared.lock);
    shared.summary.evaluations.push_back(e);
    if (shared.progress) shared.progress(e);
  }
  if (shared.options.stop && shared.options.stop->load()) throw nlopt::forced_stop();
  return s.last;
}

double Objective(const std::vector<double>& u, std::vector<double>&, void* data) {
  OneSearch& s = *static_cast<OneSearch*>(data);
  const EvaluationOutcome& outcome = OutcomeAt(s, u);
  if (s.shared->plan.search.algorithm == PlanAlgorithm::kCobyla && outcome.Converged())
    return *outcome.objective;  // COBYLA sees the constraints as themselves
  return s.last_value;
}

struct ConstraintData {
  OneSearch* search;
  size_t index;
};

double Constraint(const std::vector<double>& u, std::vector<double>&, void* data) {
  const ConstraintData& c = *static_cast<ConstraintData*>(data);
  const EvaluationOutcome& outcome = OutcomeAt(*c.search, u);
  if (c.index < outcome.constraints.size()) return outcome.constraints[c.index].Value();
  return 1;  // not measured (no result): not met
}

size_t ConstraintCount(const PlanConstraints& k) {
  return k.stable + k.layers + k.grippers_outside + k.max_gripper_force.has_value() +
         k.no_slip.has_value();
}

std::string ResultText(nlopt::result r) {
  switch (r) {
    case nlopt::STOPVAL_REACHED:
      return "the objective reached its target";
    case nlopt::FTOL_REACHED:
      return "the objective changed by less than the tolerance";
    case nlopt::XTOL_REACHED:
      return "the parameters changed by less than 1e-4 of their range";
    case nlopt::MAXEVAL_REACHED:
      return "the evaluations ran out";
    default:
      return "the search converged";
  }
}

void Search(SharedSearch& shared, int start, const std::vector<double>& x0, int budget) {
  const Plan& plan = shared.plan;
  const size_t n = plan.parameters.size();
  const bool cobyla = plan.search.algorithm == PlanAlgorithm::kCobyla;
  nlopt::opt opt(cobyla ? nlopt::LN_COBYLA : nlopt::LN_BOBYQA, static_cast<unsigned>(n));
  OneSearch s;
  s.shared = &shared;
  s.start = start;
  s.opt = &opt;
  opt.set_lower_bounds(std::vector<double>(n, 0.0));
  opt.set_upper_bounds(std::vector<double>(n, 1.0));
  opt.set_initial_step(kInitialStep);
  opt.set_min_objective(Objective, &s);
  std::vector<ConstraintData> constraints;
  if (cobyla) {
    constraints.reserve(ConstraintCount(plan.constraints));
    for (size_t i = 0; i < ConstraintCount(plan.constraints); ++i) {
      constraints.push_back({&s, i});
      opt.add_inequality_constraint(Constraint, &constraints.back(), 0.0);
    }
  }
  opt.set_maxeval(budget);
  opt.set_ftol_abs(plan.search.tolerance);
  opt.set_xtol_rel(1e-4);
  std::vector<double> u(n);
  for (size_t i = 0; i < n; ++i) {
    const PlanParameter& p = plan.parameters[i];
    u[i] = (x0[i] - p.min) / (p.max - p.min);
  }
  double value = 0;
  std::string reason;
  try {
    reason = ResultText(opt.optimize(u, value));
  } catch (const nlopt::forced_stop&) {
    reason = s.error.empty() ? "interrupted" : "stopped: " + s.error;
  } catch (const nlopt::roundoff_limited&) {
    reason = "the search was limited by round-off";
  } catch (const std::exception& e) {
    reason = std::string("the search failed: ") + e.what();
  }
  std::lock_guard<std::mutex> guard(shared.lock);
  if (reason == "interrupted") shared.summary.interrupted = true;
  std::string& all = shared.summary.stop_reason;
  if (all.find(reason) == std::string::npos) all += (all.empty() ? "" : "; ") + reason;
}

}  // namespace

std::vector<std::vector<double>> StartingPoints(const Plan& plan, int starts) {
  static constexpr int kPrimes[] = {2,  3,  5,  7,  11, 13, 17, 19, 23, 29,
                                    31, 37, 41, 43, 47, 53, 59, 61, 67, 71};
  std::vector<std::vector<double>> points{StartOf(plan)};
  for (int k = 1; k < starts; ++k) {
    std::vector<double> x;
    for (size_t i = 0; i < plan.parameters.size(); ++i) {
      const PlanParameter& p = plan.parameters[i];
      x.push_back(p.min + Halton(k, kPrimes[i % 20]) * (p.max - p.min));
    }
    points.push_back(std::move(x));
  }
  return points;
}

PlanSearchSummary RunPlanSearch(const Plan& plan,
                                const PlanEvaluator& evaluate,
                                const PlanProgress& progress,
                                const PlanSearchOptions& options) {
  SharedSearch shared{plan, evaluate, progress, options, PlanScale(plan), {}, {}};
  const int starts = std::max(1, options.starts);
  const auto points = StartingPoints(plan, starts);
  const int budget = std::max(1, plan.search.max_evaluations / starts);
  if (starts == 1) {
    Search(shared, 0, points[0], budget);
  } else {
    std::vector<std::thread> threads;
    for (int k = 0; k < starts; ++k)
      threads.emplace_back([&, k] { Search(shared, k, points[k], budget); });
    for (std::thread& t : threads) t.join();
  }
  PlanSearchSummary& summary = shared.summary;
  for (size_t i = 0; i < summary.evaluations.size(); ++i) {
    const PlanEvaluation& e = summary.evaluations[i];
    if (e.outcome.Feasible() &&
        (!summary.best ||
         *e.outcome.objective < *summary.evaluations[*summary.best].outcome.objective))
      summary.best = i;
    if (!summary.closest || e.value < summary.evaluations[*summary.closest].value)
      summary.closest = i;
  }
  return std::move(summary);
}

std::string InfeasibilityReport(const Plan& plan, const PlanSearchSummary& summary) {
  if (summary.best) return "";
  if (summary.evaluations.empty()) return "no evaluation ended";
  std::vector<std::string> never;
  bool converged = false;
  std::map<std::string, bool> met;
  for (const PlanEvaluation& e : summary.evaluations) {
    converged = converged || e.outcome.Converged();
    for (const ConstraintMargin& c : e.outcome.constraints)
      met[c.name] = met[c.name] || c.Violation() == 0;
  }
  std::string text;
  if (!converged) text = "no evaluation converged";
  for (const auto& [name, ok] : met)
    if (!ok) text += (text.empty() ? "" : "; ") + std::string("no evaluation met '") + name + "'";
  if (text.empty()) text = "no evaluation met every constraint at once";
  if (summary.closest) {
    const PlanEvaluation& e = summary.evaluations[*summary.closest];
    text += Format("; the closest: evaluation %d of start %d (%s), %s",
                   e.index,
                   e.start + 1,
                   DescribePoint(plan, e.x).c_str(),
                   e.outcome.status.c_str());
    for (const ConstraintMargin& c : e.outcome.constraints)
      if (c.Violation() > 0)
        text += Format(", %s short by %.3g %s at step %d",
                       c.name.c_str(),
                       -c.margin,
                       c.unit.c_str(),
                       c.worst_step);
  }
  return text;
}

}  // namespace drape
