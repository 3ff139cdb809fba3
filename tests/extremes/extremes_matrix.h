// The extremes matrix's one test, instantiated over the fast cases by
// extremes_test.cc and over the slow ones by extremes_slow_test.cc (one
// executable each, so each includes this once).
#pragma once

#include <gtest/gtest.h>

#include "support/extreme_case.h"

namespace drape::test {

class Extremes : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(Extremes, EndsAsAssertedWithFiniteOutputs) {
  RunExtremeCase(GetParam());
}

}  // namespace drape::test
