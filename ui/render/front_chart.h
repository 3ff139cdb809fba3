// The speed–accuracy front of a study (front.png): each run's time against
// its error, on log axes, each point labelled, the runs no other run beats
// on both drawn larger and joined. VTK's charts, offscreen; no Qt.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace drape {

struct FrontPoint {
  std::string label;  // e.g. "run_003 [20,2] 1e-05"
  double time_s = 0;  // > 0
  double error = 0;   // > 0, in `error_unit`
  bool on_front = false;
};

struct FrontChartOptions {
  std::string title;
  std::string error_axis = "largest nodal error (m)";
  int width = 1200, height = 800;
};

// Writes the chart as a PNG. Throws std::invalid_argument when no point has
// a positive time and error, std::runtime_error when it cannot draw or write.
void WriteFrontChart(const std::vector<FrontPoint>& points,
                     const FrontChartOptions& options,
                     const std::filesystem::path& png);

}  // namespace drape
