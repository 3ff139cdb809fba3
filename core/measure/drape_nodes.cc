#include "core/measure/drape_nodes.h"

#include <algorithm>

namespace drape {
namespace {

// The lowest radius walking from `from` in direction `step` (±1) until a
// radius larger than r[from], or all the way round.
double LowestBeforeHigher(const std::vector<double>& r, int from, int step) {
  const int n = static_cast<int>(r.size());
  double lowest = r[from];
  for (int k = 1; k < n; ++k) {
    const double x = r[((from + step * k) % n + n) % n];
    if (x > r[from]) break;
    lowest = std::min(lowest, x);
  }
  return lowest;
}

// The lowest radius strictly between indices a and b going forward round the circle.
double LowestBetween(const std::vector<double>& r, int a, int b) {
  const int n = static_cast<int>(r.size());
  double lowest = r[a];
  for (int k = (a + 1) % n; k != b; k = (k + 1) % n) lowest = std::min(lowest, r[k]);
  return lowest;
}

}  // namespace

std::vector<DrapeNode> FindDrapeNodes(const RadialProfile& profile, double min_prominence) {
  const std::vector<double>& r = profile.radius;
  const int n = static_cast<int>(r.size());
  std::vector<int> peaks;
  for (int i = 0; i < n; ++i) {
    const double before = r[(i + n - 1) % n], after = r[(i + 1) % n];
    // A plateau counts once, at its first sample.
    if (!(r[i] > before && r[i] >= after)) continue;
    const double col = std::max(LowestBeforeHigher(r, i, -1), LowestBeforeHigher(r, i, +1));
    if (r[i] - col >= min_prominence) peaks.push_back(i);
  }
  std::vector<DrapeNode> nodes;
  const int m = static_cast<int>(peaks.size());
  for (int k = 0; k < m; ++k) {
    const int i = peaks[k];
    const int previous = peaks[(k + m - 1) % m], next = peaks[(k + 1) % m];
    const double low_before = LowestBetween(r, previous, i);
    const double low_after = LowestBetween(r, i, next);
    nodes.push_back({profile.angle[i], r[i], r[i] - 0.5 * (low_before + low_after)});
  }
  return nodes;
}

}  // namespace drape
