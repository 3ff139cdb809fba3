#include "ui/render/front_chart.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartXY.h>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
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

// The points drawn by vtkPlotPoints, each with its label beside it. The
// chart paints a plot in data coordinates; text is anchored there and drawn
// in pixels.
class LabelledPoints : public vtkPlotPoints {
 public:
  static LabelledPoints* New();
  vtkTypeMacro(LabelledPoints, vtkPlotPoints);

  void SetLabels(std::vector<std::array<float, 2>> at, std::vector<std::string> labels) {
    at_ = std::move(at);
    labels_ = std::move(labels);
  }
  // The picture's size [px]: a label must stay inside it, clear of the
  // left axis.
  void SetCanvas(int width, int height) {
    width_ = width;
    height_ = height;
  }

  // Each label goes where it overlaps no label placed before it: beside
  // its point, then further above or below (runs that differ in a key that
  // changes little sit on top of each other). Placed in pixels, under the
  // chart's data-to-pixel transform.
  bool Paint(vtkContext2D* painter) override {
    if (!Superclass::Paint(painter)) return false;
    vtkNew<vtkTextProperty> text;
    text->SetFontSize(13);
    text->SetColor(0.15, 0.15, 0.15);
    text->SetVerticalJustificationToCentered();
    std::vector<std::array<double, 2>> pixels(at_.size());
    for (size_t i = 0; i < at_.size(); ++i) {
      const float in[2] = {at_[i][0], at_[i][1]};
      float out[2];
      painter->GetTransform()->TransformPoints(in, out, 1);
      pixels[i] = {out[0], out[1]};
    }
    painter->PushMatrix();
    vtkNew<vtkTransform2D> identity;
    painter->SetTransform(identity);
    struct Box {
      double x0, y0, x1, y1;
    };
    std::vector<Box> placed;
    for (const auto& p : pixels) placed.push_back({p[0] - 5, p[1] - 5, p[0] + 5, p[1] + 5});
    constexpr double kCharWidth = 7.2, kLineHeight = 15;
    for (size_t i = 0; i < at_.size(); ++i) {
      const double width = kCharWidth * labels_[i].size();
      Box best{};
      double best_overlap = 1e300;
      for (int k = 0; k < 16 && best_overlap > 0; ++k) {
        const bool right = k % 4 < 2;  // the label right of its point, or left
        const double dy = (k % 2 ? -1 : 1) * kLineHeight * (0.5 + k / 4);
        const double x0 = right ? pixels[i][0] + 8 : pixels[i][0] - 8 - width;
        const Box box{x0,
                      pixels[i][1] + dy - kLineHeight / 2,
                      x0 + width,
                      pixels[i][1] + dy + kLineHeight / 2};
        // Outside the picture (or over the left axis's numbers) is worse
        // than any overlap.
        double overlap =
            box.x0 < 70 || box.x1 > width_ || box.y0 < 0 || box.y1 > height_ ? 1e12 : 0;
        for (const Box& o : placed)
          overlap += std::max(0.0, std::min(box.x1, o.x1) - std::max(box.x0, o.x0)) *
                     std::max(0.0, std::min(box.y1, o.y1) - std::max(box.y0, o.y0));
        if (overlap < best_overlap) {
          best_overlap = overlap;
          best = box;
        }
      }
      placed.push_back(best);
      text->SetJustificationToLeft();
      painter->ApplyTextProp(text);
      painter->DrawString(best.x0, (best.y0 + best.y1) / 2, labels_[i].c_str());
    }
    painter->PopMatrix();
    return true;
  }

 private:
  std::vector<std::array<float, 2>> at_;
  std::vector<std::string> labels_;
  int width_ = 0, height_ = 0;
};
vtkStandardNewMacro(LabelledPoints);

// Decades covering [lo, hi] (log10 values), as tick positions and labels.
void DecadeTicks(vtkAxis* axis, double lo, double hi) {
  const int first = static_cast<int>(std::floor(lo)), last = static_cast<int>(std::ceil(hi));
  vtkNew<vtkDoubleArray> positions;
  vtkNew<vtkStringArray> labels;
  for (int k = first; k <= last; ++k) {
    positions->InsertNextValue(k);
    char text[16];
    std::snprintf(text, sizeof text, "1e%d", k);
    labels->InsertNextValue(text);
  }
  axis->SetCustomTickPositions(positions, labels);
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(first, std::max(last, first + 1));
}

vtkSmartPointer<vtkTable> TableOf(const std::vector<std::array<float, 2>>& xy) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkFloatArray> x, y;
  x->SetName("log10 time");
  y->SetName("log10 error");
  for (const auto& p : xy) {
    x->InsertNextValue(p[0]);
    y->InsertNextValue(p[1]);
  }
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

}  // namespace

void WriteFrontChart(const std::vector<FrontPoint>& points,
                     const FrontChartOptions& options,
                     const std::filesystem::path& png) {
  std::vector<std::array<float, 2>> all, front;
  std::vector<std::string> labels;
  for (const FrontPoint& p : points) {
    if (!(p.time_s > 0 && p.error > 0 && std::isfinite(p.time_s) && std::isfinite(p.error)))
      continue;
    const std::array<float, 2> at{static_cast<float>(std::log10(p.time_s)),
                                  static_cast<float>(std::log10(p.error))};
    all.push_back(at);
    labels.push_back(p.label);
    if (p.on_front) front.push_back(at);
  }
  if (all.empty())
    throw std::invalid_argument(
        "no run has both a time and an error to draw (did the reference "
        "converge?)");
  std::sort(front.begin(), front.end());

  OffscreenChart drawing(options.width, options.height, options.title);
  vtkChartXY* chart = drawing.chart.GetPointer();

  if (front.size() > 1) {
    vtkPlot* line = chart->AddPlot(vtkChart::LINE);
    line->SetInputData(TableOf(front), 0, 1);
    line->SetColor(0.85, 0.37, 0.01);  // the front, orange
    line->SetWidth(2);
  }
  auto dots = vtkSmartPointer<LabelledPoints>::New();
  dots->SetInputData(TableOf(all), 0, 1);
  dots->SetMarkerStyle(vtkPlotPoints::CIRCLE);
  dots->SetMarkerSize(9);
  dots->SetColor(0.12, 0.35, 0.65);
  dots->SetLabels(all, labels);
  dots->SetCanvas(options.width, options.height);
  chart->AddPlot(dots);

  float x_lo = all[0][0], x_hi = x_lo, y_lo = all[0][1], y_hi = y_lo;
  for (const auto& p : all) {
    x_lo = std::min(x_lo, p[0]);
    x_hi = std::max(x_hi, p[0]);
    y_lo = std::min(y_lo, p[1]);
    y_hi = std::max(y_hi, p[1]);
  }
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  x->SetTitle("run time (s)");
  y->SetTitle(options.error_axis);
  // A decade of room on the right for the labels.
  DecadeTicks(x, x_lo, x_hi + 0.5);
  DecadeTicks(y, y_lo, y_hi);
  drawing.StyleAxes();

  drawing.Render();
  drawing.WritePng(png);
}

}  // namespace drape
