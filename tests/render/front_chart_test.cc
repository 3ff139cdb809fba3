// front.png: the chart of a study's runs, time against error on log axes.
// Drawn from points made here, read back and looked for: the markers in
// their colour, the front's line in its own, the picture's size.
#include "ui/render/front_chart.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "support/display_required.h"
#include "ui/render/display.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

struct Pixels {
  int width = 0, height = 0;
  int blue = 0, orange = 0;  // the markers' and the front's colours, within 40 per channel
};

Pixels Read(const fs::path& png) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(png.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Pixels p{dims[0], dims[1], 0, 0};
  const int channels = image->GetNumberOfScalarComponents();
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  auto near = [](const unsigned char* c, int r, int g, int b) {
    return std::abs(c[0] - r) < 40 && std::abs(c[1] - g) < 40 && std::abs(c[2] - b) < 40;
  };
  for (int i = 0; i < dims[0] * dims[1]; ++i) {
    const unsigned char* c = data + static_cast<size_t>(i) * channels;
    p.blue += near(c, 31, 89, 166);
    p.orange += near(c, 217, 94, 3);
  }
  return p;
}

class FrontChart : public ::testing::Test {
 protected:
  void SetUp() override {
    DRAPE_REQUIRE_DISPLAY();
    png_ = fs::temp_directory_path() / ("drape-front-" + std::to_string(getpid()) + ".png");
  }
  void TearDown() override { fs::remove(png_); }
  fs::path png_;
};

TEST_F(FrontChart, DrawsEveryRunAndTheFrontOnLogAxes) {
  // Three on the front (each faster or more accurate than the others), one
  // beaten by the second.
  const std::vector<FrontPoint> points = {{"coarse", 0.01, 1e-2, true},
                                          {"middle", 0.1, 1e-3, true},
                                          {"fine", 1.0, 1e-5, true},
                                          {"wasteful", 0.5, 2e-3, false}};
  WriteFrontChart(points, {"a study", "error (m)", 900, 600}, png_);
  const Pixels p = Read(png_);
  EXPECT_EQ(p.width, 900);
  EXPECT_EQ(p.height, 600);
  // Four markers of 9 px, about 30 pixels of their colour each; a line over
  // three decades: hundreds.
  std::printf("marker pixels %d, front pixels %d\n", p.blue, p.orange);
  EXPECT_GT(p.blue, 4 * 20);
  EXPECT_GT(p.orange, 200);

  // Without a front of two points there is no line.
  WriteFrontChart({{"alone", 0.3, 1e-3, true}}, {"one run", "error (m)", 900, 600}, png_);
  const Pixels alone = Read(png_);
  EXPECT_GT(alone.blue, 20);
  EXPECT_EQ(alone.orange, 0);
}

TEST_F(FrontChart, NothingToDrawIsAnError) {
  EXPECT_THROW(WriteFrontChart({}, {}, png_), std::invalid_argument);
  // A run with no error (failed, or the reference) is not a point.
  EXPECT_THROW(WriteFrontChart({{"failed", 1.0, 0.0, false}}, {}, png_), std::invalid_argument);
}

}  // namespace
}  // namespace drape
