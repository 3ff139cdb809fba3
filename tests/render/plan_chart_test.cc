// plan.png: a plan's evaluations, the objective on a log axis against the
// evaluation. Drawn from points made here and read back: each kind of
// point in its colour, where its value puts it.
#include "ui/render/plan_chart.h"

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

namespace drape {
namespace {

namespace fs = std::filesystem;

// The pixels of one colour (within 30 per channel): how many, and their
// mean column and row (row 0 at the bottom, as VTK reads a PNG).
struct Blob {
  int count = 0;
  double x = 0, y = 0;
};

struct Picture {
  int width = 0, height = 0;
  Blob feasible, infeasible, best;
  Blob feasible_left, feasible_right;  // the feasible dots in each half
};

Picture Read(const fs::path& png) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(png.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Picture p{dims[0], dims[1], {}, {}, {}};
  const int channels = image->GetNumberOfScalarComponents();
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  auto add = [&](Blob& b, const int(&rgb)[3], const unsigned char* c, int x, int y) {
    if (std::abs(c[0] - rgb[0]) < 30 && std::abs(c[1] - rgb[1]) < 30 &&
        std::abs(c[2] - rgb[2]) < 30) {
      b.x += x, b.y += y, ++b.count;
    }
  };
  // The legend (top right) shows each colour too: leave out its corner.
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      if (x > 0.55 * dims[0] && y > 0.8 * dims[1]) continue;
      const unsigned char* c = data + (static_cast<size_t>(y) * dims[0] + x) * channels;
      add(p.feasible, kPlanFeasibleColour, c, x, y);
      add(x < dims[0] / 2 ? p.feasible_left : p.feasible_right, kPlanFeasibleColour, c, x, y);
      add(p.infeasible, kPlanInfeasibleColour, c, x, y);
      add(p.best, kPlanBestColour, c, x, y);
    }
  for (Blob* b : {&p.feasible, &p.infeasible, &p.best, &p.feasible_left, &p.feasible_right})
    if (b->count) b->x /= b->count, b->y /= b->count;
  return p;
}

class PlanChart : public ::testing::Test {
 protected:
  void SetUp() override {
    DRAPE_REQUIRE_DISPLAY();
    png_ = fs::temp_directory_path() / ("drape-plan-chart-" + std::to_string(getpid()) + ".png");
  }
  void TearDown() override { fs::remove(png_); }
  fs::path png_;
};

TEST_F(PlanChart, EachEvaluationWhereItsObjectivePutsIt) {
  // A feasible point at 10 mm, then a failure, then a feasible one at
  // 0.1 mm: the first dot high on the left, the second low on the right,
  // the cross at the top in the middle.
  WritePlanChart(
      {{1, 0.01, true}, {2, std::nullopt, false}, {3, 1e-4, true}}, {"a plan", 900, 600}, png_);
  const Picture one = Read(png_);
  EXPECT_EQ(one.width, 900);
  EXPECT_EQ(one.height, 600);
  std::printf("feasible %d px, infeasible %d px, best line %d px\n",
              one.feasible.count,
              one.infeasible.count,
              one.best.count);
  EXPECT_GT(one.feasible.count, 2 * 20);
  EXPECT_GT(one.infeasible.count, 10);
  EXPECT_GT(one.best.count, 100);
  // The axis runs a decade per tick from 0.1 mm to 100 mm (a decade above
  // the highest point, for the crosses), the crosses at 10^1.75 mm: from the
  // low dot, the high one is 2 decades up and the cross 2.75, whatever the
  // plot's size in pixels. Midway across, the cross.
  const double up = one.feasible_left.y - one.feasible_right.y;
  const double cross = one.infeasible.y - one.feasible_right.y;
  EXPECT_GT(up, 100);
  EXPECT_NEAR(up / cross, 2 / 2.75, 0.03);
  EXPECT_NEAR(one.infeasible.x, (one.feasible_left.x + one.feasible_right.x) / 2, 10);
}

TEST_F(PlanChart, NoEvaluationIsAnError) {
  EXPECT_THROW(WritePlanChart({}, {}, png_), std::invalid_argument);
}

}  // namespace
}  // namespace drape
