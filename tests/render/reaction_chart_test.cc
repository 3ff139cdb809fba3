// The reactions chart (drape render RESULT --plot reactions): series made
// here, drawn, read back and looked for: the picture's size, each series'
// line in its colour, and a constant and a ramp where their values put them
// on the axes.
#include "ui/render/reaction_chart.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "support/display_required.h"
#include "ui/render/display.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// The picture, rows from the bottom as vtkPNGReader gives them.
struct Picture {
  int width = 0, height = 0, channels = 0;
  vtkSmartPointer<vtkImageData> image;

  const unsigned char* At(int x, int y) const {
    return static_cast<const unsigned char*>(image->GetScalarPointer()) +
           (static_cast<size_t>(y) * width + x) * channels;
  }
  // Within 40 per channel of `c`.
  bool Is(int x, int y, const std::array<int, 3>& c) const {
    const unsigned char* p = At(x, y);
    return std::abs(p[0] - c[0]) < 40 && std::abs(p[1] - c[1]) < 40 && std::abs(p[2] - c[2]) < 40;
  }
  int Count(const std::array<int, 3>& c) const {
    int n = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) n += Is(x, y, c);
    return n;
  }
  // The middle of the pixels of colour `c` in column x (between rows lo and
  // hi), or NaN when there are none.
  double RowOf(int x, const std::array<int, 3>& c, int lo, int hi) const {
    std::vector<int> rows;
    for (int y = std::max(lo, 0); y <= std::min(hi, height - 1); ++y)
      if (Is(x, y, c)) rows.push_back(y);
    if (rows.empty()) return std::numeric_limits<double>::quiet_NaN();
    return 0.5 * (rows.front() + rows.back());
  }
};

Picture Read(const fs::path& png) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(png.c_str());
  reader->Update();
  Picture p;
  p.image = reader->GetOutput();
  int dims[3];
  p.image->GetDimensions(dims);
  p.width = dims[0];
  p.height = dims[1];
  p.channels = p.image->GetNumberOfScalarComponents();
  return p;
}

class ReactionChart : public ::testing::Test {
 protected:
  void SetUp() override {
    DRAPE_REQUIRE_DISPLAY();
    png_ = fs::temp_directory_path() / ("drape-reactions-" + std::to_string(getpid()) + ".png");
  }
  void TearDown() override { fs::remove(png_); }
  fs::path png_;
};

// A constant 2 N, a ramp from 0 to 4 N over steps 1-21, a third hold at
// 1 N: the ramp crosses the constant at step 11.
std::vector<ReactionSeries> Series() {
  ReactionSeries constant{"constant (gripper)", {}, {}}, ramp{"ramp (support)", {}, {}},
      low{"low (support)", {}, {}};
  for (int s = 1; s <= 21; ++s) {
    constant.steps.push_back(s);
    constant.forces.push_back(2.0);
    ramp.steps.push_back(s);
    ramp.forces.push_back(4.0 * (s - 1) / 20.0);
    low.steps.push_back(s);
    low.forces.push_back(1.0);
  }
  return {constant, ramp, low};
}

TEST_F(ReactionChart, DrawsEachSeriesInItsColourWhereItsValuesAre) {
  const ChartArea area =
      WriteReactionChart(Series(), {"a scene", {{1, "SW"}, {8, "R"}}, 900, 600}, png_);
  const Picture p = Read(png_);
  ASSERT_EQ(p.width, 900);
  ASSERT_EQ(p.height, 600);
  // Step 1 starts one after the reference state; the forces from 0.
  EXPECT_DOUBLE_EQ(area.step_lo, 0);
  EXPECT_DOUBLE_EQ(area.step_hi, 21);
  EXPECT_DOUBLE_EQ(area.force_lo, 0);
  EXPECT_GT(area.force_hi, 4);
  ASSERT_GT(area.right - area.left, 400);
  ASSERT_GT(area.top - area.bottom, 300);
  ASSERT_LE(area.right, p.width);
  ASSERT_LE(area.top, p.height);

  // Lines 2.5 px wide across most of 600 px: hundreds of pixels each.
  for (size_t k = 0; k < 3; ++k) {
    const int n = p.Count(ReactionColour(k));
    std::printf("series %zu: %d pixels\n", k, n);
    EXPECT_GT(n, 800) << "series " << k;
  }
  // Where a value lands: a row of the plot area by the axis' range.
  auto column = [&](double step) {
    return static_cast<int>(
        std::lround(area.left + (step - area.step_lo) / (area.step_hi - area.step_lo) *
                                    (area.right - area.left)));
  };
  auto row = [&](double force) {
    return area.bottom +
           (force - area.force_lo) / (area.force_hi - area.force_lo) * (area.top - area.bottom);
  };
  for (double step : {3.0, 9.0, 16.0, 19.0}) {
    const int x = column(step);
    EXPECT_NEAR(p.RowOf(x, ReactionColour(0), area.bottom, area.top), row(2.0), 3) << step;
    EXPECT_NEAR(p.RowOf(x, ReactionColour(2), area.bottom, area.top), row(1.0), 3) << step;
    EXPECT_NEAR(p.RowOf(x, ReactionColour(1), area.bottom, area.top), row(4.0 * (step - 1) / 20), 4)
        << step;
  }
  // Left of step 1 (the reference state) nothing is drawn.
  EXPECT_TRUE(std::isnan(p.RowOf(column(0.5), ReactionColour(0), area.bottom, area.top)));
}

// In gram-force (1 gf = 9.80665e-3 N, units.h) the axis spans the same
// lines, its range in gf: the constant 2 N stands at 2 / 9.80665e-3 gf.
TEST_F(ReactionChart, DrawsTheForcesInTheChosenUnit) {
  ReactionChartOptions options{"in gf", {}, 900, 600};
  options.force_unit = UnitFor(Measure::kForce, UnitSystem::kTextile);
  ASSERT_EQ(options.force_unit.label, "gf");
  const double gf = 9.80665e-3;
  const ChartArea area = WriteReactionChart(Series(), options, png_);
  EXPECT_GT(area.force_hi, 4 / gf);
  EXPECT_LT(area.force_hi, 1.2 * 4 / gf);
  const Picture p = Read(png_);
  const int x = static_cast<int>(std::lround(
      area.left + (9 - area.step_lo) / (area.step_hi - area.step_lo) * (area.right - area.left)));
  const double row_of_2N = area.bottom + (2 / gf - area.force_lo) /
                                             (area.force_hi - area.force_lo) *
                                             (area.top - area.bottom);
  EXPECT_NEAR(p.RowOf(x, ReactionColour(0), area.bottom, area.top), row_of_2N, 3);
}

TEST_F(ReactionChart, OneStepIsAMarker) {
  ReactionSeries one{"end (gripper)", {5}, {0.25}};
  const ChartArea area = WriteReactionChart({one}, {"one step", {}, 400, 300}, png_);
  const Picture p = Read(png_);
  EXPECT_EQ(p.width, 400);
  EXPECT_EQ(p.height, 300);
  EXPECT_DOUBLE_EQ(area.step_lo, 4);
  EXPECT_DOUBLE_EQ(area.step_hi, 6);
  EXPECT_GT(p.Count(ReactionColour(0)), 10);
}

TEST_F(ReactionChart, ANonFiniteValueIsRefusedAndNothingIsDrawn) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1.0}) {
    std::vector<ReactionSeries> series = Series();
    series[1].forces[7] = bad;
    try {
      WriteReactionChart(series, {"bad", {}, 400, 300}, png_);
      ADD_FAILURE() << "drawn with " << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("reaction of 'ramp (support)' at step 8"),
                std::string::npos)
          << e.what();
    }
    EXPECT_FALSE(fs::exists(png_));
  }
  std::vector<ReactionSeries> series = Series();
  series[0].steps[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(WriteReactionChart(series, {}, png_), std::invalid_argument);
  series = Series();
  series[2].forces.pop_back();
  EXPECT_THROW(WriteReactionChart(series, {}, png_), std::invalid_argument);
  EXPECT_THROW(WriteReactionChart({}, {}, png_), std::invalid_argument);
  EXPECT_THROW(WriteReactionChart({{"empty", {}, {}}}, {}, png_), std::invalid_argument);
  EXPECT_FALSE(fs::exists(png_));
  EXPECT_THROW(WriteReactionChart(Series(), {}, "/no/such/folder/r.png"), std::runtime_error);
}

}  // namespace
}  // namespace drape
