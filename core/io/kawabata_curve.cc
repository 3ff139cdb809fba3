// The measured loop turned into one curve: runs of one direction of
// curvature, split by sign into loading and unloading branches, one branch
// or their average kept per sign, and the two sides joined at K = 0.
#include "core/io/kawabata_parser.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace drape {
namespace kawabata {
namespace {

int Sign(double x) {
  return (x > 0) - (x < 0);
}

// Moment at `k` on a run of increasing curvature that covers k, linear between samples.
double MomentAt(const Run& run, double k) {
  const auto above = std::ranges::lower_bound(run, k, {}, &Point::k);
  if (above->k == k) return above->m;
  const Point& a = *std::prev(above);
  const Point& b = *above;
  return a.m + (b.m - a.m) * (k - a.k) / (b.k - a.k);
}

// Loading and unloading (both in increasing K) averaged at the union of their
// curvatures within their common range, so no sample of either is lost there.
// Empty when the ranges do not overlap.
Run Average(const Run& a, const Run& b) {
  const double low = std::max(a.front().k, b.front().k);
  const double high = std::min(a.back().k, b.back().k);
  if (!(low < high)) return {};
  std::vector<double> ks;
  for (const Run* run : {&a, &b}) {
    for (const Point& p : *run) {
      if (p.k >= low && p.k <= high) ks.push_back(p.k);
    }
  }
  std::ranges::sort(ks);
  // Curvatures equal but for rounding (0.3 vs 0.1 * 3) are one sample.
  const double tolerance = 1e-12 * std::max(std::abs(low), std::abs(high));
  Run mean;
  for (const double k : ks) {
    if (!mean.empty() && k - mean.back().k <= tolerance) continue;
    mean.push_back({k, 0.5 * (MomentAt(a, k) + MomentAt(b, k)), 0});
  }
  return mean;
}

// Splits a run where it crosses K = 0 so that each piece has one sign; a
// crossing between two samples gets an interpolated point at K = 0 on both
// sides. Pieces of a single point are dropped.
std::vector<Run> SplitAtZero(const Run& run) {
  std::vector<Run> pieces(1);
  int sign = 0;  // of the current piece, 0 until it leaves K = 0
  for (const Point& p : run) {
    if (Sign(p.k) != 0 && sign != 0 && Sign(p.k) != sign) {
      Point zero = pieces.back().back();
      if (zero.k != 0.0) {
        zero = {0.0, zero.m + (p.m - zero.m) * (0.0 - zero.k) / (p.k - zero.k), p.line};
        pieces.back().push_back(zero);
      }
      pieces.push_back({zero});
    }
    if (Sign(p.k) != 0) sign = Sign(p.k);
    pieces.back().push_back(p);
  }
  std::erase_if(pieces, [](const Run& piece) { return piece.size() < 2; });
  return pieces;
}

std::string LineRange(const Run& run) {
  int first = std::numeric_limits<int>::max();
  int last = 0;
  for (const Point& p : run) {
    if (p.line == 0) continue;
    first = std::min(first, p.line);
    last = std::max(last, p.line);
  }
  return "lines " + std::to_string(first) + "-" + std::to_string(last);
}

}  // namespace

// Splits the points where the curvature turns back. A turning point is shared
// by the runs on both sides. A repeated curvature (the vertical step of a
// hysteresis loop at ±Kmax, where the moment drops from loading to unloading)
// ends a run without being shared, so both moments there are kept.
std::vector<Run> SplitRuns(const std::vector<Point>& points) {
  std::vector<Run> runs;
  Run run = {points.front()};
  int direction = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const int step = Sign(points[i].k - points[i - 1].k);
    if (step == 0) {
      runs.push_back(std::move(run));
      run = {points[i]};
      direction = 0;
      continue;
    }
    if (direction != 0 && step != direction) {
      runs.push_back(std::move(run));
      run = {points[i - 1]};
    }
    direction = step;
    run.push_back(points[i]);
  }
  runs.push_back(std::move(run));
  return runs;
}

// The negative side (ending at K <= 0) followed by the positive one (starting
// at K >= 0); when both reach K = 0 they share one point midway between their
// moments there.
Run Joined(Run negative, const Run& positive) {
  auto begin = positive.begin();
  if (!negative.empty() && begin != positive.end() && negative.back().k == 0.0 && begin->k == 0.0) {
    negative.back().m = 0.5 * (negative.back().m + begin->m);
    ++begin;
  }
  negative.insert(negative.end(), begin, positive.end());
  return negative;
}

// Drops single points (the middle of a vertical step), joins runs that a
// repeated curvature split although they go the same way, and refuses zig-zag
// noise: one step back between two runs is neither loading nor unloading.
// A one-step run at either end of the data is dropped with a warning.
std::vector<Run> KawabataParser::CleanRuns(std::vector<Run> runs) {
  const auto direction = [](const Run& run) { return Sign(run.back().k - run.front().k); };
  std::vector<Run> kept;
  for (Run& run : runs) {
    if (run.size() < 2) continue;
    if (!kept.empty() && direction(kept.back()) == direction(run)) {
      warnings_.push_back("line " + std::to_string(run.front().line) +
                          " repeats the curvature of line " +
                          std::to_string(kept.back().back().line) + "; the first was kept");
      kept.back().insert(kept.back().end(), run.begin() + 1, run.end());
      continue;
    }
    kept.push_back(std::move(run));
  }
  for (std::size_t i = 1; i + 1 < kept.size(); ++i) {
    if (kept[i].size() == 2) {
      Fail(kept[i][1].line,
           "the curvature turns back for a single step (zig-zag); loading and unloading "
           "branches cannot be told apart");
    }
  }
  for (const bool last : {true, false}) {
    if (kept.size() < 2) break;
    const Run& end = last ? kept.back() : kept.front();
    if (end.size() != 2) continue;
    warnings_.push_back("a single step of curvature at " + LineRange(end) + " was left out");
    kept.erase(last ? kept.end() - 1 : kept.begin());
  }
  return kept;
}

// Pieces of the runs by sign ([0]: K < 0, [1]: K > 0) and branch: loading
// while |K| rises. A second piece of the same kind means the curvature went
// back and forth more than one KES cycle does.
std::array<SignBranches, 2> KawabataParser::Classify(const std::vector<Run>& runs) const {
  std::array<SignBranches, 2> branches;
  for (const Run& run : runs) {
    for (Run& piece : SplitAtZero(run)) {
      const bool loading = std::abs(piece.back().k) > std::abs(piece.front().k);
      const bool positive = piece.front().k + piece.back().k > 0;
      std::optional<Run>& slot =
          loading ? branches[positive].loading : branches[positive].unloading;
      if (slot) {
        Fail(piece.front().line,
             std::string("a second ") + (loading ? "loading" : "unloading") + " run for " +
                 (positive ? "K > 0" : "K < 0") + " starts here (the first is at " +
                 LineRange(*slot) + "); the curvature must go through one KES cycle");
      }
      slot = std::move(piece);
    }
  }
  return branches;
}

// `run` in increasing curvature, once it is known to have enough points.
Run KawabataParser::Checked(Run run, const std::string& what) const {
  if (run.size() < kMinBranchPoints) {
    Fail(run.front().line,
         what + " (" + LineRange(run) + ") has only " + std::to_string(run.size()) +
             " points; at least " + std::to_string(kMinBranchPoints) + " are needed");
  }
  if (run.front().k > run.back().k) std::ranges::reverse(run);
  return run;
}

// The curve for one sign of curvature: the chosen branch or the average of
// both; whichever was found when the other is missing.
std::optional<Run> KawabataParser::SignCurve(const SignBranches& branches, std::string_view side) {
  const std::string on = " for " + std::string(side);
  const auto& loading = branches.loading;
  const auto& unloading = branches.unloading;
  if (!loading && !unloading) return std::nullopt;
  if (options_.branch == KawabataBranch::kLoading && loading) {
    return Checked(*loading, "the loading branch" + on);
  }
  if (options_.branch == KawabataBranch::kUnloading && unloading) {
    return Checked(*unloading, "the unloading branch" + on);
  }
  if (options_.branch == KawabataBranch::kAverage && loading && unloading) {
    const Run l = Checked(*loading, "the loading branch" + on);
    const Run u = Checked(*unloading, "the unloading branch" + on);
    Run mean = Average(l, u);
    if (mean.empty()) {
      Fail(loading->front().line,
           "the loading and unloading branches" + on + " do not overlap in curvature");
    }
    if (mean.front().k != std::min(l.front().k, u.front().k) ||
        mean.back().k != std::max(l.back().k, u.back().k)) {
      warnings_.push_back("loading and unloading" + on +
                          " cover different curvatures; averaged where both exist");
    }
    return mean;
  }
  const bool has_loading = loading.has_value();
  warnings_.push_back(std::string("only one branch found") + on + " (" +
                      (has_loading ? "loading" : "unloading") + "); used as is");
  return Checked(has_loading ? *loading : *unloading,
                 std::string("the ") + (has_loading ? "loading" : "unloading") + " branch" + on);
}

std::optional<double> LoopWidth(const std::array<SignBranches, 2>& sides) {
  // Kawabata reads 2HB at |K| = 1 1/cm (in the middle of the 0.5–1.5 1/cm
  // range where B is the slope).
  constexpr double kAt = 100.0;  // [1/m]
  auto moment_at = [](Run run, double k) -> std::optional<double> {
    std::ranges::sort(run, {}, &Point::k);
    if (run.size() < 2 || k < run.front().k || k > run.back().k) return std::nullopt;
    return MomentAt(run, k);
  };
  double sum = 0;
  int count = 0;
  for (int side = 0; side < 2; ++side) {
    const SignBranches& b = sides[side];
    if (!b.loading || !b.unloading) continue;
    const double k = side == 0 ? -kAt : kAt;
    const auto loading = moment_at(*b.loading, k), unloading = moment_at(*b.unloading, k);
    if (!loading || !unloading) continue;
    sum += std::abs(*loading - *unloading);
    ++count;
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

KawabataCurve KawabataParser::Finish(const Run& curve) {
  if (curve.front().k >= 0.0) {
    warnings_.push_back("the data cover K >= 0 only; the curve is extended by symmetry");
  } else if (curve.back().k <= 0.0) {
    warnings_.push_back("the data cover K <= 0 only; the curve is extended by symmetry");
  }
  KawabataCurve result;
  for (const Point& p : curve) {
    result.curvature.push_back(p.k);
    result.moment.push_back(p.m);
  }
  result.warnings = std::move(warnings_);
  result.curvature_read = curvature_read_;
  result.moment_read = moment_read_;
  result.hysteresis_width = loop_width_;
  return result;
}

}  // namespace kawabata
}  // namespace drape
