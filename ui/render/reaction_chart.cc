#include "ui/render/reaction_chart.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTransform2D.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "ui/render/offscreen_chart.h"

namespace drape {
namespace {

// The stages' boundaries: a dashed vertical line across the plot at each
// stage's start, and the stage's name beside it at the top. Painted in data
// coordinates (the chart's transform), the names in pixels; no legend entry.
class StageMarks : public vtkPlotPoints {
 public:
  static StageMarks* New();
  vtkTypeMacro(StageMarks, vtkPlotPoints);

  void Set(std::vector<StageMark> marks, double x_lo, double y_lo, double y_hi) {
    marks_ = std::move(marks);
    x_lo_ = x_lo;
    y_lo_ = y_lo;
    y_hi_ = y_hi;
  }

  bool Paint(vtkContext2D* painter) override {
    vtkNew<vtkTransform2D> identity;
    std::vector<std::array<float, 2>> tops;
    painter->GetPen()->SetColor(140, 140, 140);
    painter->GetPen()->SetWidth(1);
    painter->GetPen()->SetLineType(vtkPen::DASH_LINE);
    for (size_t i = 0; i < marks_.size(); ++i) {
      const float x = static_cast<float>(marks_[i].first_step - 0.5);
      if (i > 0 && x > x_lo_)
        painter->DrawLine(x, static_cast<float>(y_lo_), x, static_cast<float>(y_hi_));
      const float in[2] = {std::max(x, static_cast<float>(x_lo_)), static_cast<float>(y_hi_)};
      float out[2];
      painter->GetTransform()->TransformPoints(in, out, 1);
      tops.push_back({out[0], out[1]});
    }
    painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
    vtkNew<vtkTextProperty> text;
    text->SetFontSize(13);
    text->SetColor(0.3, 0.3, 0.3);
    text->SetJustificationToLeft();
    text->SetVerticalJustificationToTop();
    painter->PushMatrix();
    painter->SetTransform(identity);
    painter->ApplyTextProp(text);
    // A name that would run into the one before it goes a line lower.
    constexpr float kCharWidth = 7.5f, kLineHeight = 16;
    float previous_end = -1e30f;
    int line = 0;
    for (size_t i = 0; i < marks_.size(); ++i) {
      const float x = tops[i][0] + 4;
      line = x < previous_end + 6 ? line + 1 : 0;
      painter->DrawString(x, tops[i][1] - 4 - line * kLineHeight, marks_[i].name.c_str());
      previous_end = std::max(previous_end, x + kCharWidth * marks_[i].name.size());
    }
    painter->PopMatrix();
    return true;
  }

 private:
  std::vector<StageMark> marks_;
  double x_lo_ = 0, y_lo_ = 0, y_hi_ = 1;
};
vtkStandardNewMacro(StageMarks);

vtkSmartPointer<vtkTable> TableOf(const std::vector<double>& x, const std::vector<double>& y) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> xs, ys;
  xs->SetName("step");
  ys->SetName("reaction");
  for (size_t i = 0; i < x.size(); ++i) {
    xs->InsertNextValue(x[i]);
    ys->InsertNextValue(y[i]);
  }
  table->AddColumn(xs);
  table->AddColumn(ys);
  return table;
}

std::string Number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// The steps' and the forces' extent over every series; throws
// std::invalid_argument naming the series and the step when a value is not
// finite, a force is negative, or a series' steps and forces differ in length.
struct Extent {
  double x_lo = 1e300, x_hi = -1e300, y_hi = 0;
};

Extent CheckedExtent(const std::vector<ReactionSeries>& series) {
  Extent e;
  for (const ReactionSeries& s : series) {
    if (s.steps.size() != s.forces.size())
      throw std::invalid_argument("reactions of '" + s.name +
                                  "': " + std::to_string(s.steps.size()) + " steps but " +
                                  std::to_string(s.forces.size()) + " forces");
    for (size_t i = 0; i < s.steps.size(); ++i) {
      if (!std::isfinite(s.steps[i]))
        throw std::invalid_argument("reactions of '" + s.name + "': step " + Number(s.steps[i]) +
                                    " is not a finite number");
      if (!std::isfinite(s.forces[i]) || s.forces[i] < 0)
        throw std::invalid_argument("reaction of '" + s.name + "' at step " + Number(s.steps[i]) +
                                    ": |F| = " + Number(s.forces[i]) +
                                    " N is not a finite magnitude; nothing drawn");
      e.x_lo = std::min(e.x_lo, s.steps[i]);
      e.x_hi = std::max(e.x_hi, s.steps[i]);
      e.y_hi = std::max(e.y_hi, s.forces[i]);
    }
  }
  return e;
}

// One line per series in its colour, forces shown in units of `per_unit` N.
void AddSeriesLines(vtkChartXY* chart, const std::vector<ReactionSeries>& series, double per_unit) {
  for (size_t k = 0; k < series.size(); ++k) {
    const ReactionSeries& s = series[k];
    if (s.steps.empty()) continue;
    auto line = vtkSmartPointer<vtkPlotLine>::New();
    std::vector<double> shown(s.forces.size());
    std::transform(
        s.forces.begin(), s.forces.end(), shown.begin(), [&](double f) { return f / per_unit; });
    line->SetInputData(TableOf(s.steps, shown), 0, 1);
    const auto c = ReactionColour(k);
    line->SetColor(static_cast<unsigned char>(c[0]),
                   static_cast<unsigned char>(c[1]),
                   static_cast<unsigned char>(c[2]),
                   255);
    line->SetWidth(2.5);
    line->SetLabel(s.name);
    // Few steps: each one marked (one step is only a marker).
    if (s.steps.size() <= 40) {
      line->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      line->SetMarkerSize(6);
    }
    chart->AddPlot(line);
  }
}

// Where the rendered chart's axes put the plot area, and their ranges.
ChartArea AreaOf(vtkAxis* x, vtkAxis* y) {
  ChartArea area;
  area.left = static_cast<int>(std::lround(x->GetPoint1()[0]));
  area.right = static_cast<int>(std::lround(x->GetPoint2()[0]));
  area.bottom = static_cast<int>(std::lround(y->GetPoint1()[1]));
  area.top = static_cast<int>(std::lround(y->GetPoint2()[1]));
  area.step_lo = x->GetMinimum();
  area.step_hi = x->GetMaximum();
  area.force_lo = y->GetMinimum();
  area.force_hi = y->GetMaximum();
  return area;
}

}  // namespace

std::array<int, 3> ReactionColour(size_t i) {
  static constexpr std::array<std::array<int, 3>, 8> kOkabeIto = {{{0, 114, 178},
                                                                   {213, 94, 0},
                                                                   {0, 158, 115},
                                                                   {204, 121, 167},
                                                                   {230, 159, 0},
                                                                   {86, 180, 233},
                                                                   {90, 90, 90},
                                                                   {240, 228, 66}}};
  return kOkabeIto[i % kOkabeIto.size()];
}

ChartArea WriteReactionChart(const std::vector<ReactionSeries>& series,
                             const ReactionChartOptions& options,
                             const std::filesystem::path& png) {
  if (options.width < 16 || options.height < 16)
    throw std::invalid_argument("the chart needs at least 16 x 16 pixels");
  const auto [x_lo, x_hi, y_hi] = CheckedExtent(series);
  std::error_code ec;
  const std::filesystem::path folder = png.parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw std::runtime_error("cannot write the image " + png.string() + ": no folder " +
                             folder.string());
  if (x_lo > x_hi)
    throw std::invalid_argument("no reaction to draw (no support or gripper, or no step)");

  OffscreenChart drawing(options.width, options.height, options.title);
  vtkChartXY* chart = drawing.chart.GetPointer();

  // Step 1 starts at 0 (the reference state, before any load); a single
  // step gets a width of one either side.
  const double step_lo = x_lo == x_hi ? x_lo - 1 : std::min(x_lo, std::max(0.0, x_lo - 1));
  const double step_hi = x_lo == x_hi ? x_hi + 1 : x_hi;
  const double per_unit = options.force_unit.si_factor;
  const double force_hi = y_hi > 0 ? 1.08 * y_hi / per_unit : 1;

  if (!options.stages.empty()) {
    auto marks = vtkSmartPointer<StageMarks>::New();
    marks->SetInputData(TableOf({step_lo, step_hi}, {0, force_hi}), 0, 1);
    marks->Set(options.stages, step_lo, 0, force_hi);
    marks->SetLegendVisibility(false);
    chart->AddPlot(marks);
  }
  AddSeriesLines(chart, series, per_unit);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetInline(false);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(14);

  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  x->SetTitle("step");
  y->SetTitle("reaction [" + options.force_unit.label + "]");
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(step_lo, step_hi);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(0, force_hi);
  drawing.StyleAxes();

  drawing.Render();
  ChartArea area = AreaOf(x, y);

  drawing.WritePng(png);
  return area;
}

}  // namespace drape
