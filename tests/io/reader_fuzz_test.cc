// Every reader of the engine but the scene reader (scene_fuzz_test.cc) and
// result.json (tests/cli/result_fuzz_test.cc, which needs a run) must answer
// any input with its result or its documented error: never a crash, a hang,
// a sanitizer report, another exception, or a number that is not finite.
// Inputs are seeded mutations of real files (support/fuzz_input.h); their
// count per reader is DRAPE_FUZZ_INPUTS (default 2000), so a long run is
//   DRAPE_FUZZ_INPUTS=100000 ./io_tests --gtest_filter='ReaderFuzz*'
// This file: the Kawabata CSV/TSV reader and the unit parser; OBJ and STL in
// reader_fuzz_mesh_test.cc, states.bin in reader_fuzz_states_test.cc. After
// each reader's fuzz loop: one regression test per defect the fuzzing found.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/io/kawabata_reader.h"
#include "core/model/units.h"
#include "support/fuzz_files.h"
#include "support/fuzz_input.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::Contains;
using test::FuzzAlphabet;
using test::FuzzInputs;
using test::FuzzTally;
using test::Mutator;
using test::ReadBytes;
using test::ShippedFiles;
using test::TempFile;

// ---- Kawabata -----------------------------------------------------------------

std::string Replaced(std::string text, char from, char to) {
  std::ranges::replace(text, from, to);
  return text;
}

// The shipped files and variants of the first that reach the other paths of
// the reader: tab and ';' with decimal commas, no header (KES units), CRLF
// with a BOM, SI units, one loading run only.
std::vector<std::string> KawabataSeeds() {
  std::vector<std::string> seeds;
  for (const fs::path& file : ShippedFiles({".csv", ".tsv"})) seeds.push_back(ReadBytes(file));
  EXPECT_FALSE(seeds.empty()) << "no .csv/.tsv files under resources/ or tests/";
  if (seeds.empty()) return seeds;
  std::vector<std::string> rows;  // header and data rows of the first, without comments
  std::istringstream in(seeds.front());
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.front() != '#') rows.push_back(line);
  std::string csv, headerless, crlf, loading;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    csv += rows[i] + "\n";
    if (i > 0) headerless += rows[i] + "\n";
    crlf += rows[i] + "\r\n";
    if (i < rows.size() / 4) loading += rows[i] + "\n";
  }
  seeds.push_back(Replaced(csv, ',', '\t'));
  seeds.push_back(Replaced(Replaced(csv, ',', ';'), '.', ','));
  seeds.push_back(Replaced(Replaced(csv, ',', '\t'), '.', ','));
  seeds.push_back(headerless);
  seeds.push_back("\xEF\xBB\xBF" + crlf);
  seeds.push_back(loading);
  std::string si = "K (1/m);M (N*m/m);T (s)\n";
  for (int i = -8; i <= 8; ++i) si += std::to_string(i) + ";" + std::to_string(0.3 * i) + ";1\n";
  seeds.push_back(si);
  return seeds;
}

FuzzAlphabet KawabataAlphabet() {
  return {"0123456789.,;\t\n\r-+eE#\" ()/*KMcmgfN", {",",          ";",
                                                     "\t",         "\n",
                                                     "\r\n",       "#",
                                                     "\"",         "(1/cm)",
                                                     "(gf*cm/cm)", "(N*m/m)",
                                                     "(1/m)",      "(m)",
                                                     "(",          ")",
                                                     "1e308",      "-1e308",
                                                     "1.7e308",    "1e-320",
                                                     "nan",        "inf",
                                                     "-inf",       "1e999",
                                                     "0",          "-0",
                                                     "0.0",        "2.5",
                                                     "-2.5",       "curvature",
                                                     "moment",     "K",
                                                     "M",          "\xEF\xBB\xBF",
                                                     "1,5",        "99999999999999999999",
                                                     "e",          "+"}};
}

// The curve's promises: same lengths, enough points, K strictly increasing, finite.
void ExpectSoundCurve(const KawabataCurve& curve, const std::string& input) {
  ASSERT_EQ(curve.curvature.size(), curve.moment.size()) << input;
  ASSERT_GE(curve.curvature.size(), 2u) << input;
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    ASSERT_TRUE(std::isfinite(curve.curvature[i]) && std::isfinite(curve.moment[i]))
        << "point " << i << " of\n"
        << input;
    if (i > 0) {
      ASSERT_LT(curve.curvature[i - 1], curve.curvature[i]) << input;
    }
  }
}

KawabataOptions KawabataOptionsFor(std::uint64_t r) {
  KawabataOptions options;
  options.branch = std::array{
      KawabataBranch::kAverage, KawabataBranch::kLoading, KawabataBranch::kUnloading}[r % 3];
  // Mostly automatic columns; sometimes named ones, right and wrong.
  static const char* const kNames[] = {"curvature", "moment", "K", "M", "T", "nothing"};
  if ((r >> 8) % 8 == 0) options.curvature_column = kNames[(r >> 16) % 6];
  if ((r >> 24) % 8 == 0) options.moment_column = kNames[(r >> 32) % 6];
  return options;
}

TEST(ReaderFuzzKawabata, MutatedFilesGiveACurveOrAKawabataError) {
  const std::vector<std::string> seeds = KawabataSeeds();
  ASSERT_FALSE(seeds.empty());
  Mutator mutator(20260501, KawabataAlphabet());
  FuzzTally tally{"Kawabata CSV/TSV"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const std::string text = mutator.Make(seeds);
    const KawabataOptions options = KawabataOptionsFor(mutator.Next());
    try {
      // Now and then through a file, so that ReadKawabata is fuzzed too.
      if (i % 64 == 0) {
        const TempFile file(".csv", text);
        ExpectSoundCurve(ReadKawabata(file.path(), options), text);
      } else {
        ExpectSoundCurve(ParseKawabata(text, "fuzz.csv", options), text);
      }
      ++tally.accepted;
    } catch (const KawabataError& e) {
      ASSERT_FALSE(e.message().empty()) << text;
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

std::string KawabataMessage(const std::string& text) {
  try {
    ParseKawabata(text, "big.csv");
  } catch (const KawabataError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no KawabataError for\n" << text;
  return "";
}

// Finite moments near the largest double: the average of loading and
// unloading, and interpolation between rows, overflowed to infinity.
TEST(ReaderFuzzRegression, KawabataRefusesNumbersTooLargeToComputeWith) {
  std::string text = "K (1/m),M (N*m/m)\n";
  for (const int k : {0, 1, 2, 3, 4, 4, 3, 2, 1, 0}) text += std::to_string(k) + ",1.5e308\n";
  EXPECT_TRUE(Contains(KawabataMessage(text), "big.csv, line 2: column 'M': '1.5e308'"));
  EXPECT_TRUE(Contains(KawabataMessage(text), "too large"));
  // In KES units the factor makes it so.
  EXPECT_TRUE(Contains(KawabataMessage("curvature,moment\n1e99,1\n2e99,1\n"),
                       "line 2: column 'curvature': '1e99' is too large"));
}

// ---- units --------------------------------------------------------------------

const std::vector<std::string>& UnitSeeds() {
  static const std::vector<std::string> seeds = {
      "1.73 oz/in^2", "12 gf*cm^2/cm", "3 mm",
      "2e5 N/m",      "g/m2",          "0.489 mm",
      "1.5 1/cm",     "2e-3 m",        "5.425e-3 oz/in^2",
      "2688 oz/in^2", "45 deg",        "1 rad",
      "0.3",          "-2 cm",         "+4 in",
      "3 kg*m/s^2",   "1 N*m/m",       "7 gf·cm²/cm",
      "2 m⁻¹",        "1 (N/m)^2/Pa",  "10 kPa",
      "1 psi",        "9.8 m/s²",      "3 lbf/in",
      "1e-6 um",      "2.5 1/mm",      "1 gmf*cm/cm",
      "4 kgf/cm^-2",  "0.5 g/cm^3",    ".5 ft"};
  return seeds;
}

FuzzAlphabet UnitAlphabet() {
  return {"0123456789.eE+- */^()·²³⁻¹mcgNsnkPaiuftrdoxlbz\t",
          {"m",
           "cm",
           "mm",
           "um",
           "in",
           "ft",
           "N",
           "kN",
           "mN",
           "gf",
           "gmf",
           "kgf",
           "ozf",
           "oz",
           "lbf",
           "lb",
           "kg",
           "g",
           "Pa",
           "kPa",
           "MPa",
           "GPa",
           "psi",
           "deg",
           "rad",
           "s",
           "^",
           "^-",
           "^99",
           "^100",
           "^-99",
           "²",
           "³",
           "⁻¹",
           "⁹⁹",
           "·",
           "⋅",
           "*",
           "/",
           "(",
           ")",
           "(((",
           ")))",
           "1",
           "1e308",
           "1e-308",
           "1e999",
           "nan",
           "inf",
           "e",
           "9999999999",
           "^2147483647",
           "^-2147483648",
           "\xE2\x81",
           "\xC2"}};
}

constexpr Dimension kExpected[] = {dim::kNone,
                                   dim::kLength,
                                   dim::kForce,
                                   dim::kPressure,
                                   dim::kArealDensity,
                                   dim::kCurvature,
                                   dim::kMomentPerWidth,
                                   dim::kBendingRigidity,
                                   dim::kForcePerLength,
                                   dim::kAngle};

TEST(ReaderFuzzUnits, MutatedQuantitiesGiveAValueOrAUnitError) {
  Mutator mutator(1733, UnitAlphabet());
  FuzzTally tally{"units (ParseUnit, ParseQuantity, ParseQuantityAs)"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const std::string text = mutator.Make(UnitSeeds());
    // The number and the unit of a quantity, and the text whole as a unit.
    try {
      const Quantity q = ParseQuantity(text);
      ASSERT_TRUE(std::isfinite(q.value_si)) << text;
      ++tally.accepted;
    } catch (const UnitError& e) {
      ASSERT_NE(std::string(e.what()), "") << text;
      ++tally.rejected;
    }
    try {
      const Unit u = ParseUnit(text);
      ASSERT_TRUE(std::isfinite(u.si_factor) && u.si_factor != 0.0) << text;
    } catch (const UnitError&) {
    }
    try {
      const double v = ParseQuantityAs(text, kExpected[mutator.Below(std::size(kExpected))]);
      ASSERT_TRUE(std::isfinite(v)) << text;
    } catch (const UnitError&) {
    }
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

std::string UnitMessage(const std::string& text) {
  try {
    ParseQuantity(text);
  } catch (const UnitError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UnitError for " << text.substr(0, 100);
  return "";
}

// Each '(' was a level of recursion: deep enough, the stack overflowed.
TEST(ReaderFuzzRegression, UnitsRefuseParenthesesNestedTooDeeply) {
  const std::string deep = "1 " + std::string(100000, '(') + "m" + std::string(100000, ')');
  EXPECT_TRUE(Contains(UnitMessage(deep),
                       "parentheses nested more than 32 deep, at character 33 of the unit"));
  // Thirty-two levels are plenty, and still read.
  const std::string fine = "2 " + std::string(32, '(') + "cm" + std::string(32, ')');
  EXPECT_DOUBLE_EQ(ParseQuantity(fine).value_si, 0.02);
}

// Exponents add up across '*' and '/' without the bound '^' keeps: past
// INT_MAX that is undefined behaviour; now the product is bounded too.
TEST(ReaderFuzzRegression, UnitsRefuseProductsOfTooHighAPower) {
  std::string unit = "m^99";
  for (int i = 0; i < 3; ++i) unit += "*m^99";
  EXPECT_TRUE(Contains(UnitMessage("1 " + unit), "exponent too large"));
}

}  // namespace
}  // namespace drape
