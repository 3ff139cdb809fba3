// What the offscreen charts (study fronts, reaction charts) share: a VTK
// context view of a given size with one titled XY chart, drawn without a
// window, and its PNG.
#pragma once

#include <vtkChartXY.h>
#include <vtkContextView.h>
#include <vtkNew.h>

#include <filesystem>
#include <string>

namespace drape {

struct OffscreenChart {
  vtkNew<vtkContextView> view;
  vtkNew<vtkChartXY> chart;

  // White, no multisampling (slow under Xvfb's software GL), `title` at 18 pt.
  OffscreenChart(int width, int height, const std::string& title);

  // The bottom and left axes' titles at 15 pt, their numbers at 13 pt.
  void StyleAxes();
  // Draws the chart and writes it; throws std::runtime_error naming `png`
  // when the file is not there afterwards.
  void Render();
  void WritePng(const std::filesystem::path& png);
};

}  // namespace drape
