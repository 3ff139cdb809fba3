// A bandwidth-reducing ordering of a symmetric matrix's rows: reverse
// Cuthill–McKee (George & Liu, "Computer Solution of Large Sparse Positive
// Definite Systems", 1981, §4.3), started in each connected component from a
// pseudo-peripheral row. A strip's or a small sheet's tangent ordered so has
// a narrow band, which band_ldlt.h factorises with dense kernels.
#pragma once

#include <Eigen/SparseCore>

#include <vector>

namespace drape {

// Where each connected component's breadth-first levels start: at a
// pseudo-peripheral row, or at the whole last level of the levels rooted
// there. On a strip's mesh the first gives levels shaped like the corner's
// neighbourhoods (wider than the strip near its corners); the second starts
// from the far end's whole cross-section, and its levels are cross-sections.
enum class RcmStart { kPeripheralRow, kFarLevel };

// The ordering of `upper` (the upper triangle of a symmetric matrix,
// compressed, column-major): row r of the ordered matrix is row perm[r].
std::vector<int> ReverseCuthillMcKee(const Eigen::SparseMatrix<double>& upper, RcmStart start);

// The narrowest band of three: reverse Cuthill–McKee from either start, and
// the matrix's own numbering (a mesher numbering a sheet row by row beats
// both on a square, where the levels from a corner are L-shaped).
std::vector<int> NarrowBandOrdering(const Eigen::SparseMatrix<double>& upper);

// The half-bandwidth of `upper` ordered by `perm`: the largest |i − j| over
// its entries in the new numbering.
int HalfBandwidth(const Eigen::SparseMatrix<double>& upper, const std::vector<int>& perm);

}  // namespace drape
