// Sparse symmetric test matrices with known spectra for the factorisation
// tests (tests/linalg/sparse_cholesky*_test.cc): 1-D and 2-D Laplacians and
// their eigenvalues in closed form, shifts that put a chosen number of them
// below zero, random SPD and shell-like block matrices, symmetric scalings,
// and Eigen's dense eigenvalues as an independent check.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/linalg/sparse_cholesky.h"

namespace drape::test {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

// The upper triangle, compressed, of the symmetric matrix given by triplets of
// both triangles (or of the upper one only).
inline SparseMatrix Upper(int n, const Triplets& t) {
  Triplets upper;
  for (const auto& e : t)
    if (e.row() <= e.col()) upper.push_back(e);
  SparseMatrix k(n, n);
  k.setFromTriplets(upper.begin(), upper.end());
  k.makeCompressed();
  return k;
}

inline double RelativeResidual(const SparseMatrix& upper,
                               const Eigen::VectorXd& x,
                               const Eigen::VectorXd& b) {
  const Eigen::VectorXd kx = upper.selfadjointView<Eigen::Upper>() * x;
  return (kx - b).norm() / b.norm();
}

inline Eigen::VectorXd RandomVector(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

// tridiag(−1, 2, −1) − σI of size n (Dirichlet ends), as upper triplets at
// offset `first`; with `neumann`, the end diagonals are 1 (a zero eigenvalue).
inline void AddLaplacian1D(int first, int n, double sigma, bool neumann, Triplets& t) {
  for (int i = 0; i < n; ++i) {
    double d = 2.0 - sigma;
    if (neumann && (i == 0 || i == n - 1)) d -= 1.0;
    t.emplace_back(first + i, first + i, d);
    if (i + 1 < n) t.emplace_back(first + i, first + i + 1, -1.0);
  }
}

inline SparseMatrix Laplacian1D(int n, double sigma, bool neumann = false) {
  Triplets t;
  AddLaplacian1D(0, n, sigma, neumann, t);
  return Upper(n, t);
}

// Eigenvalues of the Dirichlet tridiag(−1, 2, −1): 2 − 2cos(kπ/(n+1)), k = 1..n.
inline std::vector<double> Laplacian1DEigenvalues(int n) {
  std::vector<double> ev;
  for (int k = 1; k <= n; ++k) ev.push_back(2.0 - 2.0 * std::cos(k * std::numbers::pi / (n + 1)));
  std::sort(ev.begin(), ev.end());
  return ev;
}

// T_nx ⊗ I + I ⊗ T_ny − σI on an nx × ny grid (5-point stencil).
inline SparseMatrix Laplacian2D(int nx, int ny, double sigma, bool neumann = false) {
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
inline std::vector<double> Laplacian2DEigenvalues(int nx, int ny) {
  std::vector<double> ev;
  for (double a : Laplacian1DEigenvalues(nx))
    for (double b : Laplacian1DEigenvalues(ny)) ev.push_back(a + b);
  std::sort(ev.begin(), ev.end());
  return ev;
}

// A shift with exactly `m` of the sorted eigenvalues below it: midway between
// the m-th and (m+1)-th, moved up past clusters (returns the count below it).
inline double ShiftBelow(const std::vector<double>& ev, int& m) {
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
inline SparseMatrix ScaleSymmetric(const SparseMatrix& upper, const Eigen::VectorXd& s) {
  SparseMatrix k = upper;
  for (int j = 0; j < k.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(k, j); it; ++it) it.valueRef() *= s[it.row()] * s[j];
  return k;
}

// Random per-DOF scales 10^[−e, e]: units in which the same problem is posed.
inline Eigen::VectorXd RandomScales(int n, double e, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-e, e);
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s[i] = std::pow(10.0, u(rng));
  return s;
}

// MᵀM + shift·I, M with random entries on a 5-point stencil of an nx × ny grid.
inline SparseMatrix RandomSpd(int nx, int ny, double shift, std::mt19937_64& rng) {
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
inline SparseMatrix ShellLike(
    int nx, int ny, double sigma, std::mt19937_64& rng, bool singular = false) {
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
inline std::vector<double> DenseEigenvalues(const SparseMatrix& upper) {
  const Eigen::MatrixXd dense =
      Eigen::MatrixXd(SparseMatrix(upper.selfadjointView<Eigen::Upper>()));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd ev = solver.eigenvalues();
  return std::vector<double>(ev.data(), ev.data() + ev.size());
}

// Analyse, factorise and check the inertia and the solve, by every path.
inline void ExpectInertia(const SparseMatrix& k,
                          int negative,
                          double tolerance,
                          std::mt19937_64& rng) {
  for (FactorizationPath path :
       {FactorizationPath::kLltFirst, FactorizationPath::kLdltOnly, FactorizationPath::kBand}) {
    SCOPED_TRACE(path == FactorizationPath::kLltFirst   ? "LLT first"
                 : path == FactorizationPath::kLdltOnly ? "LDLT only"
                                                        : "band");
    SparseCholesky chol(path);
    chol.Analyze(k);
    const FactorizationInfo info = chol.Factorize(k);
    EXPECT_EQ(info.negative_pivots, negative);
    EXPECT_EQ(info.zero_pivots, 0);
    EXPECT_EQ(info.positive_definite, negative == 0);
    EXPECT_EQ(info.used_ldlt, path != FactorizationPath::kLltFirst || negative != 0);
    const Eigen::VectorXd b = RandomVector(static_cast<int>(k.rows()), rng);
    EXPECT_LT(RelativeResidual(k, chol.Solve(b), b), tolerance);
  }
}

}  // namespace drape::test
