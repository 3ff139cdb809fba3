// SparseCholesky over its life: one analysis for many factorisations, the
// LLᵀ skipped after an indefinite matrix, its own copy of the matrix,
// concurrent solves, misuse refused, and a factor too large for memory.
#include "core/linalg/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "support/test_matrices.h"

namespace drape {
namespace {

using test::Laplacian1D;
using test::Laplacian1DEigenvalues;
using test::Laplacian2D;
using test::Laplacian2DEigenvalues;
using test::RandomVector;
using test::RelativeResidual;
using test::ShiftBelow;
using test::SparseMatrix;

// One analysis, many factorisations: values go from SPD to indefinite and
// back; each one must be right.
TEST(SparseCholesky, RefactorizesWithOneAnalysis) {
  std::mt19937_64 rng(7);
  const int nx = 25, ny = 18, n = nx * ny;
  const std::vector<double> ev = Laplacian2DEigenvalues(nx, ny);
  SparseCholesky chol(FactorizationPath::kLltFirst);
  chol.Analyze(Laplacian2D(nx, ny, 0.0));
  const int sequence[] = {0, 0, 3, 0, 40, 41, 150, 0, n, 7, 0, 1, 0, n / 4, 0, 0, 99, 3};
  for (int round = 0; round < 3; ++round)
    for (int wanted : sequence) {
      int m = wanted;
      const double sigma = ShiftBelow(ev, m);
      SCOPED_TRACE(testing::Message() << "round " << round << ", m = " << m);
      const SparseMatrix k = Laplacian2D(nx, ny, sigma);
      const FactorizationInfo info = chol.Factorize(k);
      EXPECT_EQ(info.negative_pivots, m);
      EXPECT_EQ(info.zero_pivots, 0);
      EXPECT_EQ(info.positive_definite, m == 0);
      EXPECT_EQ(info.used_ldlt, m != 0);
      const Eigen::VectorXd b = RandomVector(n, rng);
      EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-10);
    }

  // A new pattern: analyse again, and the object works as new.
  const int n1 = 300;
  const std::vector<double> ev1 = Laplacian1DEigenvalues(n1);
  chol.Analyze(Laplacian1D(n1, 0.0));
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(n1)), std::logic_error);
  for (int wanted : {5, 0, 150}) {
    int m = wanted;
    const double sigma = ShiftBelow(ev1, m);
    const SparseMatrix k = Laplacian1D(n1, sigma);
    EXPECT_EQ(chol.Factorize(k).negative_pivots, m);
    const Eigen::VectorXd b = RandomVector(n1, rng);
    EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-10);
  }
}

// kAuto on a matrix large enough for the supernodal LLᵀ: after an indefinite
// factorisation the next one goes straight to the LDLᵀ (the LLᵀ would fail),
// after a definite one the LLᵀ is tried again; the inertia is right each time.
TEST(SparseCholesky, AutoSkipsTheLltRightAfterAnIndefiniteMatrix) {
  std::mt19937_64 rng(11);
  const int nx = 100, ny = 100, n = nx * ny;  // above kAuto's LDLᵀ-only size
  const std::vector<double> ev = Laplacian2DEigenvalues(nx, ny);
  SparseCholesky chol(FactorizationPath::kAuto);
  chol.Analyze(Laplacian2D(nx, ny, 0.0));
  struct Case {
    int negative;
    bool ldlt;  // expected path
  };
  // The first SPD matrix takes the LLᵀ; 0 after 5 is factorised by the LDLᵀ
  // (skipped LLᵀ) and the 0 after it by the LLᵀ again.
  for (const Case c : {Case{0, false},
                       Case{5, true},
                       Case{0, true},
                       Case{0, false},
                       Case{12, true},
                       Case{3, true},
                       Case{0, true},
                       Case{0, false}}) {
    int m = c.negative;
    const double sigma = ShiftBelow(ev, m);
    SCOPED_TRACE(testing::Message() << "m = " << m);
    const SparseMatrix k = Laplacian2D(nx, ny, sigma);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.negative_pivots, m);
    EXPECT_EQ(info.positive_definite, m == 0);
    EXPECT_EQ(info.used_ldlt, c.ldlt);
    const Eigen::VectorXd b = RandomVector(n, rng);
    EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-10);
  }
}

// The solution of the last factorisation does not depend on the caller's
// matrix staying alive or unchanged.
TEST(SparseCholesky, SolveUsesItsOwnCopyOfTheMatrix) {
  std::mt19937_64 rng(8);
  const std::vector<double> ev = Laplacian1DEigenvalues(500);
  int m = 100;
  const double sigma = ShiftBelow(ev, m);
  const SparseMatrix k = Laplacian1D(500, sigma);
  SparseCholesky chol(FactorizationPath::kLltFirst);
  {
    SparseMatrix temporary = k;
    chol.Analyze(temporary);
    chol.Factorize(temporary);
    temporary.coeffs().setZero();
  }
  const Eigen::VectorXd b = RandomVector(500, rng);
  EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-10);
}

TEST(SparseCholesky, ConcurrentSolvesAgree) {
  std::mt19937_64 rng(9);
  for (int m : {0, 30}) {
    const std::vector<double> ev = Laplacian2DEigenvalues(30, 30);
    const double sigma = ShiftBelow(ev, m);
    const SparseMatrix k = Laplacian2D(30, 30, sigma);
    SparseCholesky chol(FactorizationPath::kLltFirst);
    chol.Analyze(k);
    chol.Factorize(k);
    std::vector<Eigen::VectorXd> b, x(4);
    for (int i = 0; i < 4; ++i) b.push_back(RandomVector(900, rng));
    std::vector<std::thread> threads;
    for (int i = 0; i < 4; ++i) threads.emplace_back([&, i] { x[i] = chol.Solve(b[i]); });
    for (auto& t : threads) t.join();
    for (int i = 0; i < 4; ++i) EXPECT_EQ(x[i], chol.Solve(b[i]));
  }
}
TEST(SparseCholesky, RejectsMisuse) {
  const SparseMatrix k = Laplacian1D(20, 0.0);
  SparseCholesky chol(FactorizationPath::kLltFirst);
  EXPECT_THROW(chol.Factorize(k), std::logic_error);
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(20)), std::logic_error);

  chol.Analyze(k);
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(20)), std::logic_error);   // not factorised
  EXPECT_THROW(chol.Factorize(Laplacian1D(21, 0.0)), std::logic_error);    // size
  EXPECT_THROW(chol.Factorize(Laplacian2D(4, 5, 0.0)), std::logic_error);  // pattern

  SparseMatrix uncompressed = k;
  uncompressed.coeffRef(0, 5) = 0.0;  // a new entry: leaves the matrix uncompressed
  ASSERT_FALSE(uncompressed.isCompressed());
  EXPECT_THROW(chol.Analyze(uncompressed), std::logic_error);
  EXPECT_THROW(chol.Analyze(SparseMatrix(3, 4)), std::logic_error);

  SparseMatrix not_finite = k;
  not_finite.coeffRef(3, 4) = std::nan("");
  EXPECT_THROW(chol.Factorize(not_finite), std::runtime_error);
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(20)), std::logic_error);  // failed

  EXPECT_TRUE(chol.Factorize(k).positive_definite);
  EXPECT_THROW(chol.Solve(Eigen::VectorXd::Ones(19)), std::logic_error);  // rhs size
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(20);
  EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-12);
}

// Before any numeric work: a factor larger than the memory limit is refused
// with one message giving the estimate. The estimate is at least the
// values and indices of the matrix's own triangle (L holds its pattern).
TEST(SparseCholesky, AFactorThatWouldNotFitIsRefusedWithItsSize) {
  const SparseMatrix upper = Laplacian2D(60, 60, 0.0);  // positive definite
  SparseCholesky probe;
  probe.Analyze(upper);
  const double bytes = probe.FactorBytes();
  EXPECT_GE(bytes, 12.0 * upper.nonZeros());

  SparseCholesky limited;
  limited.SetMemoryLimit(0.5 * bytes);
  try {
    limited.Analyze(upper);
    ADD_FAILURE() << "no error for a factor of " << bytes << " bytes";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("the factorisation needs about"), std::string::npos) << message;
    EXPECT_NE(message.find("3600 unknowns"), std::string::npos) << message;
    EXPECT_NE(message.find("solver.sequencing"), std::string::npos) << message;
  }
  limited.SetMemoryLimit(2 * bytes);
  limited.Analyze(upper);
  EXPECT_EQ(limited.Factorize(upper).negative_pivots, 0);

  const double available = AvailableMemoryBytes();
  EXPECT_GT(available, 0);
  EXPECT_TRUE(std::isfinite(available));  // Linux: /proc/meminfo
}

}  // namespace
}  // namespace drape
