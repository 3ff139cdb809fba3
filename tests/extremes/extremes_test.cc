// The extremes matrix (extreme_cases.cc; docs/robustness.md), all but the
// slow cases.
#include <gtest/gtest.h>

#include "support/extreme_case.h"

namespace drape {
namespace {

class Extremes : public ::testing::TestWithParam<test::ExtremeCase> {};

TEST_P(Extremes, EndsAsAssertedWithFiniteOutputs) {
  test::RunExtremeCase(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Matrix,
                         Extremes,
                         ::testing::ValuesIn(test::ExtremeCases(false)),
                         test::TestName);

}  // namespace
}  // namespace drape
