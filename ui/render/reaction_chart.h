// The reaction force of each gripper and support along a run (`drape render
// RESULT --plot reactions`): its magnitude |F| against the step in the
// chosen force unit, one line per hold, the stages' boundaries marked and
// named. VTK's charts, offscreen; no Qt.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/model/unit_system.h"

namespace drape {

struct ReactionSeries {
  std::string name;            // the legend's entry, e.g. "end (gripper)"
  std::vector<double> steps;   // step numbers, increasing
  std::vector<double> forces;  // |F| [N] at each step, finite and >= 0
};

// A stage's first step: a dashed line half a step before it, and the
// stage's name (the first stage of the chart is only named).
struct StageMark {
  double first_step = 0;
  std::string name;
};

struct ReactionChartOptions {
  std::string title;
  std::vector<StageMark> stages;
  int width = 1280, height = 720;
  DisplayUnit force_unit{"N", 1.0};  // the axis' unit: UnitFor(Measure::kForce, …)
};

// The line colour of series i (RGB, 0-255): the Okabe-Ito colour-blind safe
// hues, repeating after eight.
std::array<int, 3> ReactionColour(size_t i);

// Where the plot area lies in the picture: pixels from its bottom-left
// corner (as VTK and vtkPNGReader count them), x to the right, y up.
struct ChartArea {
  int left = 0, bottom = 0, right = 0, top = 0;
  double step_lo = 0, step_hi = 0;    // the step axis' range
  double force_lo = 0, force_hi = 0;  // the reaction axis' range, in force_unit
};

// Writes the chart as a PNG of options.width x options.height and returns
// its plot area. Throws std::invalid_argument, naming the series and the
// step, when a value is not finite (or a force is negative, or a series'
// steps and forces differ in length), or when there is no point at all;
// std::runtime_error when it cannot write the file.
ChartArea WriteReactionChart(const std::vector<ReactionSeries>& series,
                             const ReactionChartOptions& options,
                             const std::filesystem::path& png);

}  // namespace drape
