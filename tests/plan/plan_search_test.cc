// The search of a plan (core/plan/plan_search.h) on evaluators whose answer
// is known: a distance with its minimum at a chosen point, a region where
// every run fails, a constraint never met, a stop asked for mid-search.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/plan/plan_file.h"
#include "core/plan/plan_outcome.h"
#include "core/plan/plan_search.h"
#include "support/test_paths.h"

namespace drape {
namespace {

// The shipped recovery plan: two parameters, a centre in [−5, 5] cm and an
// angle in [140, 200], started at (3 cm, 160).
Plan RecoveryPlan(PlanAlgorithm algorithm) {
  Plan plan = ReadPlan(test::SourceDir() / "resources/plans/strip-fold-recovery.json");
  plan.search.algorithm = algorithm;
  return plan;
}

// A converged, stable run whose objective is the distance from (c*, θ*),
// the angle weighted to metres by the 10 cm radius (the arc length it
// moves the end by).
EvaluationOutcome DistanceFrom(double c, double theta, const std::vector<double>& x) {
  EvaluationOutcome out;
  out.status = "converged";
  const double d = std::hypot(x[0] - c, 0.1 * (x[1] - theta) * M_PI / 180);
  out.probe_distances = {d};
  out.objective = d;
  out.constraints = {{"stable", 0, "pivots", 1, 0}};
  return out;
}

TEST(PlanSearch, BothAlgorithmsFindAKnownMinimum) {
  for (PlanAlgorithm algorithm : {PlanAlgorithm::kBobyqa, PlanAlgorithm::kCobyla}) {
    const Plan plan = RecoveryPlan(algorithm);
    const PlanSearchSummary summary = RunPlanSearch(
        plan,
        [](int, int, const std::vector<double>& x) { return DistanceFrom(-0.012, 177.0, x); },
        nullptr,
        {});
    ASSERT_TRUE(summary.best);
    const PlanEvaluation& best = summary.evaluations[*summary.best];
    EXPECT_LT(*best.outcome.objective, 2e-4) << summary.stop_reason;
    EXPECT_NEAR(best.x[0], -0.012, 2e-4);
    EXPECT_NEAR(best.x[1], 177.0, 0.2);
    EXPECT_LE(summary.evaluations.size(), 60u);
    EXPECT_FALSE(summary.interrupted);
    EXPECT_TRUE(InfeasibilityReport(plan, summary).empty());
  }
}

// Every point with an angle past 185 fails; the search goes on, a failure
// is never the best, and its value is the penalty the header promises.
TEST(PlanSearch, AFailedEvaluationIsPenalisedAndTheSearchGoesOn) {
  const Plan plan = RecoveryPlan(PlanAlgorithm::kBobyqa);
  const double scale = PlanScale(plan);
  EXPECT_NEAR(scale, std::hypot(0.2, 0.02), 1e-15);  // the 20 × 2 cm strip's diagonal
  const PlanSearchSummary summary = RunPlanSearch(plan,
                                                  [](int, int, const std::vector<double>& x) {
                                                    if (x[1] > 185) {
                                                      EvaluationOutcome failed;
                                                      failed.status = "failed";
                                                      return failed;
                                                    }
                                                    return DistanceFrom(0.0, 184.0, x);
                                                  },
                                                  nullptr,
                                                  {});
  int failures = 0;
  std::optional<double> worst;
  for (const PlanEvaluation& e : summary.evaluations) {
    if (e.outcome.status == "failed") {
      ++failures;
      // Above the worst feasible point seen before it, by 0.1 × scale × (1 + 2).
      ASSERT_TRUE(worst);
      EXPECT_NEAR(e.value, *worst + 0.3 * scale, 1e-12);
    } else {
      EXPECT_EQ(e.value, *e.outcome.objective);
      worst = std::max(worst.value_or(0.0), *e.outcome.objective);
    }
  }
  EXPECT_GT(failures, 0);
  ASSERT_TRUE(summary.best);
  const PlanEvaluation& best = summary.evaluations[*summary.best];
  EXPECT_EQ(best.outcome.status, "converged");
  EXPECT_LT(*best.outcome.objective, 1e-3);
}

TEST(PlanSearch, PenaltiesBeforeAnyFeasiblePoint) {
  EvaluationOutcome failed;
  failed.status = "failed";
  EXPECT_EQ(PenalisedValue(failed, 0.2), 2.0);
  failed.progress = 0.75;  // three of four stages done: a quarter unfinished
  EXPECT_NEAR(PenalisedValue(failed, 0.2), 0.2 * (2 + 8 * 0.25), 1e-15);
  EXPECT_NEAR(PenalisedValue(failed, 0.2, 0.05), 0.05 + 0.02 * (1 + 2 * 0.25), 1e-15);
  failed.progress = 0;
  EvaluationOutcome unstable = DistanceFrom(0, 180, {0.01, 180});
  unstable.constraints[0].margin = -2;  // two negative pivots
  EXPECT_FALSE(unstable.Feasible());
  EXPECT_NEAR(PenalisedValue(unstable, 0.2), 0.01 + 0.2 * 3, 1e-15);
  EXPECT_NEAR(PenalisedValue(unstable, 0.2, 0.05), 0.05 + 0.02 * 3, 1e-15);
}

TEST(PlanSearch, BoundsThatAllowNoFeasiblePathSayWhichConstraintAndTheClosest) {
  const Plan plan = RecoveryPlan(PlanAlgorithm::kCobyla);
  const PlanSearchSummary summary = RunPlanSearch(
      plan,
      [](int, int, const std::vector<double>& x) {
        EvaluationOutcome out = DistanceFrom(0, 180, x);
        out.constraints[0].margin = -std::ceil(std::abs(x[0]) * 100);  // pivots grow off-centre
        out.constraints[0].worst_step = 12;
        if (out.constraints[0].margin == 0) out.constraints[0].margin = -1;
        return out;
      },
      nullptr,
      {});
  EXPECT_FALSE(summary.best);
  ASSERT_TRUE(summary.closest);
  const std::string report = InfeasibilityReport(plan, summary);
  EXPECT_NE(report.find("no evaluation met 'stable'"), std::string::npos) << report;
  EXPECT_NE(report.find("the closest: evaluation "), std::string::npos) << report;
  EXPECT_NE(report.find("stable short by 1 pivots at step 12"), std::string::npos) << report;
}

TEST(PlanSearch, AStopEndsEverySearchAfterItsEvaluation) {
  const Plan plan = RecoveryPlan(PlanAlgorithm::kBobyqa);
  std::atomic<bool> stop{false};
  PlanSearchOptions options;
  options.stop = &stop;
  options.starts = 2;
  std::atomic<int> calls{0};
  const PlanSearchSummary summary = RunPlanSearch(
      plan,
      [&](int, int, const std::vector<double>& x) {
        if (++calls == 3) stop = true;
        return DistanceFrom(0, 180, x);
      },
      nullptr,
      options);
  EXPECT_TRUE(summary.interrupted);
  // The two searches each finish the evaluation they were in.
  EXPECT_GE(summary.evaluations.size(), 3u);
  EXPECT_LE(summary.evaluations.size(), 4u);
}

// No run at all (the program cannot be started) is not a failed run: the
// search stops and says why.
TEST(PlanSearch, AnEvaluationThatCannotBeMadeStopsTheSearchSayingWhy) {
  const Plan plan = RecoveryPlan(PlanAlgorithm::kCobyla);
  int calls = 0;
  const PlanSearchSummary summary =
      RunPlanSearch(plan,
                    [&](int, int, const std::vector<double>& x) {
                      if (++calls == 3) throw std::runtime_error("cannot start /nowhere/drape");
                      return DistanceFrom(0, 180, x);
                    },
                    nullptr,
                    {});
  EXPECT_EQ(summary.evaluations.size(), 2u);
  EXPECT_EQ(summary.stop_reason, "stopped: cannot start /nowhere/drape");
  EXPECT_FALSE(summary.interrupted);
}

TEST(PlanSearch, StartingPointsBeginAtThePlansStartAndStayInBounds) {
  const Plan plan = RecoveryPlan(PlanAlgorithm::kBobyqa);
  const auto points = StartingPoints(plan, 4);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[0], StartOf(plan));
  // Halton: base 2 for the first key, base 3 for the second.
  EXPECT_NEAR(points[1][0], -0.05 + 0.5 * 0.1, 1e-15);
  EXPECT_NEAR(points[1][1], 140 + 60.0 / 3, 1e-12);
  EXPECT_NEAR(points[3][0], -0.05 + 0.75 * 0.1, 1e-15);
  EXPECT_NEAR(points[3][1], 140 + 60.0 / 9, 1e-12);
  EXPECT_EQ(StartingPoints(plan, 4), points);
}

}  // namespace
}  // namespace drape
