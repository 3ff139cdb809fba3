#include "ui/render/plan_chart.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "ui/render/offscreen_chart.h"

namespace drape {
namespace {

vtkSmartPointer<vtkTable> TableOf(const std::vector<double>& x, const std::vector<double>& y) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkFloatArray> xs, ys;
  xs->SetName("evaluation");
  ys->SetName("log10 objective");
  for (size_t i = 0; i < x.size(); ++i) {
    xs->InsertNextValue(static_cast<float>(x[i]));
    ys->InsertNextValue(static_cast<float>(y[i]));
  }
  table->AddColumn(xs);
  table->AddColumn(ys);
  return table;
}

// Millimetres on a log axis: a tick per decade, labelled as a person writes
// it ("0.01 mm", "10 mm").
void MillimetreDecades(vtkAxis* axis, int first, int last) {
  vtkNew<vtkDoubleArray> positions;
  vtkNew<vtkStringArray> labels;
  for (int k = first; k <= last; ++k) {
    positions->InsertNextValue(k);
    char text[32];
    std::snprintf(text, sizeof text, "%g mm", std::pow(10.0, k));
    labels->InsertNextValue(text);
  }
  axis->SetCustomTickPositions(positions, labels);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(first, last);
}

void AddPoints(vtkChartXY* chart,
               const std::vector<double>& x,
               const std::vector<double>& y,
               const int (&colour)[3],
               int marker,
               const std::string& label) {
  if (x.empty()) return;
  auto points = vtkSmartPointer<vtkPlotPoints>::New();
  points->SetInputData(TableOf(x, y), 0, 1);
  points->SetColor(colour[0], colour[1], colour[2], 255);
  points->SetMarkerStyle(marker);
  points->SetMarkerSize(9);
  points->SetLabel(label);
  chart->AddPlot(points);
}

}  // namespace

void WritePlanChart(const std::vector<PlanChartPoint>& points,
                    const PlanChartOptions& options,
                    const std::filesystem::path& png) {
  if (points.empty()) throw std::invalid_argument("no evaluation to draw");
  double lo = INFINITY, hi = -INFINITY;
  for (const PlanChartPoint& p : points)
    if (p.objective && *p.objective > 0) {
      lo = std::min(lo, std::log10(*p.objective * 1e3));
      hi = std::max(hi, std::log10(*p.objective * 1e3));
    }
  if (!(lo <= hi)) lo = hi = 0;
  const int first = static_cast<int>(std::floor(lo)), top = static_cast<int>(std::ceil(hi)) + 1;
  // Crosses along the top: no objective, or one a constraint forbids.
  const double ceiling = top - 0.25;
  std::vector<double> fx, fy, ix, iy, bx, by;
  double best = INFINITY;
  for (const PlanChartPoint& p : points) {
    const double y = p.objective && *p.objective > 0 ? std::log10(*p.objective * 1e3) : ceiling;
    if (p.feasible && p.objective && *p.objective > 0) {
      fx.push_back(p.evaluation);
      fy.push_back(y);
      best = std::min(best, y);
    } else {
      ix.push_back(p.evaluation);
      iy.push_back(p.feasible ? y : ceiling);
    }
    if (std::isfinite(best)) {
      bx.push_back(p.evaluation);
      by.push_back(best);
    }
  }
  OffscreenChart drawing(options.width, options.height, options.title);
  vtkChartXY* chart = drawing.chart.GetPointer();
  if (!bx.empty()) {
    auto line = vtkSmartPointer<vtkPlotLine>::New();
    line->SetInputData(TableOf(bx, by), 0, 1);
    line->SetColor(kPlanBestColour[0], kPlanBestColour[1], kPlanBestColour[2], 255);
    line->SetWidth(3);
    line->SetLabel("best feasible so far");
    chart->AddPlot(line);
  }
  AddPoints(chart, fx, fy, kPlanFeasibleColour, vtkPlotPoints::CIRCLE, "feasible");
  AddPoints(chart,
            ix,
            iy,
            kPlanInfeasibleColour,
            vtkPlotPoints::CROSS,
            "failed or infeasible (drawn at the top)");
  chart->SetShowLegend(true);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  x->SetTitle("evaluation");
  y->SetTitle("objective");
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(0.5, points.back().evaluation + 0.5);
  MillimetreDecades(y, first, top);
  drawing.StyleAxes();
  drawing.Render();
  drawing.WritePng(png);
}

}  // namespace drape
