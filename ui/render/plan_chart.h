// The search of a plan (plan.png, docs/plan.md): each evaluation's
// objective against its number on a log axis, the feasible ones as dots,
// the infeasible and failed ones as crosses along the top, and the best
// feasible so far as a line. VTK's charts, offscreen; no Qt.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drape {

struct PlanChartPoint {
  int evaluation = 0;               // 1, 2, … in the order they ended
  std::optional<double> objective;  // [m], > 0 or absent (failed)
  bool feasible = false;
};

struct PlanChartOptions {
  std::string title;
  int width = 1200, height = 700;
};

// The colours (RGB 0-255) of feasible dots, crosses and the best line.
inline constexpr int kPlanFeasibleColour[3] = {0, 114, 178};
inline constexpr int kPlanInfeasibleColour[3] = {213, 94, 0};
inline constexpr int kPlanBestColour[3] = {0, 158, 115};

// Writes the chart as a PNG. Throws std::invalid_argument when there is no
// evaluation, std::runtime_error when it cannot draw or write.
void WritePlanChart(const std::vector<PlanChartPoint>& points,
                    const PlanChartOptions& options,
                    const std::filesystem::path& png);

}  // namespace drape
