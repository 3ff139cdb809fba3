#include "ui/render/offscreen_chart.h"

#include <vtkAxis.h>
#include <vtkContextScene.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include "ui/render/window_png.h"

namespace drape {

OffscreenChart::OffscreenChart(int width, int height, const std::string& title) {
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetSize(width, height);
  view->GetRenderWindow()->SetMultiSamples(0);
  view->GetRenderer()->SetBackground(1, 1, 1);
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(18);
}

void OffscreenChart::StyleAxes() {
  for (int side : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
    vtkAxis* a = chart->GetAxis(side);
    a->GetTitleProperties()->SetFontSize(15);
    a->GetLabelProperties()->SetFontSize(13);
  }
}

void OffscreenChart::Render() {
  view->GetRenderWindow()->Render();
}

void OffscreenChart::WritePng(const std::filesystem::path& png) {
  WriteWindowPng(view->GetRenderWindow(), png);
}

}  // namespace drape
