// The spread a lab reports over its specimens: mean and sample standard
// deviation, worked by hand.
#include "core/io/study_table.h"

#include <gtest/gtest.h>

namespace drape {
namespace {

StudyRow Specimen(std::optional<double> dc, std::optional<int> nodes) {
  StudyRow row;
  row.status = "converged";
  row.drape_coefficient = dc;
  row.drape_nodes = nodes;
  return row;
}

TEST(DrapeSpread, MeanAndSampleDeviationOfTheSpecimensThatHaveThem) {
  // 0.8, 0.9, 1.0: mean 0.9, Σ(x − x̄)² = 0.02, s = √(0.02/2) = 0.1.
  // Nodes 4, 5, 6: mean 5, s = 1. The failed run has neither.
  const std::vector<StudyRow> rows = {
      Specimen(0.8, 4), Specimen(std::nullopt, std::nullopt), Specimen(0.9, 5), Specimen(1.0, 6)};
  const auto spread = SpreadOfDrape(rows);
  ASSERT_TRUE(spread);
  EXPECT_EQ(spread->specimens, 3);
  EXPECT_NEAR(spread->mean_coefficient, 0.9, 1e-15);
  EXPECT_NEAR(spread->sd_coefficient, 0.1, 1e-15);
  EXPECT_NEAR(spread->mean_nodes, 5, 1e-15);
  EXPECT_NEAR(spread->sd_nodes, 1, 1e-15);
  EXPECT_EQ(spread->fewest_nodes, 4);
  EXPECT_EQ(spread->most_nodes, 6);
  // One specimen has no spread; none has no report.
  EXPECT_EQ(SpreadOfDrape({Specimen(0.7, 3)})->sd_coefficient, 0);
  EXPECT_FALSE(SpreadOfDrape({Specimen(std::nullopt, std::nullopt)}));
}

}  // namespace
}  // namespace drape
