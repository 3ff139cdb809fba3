// Kawabata reader: text rows → (K, M) points in SI → monotone runs of
// curvature → loading/unloading branches per sign → one curve. The rows and
// points are read here; the runs, branches and curve are kawabata_curve.cc's.
#include "core/io/kawabata_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "core/io/kawabata_parser.h"

namespace drape {

KawabataError::KawabataError(std::string source, int line, std::string message)
    : std::runtime_error(source + (line > 0 ? ", line " + std::to_string(line) : std::string()) +
                         ": " + message),
      source_(std::move(source)),
      line_(line),
      message_(std::move(message)) {}

namespace {

namespace fs = std::filesystem;
using kawabata::KawabataParser;

}  // namespace

namespace kawabata {
namespace {

// KES-FB2's own units, for a column whose header gives none (or without a header).
constexpr std::string_view kKesCurvatureUnit = "1/cm";
constexpr std::string_view kKesMomentUnit = "gf*cm/cm";
// Finite values near the largest double overflowed the sums and differences
// of averaging and interpolation to infinity. Bending data in SI are nowhere
// near; below this, every product of two differences stays finite.
constexpr double kMaxMagnitude = 1e100;
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

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

}  // namespace

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
  loop_width_ = LoopWidth(branches);
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

}  // namespace kawabata

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
