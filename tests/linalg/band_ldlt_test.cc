// The band LDLᵀ and its ordering: reverse Cuthill–McKee gives a permutation
// whose band is that of a grid numbered across its width, and the band
// factorisation's inertia and solves agree with dense eigenvalues (Eigen's
// QR algorithm) and residuals.
#include "core/linalg/band_ldlt.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "core/linalg/band_ordering.h"
#include "core/linalg/sparse_cholesky.h"
#include "support/test_matrices.h"

namespace drape {
namespace {

using test::DenseEigenvalues;
using test::RandomVector;
using test::RelativeResidual;
using test::ShellLike;
using test::SparseMatrix;
using test::Triplets;
using test::Upper;

// `upper` with its rows and columns renumbered: row r of the result is row
// perm[r] of `upper`.
SparseMatrix Permuted(const SparseMatrix& upper, const std::vector<int>& perm) {
  std::vector<int> inverse(perm.size());
  for (size_t r = 0; r < perm.size(); ++r) inverse[perm[r]] = static_cast<int>(r);
  Triplets t;
  for (int j = 0; j < upper.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(upper, j); it; ++it) {
      const int a = inverse[it.row()], b = inverse[j];
      t.emplace_back(std::min(a, b), std::max(a, b), it.value());
    }
  return Upper(static_cast<int>(perm.size()), t);
}

// A random renumbering of `upper`'s rows (what a mesher's numbering may be).
SparseMatrix Shuffled(const SparseMatrix& upper, std::mt19937_64& rng) {
  std::vector<int> perm(upper.rows());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  return Permuted(upper, perm);
}

bool IsPermutation(std::vector<int> perm, int n) {
  std::sort(perm.begin(), perm.end());
  for (int r = 0; r < n; ++r)
    if (perm[r] != r) return false;
  return static_cast<int>(perm.size()) == n;
}

int NegativeEigenvalues(const SparseMatrix& upper) {
  const std::vector<double> ev = DenseEigenvalues(upper);
  return static_cast<int>(std::count_if(ev.begin(), ev.end(), [](double e) { return e < 0; }));
}

// A strip of nx × ny nodes (5 DOFs each, quads), renumbered at random. From
// the far level set, the breadth-first levels are the strip's cross-sections
// of `across` nodes, and a node's neighbours lie in its own level or the next
// ones: at most 2·across − 1 nodes further on, a half-bandwidth of at most
// 5(2·across − 1) + 4. The band cannot be narrower than a cross-section's
// 5·across DOFs.
TEST(ReverseCuthillMcKee, FindsTheBandOfAStripFromAShuffledNumbering) {
  std::mt19937_64 rng(11);
  for (auto [nx, ny] : {std::pair{81, 3}, {41, 2}, {5, 40}, {120, 4}}) {
    SCOPED_TRACE(testing::Message() << nx << " x " << ny << " nodes");
    const SparseMatrix k = Shuffled(ShellLike(nx, ny, 0.0, rng), rng);
    const std::vector<int> perm = ReverseCuthillMcKee(k, RcmStart::kFarLevel);
    ASSERT_TRUE(IsPermutation(perm, static_cast<int>(k.rows())));
    const int across = std::min(nx, ny);
    EXPECT_LE(HalfBandwidth(k, perm), 5 * (2 * across - 1) + 4);
    EXPECT_GT(HalfBandwidth(k, perm), 5 * across);
    const std::vector<int> best = NarrowBandOrdering(k);
    ASSERT_TRUE(IsPermutation(best, static_cast<int>(k.rows())));
    EXPECT_LE(HalfBandwidth(k, best), HalfBandwidth(k, perm));
  }
}

// A square sheet numbered row by row has the band 5(nx + 1) + 4; reverse
// Cuthill–McKee from a corner has L-shaped levels, nearly twice as wide.
// The narrowest of the candidates keeps the row-by-row numbering.
TEST(NarrowBandOrdering, KeepsARowByRowNumberingOfASquare) {
  std::mt19937_64 rng(15);
  const SparseMatrix k = ShellLike(21, 21, 0.0, rng);
  std::vector<int> natural(k.rows());
  std::iota(natural.begin(), natural.end(), 0);
  EXPECT_EQ(HalfBandwidth(k, natural), 5 * 22 + 4);
  EXPECT_GT(HalfBandwidth(k, ReverseCuthillMcKee(k, RcmStart::kPeripheralRow)), 5 * 22 + 4);
  EXPECT_EQ(HalfBandwidth(k, NarrowBandOrdering(k)), 5 * 22 + 4);
}

TEST(ReverseCuthillMcKee, OrdersEveryComponentOfADisconnectedMatrix) {
  std::mt19937_64 rng(12);
  // Two strips side by side in one matrix (two layers of fabric), and an
  // isolated row (a DOF nothing couples).
  const SparseMatrix a = ShellLike(30, 2, 0.0, rng);
  const int n = static_cast<int>(a.rows());
  Triplets t;
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it) {
      t.emplace_back(it.row(), j, it.value());
      t.emplace_back(n + it.row(), n + j, it.value());
    }
  t.emplace_back(2 * n, 2 * n, 1.0);
  const SparseMatrix k = Shuffled(Upper(2 * n + 1, t), rng);
  const std::vector<int> perm = ReverseCuthillMcKee(k, RcmStart::kFarLevel);
  ASSERT_TRUE(IsPermutation(perm, 2 * n + 1));
  EXPECT_LE(HalfBandwidth(k, perm), 5 * 4 + 4);
}

// Random symmetric band matrices, shifted to have a chosen share of negative
// eigenvalues: the pivots' signs must count them (Sylvester), and the solve
// must reach round-off.
TEST(BandLdlt, InertiaAndSolvesOfRandomBandMatrices) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int band : {0, 1, 5, 16, 17, 40}) {
    for (double shift : {-3.0, 0.0, 2.0, 4.0}) {
      const int n = 150;
      Triplets t;
      for (int j = 0; j < n; ++j) {
        t.emplace_back(j, j, 4.0 + shift + u(rng));
        for (int i = std::max(0, j - band); i < j; ++i) t.emplace_back(i, j, u(rng) / (band + 1));
      }
      const SparseMatrix k = Upper(n, t);
      SCOPED_TRACE(testing::Message() << "band " << band << ", shift " << shift);
      BandLdlt ldlt(n, band);
      const BandLdlt::Inertia inertia = ldlt.Factorize(k, n * 1e-16);
      EXPECT_EQ(inertia.zero, 0);
      EXPECT_EQ(inertia.negative, NegativeEigenvalues(k));
      const Eigen::VectorXd b = RandomVector(n, rng);
      EXPECT_LT(RelativeResidual(k, ldlt.Solve(b), b), 1e-12);
    }
  }
}

// A shell-like block matrix in its RCM ordering, indefinite by a shift: the
// band factorisation of the renumbered matrix has the dense inertia.
TEST(BandLdlt, ShellLikeMatricesInRcmOrder) {
  std::mt19937_64 rng(14);
  for (auto [nx, ny] : {std::pair{3, 20}, {9, 8}}) {
    for (double sigma : {0.0, 1.0, 3.0}) {
      const SparseMatrix k0 = ShellLike(nx, ny, sigma, rng);
      const std::vector<int> perm = NarrowBandOrdering(k0);
      const SparseMatrix k = Permuted(k0, perm);
      const int n = static_cast<int>(k.rows());
      SCOPED_TRACE(testing::Message() << nx << " x " << ny << ", sigma " << sigma);
      BandLdlt ldlt(n, HalfBandwidth(k0, perm));
      const BandLdlt::Inertia inertia = ldlt.Factorize(k, n * 1e-15);
      EXPECT_EQ(inertia.zero, 0);
      EXPECT_EQ(inertia.negative, NegativeEigenvalues(k));
      const Eigen::VectorXd b = RandomVector(n, rng);
      EXPECT_LT(RelativeResidual(k, ldlt.Solve(b), b), 1e-9);
    }
  }
}

// kAuto takes the band for every factorisation of a strip's tangent (its
// band's work is close to the fill-reducing factor's). A large scalar 2-D
// Laplacian, whose band is wide for its fill, takes CHOLMOD's LLᵀ, and the
// band only when the LLᵀ finds it indefinite. Each counts the negative
// eigenvalues (dense, and in closed form for the Laplacian).
TEST(SparseCholeskyAuto, TakesTheBandWhereItPays) {
  std::mt19937_64 rng(16);
  const SparseMatrix strip = Shuffled(ShellLike(81, 3, 2.0, rng), rng);
  const std::vector<double> ev = test::Laplacian2DEigenvalues(150, 150);
  int below = 5;
  const double sigma = test::ShiftBelow(ev, below);
  const SparseMatrix definite = test::Laplacian2D(150, 150, 0.0);
  const SparseMatrix indefinite = test::Laplacian2D(150, 150, sigma);
  for (const auto& [k, band, negative] : {std::tuple{&strip, true, NegativeEigenvalues(strip)},
                                          {&definite, false, 0},
                                          {&indefinite, true, below}}) {
    SparseCholesky chol;
    chol.Analyze(*k);
    const FactorizationInfo info = chol.Factorize(*k);
    EXPECT_EQ(info.used_band, band);
    EXPECT_EQ(info.negative_pivots, negative);
    const Eigen::VectorXd b = RandomVector(static_cast<int>(k->rows()), rng);
    EXPECT_LT(RelativeResidual(*k, chol.Solve(b), b), 1e-10);
  }
}

TEST(BandLdlt, RefusesAnEntryOutsideItsBand) {
  Triplets t{{0, 0, 1.0}, {1, 1, 1.0}, {2, 2, 1.0}, {0, 2, 0.5}};
  BandLdlt ldlt(3, 1);
  EXPECT_THROW(ldlt.Factorize(Upper(3, t), 1e-15), std::invalid_argument);
  EXPECT_THROW(ldlt.Solve(Eigen::VectorXd::Ones(2)), std::invalid_argument);
}

}  // namespace
}  // namespace drape
