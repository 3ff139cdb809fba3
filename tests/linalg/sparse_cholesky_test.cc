#include "core/linalg/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

namespace drape {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// The upper triangle, compressed, of the symmetric matrix given by triplets of
// both triangles (or of the upper one only).
SparseMatrix Upper(int n, const Triplets& t) {
  Triplets upper;
  for (const auto& e : t)
    if (e.row() <= e.col()) upper.push_back(e);
  SparseMatrix k(n, n);
  k.setFromTriplets(upper.begin(), upper.end());
  k.makeCompressed();
  return k;
}

double RelativeResidual(const SparseMatrix& upper,
                        const Eigen::VectorXd& x,
                        const Eigen::VectorXd& b) {
  const Eigen::VectorXd kx = upper.selfadjointView<Eigen::Upper>() * x;
  return (kx - b).norm() / b.norm();
}

Eigen::VectorXd RandomVector(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

// tridiag(−1, 2, −1) − σI of size n (Dirichlet ends), as upper triplets at
// offset `first`; with `neumann`, the end diagonals are 1 (a zero eigenvalue).
void AddLaplacian1D(int first, int n, double sigma, bool neumann, Triplets& t) {
  for (int i = 0; i < n; ++i) {
    double d = 2.0 - sigma;
    if (neumann && (i == 0 || i == n - 1)) d -= 1.0;
    t.emplace_back(first + i, first + i, d);
    if (i + 1 < n) t.emplace_back(first + i, first + i + 1, -1.0);
  }
}

SparseMatrix Laplacian1D(int n, double sigma, bool neumann = false) {
  Triplets t;
  AddLaplacian1D(0, n, sigma, neumann, t);
  return Upper(n, t);
}

// Eigenvalues of the Dirichlet tridiag(−1, 2, −1): 2 − 2cos(kπ/(n+1)), k = 1..n.
std::vector<double> Laplacian1DEigenvalues(int n) {
  std::vector<double> ev;
  for (int k = 1; k <= n; ++k) ev.push_back(2.0 - 2.0 * std::cos(k * std::numbers::pi / (n + 1)));
  std::sort(ev.begin(), ev.end());
  return ev;
}

// T_nx ⊗ I + I ⊗ T_ny − σI on an nx × ny grid (5-point stencil).
SparseMatrix Laplacian2D(int nx, int ny, double sigma, bool neumann = false) {
  Triplets t;
  auto id = [nx](int i, int j) { return i + nx * j; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      double d = 4.0 - sigma;
      if (neumann) d -= (i == 0) + (i == nx - 1) + (j == 0) + (j == ny - 1);
      t.emplace_back(id(i, j), id(i, j), d);
      if (i + 1 < nx) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (j + 1 < ny) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
  return Upper(nx * ny, t);
}

// All sums λ_i(nx) + λ_j(ny), sorted.
std::vector<double> Laplacian2DEigenvalues(int nx, int ny) {
  std::vector<double> ev;
  for (double a : Laplacian1DEigenvalues(nx))
    for (double b : Laplacian1DEigenvalues(ny)) ev.push_back(a + b);
  std::sort(ev.begin(), ev.end());
  return ev;
}

// A shift with exactly `m` of the sorted eigenvalues below it: midway between
// the m-th and (m+1)-th, moved up past clusters (returns the count below it).
double ShiftBelow(const std::vector<double>& ev, int& m) {
  const int n = static_cast<int>(ev.size());
  if (m <= 0) {
    m = 0;
    return ev.front() - 1.0;
  }
  while (m < n && ev[m] - ev[m - 1] < 1e-9) ++m;
  if (m >= n) {
    m = n;
    return ev.back() + 1.0;
  }
  return 0.5 * (ev[m - 1] + ev[m]);
}

// S K S for the upper triangle K.
SparseMatrix ScaleSymmetric(const SparseMatrix& upper, const Eigen::VectorXd& s) {
  SparseMatrix k = upper;
  for (int j = 0; j < k.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(k, j); it; ++it) it.valueRef() *= s[it.row()] * s[j];
  return k;
}

// Random per-DOF scales 10^[−e, e]: units in which the same problem is posed.
Eigen::VectorXd RandomScales(int n, double e, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-e, e);
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s[i] = std::pow(10.0, u(rng));
  return s;
}

// MᵀM + shift·I, M with random entries on a 5-point stencil of an nx × ny grid.
SparseMatrix RandomSpd(int nx, int ny, double shift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = nx * ny;
  Triplets t;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int row = i + nx * j;
      t.emplace_back(row, row, u(rng));
      if (i > 0) t.emplace_back(row, row - 1, u(rng));
      if (i + 1 < nx) t.emplace_back(row, row + 1, u(rng));
      if (j > 0) t.emplace_back(row, row - nx, u(rng));
      if (j + 1 < ny) t.emplace_back(row, row + nx, u(rng));
    }
  SparseMatrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  SparseMatrix identity(n, n);
  identity.setIdentity();
  SparseMatrix a = SparseMatrix(m.transpose() * m) + shift * identity;
  SparseMatrix upper = a.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  return upper;
}

// A shell-tangent-like matrix: 5 DOFs per node on an nx × ny grid of nodes,
// one random SPD 20 × 20 block per 4-node element, minus σI. With `singular`,
// each block is projected to annihilate the vector of ones (as element
// tangents annihilate rigid motions): the sum is semidefinite with exactly one
// zero eigenvalue (generic random blocks).
SparseMatrix ShellLike(int nx, int ny, double sigma, std::mt19937_64& rng, bool singular = false) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 5 * nx * ny;
  Triplets t;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      Eigen::Matrix<double, 20, 20> r;
      for (int a = 0; a < 20; ++a)
        for (int b = 0; b < 20; ++b) r(a, b) = u(rng);
      Eigen::Matrix<double, 20, 20> block =
          r.transpose() * r + 0.1 * Eigen::Matrix<double, 20, 20>::Identity();
      if (singular) {
        const Eigen::Matrix<double, 20, 20> p = Eigen::Matrix<double, 20, 20>::Identity() -
                                                Eigen::Matrix<double, 20, 20>::Constant(1.0 / 20.0);
        block = p * block * p;
      }
      const int nodes[4] = {i + nx * j, i + 1 + nx * j, i + 1 + nx * (j + 1), i + nx * (j + 1)};
      for (int a = 0; a < 20; ++a)
        for (int b = 0; b < 20; ++b) {
          const int ga = 5 * nodes[a / 5] + a % 5;
          const int gb = 5 * nodes[b / 5] + b % 5;
          if (ga <= gb) t.emplace_back(ga, gb, block(a, b));
        }
    }
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, -sigma);
  return Upper(n, t);
}

// Eigenvalues of a symmetric matrix from its upper triangle, densely (Eigen's
// QR algorithm: independent of the code under test).
std::vector<double> DenseEigenvalues(const SparseMatrix& upper) {
  const Eigen::MatrixXd dense =
      Eigen::MatrixXd(SparseMatrix(upper.selfadjointView<Eigen::Upper>()));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd ev = solver.eigenvalues();
  return std::vector<double>(ev.data(), ev.data() + ev.size());
}

// Analyse, factorise and check the inertia and the solve, by both paths.
void ExpectInertia(const SparseMatrix& k, int negative, double tolerance, std::mt19937_64& rng) {
  for (FactorizationPath path : {FactorizationPath::kLltFirst, FactorizationPath::kLdltOnly}) {
    SCOPED_TRACE(path == FactorizationPath::kLltFirst ? "LLT first" : "LDLT only");
    SparseCholesky chol(path);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.negative_pivots, negative);
    EXPECT_EQ(info.zero_pivots, 0);
    EXPECT_EQ(info.positive_definite, negative == 0);
    EXPECT_EQ(info.used_ldlt, path == FactorizationPath::kLdltOnly || negative != 0);
    const Eigen::VectorXd b = RandomVector(static_cast<int>(k.rows()), rng);
    EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), tolerance);
  }
}

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
    SparseCholesky chol(FactorizationPath::kLltFirst);
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

// The solution of the last factorisation does not depend on the caller's
// matrix staying alive or unchanged.
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

TEST(SparseCholesky, SingularMatricesReportZeroPivots) {
  std::mt19937_64 rng(10);
  // Neumann Laplacians: positive semidefinite, one zero eigenvalue.
  for (int n : {2, 50, 1000, 5000}) {
    SCOPED_TRACE(testing::Message() << "1-D Neumann, n = " << n);
    SparseCholesky chol(FactorizationPath::kLltFirst);
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
      SparseCholesky chol(FactorizationPath::kLltFirst);
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
      SparseCholesky chol(FactorizationPath::kLltFirst);
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
    SparseCholesky chol(FactorizationPath::kLltFirst);
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
    SparseCholesky chol(FactorizationPath::kLltFirst);
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
    SparseCholesky chol(FactorizationPath::kLltFirst);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.zero_pivots, 10);
    EXPECT_EQ(info.negative_pivots, 0);
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
