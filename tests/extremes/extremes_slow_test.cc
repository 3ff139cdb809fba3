// The extremes matrix's slow cases (extreme_cases.cc: 200 × 200 elements, a
// 10 µm sheet, a sheet on the dress form): seconds to tens of seconds here,
// minutes under the sanitizers, so they are in the slow tier
// (tests/CMakeLists.txt).
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
                         ::testing::ValuesIn(test::ExtremeCases(true)),
                         test::TestName);

}  // namespace
}  // namespace drape
