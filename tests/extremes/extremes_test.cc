// The extremes matrix (extreme_cases.cc; docs/robustness.md), all but the
// slow cases.
#include "extremes/extremes_matrix.h"

namespace drape::test {

INSTANTIATE_TEST_SUITE_P(Matrix, Extremes, ::testing::ValuesIn(ExtremeCases(false)), TestName);

}  // namespace drape::test
