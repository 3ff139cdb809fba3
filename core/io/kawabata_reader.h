// Reading Kawabata KES-FB2 pure-bending data (docs/format.md, "Kawabata"):
// a CSV/TSV file with a curvature and a moment-per-width column, recorded over
// a full cycle 0 → +Kmax → 0 → −Kmax → 0.
//
// The reader splits the cycle into loading (|K| rising) and unloading (|K|
// falling) branches by the direction of curvature and returns one branch, or
// their average, as a single curve with strictly increasing K in SI units.
//
// Signs: the moment follows the curvature, and hysteresis makes |M| larger
// while loading. So with M_loading(K) = a K + h0 for K > 0 the negative side
// loads along a K − h0: kLoading gives a K + h0 for K > 0 and a K − h0 for
// K < 0, kUnloading the reverse, and kAverage a K on both sides. Where the two
// sides meet at K = 0 their moments are averaged into one point.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace drape {

enum class KawabataBranch { kAverage, kLoading, kUnloading };

struct KawabataOptions {
  // Header name (case-insensitive, without the unit), or "" = auto: the column
  // whose name contains "curv" (any case) or "K", else the first.
  std::string curvature_column;
  // "" = auto: the column whose name contains "moment" (any case) or "M", else
  // the first column other than the curvature one.
  std::string moment_column;
  KawabataBranch branch = KawabataBranch::kAverage;
};

struct KawabataCurve {
  std::vector<double> curvature;      // K [1/m], strictly increasing
  std::vector<double> moment;         // M [N·m/m], same length
  std::vector<std::string> warnings;  // e.g. "only one branch found; used as is"
  // Which columns were read and in which units, e.g. "column 'moment' in
  // gf*cm/cm" or "column 2 in gf*cm/cm (KES units: none given)".
  std::string curvature_read, moment_read;
  // The loop's width 2HB [N·m/m] (Kawabata's hysteresis of bending moment):
  // |M_loading − M_unloading| at |K| = 1 1/cm, the mean over the signs whose
  // branches both reach it; nullopt for a file without such a loop.
  std::optional<double> hysteresis_width;
};

// What is wrong with a Kawabata file, and where: what() reads
// "<source>, line <L>: <message>" (without the line when none applies).
class KawabataError : public std::runtime_error {
 public:
  KawabataError(std::string source, int line, std::string message);

  const std::string& source() const { return source_; }
  int line() const { return line_; }  // 1-based; 0 when no single line applies
  const std::string& message() const { return message_; }

 private:
  std::string source_;
  int line_;
  std::string message_;
};

// Reads a file; throws KawabataError when it is missing, unreadable or malformed.
KawabataCurve ReadKawabata(const std::filesystem::path& file, const KawabataOptions& options = {});

// Parses the text of a file; `source_name` names it in error messages.
KawabataCurve ParseKawabata(std::string_view text,
                            const std::string& source_name,
                            const KawabataOptions& options = {});

}  // namespace drape
