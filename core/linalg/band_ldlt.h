// LDLᵀ of a symmetric band matrix without pivoting, blocked so that its
// work is dense matrix products (LAPACK's dpbtrf layout, with D for the
// indefinite tangents past a critical point). For the small tangents of
// strips and small sheets ordered by reverse Cuthill–McKee
// (band_ordering.h) it does in one pass, with dense kernels, what CHOLMOD's
// simplicial LDLᵀ does entry by entry: the factorisation and the inertia.
//
// Pivots with |d| ≤ `zero_bound` are replaced by ±zero_bound (+ for an exact
// zero) and counted as zero, CHOLMOD's dbound rule, so the factorisation runs
// to the end and reports them.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <limits>
#include <vector>

namespace drape {

class BandLdlt {
 public:
  // Storage for a matrix of order `n` and half-bandwidth `band`.
  BandLdlt(int n, int band);

  int size() const { return n_; }
  int band() const { return band_; }
  // Floating-point operations of one factorisation of order n and
  // half-bandwidth b, n·b·(b + 1) (as CHOLMOD counts: a multiply-add is 2).
  static double Flops(int n, int band);
  double Bytes() const { return 8.0 * static_cast<double>(data_.size()); }
  // The storage of a factor of order n and half-bandwidth b [bytes].
  static double Bytes(int n, int band);

  struct Inertia {
    int negative = 0;
    int zero = 0;
    double smallest = std::numeric_limits<double>::infinity();  // |d| above the bound
  };
  // Factorises `upper` (the upper triangle, compressed, column-major, every
  // entry within the band).
  Inertia Factorize(const Eigen::SparseMatrix<double>& upper, double zero_bound);

  // x = (L D Lᵀ)⁻¹ b with the last factorisation.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;

 private:
  // Entry (i, j), j ≤ i ≤ j + ld − 1, lives at data_[j·(ld − 1) + i]: every
  // column holds ld rows from its diagonal down, so a block of rows below a
  // block of columns is a dense matrix of outer stride ld − 1 (LAPACK's
  // band storage read with LDAB − 1). ld = band + block: the rows a panel's
  // first column reaches.
  double* At(int i, int j) { return data_.data() + static_cast<size_t>(j) * stride_ + i; }
  const double* At(int i, int j) const {
    return data_.data() + static_cast<size_t>(j) * stride_ + i;
  }
  void Load(const Eigen::SparseMatrix<double>& upper);
  void FactorizePanel(int first, int end, int rows_end, double zero_bound, Inertia& inertia);
  void UpdateTrailing(int first, int end, int rows_end);

  int n_, band_, block_, ld_, stride_;
  std::vector<double> data_;
  Eigen::VectorXd d_;
};

}  // namespace drape
