// Render and workbench tests need a display. Without one a test is skipped,
// unless the run expects a display (DRAPE_EXPECT_DISPLAY set, as ./test.sh
// sets it under xvfb-run): then a broken display fails the test instead of
// letting the run pass with every picture unchecked.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "ui/render/display.h"

namespace drape {

inline bool DisplayExpected() {
  const char* expected = std::getenv("DRAPE_EXPECT_DISPLAY");
  return expected && *expected && std::string(expected) != "0";
}

}  // namespace drape

// In SetUp or a test body: returns from it, skipping or failing the test,
// when there is no usable display.
#define DRAPE_REQUIRE_DISPLAY()                                                                  \
  do {                                                                                           \
    if (const std::string drape_display_problem = ::drape::DisplayProblem();                     \
        !drape_display_problem.empty()) {                                                        \
      if (::drape::DisplayExpected())                                                            \
        FAIL() << "a display was expected (DRAPE_EXPECT_DISPLAY) but " << drape_display_problem; \
      GTEST_SKIP() << drape_display_problem << " (run under xvfb-run -a)";                       \
    }                                                                                            \
  } while (0)
