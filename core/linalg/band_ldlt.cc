#include "core/linalg/band_ldlt.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drape {
namespace {

// Columns per panel. The panel is factorised column by column (vector
// updates); what lies below it is updated by one matrix product per panel.
constexpr int kMaxBlock = 16;

using Stride = Eigen::OuterStride<>;
using BlockMap = Eigen::Map<Eigen::MatrixXd, 0, Stride>;

}  // namespace

BandLdlt::BandLdlt(int n, int band)
    : n_(n),
      band_(std::max(band, 0)),
      block_(std::clamp(band, 1, kMaxBlock)),
      ld_(band_ + block_),
      stride_(ld_ - 1),
      data_(static_cast<size_t>(std::max(n, 0)) * ld_, 0.0),
      d_(std::max(n, 0)) {
  if (n < 0 || band < 0)
    throw std::invalid_argument("BandLdlt: a matrix of order " + std::to_string(n) +
                                " and half-bandwidth " + std::to_string(band));
}

double BandLdlt::Bytes(int n, int band) {
  return 8.0 * static_cast<double>(n) * (band + std::clamp(band, 1, kMaxBlock));
}

double BandLdlt::Flops(int n, int band) {
  return static_cast<double>(n) * band * (band + 1);
}

void BandLdlt::Load(const Eigen::SparseMatrix<double>& upper) {
  if (upper.rows() != n_ || upper.cols() != n_)
    throw std::invalid_argument("BandLdlt: a matrix of order " + std::to_string(upper.rows()) +
                                " for a factor of order " + std::to_string(n_));
  std::fill(data_.begin(), data_.end(), 0.0);
  const int* p = upper.outerIndexPtr();
  const int* i = upper.innerIndexPtr();
  const double* x = upper.valuePtr();
  for (int j = 0; j < n_; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k) {
      if (i[k] > j) continue;  // the lower triangle of an upper-triangle input: none
      if (j - i[k] > band_)
        throw std::invalid_argument("BandLdlt: entry (" + std::to_string(i[k]) + ", " +
                                    std::to_string(j) + ") lies outside the half-bandwidth " +
                                    std::to_string(band_));
      *At(j, i[k]) = x[k];  // stored as the lower triangle
    }
}

// Columns [first, end) down to row rows_end: each pivot, then its column
// scaled and its rank-one update of the panel's later columns.
void BandLdlt::FactorizePanel(
    int first, int end, int rows_end, double zero_bound, Inertia& inertia) {
  for (int j = first; j < end; ++j) {
    double d = *At(j, j);
    if (!(std::abs(d) > zero_bound)) {
      ++inertia.zero;
      d = d < 0 ? -zero_bound : zero_bound;
    } else {
      inertia.negative += d < 0;
      inertia.smallest = std::min(inertia.smallest, std::abs(d));
    }
    *At(j, j) = d;
    d_[j] = d;
    const int below = rows_end - j - 1;
    if (below <= 0) continue;
    Eigen::Map<Eigen::VectorXd> column(At(j + 1, j), below);
    for (int c = j + 1; c < end; ++c) {
      const int length = rows_end - c;
      Eigen::Map<Eigen::VectorXd>(At(c, c), length) -=
          (column[c - j - 1] / d) * column.tail(length);
    }
    column /= d;
  }
}

// A22 −= L21 D1 L21ᵀ below the panel [first, end), lower triangle only.
void BandLdlt::UpdateTrailing(int first, int end, int rows_end) {
  const int rows = rows_end - end, cols = end - first;
  const BlockMap l21(At(end, first), rows, cols, Stride(stride_));
  const Eigen::MatrixXd weighted = l21 * d_.segment(first, cols).asDiagonal();
  BlockMap a22(At(end, end), rows, rows, Stride(stride_));
  a22.triangularView<Eigen::Lower>() -= weighted * l21.transpose();
}

BandLdlt::Inertia BandLdlt::Factorize(const Eigen::SparseMatrix<double>& upper, double zero_bound) {
  Load(upper);
  Inertia inertia;
  for (int first = 0; first < n_; first += block_) {
    const int end = std::min(n_, first + block_);
    const int rows_end = std::min(n_, end + band_);
    FactorizePanel(first, end, rows_end, zero_bound, inertia);
    if (rows_end > end) UpdateTrailing(first, end, rows_end);
  }
  return inertia;
}

// Panel by panel, as the factorisation: a small unit-triangular solve on the
// panel's rows, then one matrix-vector product for the rows below it (each
// row of x read once per panel, not once per column).
Eigen::VectorXd BandLdlt::Solve(const Eigen::VectorXd& b) const {
  if (b.size() != n_)
    throw std::invalid_argument("BandLdlt: a right-hand side of size " + std::to_string(b.size()) +
                                " for a factor of order " + std::to_string(n_));
  using ConstBlock = Eigen::Map<const Eigen::MatrixXd, 0, Stride>;
  Eigen::VectorXd x = b;
  for (int first = 0; first < n_; first += block_) {
    const int cols = std::min(n_, first + block_) - first;
    const int rows = std::min(n_, first + cols + band_) - first - cols;
    const ConstBlock l11(At(first, first), cols, cols, Stride(stride_));
    l11.triangularView<Eigen::UnitLower>().solveInPlace(x.segment(first, cols));
    if (rows > 0)
      x.segment(first + cols, rows).noalias() -=
          ConstBlock(At(first + cols, first), rows, cols, Stride(stride_)) * x.segment(first, cols);
  }
  x.array() /= d_.array();
  const int last = ((n_ - 1) / block_) * block_;
  for (int first = last; first >= 0; first -= block_) {
    const int cols = std::min(n_, first + block_) - first;
    const int rows = std::min(n_, first + cols + band_) - first - cols;
    if (rows > 0)
      x.segment(first, cols).noalias() -=
          ConstBlock(At(first + cols, first), rows, cols, Stride(stride_)).transpose() *
          x.segment(first + cols, rows);
    const ConstBlock l11(At(first, first), cols, cols, Stride(stride_));
    l11.triangularView<Eigen::UnitLower>().transpose().solveInPlace(x.segment(first, cols));
  }
  return x;
}

}  // namespace drape
