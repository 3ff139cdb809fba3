// Element kernel: energy, gradient and Hessian of one shell element at a
// deformed large-rotation state (issue target: < 2 µs).
#include <benchmark/benchmark.h>

#include "core/mechanics/shell_element.h"
#include "support/random_element.h"

namespace drape {
namespace {

void BM_ShellElement(benchmark::State& bench, ElementOutput output) {
  SplitMix64 rng(1);
  const NodeColumns x0 = test::RandomFlatQuad(rng, 0.01, 0.1);
  NodeColumns t0;
  t0.colwise() = Eigen::Vector3d::UnitZ();
  const auto reference = MakeShellElementReference(x0, t0, Eigen::Vector3d::UnitX());
  const ShellSection section = IsotropicSection(1e6, 0.3, 5e-4);
  const ShellElementState state = test::RandomDeformedState(rng, x0, 0.01, 1.0).Element();
  ElementEnergy result;
  for (auto _ : bench) {
    EvaluateShellElement(reference, section, state, output, result);
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK_CAPTURE(BM_ShellElement, energy, ElementOutput::kEnergy);
BENCHMARK_CAPTURE(BM_ShellElement, gradient, ElementOutput::kGradient);
BENCHMARK_CAPTURE(BM_ShellElement, hessian, ElementOutput::kHessian);

}  // namespace
}  // namespace drape
