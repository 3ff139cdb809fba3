#include "core/io/kawabata_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace drape {
namespace {

constexpr double kPerCm = 100.0;           // 1/cm in 1/m
constexpr double kGfCmPerCm = 9.80665e-3;  // gf·cm/cm = gf, in N·m/m (= N)

// A KES-FB2 cycle 0 → +kmax → 0 → −kmax → 0 in SI, with loading moments
// a K ± h0 (|M| larger while |K| rises) and unloading a K ∓ h0: the
// hysteresis 2HB is 2 h0 on both sides. At ±kmax the moment drops from
// loading to unloading at a repeated curvature, as a KES record does; at
// K = 0 the unloading of one side continues into the loading of the other.
std::string Loop(double a, double h0, double kmax = 10.0, double step = 0.5) {
  std::ostringstream text;
  text.precision(17);
  text << "curvature (1/m),moment (N*m/m)\n";
  const int n = static_cast<int>(std::lround(kmax / step));
  const auto row = [&](double k, double m) { text << k << ',' << m << '\n'; };
  for (int i = 0; i <= n; ++i) row(i * step, a * i * step + h0);    // loading, K > 0
  for (int i = n; i >= 0; --i) row(i * step, a * i * step - h0);    // unloading, K > 0
  for (int i = 1; i <= n; ++i) row(-i * step, -a * i * step - h0);  // loading, K < 0
  for (int i = n; i >= 0; --i) row(-i * step, -a * i * step + h0);  // unloading, K < 0
  return text.str();
}

KawabataCurve Parse(const std::string& text, const KawabataOptions& options = {}) {
  return ParseKawabata(text, "test.csv", options);
}

KawabataOptions Branch(KawabataBranch branch) {
  KawabataOptions options;
  options.branch = branch;
  return options;
}

void ExpectStrictlyIncreasing(const std::vector<double>& values) {
  for (std::size_t i = 1; i < values.size(); ++i) EXPECT_LT(values[i - 1], values[i]) << i;
}

bool HasWarning(const KawabataCurve& curve, const std::string& words) {
  for (const std::string& warning : curve.warnings) {
    if (warning.find(words) != std::string::npos) return true;
  }
  return false;
}

TEST(KawabataReader, AverageOfHysteresisLoopIsTheMiddleLine) {
  const double a = 0.7, h0 = 0.05;
  const KawabataCurve curve = Parse(Loop(a, h0));
  ASSERT_EQ(curve.curvature.size(), 41u);  // −10 … 10 in steps of 0.5, K = 0 once
  ASSERT_EQ(curve.moment.size(), curve.curvature.size());
  ExpectStrictlyIncreasing(curve.curvature);
  EXPECT_EQ(curve.curvature.front(), -10.0);
  EXPECT_EQ(curve.curvature.back(), 10.0);
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    const double expected = a * curve.curvature[i];
    EXPECT_NEAR(curve.moment[i], expected, 1e-12 * std::abs(expected)) << curve.curvature[i];
  }
  EXPECT_TRUE(curve.warnings.empty()) << curve.warnings.front();
}

// Loading is where |K| rises and hysteresis makes |M| larger: above the middle
// line for K > 0, below it for K < 0. The two sides meet at K = 0, where their
// moments (+h0 and −h0) are averaged into one point.
TEST(KawabataReader, LoadingBranchHasTheLargerMagnitudeOnBothSides) {
  const double a = 0.7, h0 = 0.05;
  const KawabataCurve curve = Parse(Loop(a, h0), Branch(KawabataBranch::kLoading));
  ASSERT_EQ(curve.curvature.size(), 41u);
  ExpectStrictlyIncreasing(curve.curvature);
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    const double k = curve.curvature[i];
    const double expected = k > 0 ? a * k + h0 : k < 0 ? a * k - h0 : 0.0;
    EXPECT_NEAR(curve.moment[i], expected, 1e-12 * std::abs(expected)) << k;
  }
}

TEST(KawabataReader, UnloadingBranchHasTheSmallerMagnitudeOnBothSides) {
  const double a = 0.7, h0 = 0.05;
  const KawabataCurve curve = Parse(Loop(a, h0), Branch(KawabataBranch::kUnloading));
  ASSERT_EQ(curve.curvature.size(), 41u);
  ExpectStrictlyIncreasing(curve.curvature);
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    const double k = curve.curvature[i];
    const double expected = k > 0 ? a * k - h0 : k < 0 ? a * k + h0 : 0.0;
    EXPECT_NEAR(curve.moment[i], expected, 1e-12 * std::abs(expected)) << k;
  }
}

TEST(KawabataReader, CrossingZeroBetweenSamplesInterpolatesAPointAtZero) {
  // The loop M = 2K ± 1 sampled at K = 0, ±0.25, ±0.75, …: going from +Kmax
  // to −Kmax the curvature jumps from 0.25 to −0.25 across zero.
  std::ostringstream text;
  text << "K (1/m)\tM (N*m/m)\n0\t1\n";
  for (double k = 0.25; k <= 4; k += 0.5) text << k << '\t' << 2 * k + 1 << '\n';
  for (double k = 3.75; k >= -4; k -= 0.5) text << k << '\t' << 2 * k - 1 << '\n';
  for (double k = -3.75; k <= 0; k += 0.5) text << k << '\t' << 2 * k + 1 << '\n';
  text << "0\t1\n";
  const KawabataCurve curve = Parse(text.str());
  ExpectStrictlyIncreasing(curve.curvature);
  bool has_zero = false;
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    if (curve.curvature[i] == 0.0) has_zero = true;
    EXPECT_NEAR(curve.moment[i], 2 * curve.curvature[i], 1e-12) << curve.curvature[i];
  }
  EXPECT_TRUE(has_zero);
}

TEST(KawabataReader, ConvertsHeaderUnitsToSI) {
  const KawabataCurve curve = Parse("curvature (1/mm),moment (N*m/m)\n0,0\n0.5,0.25\n1,1.5\n2,4\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[1], 500.0);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 2000.0);
  EXPECT_DOUBLE_EQ(curve.moment[1], 0.25);
  EXPECT_DOUBLE_EQ(curve.moment[3], 4.0);
  EXPECT_TRUE(HasWarning(curve, "only one monotone run"));
  EXPECT_TRUE(HasWarning(curve, "K >= 0 only"));
  // What was read, for the user to check.
  EXPECT_EQ(curve.curvature_read, "column 'curvature' in 1/mm");
  EXPECT_EQ(curve.moment_read, "column 'moment' in N*m/m");
}

// KES's own units when none are given: 1/cm = 100 1/m and 1 gf·cm/cm = 1 gf =
// 9.80665e-3 N·m/m (a moment per width has the dimension of a force; 9.80665e-5
// would be gf·cm → N·m without the per-width).
TEST(KawabataReader, WithoutUnitsTheUnitsAreKesOwn) {
  for (const std::string& text : {std::string("0,0\n0.5,1\n1,2.5\n2,4\n"),
                                  std::string("curvature,moment\n0,0\n0.5,1\n1,2.5\n2,4\n")}) {
    SCOPED_TRACE(text);
    const KawabataCurve curve = Parse(text);
    ASSERT_EQ(curve.curvature.size(), 4u);
    EXPECT_DOUBLE_EQ(curve.curvature[1], 0.5 * kPerCm);
    EXPECT_DOUBLE_EQ(curve.curvature[2], 100.0);
    EXPECT_DOUBLE_EQ(curve.moment[1], 9.80665e-3);
    EXPECT_DOUBLE_EQ(curve.moment[2], 2.5 * 9.80665e-3);
    EXPECT_NE(curve.moment_read.find("gf*cm/cm (KES units: none given)"), std::string::npos)
        << curve.moment_read;
  }
}

TEST(KawabataReader, ReadsTabSeparatedValues) {
  const KawabataCurve curve =
      Parse("K (1/cm)\tM (gf*cm/cm)\n0\t0\n0.1\t0.2\n0.2\t0.3\n0.3\t0.35\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 0.3 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 0.35 * kGfCmPerCm);
}

TEST(KawabataReader, ReadsSemicolonsWithDecimalCommas) {
  const KawabataCurve curve =
      Parse("curvature (1/cm);moment (gf*cm/cm)\n0;0\n0,5;1,25\n1,0;2,5\n1,5;3,75\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[1], 0.5 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[1], 1.25 * kGfCmPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 3.75 * kGfCmPerCm);
}

TEST(KawabataReader, AcceptsBomWindowsLineEndingsCommentsAndBlankLines) {
  const KawabataCurve curve = Parse(
      "\xEF\xBB\xBF# KES-FB2, sample 3\r\n"
      "curvature (1/cm),moment (gf*cm/cm)\r\n"
      "\r\n"
      "0,0\r\n"
      "  # a comment between rows\r\n"
      "0.5,1\r\n"
      "1,2\r\n"
      "\"1.5\",\"3\"\r\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 1.5 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 3 * kGfCmPerCm);
}

TEST(KawabataReader, SelectsColumnsByName) {
  const std::string text =
      "time (s),Moment (gf*cm/cm),bend (1/cm)\n0,0,0\n1,1,0.5\n2,2,1\n3,2.5,1.5\n";
  KawabataOptions options;
  options.curvature_column = "BEND";  // any case
  const KawabataCurve curve = Parse(text, options);
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 1.5 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 2.5 * kGfCmPerCm);

  options.moment_column = "time";  // any pair can be asked for; this one has the wrong unit
  try {
    Parse(text, options);
    ADD_FAILURE() << "no error";
  } catch (const KawabataError& e) {
    EXPECT_NE(std::string(e.what()).find("column 'time': unit 's'"), std::string::npos) << e.what();
  }
}

TEST(KawabataReader, NamedMomentColumnLeavesTheOtherForCurvature) {
  KawabataOptions options;
  options.moment_column = "torque";
  const KawabataCurve curve =
      Parse("torque (gf*cm/cm),c (1/cm)\n0,0\n1,0.5\n2,1\n2.5,1.5\n", options);
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 1.5 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 2.5 * kGfCmPerCm);
}

TEST(KawabataReader, FindsCurvatureAndMomentColumnsByTheirNames) {
  const KawabataCurve curve = Parse(
      "time (s),Curvature (1/cm),Bending moment (gf*cm/cm)\n0,0,0\n1,0.5,1\n2,1,2\n3,1.5,2.5\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.curvature[3], 1.5 * kPerCm);
  EXPECT_DOUBLE_EQ(curve.moment[3], 2.5 * kGfCmPerCm);
}

TEST(KawabataReader, PositiveHalfCycleCoversPositiveCurvatureOnly) {
  const KawabataCurve curve =
      Parse("curvature (1/m),moment (N*m/m)\n0,1\n1,2\n2,3\n3,4\n3,2\n2,1\n1,0\n0,-1\n");
  ASSERT_EQ(curve.curvature.size(), 4u);
  EXPECT_EQ(curve.curvature.front(), 0.0);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(curve.moment[i], curve.curvature[i]);
  EXPECT_TRUE(HasWarning(curve, "K >= 0 only")) << curve.warnings.size();
}

TEST(KawabataReader, MissingBranchOnOneSideIsUsedAsIs) {
  // 0 → 3 → −3: K < 0 has its loading branch only.
  const KawabataCurve curve = Parse(
      "curvature (1/m),moment "
      "(N*m/m)\n0,1\n1,2\n2,3\n3,4\n3,2\n2,1\n1,0\n0,-1\n-1,-2\n-2,-3\n-3,-4\n");
  ExpectStrictlyIncreasing(curve.curvature);
  EXPECT_TRUE(HasWarning(curve, "only one branch found for K < 0 (loading); used as is"));
  EXPECT_DOUBLE_EQ(curve.moment.front(), -4.0);
}

// Synthetic data from the paper's fitted law with ±0.02 gf·cm/cm hysteresis:
// averaging the branches gives the law back at every sample.
TEST(KawabataReader, CottonTwillExampleAveragesToThePapersFit) {
  const auto file =
      test::SourceDir() / "resources" / "materials" / "kawabata" / "cotton-twill-warp.csv";
  const KawabataCurve curve = ReadKawabata(file);
  EXPECT_TRUE(curve.warnings.empty());
  ASSERT_EQ(curve.curvature.size(), 51u);  // −2.5 … 2.5 in steps of 0.1 1/cm
  ExpectStrictlyIncreasing(curve.curvature);
  const double c[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  for (std::size_t i = 0; i < curve.curvature.size(); ++i) {
    const double k = curve.curvature[i] / kPerCm;
    EXPECT_NEAR(k, (static_cast<double>(i) - 25) / 10, 1e-12);
    double m = 0.0, power = 1.0;
    for (const double ci : c) m += ci * (power *= std::abs(k));
    EXPECT_NEAR(curve.moment[i] / kGfCmPerCm, std::copysign(m, k), 1e-9) << k;
  }
}

// 2HB, Kawabata's hysteresis of bending moment: the branches' distance at
// |K| = 1 1/cm. The synthetic loop's is 2 h0 by construction; the cotton
// file's header states ±0.02 gf·cm/cm, so 0.04.
TEST(KawabataReader, TheLoopsWidthIsTwoHb) {
  // K = 1 1/cm = 100 1/m: inside a loop of kmax 150 1/m on a 7.5 1/m grid
  // (100 lies between samples: interpolated).
  const KawabataCurve curve = Parse(Loop(0.7, 0.05, 150.0, 7.5));
  ASSERT_TRUE(curve.hysteresis_width.has_value());
  EXPECT_NEAR(*curve.hysteresis_width, 0.1, 1e-12);
  const auto cotton = ReadKawabata(test::SourceDir() / "resources" / "materials" / "kawabata" /
                                   "cotton-twill-warp.csv");
  ASSERT_TRUE(cotton.hysteresis_width.has_value());
  EXPECT_NEAR(*cotton.hysteresis_width, 0.04 * kGfCmPerCm, 1e-12);
  // A loop that turns before 1 1/cm, and a single branch, have none.
  EXPECT_FALSE(Parse(Loop(0.7, 0.05, 50.0, 5.0)).hysteresis_width.has_value());
  EXPECT_FALSE(Parse("K (1/cm),M (gf*cm/cm)\n0,0\n0.5,0.3\n1,0.5\n1.5,0.7\n2,0.8\n")
                   .hysteresis_width.has_value());
}

TEST(KawabataReader, MissingFileIsAnErrorNamingIt) {
  const auto file = std::filesystem::temp_directory_path() / "no-such-kawabata-file.csv";
  try {
    ReadKawabata(file);
    ADD_FAILURE() << "no error";
  } catch (const KawabataError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos);
    EXPECT_NE(e.message().find("not found"), std::string::npos);
  }
}

TEST(KawabataReader, EmptyFileIsAnError) {
  for (const std::string text : {"", "\n\n", "# only a comment\n"}) {
    try {
      Parse(text);
      ADD_FAILURE() << "no error";
    } catch (const KawabataError& e) {
      EXPECT_NE(e.message().find("empty"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("test.csv: ", 0), 0u) << e.what();
    }
  }
}

struct Malformed {
  std::string name;
  std::string text;
  int line;
  std::vector<std::string> words;
  KawabataOptions options = {};
};

const std::string kHeader = "curvature (1/cm),moment (gf*cm/cm)\n";

TEST(KawabataReader, MalformedFilesAreReportedWithLineAndReason) {
  KawabataOptions no_such_column;
  no_such_column.curvature_column = "kurv";
  KawabataOptions named;
  named.curvature_column = "curvature";
  const Malformed cases[] = {
      {"no data rows", "# KES\n" + kHeader, 2, {"no data rows"}},
      {"not a number", kHeader + "0,0\n1,abc\n", 3, {"column 'moment'", "'abc'", "not a number"}},
      {"empty cell", kHeader + "0,\n1,1\n", 2, {"column 'moment'", "empty cell"}},
      {"too many cells", kHeader + "0,0\n1,1,1\n", 3, {"3 cells", "expected 2"}},
      {"too few cells", "0,0\n1\n", 2, {"1 cell,", "expected 2"}},
      {"decimal comma with commas", kHeader + "0,1,0,2\n", 2, {"4 cells", "decimal comma"}},
      {"too few points", kHeader + "0,0\n1,1\n2,2\n", 2, {"only 3 points", "at least 4"}},
      {"short branch",
       kHeader + "0,0\n1,1\n2,2\n3,3\n2,2\n1,1\n0,0\n-1,-1\n-2,-2\n-1,-1\n0,0\n",
       8,
       {"loading branch for K < 0 (lines 8-10)", "only 3 points"}},
      {"unknown column",
       kHeader + "0,0\n",
       1,
       {"no column named 'kurv'", "'curvature', 'moment'"},
       no_such_column},
      {"named column without header", "0,0\n1,1\n", 1, {"'curvature'", "no header row"}, named},
      {"curvature unit is a length",
       "curvature (cm),moment (gf*cm/cm)\n0,0\n",
       1,
       {"column 'curvature'", "'cm'", "length", "expected a curvature"}},
      {"moment unit is a moment",
       "curvature (1/cm),moment (gf*cm)\n0,0\n",
       1,
       {"column 'moment'", "'gf*cm'", "expected a moment per width"}},
      {"unknown unit", "curvature (1/furlong),moment\n0,0\n", 1, {"unknown unit 'furlong'"}},
      {"unclosed unit", "curvature (1/cm,moment\n0,0\n", 1, {"'curvature (1/cm'", "no ')'"}},
      {"one column", "curvature\n1\n2\n", 1, {"single column"}},
      {"infinite", kHeader + "0,0\n1,inf\n2,2\n3,3\n", 3, {"'inf'", "not finite"}},
      {"too large", kHeader + "0,0\n1e400,1\n2,2\n3,3\n", 3, {"'1e400'", "not finite"}},
      {"NaN", kHeader + "0,0\n1,1\n2,2\nnan,3\n", 5, {"'nan'", "not finite"}},
      {"zig-zag", kHeader + "0,0\n0.1,1\n0.2,2\n0.3,3\n0.25,3.5\n0.4,4\n0.5,5\n", 6, {"zig-zag"}},
      {"two cycles",
       kHeader + "0,0\n1,1\n2,2\n3,3\n2,2\n1,1\n0,0\n1,1\n2,2\n3,3\n",
       8,
       {"second loading run for K > 0", "lines 2-5"}},
      {"constant curvature", kHeader + "1,0\n1,1\n1,2\n1,3\n", 2, {"never changes"}},
  };
  for (const Malformed& c : cases) {
    SCOPED_TRACE(c.name);
    try {
      ParseKawabata(c.text, "bad.csv", c.options);
      ADD_FAILURE() << "no error";
    } catch (const KawabataError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.line(), c.line) << what;
      EXPECT_EQ(what.rfind("bad.csv, line " + std::to_string(c.line) + ": ", 0), 0u) << what;
      for (const std::string& word : c.words) {
        EXPECT_NE(e.message().find(word), std::string::npos) << "'" << word << "' in: " << what;
      }
    }
  }
}

}  // namespace
}  // namespace drape
