// SparseCholesky's solves and inertia: random SPD matrices, shifted
// Laplacians with a known count of negative eigenvalues, badly scaled and
// shell-like block matrices, and singular ones reporting zero pivots.
#include "core/linalg/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "support/test_matrices.h"

namespace drape {
namespace {

using test::AddLaplacian1D;
using test::DenseEigenvalues;
using test::ExpectInertia;
using test::Laplacian1D;
using test::Laplacian1DEigenvalues;
using test::Laplacian2D;
using test::Laplacian2DEigenvalues;
using test::RandomScales;
using test::RandomSpd;
using test::RandomVector;
using test::RelativeResidual;
using test::ScaleSymmetric;
using test::ShellLike;
using test::ShiftBelow;
using test::SparseMatrix;
using test::Triplets;
using test::Upper;

TEST(SparseCholesky, SolvesRandomSpdMatrices) {
  std::mt19937_64 rng(1);
  for (auto [nx, ny] : {std::pair{3, 4}, {10, 10}, {20, 15}, {40, 40}, {70, 70}}) {
    SCOPED_TRACE(testing::Message() << nx << " x " << ny);
    const SparseMatrix k = RandomSpd(nx, ny, 0.1, rng);
    SparseCholesky chol(FactorizationPath::kLltFirst);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_TRUE(info.positive_definite);
    EXPECT_EQ(info.negative_pivots, 0);
    EXPECT_EQ(info.zero_pivots, 0);
    EXPECT_FALSE(info.used_ldlt);
    EXPECT_EQ(chol.info().negative_pivots, 0);
    EXPECT_TRUE(chol.info().positive_definite);
    for (int rhs = 0; rhs < 3; ++rhs) {
      const Eigen::VectorXd b = RandomVector(nx * ny, rng);
      EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-12);
    }
  }
}

TEST(SparseCholesky, InertiaOfShifted1DLaplacian) {
  std::mt19937_64 rng(2);
  for (int n : {1, 2, 10, 101, 1000, 4000}) {
    const std::vector<double> ev = Laplacian1DEigenvalues(n);
    // Not n/2: for even n the shift would be exactly 2, a zero diagonal (see
    // ZeroDiagonalIsFlaggedNotSilentlyWrong).
    for (int wanted : {0, 1, 2, n / 4, n / 3, 2 * n / 3, n - 1, n}) {
      int m = wanted;
      const double sigma = ShiftBelow(ev, m);
      SCOPED_TRACE(testing::Message() << "n = " << n << ", sigma = " << sigma << ", m = " << m);
      ExpectInertia(Laplacian1D(n, sigma), m, 1e-10, rng);
    }
  }
}

TEST(SparseCholesky, InertiaOfShifted2DLaplacian) {
  std::mt19937_64 rng(3);
  for (auto [nx, ny] : {std::pair{1, 6}, {7, 5}, {30, 20}, {60, 45}}) {
    const std::vector<double> ev = Laplacian2DEigenvalues(nx, ny);
    const int n = nx * ny;
    for (int wanted : {0, 1, 5, n / 8, n / 4, 3 * n / 4, n - 1, n}) {
      int m = wanted;
      const double sigma = ShiftBelow(ev, m);
      SCOPED_TRACE(testing::Message()
                   << nx << " x " << ny << ", sigma = " << sigma << ", m = " << m);
      ExpectInertia(Laplacian2D(nx, ny, sigma), m, 1e-10, rng);
    }
  }
}

// S K S has the inertia of K (Sylvester): the verdict must not depend on the
// units of the DOFs. The solve is checked in the original units: K x = b with
// x = S y, (S K S) y = S b.
TEST(SparseCholesky, InertiaDoesNotDependOnUnits) {
  std::mt19937_64 rng(4);
  const int nx = 40, ny = 31, n = nx * ny;
  const std::vector<double> ev = Laplacian2DEigenvalues(nx, ny);
  for (int wanted : {0, 17, 300, 900}) {
    int m = wanted;
    const double sigma = ShiftBelow(ev, m);
    SCOPED_TRACE(testing::Message() << "m = " << m);
    const SparseMatrix k = Laplacian2D(nx, ny, sigma);
    const Eigen::VectorXd s = RandomScales(n, 6.0, rng);
    const SparseMatrix scaled = ScaleSymmetric(k, s);
    for (FactorizationPath path : {FactorizationPath::kLltFirst, FactorizationPath::kBand}) {
      SparseCholesky chol(path);
      chol.Analyze(scaled);
      const FactorizationInfo info = chol.Factorize(scaled);
      EXPECT_EQ(info.negative_pivots, m);
      EXPECT_EQ(info.zero_pivots, 0);
      EXPECT_EQ(info.positive_definite, m == 0);
      const Eigen::VectorXd b = RandomVector(n, rng);
      const Eigen::VectorXd x = s.cwiseProduct(chol.Solve(s.cwiseProduct(b)));
      EXPECT_LT(RelativeResidual(k, x, b), 1e-10);
    }
  }
}

// The limit of an LDLᵀ without pivoting: tridiag(−1, 0, −1) of even size is
// nonsingular (eigenvalues −2cos(kπ/(n+1)), half of them negative), but its
// first pivot is zero in every ordering. It must be flagged (zero pivots), not
// reported as a wrong inertia.
TEST(SparseCholesky, ZeroDiagonalIsFlaggedNotSilentlyWrong) {
  for (int n : {2, 10, 1000}) {
    SCOPED_TRACE(testing::Message() << "n = " << n);
    const SparseMatrix k = Laplacian1D(n, 2.0);
    SparseCholesky chol(FactorizationPath::kLltFirst);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_TRUE(info.used_ldlt);
    EXPECT_FALSE(info.positive_definite);
    EXPECT_TRUE(info.zero_pivots > 0 || info.negative_pivots == n / 2)
        << info.negative_pivots << " negative, " << info.zero_pivots << " zero";
  }
}

TEST(SparseCholesky, ShellLikeBlockMatrixSpd) {
  std::mt19937_64 rng(5);
  for (auto [nx, ny] : {std::pair{2, 2}, {5, 4}, {20, 20}, {30, 35}}) {
    SCOPED_TRACE(testing::Message() << nx << " x " << ny << " nodes");
    const SparseMatrix k = ShellLike(nx, ny, 0.0, rng);
    SparseCholesky chol(FactorizationPath::kLltFirst);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_TRUE(info.positive_definite);
    EXPECT_EQ(info.negative_pivots, 0);
    EXPECT_FALSE(info.used_ldlt);
    const Eigen::VectorXd b = RandomVector(static_cast<int>(k.rows()), rng);
    EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), 1e-12);
  }
}

// Indefinite shell-like matrices, in mixed units (translations and rotations
// scaled apart as N/m against N·m would be), against a dense eigensolver.
TEST(SparseCholesky, ShellLikeBlockMatrixInertia) {
  std::mt19937_64 rng(6);
  for (auto [nx, ny] : {std::pair{6, 7}, {12, 10}}) {
    const SparseMatrix k0 = ShellLike(nx, ny, 0.0, rng);
    const int n = static_cast<int>(k0.rows());
    const std::vector<double> ev = DenseEigenvalues(k0);
    Eigen::VectorXd s(n);
    for (int i = 0; i < n; ++i) s[i] = i % 5 < 3 ? 1.0 : 1e-3;
    for (int wanted : {1, 10, n / 5, n / 2, n}) {
      int m = wanted;
      const double sigma = ShiftBelow(ev, m);
      SCOPED_TRACE(testing::Message() << nx << " x " << ny << " nodes, m = " << m);
      SparseMatrix shifted = k0;
      for (int j = 0; j < n; ++j) shifted.coeffRef(j, j) -= sigma;
      ExpectInertia(shifted, m, 1e-10, rng);
      ExpectInertia(ScaleSymmetric(shifted, s), m, 1e-10, rng);
    }
  }
}

// Each path applies the same zero-pivot rule.
void ExpectZeroPivotsOfSingularMatrices(FactorizationPath path) {
  std::mt19937_64 rng(10);
  // Neumann Laplacians: positive semidefinite, one zero eigenvalue.
  for (int n : {2, 50, 1000, 5000}) {
    SCOPED_TRACE(testing::Message() << "1-D Neumann, n = " << n);
    SparseCholesky chol(path);
    const SparseMatrix k = Laplacian1D(n, 0.0, true);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_FALSE(info.positive_definite);
    EXPECT_EQ(info.zero_pivots, 1);
    EXPECT_EQ(info.negative_pivots, 0);
    EXPECT_TRUE(info.used_ldlt);
    EXPECT_TRUE(chol.Solve(RandomVector(n, rng)).allFinite());
  }
  for (auto [nx, ny] : {std::pair{4, 4}, {30, 40}, {100, 70}}) {
    SCOPED_TRACE(testing::Message() << "2-D Neumann, " << nx << " x " << ny);
    const SparseMatrix k = Laplacian2D(nx, ny, 0.0, true);
    for (double units : {0.0, 5.0}) {
      const SparseMatrix scaled = ScaleSymmetric(k, RandomScales(nx * ny, units, rng));
      SparseCholesky chol(path);
      chol.Analyze(scaled);
      const FactorizationInfo info = chol.Factorize(scaled);
      EXPECT_EQ(info.zero_pivots, 1);
      EXPECT_EQ(info.negative_pivots, 0);
      EXPECT_TRUE(chol.Solve(RandomVector(nx * ny, rng)).allFinite());
    }
  }

  // Shell-like, semidefinite (the supernodal LLᵀ may succeed on roundoff), in
  // uniform and in mixed units.
  for (auto [nx, ny] : {std::pair{3, 3}, {20, 20}, {40, 45}}) {
    const SparseMatrix k = ShellLike(nx, ny, 0.0, rng, true);
    const int n = static_cast<int>(k.rows());
    Eigen::VectorXd s(n);
    for (int i = 0; i < n; ++i) s[i] = i % 5 < 3 ? 1.0 : 1e-3;
    for (const SparseMatrix& matrix : {k, ScaleSymmetric(k, s)}) {
      SCOPED_TRACE(testing::Message() << "shell-like " << nx << " x " << ny);
      SparseCholesky chol(path);
      chol.Analyze(matrix);
      const FactorizationInfo info = chol.Factorize(matrix);
      EXPECT_FALSE(info.positive_definite);
      EXPECT_EQ(info.zero_pivots, 1);
      EXPECT_EQ(info.negative_pivots, 0);
    }
  }

  // A zero row and column (explicit zero diagonal, and no diagonal at all):
  // the rest splits into two Dirichlet chains, both positive definite.
  for (bool stored : {true, false}) {
    SCOPED_TRACE(testing::Message() << "zero row, diagonal stored: " << stored);
    const int n = 100, zero = 37;
    Triplets t;
    AddLaplacian1D(0, zero, 0.0, false, t);
    if (stored) t.emplace_back(zero, zero, 0.0);
    AddLaplacian1D(zero + 1, n - zero - 1, 0.0, false, t);
    const SparseMatrix k = Upper(n, t);
    SparseCholesky chol(path);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_FALSE(info.positive_definite);
    EXPECT_EQ(info.zero_pivots, 1);
    EXPECT_EQ(info.negative_pivots, 0);
    EXPECT_TRUE(chol.Solve(RandomVector(n, rng)).allFinite());
  }

  // Singular and indefinite: a Neumann chain beside a negated Dirichlet chain
  // (negative definite, 60 negative eigenvalues).
  {
    Triplets t;
    AddLaplacian1D(0, 80, 0.0, true, t);
    for (int i = 0; i < 60; ++i) {
      t.emplace_back(80 + i, 80 + i, -2.0);
      if (i + 1 < 60) t.emplace_back(80 + i, 81 + i, 1.0);
    }
    const SparseMatrix k = Upper(140, t);
    SparseCholesky chol(path);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.zero_pivots, 1);
    EXPECT_EQ(info.negative_pivots, 60);
  }

  // The zero matrix.
  {
    Triplets t;
    for (int i = 0; i < 10; ++i) t.emplace_back(i, i, 0.0);
    const SparseMatrix k = Upper(10, t);
    SparseCholesky chol(path);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.zero_pivots, 10);
    EXPECT_EQ(info.negative_pivots, 0);
  }
}

TEST(SparseCholesky, SingularMatricesReportZeroPivots) {
  ExpectZeroPivotsOfSingularMatrices(FactorizationPath::kLltFirst);
}

TEST(SparseCholesky, SingularMatricesReportZeroPivotsOnTheBandPath) {
  ExpectZeroPivotsOfSingularMatrices(FactorizationPath::kBand);
}

}  // namespace
}  // namespace drape
