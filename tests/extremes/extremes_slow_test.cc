// The extremes matrix's slow cases (extreme_cases.cc: 200 × 200 elements, a
// 10 µm sheet, a sheet on the dress form): seconds to tens of seconds here,
// minutes under the sanitizers, so they are in the slow tier
// (tests/CMakeLists.txt).
#include "extremes/extremes_matrix.h"

namespace drape::test {

INSTANTIATE_TEST_SUITE_P(Matrix, Extremes, ::testing::ValuesIn(ExtremeCases(true)), TestName);

}  // namespace drape::test
