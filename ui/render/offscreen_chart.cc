#include "ui/render/offscreen_chart.h"

#include <vtkContextScene.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <stdexcept>
#include <system_error>

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

void OffscreenChart::Render() {
  view->GetRenderWindow()->Render();
}

void OffscreenChart::WritePng(const std::filesystem::path& png) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(png.string().c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::error_code ec;
  if (writer->GetErrorCode() != 0 || !std::filesystem::is_regular_file(png, ec))
    throw std::runtime_error("cannot write the image " + png.string());
}

}  // namespace drape
