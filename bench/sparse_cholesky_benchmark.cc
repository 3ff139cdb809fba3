// Factorise + solve of shell-tangent-like matrices: 5 DOFs per node on a grid
// of nodes, a random SPD 20 × 20 block per 4-node element. The SPD case takes
// the supernodal LLᵀ; the indefinite case (the same matrix minus σI) fails it
// and takes the simplicial LDLᵀ fallback with refined solves, so its time
// includes the failed LLᵀ. The arguments are the grid's nodes each way and
// the path: 0 kAuto (what the solver uses), 1 kLltFirst, 2 kLdltOnly, 3 kBand
// — to place kAuto's thresholds.
// Times are wall-clock (BLAS may use threads).
#include <benchmark/benchmark.h>

#include <Eigen/SparseCore>

#include <random>
#include <utility>
#include <vector>

#include "core/linalg/sparse_cholesky.h"

namespace drape {
namespace {

Eigen::SparseMatrix<double> ShellLike(int nx, int ny, double sigma) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 5 * nx * ny;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<size_t>(nx - 1) * (ny - 1) * 210 + n);
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      Eigen::Matrix<double, 20, 20> r;
      for (int a = 0; a < 20; ++a)
        for (int b = 0; b < 20; ++b) r(a, b) = u(rng);
      const Eigen::Matrix<double, 20, 20> block =
          r.transpose() * r + 0.1 * Eigen::Matrix<double, 20, 20>::Identity();
      const int nodes[4] = {i + nx * j, i + 1 + nx * j, i + 1 + nx * (j + 1), i + nx * (j + 1)};
      for (int a = 0; a < 20; ++a)
        for (int b = 0; b < 20; ++b) {
          const int ga = 5 * nodes[a / 5] + a % 5;
          const int gb = 5 * nodes[b / 5] + b % 5;
          if (ga <= gb) t.emplace_back(ga, gb, block(a, b));
        }
    }
  for (int k = 0; k < n; ++k) t.emplace_back(k, k, -sigma);
  Eigen::SparseMatrix<double> k(n, n);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;
}

// σ = 0 (SPD) or 2 (a handful of eigenvalues below it: 4 to 7 at these sizes).
void FactorizeSolve(benchmark::State& state, double sigma) {
  const Eigen::SparseMatrix<double> k =
      ShellLike(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), sigma);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(k.rows());
  SparseCholesky chol(static_cast<FactorizationPath>(state.range(2)));
  chol.Analyze(k);
  FactorizationInfo info;
  for (auto _ : state) {
    info = chol.Factorize(k);
    benchmark::DoNotOptimize(chol.Solve(b));
  }
  state.counters["dofs"] = static_cast<double>(k.rows());
  state.counters["negative_pivots"] = info.negative_pivots;
  state.counters["ldlt"] = info.used_ldlt;
  state.counters["band"] = info.used_band;
}

void BM_FactorizeSolveSpd(benchmark::State& state) {
  FactorizeSolve(state, 0.0);
}
void BM_FactorizeSolveIndefinite(benchmark::State& state) {
  FactorizeSolve(state, 2.0);
}

void BM_Analyze(benchmark::State& state) {
  const Eigen::SparseMatrix<double> k =
      ShellLike(static_cast<int>(state.range(0)), static_cast<int>(state.range(0)), 0.0);
  for (auto _ : state) {
    SparseCholesky chol;
    chol.Analyze(k);
  }
  state.counters["dofs"] = static_cast<double>(k.rows());
}

// Nodes x × y: the strip fold's 81 × 3 and 81 × 2, square sheets.
void SizesAndPaths(benchmark::internal::Benchmark* b) {
  for (auto [nx, ny] :
       {std::pair{81, 2}, {81, 3}, {161, 3}, {10, 10}, {21, 21}, {31, 31}, {51, 51}, {100, 100}})
    for (int path : {0, 1, 2, 3}) b->Args({nx, ny, path});
  b->ArgNames({"x", "y", "path"})->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK(BM_FactorizeSolveSpd)->Apply(SizesAndPaths);
BENCHMARK(BM_FactorizeSolveIndefinite)->Apply(SizesAndPaths);
BENCHMARK(BM_Analyze)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace drape
