// The Kawabata reader's parser, shared by its two halves: the table read
// into points in SI (kawabata_reader.cc), and the measured loop turned into
// one curve (kawabata_curve.cc). One object per file, so that both halves
// fail through the same source name and add to the same warnings. Private
// to core/io.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/io/kawabata_reader.h"
#include "core/model/units.h"

namespace drape {
namespace kawabata {

// The fewest points a branch of the curve may have.
constexpr std::size_t kMinBranchPoints = 4;

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

// The measured points cut into runs of one direction of curvature, and two
// sides' curves put end to end (kawabata_curve.cc).
std::vector<Run> SplitRuns(const std::vector<Point>& points);
Run Joined(Run negative, const Run& positive);
// The loop's width 2HB [N·m/m]: |M_loading − M_unloading| at |K| = 1 1/cm,
// the mean over the signs whose two branches both reach it; nullopt when none
// does.
std::optional<double> LoopWidth(const std::array<SignBranches, 2>& sides);

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
  std::optional<double> loop_width_;
  std::string curvature_read_, moment_read_;
};

}  // namespace kawabata
}  // namespace drape
