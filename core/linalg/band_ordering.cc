#include "core/linalg/band_ordering.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

namespace drape {
namespace {

// The symmetric adjacency of `upper` without its diagonal, as compressed
// rows: the neighbours of row r are neighbour[start[r] .. start[r + 1]).
struct Adjacency {
  std::vector<int> start, neighbour;
  int Degree(int r) const { return start[r + 1] - start[r]; }
};

Adjacency AdjacencyOf(const Eigen::SparseMatrix<double>& upper) {
  const int n = static_cast<int>(upper.cols());
  const int* p = upper.outerIndexPtr();
  const int* i = upper.innerIndexPtr();
  Adjacency a;
  a.start.assign(n + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k)
      if (i[k] != j) {
        ++a.start[i[k] + 1];
        ++a.start[j + 1];
      }
  for (int r = 0; r < n; ++r) a.start[r + 1] += a.start[r];
  a.neighbour.resize(a.start[n]);
  std::vector<int> next(a.start.begin(), a.start.end() - 1);
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k)
      if (i[k] != j) {
        a.neighbour[next[i[k]]++] = j;
        a.neighbour[next[j]++] = i[k];
      }
  return a;
}

// Breadth-first levels from `root` over rows not yet `placed`: the rows in
// visiting order; `depth` is the number of levels, `last` the first row of
// the last level's range in the returned order.
struct Levels {
  std::vector<int> order;
  int depth = 0;
  size_t last = 0;
};

Levels LevelsFrom(const Adjacency& a,
                  int root,
                  const std::vector<char>& placed,
                  std::vector<int>& mark,
                  int stamp) {
  Levels l;
  l.order.push_back(root);
  mark[root] = stamp;
  size_t begin = 0;
  while (begin < l.order.size()) {
    const size_t end = l.order.size();
    l.last = begin;
    ++l.depth;
    for (size_t q = begin; q < end; ++q) {
      const int r = l.order[q];
      for (int k = a.start[r]; k < a.start[r + 1]; ++k) {
        const int s = a.neighbour[k];
        if (!placed[s] && mark[s] != stamp) {
          mark[s] = stamp;
          l.order.push_back(s);
        }
      }
    }
    begin = end;
  }
  return l;
}

// George & Liu's pseudo-peripheral row of the component holding `root`
// (restart from a least-degree row of the last level while the level
// structure gets deeper), and the last level of the structure rooted there.
std::vector<int> PseudoPeripheral(const Adjacency& a,
                                  int root,
                                  const std::vector<char>& placed,
                                  std::vector<int>& mark,
                                  int& stamp,
                                  bool far_level) {
  Levels l = LevelsFrom(a, root, placed, mark, ++stamp);
  for (;;) {
    int best = l.order[l.last];
    for (size_t q = l.last; q < l.order.size(); ++q)
      if (a.Degree(l.order[q]) < a.Degree(best)) best = l.order[q];
    Levels next = LevelsFrom(a, best, placed, mark, ++stamp);
    if (next.depth <= l.depth) break;
    root = best;
    l = std::move(next);
  }
  if (!far_level) return {root};
  return std::vector<int>(l.order.begin() + static_cast<std::ptrdiff_t>(l.last), l.order.end());
}

}  // namespace

std::vector<int> ReverseCuthillMcKee(const Eigen::SparseMatrix<double>& upper, RcmStart start) {
  const int n = static_cast<int>(upper.cols());
  const Adjacency a = AdjacencyOf(upper);
  std::vector<char> placed(n, 0);
  std::vector<int> mark(n, 0), order;
  order.reserve(n);
  int stamp = 0;
  std::vector<int> by_degree(n);
  for (int r = 0; r < n; ++r) by_degree[r] = r;
  std::stable_sort(
      by_degree.begin(), by_degree.end(), [&](int x, int y) { return a.Degree(x) < a.Degree(y); });
  std::vector<int> children;
  for (int seed : by_degree) {
    if (placed[seed]) continue;
    size_t q = order.size();
    std::vector<int> roots =
        PseudoPeripheral(a, seed, placed, mark, stamp, start == RcmStart::kFarLevel);
    std::stable_sort(
        roots.begin(), roots.end(), [&](int x, int y) { return a.Degree(x) < a.Degree(y); });
    for (int r : roots) placed[r] = 1;
    order.insert(order.end(), roots.begin(), roots.end());
    for (; q < order.size(); ++q) {
      const int r = order[q];
      children.clear();
      for (int k = a.start[r]; k < a.start[r + 1]; ++k)
        if (!placed[a.neighbour[k]]) {
          placed[a.neighbour[k]] = 1;
          children.push_back(a.neighbour[k]);
        }
      std::stable_sort(children.begin(), children.end(), [&](int x, int y) {
        return a.Degree(x) < a.Degree(y);
      });
      order.insert(order.end(), children.begin(), children.end());
    }
  }
  std::reverse(order.begin(), order.end());
  return order;
}

int HalfBandwidth(const Eigen::SparseMatrix<double>& upper, const std::vector<int>& perm) {
  const int n = static_cast<int>(upper.cols());
  std::vector<int> inverse(n);
  for (int r = 0; r < n; ++r) inverse[perm[r]] = r;
  const int* p = upper.outerIndexPtr();
  const int* i = upper.innerIndexPtr();
  int band = 0;
  for (int j = 0; j < n; ++j)
    for (int k = p[j]; k < p[j + 1]; ++k)
      band = std::max(band, std::abs(inverse[i[k]] - inverse[j]));
  return band;
}

}  // namespace drape

namespace drape {

std::vector<int> NarrowBandOrdering(const Eigen::SparseMatrix<double>& upper) {
  std::vector<int> best(upper.cols());
  std::iota(best.begin(), best.end(), 0);
  int width = HalfBandwidth(upper, best);
  for (RcmStart start : {RcmStart::kPeripheralRow, RcmStart::kFarLevel}) {
    std::vector<int> candidate = ReverseCuthillMcKee(upper, start);
    const int w = HalfBandwidth(upper, candidate);
    if (w < width) {
      width = w;
      best = std::move(candidate);
    }
  }
  return best;
}

}  // namespace drape
