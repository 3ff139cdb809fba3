// Sparse symmetric factorisation of the tangent with CHOLMOD.
//
// Analyze once per model (the pattern does not change), Factorize per Newton
// iteration, Solve per right-hand side. Supernodal LLᵀ (fast, BLAS) is tried
// first and doubles as the positive-definiteness test; when it fails, a
// simplicial LDLᵀ gives the inertia: the number of negative pivots, the
// stability indicator of the path following (a change means a limit or
// bifurcation point was crossed). Small matrices, where the supernodal path
// does not pay, go straight to an LDLᵀ: a dense-kernel band LDLᵀ
// (band_ldlt.h) on a reverse Cuthill–McKee ordering where the band is narrow
// (strips, small sheets), CHOLMOD's simplicial one otherwise.
#pragma once

#include <Eigen/SparseCore>

#include <memory>

#include "core/linalg/machine_resources.h"

namespace drape {

struct FactorizationInfo {
  bool positive_definite = false;
  int negative_pivots = -1;  // 0 when positive definite
  int zero_pivots = 0;       // pivots below the dbound in magnitude (singular)
  bool used_ldlt = false;
  bool used_band = false;  // the band LDLᵀ (band_ldlt.h) gave the verdict
};

enum class FactorizationPath {
  kAuto,      // LDLᵀ only below a measured size, LLᵀ first above it unless the
              // last factorisation was indefinite
  kLltFirst,  // supernodal LLᵀ, LDLᵀ when it is not positive definite
  kLdltOnly,  // simplicial LDLᵀ always
  kBand,      // banded LDLᵀ on a reverse Cuthill–McKee ordering always
};

class SparseCholesky {
 public:
  explicit SparseCholesky(FactorizationPath path = FactorizationPath::kAuto);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // `upper`: the upper triangle (column-major, compressed, sorted indices) of
  // the symmetric matrix. Only its pattern is used. Throws std::runtime_error
  // when CHOLMOD fails (out of memory), or, before any numeric work, when
  // the factor would not fit in the memory limit: one message with the
  // estimate.
  void Analyze(const Eigen::SparseMatrix<double>& upper);

  // The memory the factor may take [bytes]; 0 (the default): what the
  // machine has available when Analyze runs (MemAvailable).
  void SetMemoryLimit(double bytes) { memory_limit_ = bytes; }
  // The factor's size from the last analysis [bytes].
  double FactorBytes() const { return factor_bytes_; }

  // Numeric factorisation of a matrix with the analysed pattern.
  FactorizationInfo Factorize(const Eigen::SparseMatrix<double>& upper);

  // x = K⁻¹ b with the last factorisation. After an LDLᵀ (no pivoting, so not
  // backward stable) the solution is refined iteratively against `upper`.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;

  const FactorizationInfo& info() const { return info_; }

 private:
  struct Impl;
  FactorizationPath path_;
  std::unique_ptr<Impl> impl_;
  FactorizationInfo info_;
  double memory_limit_ = 0;
  double factor_bytes_ = 0;
};

}  // namespace drape
