// Kawabata reader: text rows → (K, M) points in SI → monotone runs of
// curvature → loading/unloading branches per sign → one curve.
#include "core/io/kawabata_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "core/model/units.h"

namespace drape {

KawabataError::KawabataError(std::string source, int line, std::string message)
    : std::runtime_error(source + (line > 0 ? ", line " + std::to_string(line) : std::string()) +
                         ": " + message),
      source_(std::move(source)),
      line_(line),
      message_(std::move(message)) {}

namespace {

namespace fs = std::filesystem;

// KES-FB2's own units, for a column whose header gives none (or without a header).
constexpr std::string_view kKesCurvatureUnit = "1/cm";
constexpr std::string_view kKesMomentUnit = "gf*cm/cm";
constexpr std::size_t kMinBranchPoints = 4;
// Finite values near the largest double overflowed the sums and differences
// of averaging and interpolation to infinity. Bending data in SI are nowhere
// near; below this, every product of two differences stays finite.
constexpr double kMaxMagnitude = 1e100;
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

struct Line {
  int number = 0;  // 1-based, counting blank and comment lines
  std::string_view text;
};

struct Column {
  std::string name;   // from the header without the unit; empty without a header
  std::string unit;   // as written in parentheses; empty = KES's own
  std::string label;  // for messages: "column 'moment'" or "column 2"
};

struct Point {
  double k = 0.0;  // curvature [1/m]
  double m = 0.0;  // moment per width [N·m/m]
  int line = 0;    // the row it comes from (the next row for an interpolated point)
};

// Points whose curvature moves one way only (strictly).
using Run = std::vector<Point>;

// Loading and unloading runs of one sign of curvature, in file order.
struct SignBranches {
  std::optional<Run> loading;
  std::optional<Run> unloading;
};

int Sign(double x) {
  return (x > 0) - (x < 0);
}

std::string Enclosed(std::string_view text) {
  std::string result = "'";
  result += text;
  result += '\'';
  return result;
}

std::string Lower(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return lower;
}

std::string_view Trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// A cell without surrounding blanks and the quotes spreadsheets may add.
std::string_view CellText(std::string_view cell) {
  cell = Trimmed(cell);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') {
    cell = Trimmed(cell.substr(1, cell.size() - 2));
  }
  return cell;
}

std::vector<std::string_view> Split(std::string_view line, char delimiter) {
  std::vector<std::string_view> cells;
  for (;;) {
    const auto end = line.find(delimiter);
    cells.push_back(CellText(line.substr(0, end)));
    if (end == std::string_view::npos) return cells;
    line.remove_prefix(end + 1);
  }
}

// Rows with content and their line numbers: blank lines and '#' comments are
// skipped; a UTF-8 BOM and the '\r' of Windows line endings are dropped.
std::vector<Line> ContentLines(std::string_view text) {
  if (text.starts_with(kUtf8Bom)) text.remove_prefix(kUtf8Bom.size());
  std::vector<Line> lines;
  for (int number = 1; !text.empty(); ++number) {
    const auto end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (line.ends_with('\r')) line.remove_suffix(1);
    const std::string_view content = Trimmed(line);
    if (!content.empty() && content.front() != '#') lines.push_back({number, line});
  }
  return lines;
}

// Tab, then ';', then ',': the first that splits the first row into at least
// two cells and the second row into as many. ',' comes last because next to
// the other two it may be a decimal comma. If none is consistent, the first
// that splits the first row, so that the second row is reported.
char DetectDelimiter(const std::vector<Line>& lines) {
  std::optional<char> fallback;
  for (const char delimiter : {'\t', ';', ','}) {
    const std::size_t cells = Split(lines[0].text, delimiter).size();
    if (cells < 2) continue;
    if (lines.size() < 2 || Split(lines[1].text, delimiter).size() == cells) return delimiter;
    if (!fallback) fallback = delimiter;
  }
  return fallback.value_or(',');
}

// The number in a cell (possibly infinite or NaN), or nothing when the cell is
// not a number. With `decimal_comma`, "1,5" reads as 1.5.
std::optional<double> Number(std::string_view cell, bool decimal_comma) {
  std::string text(cell);
  if (decimal_comma) std::ranges::replace(text, ',', '.');
  const char* begin = text.data();
  const char* end = begin + text.size();
  if (begin != end && *begin == '+' && end - begin > 1 && begin[1] != '-') ++begin;
  double value = 0.0;
  const auto [stop, error] = std::from_chars(begin, end, value);
  if (begin == end || stop != end) return std::nullopt;
  // Out of range: strtod gives ±HUGE_VAL or the underflowed value.
  if (error == std::errc::result_out_of_range) return std::strtod(begin, nullptr);
  return value;
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

class KawabataParser {
 public:
  KawabataParser(const std::string& source, const KawabataOptions& options)
      : source_(source), options_(options) {}

  KawabataCurve Parse(std::string_view text);

 private:
  [[noreturn]] void Fail(int line, const std::string& message) const {
    throw KawabataError(source_, line, message);
  }
  bool DecimalComma() const { return delimiter_ != ','; }

  std::vector<Column> ReadColumns(const Line& first);
  std::pair<std::size_t, std::size_t> ChooseColumns(const std::vector<Column>& columns,
                                                    int line) const;
  std::size_t FindColumn(const std::vector<Column>& columns,
                         const std::string& wanted,
                         std::string_view word,
                         char letter,
                         std::size_t exclude,
                         int line) const;
  double UnitFactor(const Column& column,
                    int line,
                    Dimension expected,
                    std::string_view kes_unit,
                    std::string_view expected_text) const;
  std::vector<Point> ReadPoints(std::span<const Line> rows,
                                const std::vector<Column>& columns,
                                std::size_t k_column,
                                std::size_t m_column,
                                double k_factor,
                                double m_factor) const;
  double CellValue(int line, std::string_view cell, const Column& column, double factor) const;
  std::vector<Run> CleanRuns(std::vector<Run> runs);
  std::array<SignBranches, 2> Classify(const std::vector<Run>& runs) const;
  Run Checked(Run run, const std::string& what) const;
  std::optional<Run> SignCurve(const SignBranches& branches, std::string_view side);
  KawabataCurve Finish(const Run& curve);

  const std::string& source_;
  const KawabataOptions& options_;
  char delimiter_ = ',';
  bool has_header_ = false;
  std::vector<std::string> warnings_;
  std::string curvature_read_, moment_read_;
};

KawabataCurve KawabataParser::Parse(std::string_view text) {
  const std::vector<Line> lines = ContentLines(text);
  if (lines.empty()) Fail(0, "the file is empty (nothing but blank lines and '#' comments)");
  delimiter_ = DetectDelimiter(lines);
  const std::vector<Column> columns = ReadColumns(lines[0]);
  const int first_line = lines[0].number;
  const auto rows = std::span(lines).subspan(has_header_ ? 1 : 0);
  if (rows.empty()) Fail(first_line, "a header row but no data rows");

  const auto [k_column, m_column] = ChooseColumns(columns, first_line);
  const double k_factor = UnitFactor(columns[k_column],
                                     first_line,
                                     dim::kCurvature,
                                     kKesCurvatureUnit,
                                     "a curvature (1/m, 1/cm, 1/mm)");
  const double m_factor = UnitFactor(columns[m_column],
                                     first_line,
                                     dim::kMomentPerWidth,
                                     kKesMomentUnit,
                                     "a moment per width (N*m/m, gf*cm/cm)");
  const std::vector<Point> points =
      ReadPoints(rows, columns, k_column, m_column, k_factor, m_factor);
  auto read = [](const Column& c, std::string_view kes_unit) {
    return c.label + " in " +
           (c.unit.empty() ? std::string(kes_unit) + " (KES units: none given)" : c.unit);
  };
  curvature_read_ = read(columns[k_column], kKesCurvatureUnit);
  moment_read_ = read(columns[m_column], kKesMomentUnit);

  const std::vector<Run> runs = CleanRuns(SplitRuns(points));
  if (runs.empty()) {
    Fail(points.front().line,
         "the curvature never changes; at least " + std::to_string(kMinBranchPoints) +
             " points of different curvature are needed");
  }
  if (runs.size() == 1) {
    warnings_.push_back(
        "only one monotone run of curvature (no loading/unloading cycle); used as is");
    Run curve = Checked(runs.front(), "the only run of curvature");
    return Finish(curve);
  }
  const std::array<SignBranches, 2> branches = Classify(runs);
  const std::optional<Run> negative = SignCurve(branches[0], "K < 0");
  const std::optional<Run> positive = SignCurve(branches[1], "K > 0");
  return Finish(Joined(negative.value_or(Run{}), positive.value_or(Run{})));
}

// The curvature and moment columns. A named column is found first so that the
// automatic choice of the other avoids it.
std::pair<std::size_t, std::size_t> KawabataParser::ChooseColumns(
    const std::vector<Column>& columns, int line) const {
  const std::size_t none = columns.size();
  std::size_t k_column = none;
  std::size_t m_column = none;
  if (!options_.moment_column.empty() && options_.curvature_column.empty()) {
    m_column = FindColumn(columns, options_.moment_column, "moment", 'M', none, line);
  }
  k_column = FindColumn(columns, options_.curvature_column, "curv", 'K', m_column, line);
  if (m_column == none) {
    m_column = FindColumn(columns, options_.moment_column, "moment", 'M', k_column, line);
  }
  if (k_column == m_column) {
    Fail(line, "curvature and moment are the same column, " + columns[k_column].label);
  }
  return {k_column, m_column};
}

// Names and units from a header row, or unnamed columns in KES units when the
// first row is all numbers.
std::vector<Column> KawabataParser::ReadColumns(const Line& first) {
  const std::vector<std::string_view> cells = Split(first.text, delimiter_);
  has_header_ = std::ranges::any_of(
      cells, [&](std::string_view cell) { return !Number(cell, DecimalComma()).has_value(); });
  if (cells.size() < 2) {
    Fail(first.number,
         "found a single column; a Kawabata file needs a curvature and a moment column "
         "separated by tabs, commas or semicolons");
  }
  std::vector<Column> columns;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    Column column;
    column.label = "column " + std::to_string(i + 1);
    if (has_header_) {
      std::string_view cell = cells[i];
      const auto open = cell.find('(');
      if (open != std::string_view::npos) {
        if (!cell.ends_with(')')) Fail(first.number, "header cell " + Enclosed(cell) + ": no ')'");
        column.unit = Trimmed(cell.substr(open + 1, cell.size() - open - 2));
        cell = Trimmed(cell.substr(0, open));
      }
      column.name = cell;
      if (!cell.empty()) column.label = "column " + Enclosed(cell);
    }
    columns.push_back(std::move(column));
  }
  return columns;
}

// The column named `wanted` (any case); or, when `wanted` is empty, the first
// column other than `exclude` whose name contains `word` (any case), else
// `letter` ("K", "M": this case only), else the first other than `exclude`.
std::size_t KawabataParser::FindColumn(const std::vector<Column>& columns,
                                       const std::string& wanted,
                                       std::string_view word,
                                       char letter,
                                       std::size_t exclude,
                                       int line) const {
  if (!wanted.empty()) {
    if (!has_header_) {
      Fail(line, "column " + Enclosed(wanted) + " was asked for, but the file has no header row");
    }
    std::string names;
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (Lower(columns[i].name) == Lower(wanted)) return i;
      names += (i == 0 ? "" : ", ") + Enclosed(columns[i].name);
    }
    Fail(line, "no column named " + Enclosed(wanted) + "; the columns are " + names);
  }
  const auto find = [&](auto matches) -> std::optional<std::size_t> {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i != exclude && matches(columns[i].name)) return i;
    }
    return std::nullopt;
  };
  if (const auto i = find(
          [&](const std::string& name) { return Lower(name).find(word) != std::string::npos; })) {
    return *i;
  }
  if (const auto i =
          find([&](const std::string& name) { return name.find(letter) != std::string::npos; })) {
    return *i;
  }
  return exclude == 0 ? 1 : 0;
}

// SI factor of a column's unit (KES's own when the header gives none),
// checked against the dimension the column must have.
double KawabataParser::UnitFactor(const Column& column,
                                  int line,
                                  Dimension expected,
                                  std::string_view kes_unit,
                                  std::string_view expected_text) const {
  const std::string text = column.unit.empty() ? std::string(kes_unit) : column.unit;
  Unit unit;
  try {
    unit = ParseUnit(text);
  } catch (const UnitError& e) {
    Fail(line, column.label + ", unit " + Enclosed(text) + ": " + e.what());
  }
  if (unit.dimension != expected) {
    Fail(line,
         column.label + ": unit " + Enclosed(text) + " has dimension " +
             DimensionName(unit.dimension) + "; expected " + std::string(expected_text));
  }
  return unit.si_factor;
}

// One point per data row, in SI units.
std::vector<Point> KawabataParser::ReadPoints(std::span<const Line> rows,
                                              const std::vector<Column>& columns,
                                              std::size_t k_column,
                                              std::size_t m_column,
                                              double k_factor,
                                              double m_factor) const {
  std::vector<Point> points;
  for (const Line& row : rows) {
    const std::vector<std::string_view> cells = Split(row.text, delimiter_);
    if (cells.size() != columns.size()) {
      std::string message = std::to_string(cells.size()) +
                            (cells.size() == 1 ? " cell, expected " : " cells, expected ") +
                            std::to_string(columns.size()) +
                            (has_header_ ? " as in the header" : " as in the first row");
      // Twice the cells: most likely every number was split at a decimal comma.
      if (delimiter_ == ',' && cells.size() == 2 * columns.size()) {
        message += " (a decimal comma needs ';' or tab between cells)";
      }
      Fail(row.number, message);
    }
    points.push_back({CellValue(row.number, cells[k_column], columns[k_column], k_factor),
                      CellValue(row.number, cells[m_column], columns[m_column], m_factor),
                      row.number});
  }
  return points;
}

double KawabataParser::CellValue(int line,
                                 std::string_view cell,
                                 const Column& column,
                                 double factor) const {
  if (cell.empty()) Fail(line, column.label + ": empty cell, expected a number");
  const std::optional<double> value = Number(cell, DecimalComma());
  if (!value) Fail(line, column.label + ": " + Enclosed(cell) + " is not a number");
  const double si = *value * factor;
  if (!std::isfinite(si)) Fail(line, column.label + ": " + Enclosed(cell) + " is not finite");
  if (std::abs(si) > kMaxMagnitude) {
    Fail(line,
         column.label + ": " + Enclosed(cell) + " is too large (more than 1e100 in SI units)");
  }
  return si;
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
  return result;
}

}  // namespace

KawabataCurve ParseKawabata(std::string_view text,
                            const std::string& source_name,
                            const KawabataOptions& options) {
  return KawabataParser(source_name, options).Parse(text);
}

KawabataCurve ReadKawabata(const std::filesystem::path& file, const KawabataOptions& options) {
  const std::string name = file.string();
  std::error_code error;
  if (!fs::exists(file, error)) throw KawabataError(name, 0, "file not found");
  if (!fs::is_regular_file(file, error)) throw KawabataError(name, 0, "not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw KawabataError(name, 0, "cannot be opened for reading");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw KawabataError(name, 0, "could not be read");
  return ParseKawabata(text, name, options);
}

}  // namespace drape
