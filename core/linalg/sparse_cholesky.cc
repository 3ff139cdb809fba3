#include "core/linalg/sparse_cholesky.h"

#include <sys/resource.h>

#include <dlfcn.h>
#include <omp.h>
#include <suitesparse/cholmod.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/linalg/band_ldlt.h"
#include "core/linalg/band_ordering.h"

// Zero pivots. Pivots are judged against the scale of their own row: with
// s_i the power of two for which s_i²·|K_ii| lies in [1/2, 2) (for a zero
// diagonal, the row's largest |K_ij| stands in for |K_ii|; an empty row gets
// s_i = 1), the pivot d_j of row i = Perm[j] counts as zero when
// s_i²·|d_j| ≤ n·ε. This is the backward-error level of a Cholesky
// factorisation, below which a pivot cannot be told from zero, and it does not
// depend on units: a tangent mixing translations and rotations (N/m and N·m)
// gets the same verdict as in any other units. Measured: the pivot that should
// be zero in singular 2-D Laplacians and in singular 5-DOF shell-like matrices
// (n up to 25 000, AMD and METIS orderings) came out at 0.002–0.07·n·ε of its
// diagonal, a margin of 15 or more; genuine pivots of a fabric tangent (bending
// against shear and membrane terms down to about 1e-8) stay far above it
// (n·ε ≈ 2e-11 at n = 10⁵).
//
// The LDLᵀ factorises S K S (S = diag(s), exact: powers of two) with CHOLMOD's
// dbound = n·ε, so such a pivot is replaced by ±dbound (an exact zero by
// +dbound) and the factorisation runs to the end instead of stopping. A
// successful LLᵀ with such a pivot (a semidefinite matrix whose zero pivot
// came out as a positive roundoff) is redone as LDLᵀ, so both paths apply the
// same rule and report it as a zero pivot. Sylvester's law: S K S has the
// inertia of K.

namespace drape {
namespace {

// Iterative refinement after an LDLᵀ (no pivoting, so not backward stable).
constexpr int kMaxRefinementSteps = 3;
constexpr double kRefinementTolerance = 1e-14;

// Below this many flops (CHOLMOD's count for the ordered LLᵀ) the supernodal
// path does not pay: its per-supernode OpenMP regions (CHOLMOD's fixed thread
// count, not ours) and BLAS calls cost more than the arithmetic, and an
// indefinite tangent factorises twice. Such matrices go straight to the
// simplicial LDLᵀ, which gives the inertia in one pass.
// Measured (bench/sparse_cholesky_benchmark.cc): at 2 000 DOFs (1.3e7 flops)
// the two paths take the same time for a definite matrix; at 12 500 (2.6e8)
// the supernodal LLᵀ is twice as fast.
constexpr double kLdltOnlyFlops = 1e6;
// The band LDLᵀ (band_ldlt.h) on the narrowest of a few bandwidth-reducing
// orderings: its dense kernels beat CHOLMOD's simplicial LDLᵀ at every size
// measured, and the supernodal LLᵀ on small matrices, for at most
// kBandWorkRatio times the LLᵀ's flops (bench/sparse_cholesky_benchmark.cc,
// shell-like matrices; ms per factorisation and solve, LLᵀ / simplicial
// LDLᵀ / band): strip 81 × 3 nodes 0.83 / 0.44 / 0.23; 21 × 21 nodes 3.4 /
// 6.3 / 1.5; 51 × 51 36 / 125 / 31; 100 × 100 265 / 1 300 / 367. So:
// below kBandFirstFlops (the LLᵀ's) the band serves every factorisation, in
// one pass with the inertia; above, the LLᵀ comes first and the band is the
// indefinite fallback up to kBandFallbackFlops of its own (200 × 200 would
// take 2e11 and 1.7 GB).
constexpr double kBandFirstFlops = 5e8;
constexpr double kBandWorkRatio = 4;
constexpr double kBandFallbackFlops = 3e10;
// A band pivot this close to the zero-pivot bound (in units of the bound) is
// not trusted: the matrix is factorised again by CHOLMOD's simplicial LDLᵀ,
// whose verdict stands. A band ordering's last pivots gather more roundoff
// than a fill-reducing one's: the pivot that should be zero in singular
// shell-like matrices came out at up to 2·n·ε (CHOLMOD's: 0.07·n·ε), while
// genuine pivots of a fabric tangent stay above 1e-8 (n·ε ≈ 2.5e-13 for a
// strip, 5e-13 for a 20 × 20 sheet).
constexpr double kBandSuspectPivot = 64;
// Below this many flops per factorisation the BLAS runs on one thread.
constexpr double kThreadedBlasFlops = 1e9;

const char* StatusText(int status) {
  switch (status) {
    case CHOLMOD_NOT_INSTALLED:
      return "method not installed";
    case CHOLMOD_OUT_OF_MEMORY:
      return "out of memory";
    case CHOLMOD_TOO_LARGE:
      return "problem too large (integer overflow)";
    case CHOLMOD_INVALID:
      return "invalid input";
    case CHOLMOD_GPU_PROBLEM:
      return "GPU error";
    default:
      return "unknown error";
  }
}

// Errors (negative status) throw; warnings (not positive definite, small
// diagonal) are the caller's to interpret.
// Inside its scope every OpenMP parallel region runs on the calling thread
// alone. CHOLMOD's supernodal factorisation opens a region of a fixed thread
// count (compiled in) for every supernode's scatter, far too little work per
// region: on 2 cores their fork, join and spinning idle threads compete with
// the BLAS threads that do the dense work (measured at 100 × 100: half the
// factorisation time, and as much system time as user time).
class SerialOpenMp {
 public:
  SerialOpenMp() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMp() { omp_set_max_active_levels(levels_); }
  SerialOpenMp(const SerialOpenMp&) = delete;
  SerialOpenMp& operator=(const SerialOpenMp&) = delete;

 private:
  int levels_;
};

// Sets OpenBLAS's thread count when the BLAS is OpenBLAS (looked up at run
// time: Debian may provide another libblas.so.3, which keeps its own
// threading): one thread for a small factorisation, the count it started with
// for a large one. Left as set, not restored: each raise wakes its idle
// threads, which then wait spinning and take the cores from our assembly
// threads (measured: a 20 × 20 drape's assembly 1.5 to 4 times slower).
void UseBlasThreads(bool threaded) {
  using Get = int (*)();
  using Set = void (*)(int);
  static const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  static const auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  static const int initial = get ? get() : 1;
  if (!get || !set) return;
  const int wanted = threaded ? initial : 1;
  if (get() != wanted) set(wanted);
}

void ThrowOnError(const cholmod_common& c, const char* call) {
  if (c.status < CHOLMOD_OK)
    throw std::runtime_error(std::string("SparseCholesky: CHOLMOD ") + call + " failed: " +
                             StatusText(c.status) + " (status " + std::to_string(c.status) + ")");
}

void Start(cholmod_common& c) {
  cholmod_start(&c);
  c.print = 0;  // quiet: NOT_POSDEF is an expected outcome, errors become exceptions
  c.error_handler = nullptr;
}

// A common for one call, finished on every way out.
struct ScopedCommon {
  cholmod_common c;
  ScopedCommon() { Start(c); }
  ~ScopedCommon() { cholmod_finish(&c); }
  ScopedCommon(const ScopedCommon&) = delete;
  ScopedCommon& operator=(const ScopedCommon&) = delete;
};

// A matrix (upper triangle) as a cholmod_sparse, without a copy. CHOLMOD only
// reads it.
cholmod_sparse View(const Eigen::SparseMatrix<double>& a) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(a.rows());
  s.ncol = static_cast<size_t>(a.cols());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<int*>(a.outerIndexPtr());
  s.i = const_cast<int*>(a.innerIndexPtr());
  s.nz = nullptr;
  s.x = const_cast<double*>(a.valuePtr());
  s.z = nullptr;
  s.stype = 1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

// A vector as a one-column cholmod_dense, without a copy (read only).
cholmod_dense View(const Eigen::VectorXd& b) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(b.size());
  d.ncol = 1;
  d.nzmax = static_cast<size_t>(b.size());
  d.d = static_cast<size_t>(b.size());
  d.x = const_cast<double*>(b.data());
  d.z = nullptr;
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

void CheckShape(const Eigen::SparseMatrix<double>& a) {
  if (a.rows() != a.cols())
    throw std::invalid_argument("SparseCholesky: the matrix is not square (" +
                                std::to_string(a.rows()) + " x " + std::to_string(a.cols()) + ")");
  if (!a.isCompressed())
    throw std::invalid_argument("SparseCholesky: the matrix is not compressed (makeCompressed())");
}

// The row scales s (see the top of the file) into `scale`. Throws for a
// non-finite entry (checked in the same pass).
void RowScales(const Eigen::SparseMatrix<double>& a, Eigen::VectorXd& scale) {
  const int n = static_cast<int>(a.cols());
  const int* p = a.outerIndexPtr();
  const int* i = a.innerIndexPtr();
  const double* x = a.valuePtr();
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd row_max = Eigen::VectorXd::Zero(n);  // over the whole symmetric row
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k) {
      const double v = std::abs(x[k]);
      if (!std::isfinite(v))
        throw std::runtime_error("SparseCholesky: the matrix has a non-finite entry");
      if (i[k] == j) diagonal[j] = v;
      row_max[j] = std::max(row_max[j], v);
      row_max[i[k]] = std::max(row_max[i[k]], v);
    }
  scale.resize(n);
  for (int j = 0; j < n; ++j) {
    const double magnitude = diagonal[j] > 0.0 ? diagonal[j] : row_max[j];
    if (magnitude == 0.0) {
      scale[j] = 1.0;
      continue;
    }
    int e;
    std::frexp(magnitude, &e);  // magnitude = f·2^e, f in [1/2, 1)
    // s² · magnitude = f·2^(e − 2·floor(e/2)), in [1/2, 2).
    const int half = e >= 0 ? e / 2 : -((1 - e) / 2);  // floor(e / 2)
    scale[j] = std::ldexp(1.0, -half);
  }
}

// Whether every pivot L_jj² of a numeric supernodal LLᵀ factor is above the
// zero-pivot bound of its row.
bool PivotsAboveBound(const cholmod_factor& f, const Eigen::VectorXd& scale, double bound) {
  const int* super = static_cast<const int*>(f.super);
  const int* pi = static_cast<const int*>(f.pi);
  const int* px = static_cast<const int*>(f.px);
  const int* perm = static_cast<const int*>(f.Perm);
  const double* x = static_cast<const double*>(f.x);
  for (size_t s = 0; s < f.nsuper; ++s) {
    const int first = super[s];
    const int ncols = super[s + 1] - first;
    const int nrows = pi[s + 1] - pi[s];
    for (int k = 0; k < ncols; ++k) {
      const double l = x[px[s] + k * nrows + k];
      const double si = scale[perm ? perm[first + k] : first + k];
      if (!(l * l * si * si > bound)) return false;
    }
  }
  return true;
}

}  // namespace

struct SparseCholesky::Impl {
  // kDelegated: another factorisation decided (`delegate`): the simplicial
  // LDLᵀ where the band's verdict was near a zero pivot, or the band LDLᵀ in
  // its own ordering after an LLᵀ found the matrix indefinite.
  enum class Active { kNone, kLLt, kLDLt, kBand, kDelegated };

  // Two commons, each with fixed settings: supernodal LLᵀ, and the simplicial
  // LDLᵀ fallback analysed with the LLᵀ's permutation.
  cholmod_common ll;
  cholmod_common ldl;
  cholmod_factor* ll_factor = nullptr;
  cholmod_factor* ldl_factor = nullptr;  // analysed on the first fallback
  std::unique_ptr<BandLdlt> band;        // instead of both, for narrow bands
  // Analysed on first need: the simplicial LDLᵀ behind the band, or the
  // band LDLᵀ behind the LLᵀ.
  std::unique_ptr<SparseCholesky> careful, band_fallback;
  bool band_fallback_pays = false;
  const SparseCholesky* delegate = nullptr;

  int n = -1;                     // -1: not analysed
  bool ldlt_only = false;         // small factorisations: skip the LLᵀ attempt
  bool last_indefinite = false;   // the last LDLᵀ found a negative or zero pivot
  double flops = 0;               // of the LLᵀ, CHOLMOD's count
  std::vector<int> outer, inner;  // the analysed pattern
  // The fill-reducing ordering is applied here, not by CHOLMOD: both factors
  // are analysed in the natural order of `permuted` = P K Pᵀ, whose values
  // are scattered through `slot` (K's k-th entry → permuted's slot[k]). That
  // spares CHOLMOD's two permuting transposes per factorisation (12 % of a
  // small strip-fold run).
  std::vector<int> perm;  // permuted row r is row perm[r] of K
  std::vector<int> slot;
  Eigen::SparseMatrix<double> permuted;
  Active active = Active::kNone;
  Eigen::VectorXd scale;  // row scales s of the last factorised (permuted) matrix
  // S K S of the last matrix factorised by LDLᵀ: factorised, and kept for the
  // residuals of the refinement (a copy: the caller may reassemble its matrix
  // before solving).
  Eigen::SparseMatrix<double> scaled;

  Impl() {
    Start(ll);
    ll.supernodal = CHOLMOD_SUPERNODAL;  // AUTO gives small matrices a simplicial LDLᵀ
    ll.final_ll = 1;
    ll.final_asis = 1;
    Natural(ll);

    Start(ldl);
    ldl.supernodal = CHOLMOD_SIMPLICIAL;
    ldl.final_ll = 0;  // read at each simplicial factorisation: LDLᵀ, not LLᵀ
    ldl.final_asis = 1;
    Natural(ldl);
  }

  static void Natural(cholmod_common& c) {
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_NATURAL;
    c.postorder = 0;
  }

  // The ordering CHOLMOD would choose (AMD or METIS, postordered) and its
  // flop count, then `permuted`'s pattern and `slot`.
  double Order(const Eigen::SparseMatrix<double>& upper) {
    ScopedCommon scoped;
    cholmod_common& c = scoped.c;
    c.supernodal = CHOLMOD_SUPERNODAL;
    cholmod_sparse a = View(upper);
    cholmod_factor* symbolic = cholmod_analyze(&a, &c);
    ThrowOnError(c, "analyze");
    if (!symbolic) throw std::runtime_error("SparseCholesky: CHOLMOD analyze failed");
    const int* p = static_cast<const int*>(symbolic->Perm);
    perm.assign(p, p + n);
    const double flops = c.fl;
    cholmod_free_factor(&symbolic, &c);
    PermutePattern();
    return flops;
  }

  // `permuted`'s pattern and `slot` for the ordering `perm`.
  void PermutePattern() {
    std::vector<int> inverse(n);
    for (int r = 0; r < n; ++r) inverse[perm[r]] = r;
    // Entry k of K lands at (row, col) = sorted (inverse[i], inverse[j]);
    // counting sort by column, then by row within each column.
    const int nnz = static_cast<int>(inner.size());
    std::vector<int> row(nnz), col(nnz);
    for (int j = 0; j < n; ++j)
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int a = inverse[inner[k]], b = inverse[j];
        row[k] = std::min(a, b);
        col[k] = std::max(a, b);
      }
    std::vector<int> by_row(nnz), start(n + 1, 0);
    for (int k = 0; k < nnz; ++k) ++start[row[k] + 1];
    for (int r = 0; r < n; ++r) start[r + 1] += start[r];
    for (int k = 0; k < nnz; ++k) by_row[start[row[k]]++] = k;
    std::vector<int> p_outer(n + 1, 0), p_inner(nnz);
    for (int k = 0; k < nnz; ++k) ++p_outer[col[k] + 1];
    for (int j = 0; j < n; ++j) p_outer[j + 1] += p_outer[j];
    std::vector<int> next(p_outer.begin(), p_outer.end() - 1);
    slot.assign(nnz, -1);
    for (int k : by_row) {  // rows ascending: each column comes out sorted
      slot[k] = next[col[k]]++;
      p_inner[slot[k]] = row[k];
    }
    permuted = Eigen::SparseMatrix<double>(n, n);
    permuted.resizeNonZeros(nnz);
    std::copy(p_outer.begin(), p_outer.end(), permuted.outerIndexPtr());
    std::copy(p_inner.begin(), p_inner.end(), permuted.innerIndexPtr());
    permuted.coeffs().setZero();
  }

  // permuted = P K Pᵀ for K with the analysed pattern.
  void Permute(const Eigen::SparseMatrix<double>& k) {
    const double* x = k.valuePtr();
    double* y = permuted.valuePtr();
    const int nnz = static_cast<int>(slot.size());
    for (int q = 0; q < nnz; ++q) y[slot[q]] = x[q];
  }

  ~Impl() {
    FreeFactors();
    cholmod_finish(&ldl);
    cholmod_finish(&ll);
  }

  void FreeFactors() {
    if (ll_factor) cholmod_free_factor(&ll_factor, &ll);
    if (ldl_factor) cholmod_free_factor(&ldl_factor, &ldl);
    band.reset();
    careful.reset();
    band_fallback.reset();
    band_fallback_pays = false;
    delegate = nullptr;
    active = Active::kNone;
  }

  bool SamePattern(const Eigen::SparseMatrix<double>& a) const {
    return a.rows() == n && a.cols() == n &&
           a.nonZeros() == static_cast<Eigen::Index>(inner.size()) &&
           std::equal(outer.begin(), outer.end(), a.outerIndexPtr()) &&
           std::equal(inner.begin(), inner.end(), a.innerIndexPtr());
  }

  // scaled = S K S, for K with the analysed pattern.
  void Scale(const Eigen::SparseMatrix<double>& k) {
    if (scaled.rows() != n || scaled.nonZeros() != k.nonZeros()) scaled = k;
    const int* p = k.outerIndexPtr();
    const int* i = k.innerIndexPtr();
    const double* x = k.valuePtr();
    double* y = scaled.valuePtr();
    for (int j = 0; j < n; ++j)
      for (int q = p[j]; q < p[j + 1]; ++q) y[q] = scale[i[q]] * x[q] * scale[j];
  }

  // Whether the band LDLᵀ serves every factorisation: always under kBand;
  // under kAuto when the LLᵀ is small and the band's work within
  // kBandWorkRatio of it. Then `perm` is the band's ordering and `band` the
  // factor. Otherwise, under kAuto, whether it pays as the indefinite
  // fallback (`band_fallback_pays`).
  bool ChooseBand(const Eigen::SparseMatrix<double>& upper,
                  FactorizationPath path,
                  double memory_limit) {
    if (path != FactorizationPath::kBand && path != FactorizationPath::kAuto) return false;
    std::vector<int> order = NarrowBandOrdering(upper);
    const int width = HalfBandwidth(upper, order);
    const double work = BandLdlt::Flops(n, width);
    if (path == FactorizationPath::kAuto &&
        !(flops < kBandFirstFlops && work <= kBandWorkRatio * flops)) {
      band_fallback_pays =
          work <= kBandFallbackFlops && BandLdlt::Bytes(n, width) < memory_limit / 2;
      return false;
    }
    perm = std::move(order);
    PermutePattern();
    band = std::make_unique<BandLdlt>(n, width);
    return true;
  }

  // The factorisation by `solver` (analysed on first use with `path`), as
  // this one's verdict.
  FactorizationInfo Delegate(std::unique_ptr<SparseCholesky>& solver,
                             FactorizationPath path,
                             const Eigen::SparseMatrix<double>& upper,
                             double memory_limit) {
    if (!solver) {
      solver = std::make_unique<SparseCholesky>(path);
      solver->SetMemoryLimit(memory_limit);
      solver->Analyze(upper);
    }
    const FactorizationInfo info = solver->Factorize(upper);
    delegate = solver.get();
    active = Active::kDelegated;
    return info;
  }

  void AnalyzeLdlt(cholmod_sparse& a) {
    ldl_factor = cholmod_analyze(&a, &ldl);
    ThrowOnError(ldl, "analyze (LDLᵀ)");
    if (!ldl_factor) throw std::runtime_error("SparseCholesky: CHOLMOD analyze (LDLᵀ) failed");
  }

  // y = F⁻¹ b with the factor F of the active path; `c` is the caller's own.
  Eigen::VectorXd FactorSolve(const Eigen::VectorXd& b, cholmod_common& c) const {
    if (active == Active::kBand) return band->Solve(b);
    cholmod_factor* f = active == Active::kLLt ? ll_factor : ldl_factor;
    cholmod_dense rhs = View(b);
    cholmod_dense* y = cholmod_solve(CHOLMOD_A, f, &rhs, &c);
    if (!y) {
      ThrowOnError(c, "solve");
      throw std::runtime_error("SparseCholesky: CHOLMOD solve failed");
    }
    Eigen::VectorXd result = Eigen::Map<const Eigen::VectorXd>(static_cast<double*>(y->x), n);
    cholmod_free_dense(&y, &c);
    return result;
  }

  // After an LDLᵀ: K⁻¹ b = S (S K S)⁻¹ S b, and K x = S⁻¹ (S K S) S⁻¹ x.
  Eigen::VectorXd LdltSolve(const Eigen::VectorXd& b, cholmod_common& c) const {
    return scale.cwiseProduct(FactorSolve(scale.cwiseProduct(b), c));
  }
  Eigen::VectorXd Multiply(const Eigen::VectorXd& x) const {
    return (scaled.selfadjointView<Eigen::Upper>() * x.cwiseQuotient(scale)).cwiseQuotient(scale);
  }

  Eigen::VectorXd SolvePermuted(const Eigen::VectorXd& b, cholmod_common& c) const;
};

SparseCholesky::SparseCholesky(FactorizationPath path)
    : path_(path), impl_(std::make_unique<Impl>()) {}

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::Analyze(const Eigen::SparseMatrix<double>& upper) {
  CheckShape(upper);
  Impl& m = *impl_;
  m.FreeFactors();
  m.n = -1;
  m.scaled.resize(0, 0);
  info_ = FactorizationInfo{};

  const int n = static_cast<int>(upper.rows());
  m.outer.assign(upper.outerIndexPtr(), upper.outerIndexPtr() + n + 1);
  m.inner.assign(upper.innerIndexPtr(), upper.innerIndexPtr() + upper.nonZeros());
  m.n = n;
  try {
    m.flops = m.Order(upper);
    double nonzeros = 0;
    const double limit = memory_limit_ > 0 ? memory_limit_ : AvailableMemoryBytes();
    if (m.ChooseBand(upper, path_, limit)) {
      nonzeros = static_cast<double>(n) * (m.band->band() + 1);
      factor_bytes_ = m.band->Bytes();
    } else {
      m.ldlt_only = path_ == FactorizationPath::kLdltOnly ||
                    (path_ == FactorizationPath::kAuto && m.flops < kLdltOnlyFlops);
      cholmod_sparse a = View(m.permuted);
      m.ll_factor = cholmod_analyze(&a, &m.ll);
      ThrowOnError(m.ll, "analyze");
      if (!m.ll_factor) throw std::runtime_error("SparseCholesky: CHOLMOD analyze failed");
      // Values and row indices of L (a supernodal factor stores its padded
      // blocks), before any of it is allocated.
      nonzeros = m.ll.lnz;
      factor_bytes_ =
          std::max(12 * nonzeros, m.ll_factor->is_super ? 8.0 * m.ll_factor->xsize : 0.0);
    }
    if (factor_bytes_ > limit) {
      char message[320];
      std::snprintf(message,
                    sizeof message,
                    "the factorisation needs about %.3g GB (%.3g nonzeros in the factor of %d "
                    "unknowns), more than the %.3g GB of memory available: use a coarser mesh "
                    "(fabric.mesh) or solve the path on one (solver.sequencing)",
                    factor_bytes_ / 1e9,
                    nonzeros,
                    n,
                    limit / 1e9);
      throw std::runtime_error(message);
    }
  } catch (...) {
    m.n = -1;
    throw;
  }
}

FactorizationInfo SparseCholesky::Factorize(const Eigen::SparseMatrix<double>& upper) {
  Impl& m = *impl_;
  if (m.n < 0) throw std::logic_error("SparseCholesky: Factorize called before Analyze");
  CheckShape(upper);
  if (!m.SamePattern(upper))
    throw std::invalid_argument(
        "SparseCholesky: the matrix does not have the analysed pattern (" +
        std::to_string(upper.rows()) + " x " + std::to_string(upper.cols()) + ", " +
        std::to_string(upper.nonZeros()) + " entries; analysed " + std::to_string(m.n) + " x " +
        std::to_string(m.n) + ", " + std::to_string(m.inner.size()) + " entries)");
  m.active = Impl::Active::kNone;
  info_ = FactorizationInfo{};
  m.Permute(upper);
  RowScales(m.permuted, m.scale);  // throws for a non-finite entry
  const double bound = std::max(1, m.n) * std::numeric_limits<double>::epsilon();

  if (m.band) {
    m.Scale(m.permuted);
    const BandLdlt::Inertia inertia = m.band->Factorize(m.scaled, bound);
    if (inertia.zero > 0 || inertia.smallest <= kBandSuspectPivot * bound)
      return info_ = m.Delegate(m.careful, FactorizationPath::kLdltOnly, upper, memory_limit_);
    m.active = Impl::Active::kBand;
    info_.used_ldlt = true;
    info_.used_band = true;
    info_.negative_pivots = inertia.negative;
    info_.zero_pivots = inertia.zero;
    info_.positive_definite = inertia.negative == 0 && inertia.zero == 0;
    return info_;
  }
  UseBlasThreads(m.flops >= kThreadedBlasFlops);
  // Supernodal LLᵀ: the positive-definiteness test and the fast path.
  cholmod_sparse a = View(m.permuted);
  // Past a critical point the tangents stay indefinite for a while: kAuto
  // skips the LLᵀ attempt after an indefinite factorisation (it would fail
  // after much of its work), and tries it again after a definite one.
  const bool try_llt = !m.ldlt_only && !(path_ == FactorizationPath::kAuto && m.last_indefinite);
  if (try_llt) {
    const SerialOpenMp serial;
    cholmod_factorize(&a, m.ll_factor, &m.ll);
    ThrowOnError(m.ll, "factorize (LLᵀ)");
  }
  if (try_llt && m.ll.status == CHOLMOD_OK && m.ll_factor->minor == static_cast<size_t>(m.n) &&
      PivotsAboveBound(*m.ll_factor, m.scale, bound)) {
    m.active = Impl::Active::kLLt;
    info_.positive_definite = true;
    info_.negative_pivots = 0;
    return info_;
  }

  if (m.band_fallback_pays) {
    info_ = m.Delegate(m.band_fallback, FactorizationPath::kBand, upper, memory_limit_);
    m.last_indefinite = !info_.positive_definite;
    return info_;
  }
  // Simplicial LDLᵀ of S K S for the inertia, in the same ordering.
  m.Scale(m.permuted);
  cholmod_sparse s = View(m.scaled);
  if (!m.ldl_factor) m.AnalyzeLdlt(s);
  m.ldl.dbound = bound;
  cholmod_factorize(&s, m.ldl_factor, &m.ldl);
  ThrowOnError(m.ldl, "factorize (LDLᵀ)");
  const cholmod_factor& f = *m.ldl_factor;
  if (f.minor < static_cast<size_t>(m.n))
    throw std::runtime_error("SparseCholesky: the LDLᵀ factorisation broke down at column " +
                             std::to_string(f.minor) + " (pivot overflow)");
  if (f.is_super || f.is_ll)
    throw std::logic_error("SparseCholesky: CHOLMOD returned an unexpected factor type");

  const int* p = static_cast<const int*>(f.p);
  const double* x = static_cast<const double*>(f.x);
  int negative = 0, zero = 0;
  for (int j = 0; j < m.n; ++j) {
    const double d = x[p[j]];  // D(j,j): the first entry of column j
    if (!(std::abs(d) > bound))
      ++zero;
    else if (d < 0.0)
      ++negative;
  }
  m.active = Impl::Active::kLDLt;
  info_.used_ldlt = true;
  info_.negative_pivots = negative;
  info_.zero_pivots = zero;
  info_.positive_definite = negative == 0 && zero == 0;
  m.last_indefinite = !info_.positive_definite;
  return info_;
}

Eigen::VectorXd SparseCholesky::Solve(const Eigen::VectorXd& b) const {
  const Impl& m = *impl_;
  if (m.active == Impl::Active::kNone)
    throw std::logic_error("SparseCholesky: Solve called without a successful Factorize");
  if (b.size() != m.n)
    throw std::invalid_argument("SparseCholesky: right-hand side of size " +
                                std::to_string(b.size()) + ", matrix of size " +
                                std::to_string(m.n));

  if (m.active == Impl::Active::kDelegated) return m.delegate->Solve(b);
  // A common of its own: Solve changes nothing shared, so const Solves may run
  // concurrently.
  ScopedCommon scoped;
  Eigen::VectorXd permuted_b(m.n);
  for (int r = 0; r < m.n; ++r) permuted_b[r] = b[m.perm[r]];
  const Eigen::VectorXd permuted_x = m.SolvePermuted(permuted_b, scoped.c);
  Eigen::VectorXd x(m.n);
  for (int r = 0; r < m.n; ++r) x[m.perm[r]] = permuted_x[r];
  return x;
}

// P K Pᵀ y = b in the permuted order.
Eigen::VectorXd SparseCholesky::Impl::SolvePermuted(const Eigen::VectorXd& b,
                                                    cholmod_common& c) const {
  // Every LDLᵀ is refined, a definite one too: backward stable as it is, it
  // still leaves a forward error of κ·ε, and the refined residual is what
  // carries Newton through tangents of κ ≈ 1e15 (measured: a strip with
  // 1e-12 of its bending stalled at ‖R‖/‖R₀‖ = 0.13 unrefined).
  if (active == Active::kLLt) return FactorSolve(b, c);

  // LDLᵀ: refine until ‖r‖ ≤ 1e-14‖b‖, no improvement, or 3 steps.
  Eigen::VectorXd x = LdltSolve(b, c);
  const double target = kRefinementTolerance * b.norm();
  Eigen::VectorXd r = b - Multiply(x);
  double r_norm = r.norm();
  for (int step = 0; step < kMaxRefinementSteps && r_norm > target; ++step) {
    Eigen::VectorXd candidate = x + LdltSolve(r, c);
    Eigen::VectorXd candidate_r = b - Multiply(candidate);
    const double candidate_norm = candidate_r.norm();
    if (!(candidate_norm < r_norm)) break;  // no improvement: keep the better x
    x = std::move(candidate);
    r = std::move(candidate_r);
    r_norm = candidate_norm;
  }
  return x;
}

}  // namespace drape
