// Every reader of the engine but the scene reader (scene_fuzz_test.cc) and
// result.json (tests/cli/result_fuzz_test.cc, which needs a run) must answer
// any input with its result or its documented error: never a crash, a hang,
// a sanitizer report, another exception, or a number that is not finite.
// Inputs are seeded mutations of real files (support/fuzz_input.h); their
// count per reader is DRAPE_FUZZ_INPUTS (default 2000), so a long run is
//   DRAPE_FUZZ_INPUTS=100000 ./io_tests --gtest_filter='ReaderFuzz*'
// Below the fuzz loops: one regression test per defect the fuzzing found.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/kawabata_reader.h"
#include "core/io/state_file.h"
#include "core/mechanics/director.h"
#include "core/model/mesh.h"
#include "core/model/scene_error.h"
#include "core/model/triangle_mesh_geometry.h"
#include "core/model/units.h"
#include "support/fuzz_input.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::FuzzAlphabet;
using test::FuzzInputs;
using test::FuzzTally;
using test::Mutator;

std::string ReadBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Files with these extensions anywhere under resources/ and tests/.
std::vector<fs::path> ShippedFiles(const std::vector<std::string>& extensions) {
  std::vector<fs::path> files;
  for (const char* dir : {"resources", "tests"}) {
    for (const auto& entry : fs::recursive_directory_iterator(test::SourceDir() / dir)) {
      if (!entry.is_regular_file()) continue;
      std::string ext = entry.path().extension().string();
      std::ranges::transform(ext, ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (std::ranges::find(extensions, ext) != extensions.end()) files.push_back(entry.path());
    }
  }
  std::ranges::sort(files);
  return files;
}

// A file of the system's temporary directory, unique to this process and
// input, removed at the end of its scope.
class TempFile {
 public:
  TempFile(const std::string& extension, const std::string& bytes) {
    static int counter = 0;
    path_ = fs::temp_directory_path() / ("drape-reader-fuzz-" + std::to_string(getpid()) + "-" +
                                         std::to_string(counter++) + extension);
    std::ofstream(path_, std::ios::binary).write(bytes.data(), std::ssize(bytes));
  }
  ~TempFile() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

template <class Derived>
bool AllFinite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}

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

// ---- OBJ and STL --------------------------------------------------------------

struct Solid {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;  // outward, 0-based
};

Solid Tetrahedron() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
          {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

std::string AsciiStl(const Solid& s) {
  std::ostringstream out;
  out << "solid fuzz\n";
  for (const auto& f : s.faces) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (const int v : f)
      out << "      vertex " << s.vertices[v].x() << ' ' << s.vertices[v].y() << ' '
          << s.vertices[v].z() << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid fuzz\n";
  return out.str();
}

std::string BinaryStl(const Solid& s) {
  std::string bytes(80, ' ');
  const std::uint32_t count = static_cast<std::uint32_t>(s.faces.size());
  bytes.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : s.faces) {
    float values[12] = {};  // normal, then the corners
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) values[3 + 3 * k + c] = static_cast<float>(s.vertices[f[k]][c]);
    bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    bytes.append(2, '\0');
  }
  return bytes;
}

struct MeshSeed {
  std::string extension;
  std::string bytes;
};

// The shipped meshes, and small ones that reach what they do not: OBJ with
// texture/normal indices, negative indices, quads and comments; ASCII and
// binary STL of a tetrahedron.
std::vector<MeshSeed> MeshSeeds() {
  std::vector<MeshSeed> seeds;
  for (const fs::path& file : ShippedFiles({".obj", ".stl"}))
    seeds.push_back({file.extension().string(), ReadBytes(file)});
  seeds.push_back({".obj",
                   "# cube\no cube\nv -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                   "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\nvt 0 0\nvn 0 0 1\n"
                   "g sides\nusemtl none\ns off\n"
                   "f 1/1/1 4/1/1 3/1/1 2/1/1\nf 5//1 6//1 7//1 8//1\nf 1 2 6 5\n"
                   "f -6 -5 -1 -2\nf 3 4 8 7\nf 4/1 1/1 5/1 8/1\n"});
  seeds.push_back(
      {".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"});
  seeds.push_back({".stl", AsciiStl(Tetrahedron())});
  seeds.push_back({".stl", BinaryStl(Tetrahedron())});
  return seeds;
}

FuzzAlphabet MeshAlphabet() {
  return {"0123456789.-+eE /#\n\t vftn",
          {"v ",
           "f ",
           "vt ",
           "vn ",
           "v 0 0 0\n",
           "f 1 2 3\n",
           "f -1 -2 -3\n",
           "/",
           "//",
           "1e308",
           "-1e308",
           "1e-320",
           "nan",
           "inf",
           "0",
           "-1",
           "0",
           "99999999999999999999",
           "-9223372036854775808",
           "solid",
           "facet normal 0 0 1\n",
           "outer loop\n",
           "vertex 0 0 0\n",
           "vertex 1e38 1e38 1e38\n",
           "endloop\n",
           "endfacet\n",
           "endsolid\n",
           "\r\n",
           "\n"},
          true};
}

// A few points around and far from where the seeds lie.
const std::vector<Eigen::Vector3d>& QueryPoints() {
  static const std::vector<Eigen::Vector3d> points = {{0, 0, 0},
                                                      {0.25, 0.25, 0.25},
                                                      {0.5, 0.5, 0.5},
                                                      {2, 0.1, -0.3},
                                                      {-3, 5, 1},
                                                      {0, 0, 0.6},
                                                      {1e3, -2e3, 5e2},
                                                      {1e-9, 0, 0}};
  return points;
}

TEST(ReaderFuzzMesh, MutatedObjAndStlGiveAGeometryOrASceneError) {
  const std::vector<MeshSeed> seeds = MeshSeeds();
  // The dress form is slow to check: fuzzed once in 32 inputs.
  std::vector<std::string> small, all, small_extension, all_extension;
  for (const MeshSeed& s : seeds) {
    all.push_back(s.bytes);
    all_extension.push_back(s.extension);
    if (s.bytes.size() < 20000) {
      small.push_back(s.bytes);
      small_extension.push_back(s.extension);
    }
  }
  Mutator mutator(3840, MeshAlphabet());
  FuzzTally tally{"OBJ/STL meshes"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const bool any = i % 32 == 0;
    std::size_t picked = 0;
    const std::string bytes = mutator.Make(any ? all : small, &picked);
    // Mostly the seed's own extension (any case); sometimes the other one.
    std::string extension = (any ? all_extension : small_extension)[picked];
    if (mutator.Below(8) == 0) extension = extension == ".obj" ? ".stl" : ".obj";
    if (mutator.Below(8) == 0)
      std::ranges::transform(
          extension, extension.begin(), [](unsigned char c) { return std::toupper(c); });
    const TempFile file(extension, bytes);
    try {
      const auto geometry = MakeTriangleMeshGeometry(file.path(), "fuzz");
      for (const Eigen::Vector3d& x : QueryPoints()) {
        const DistanceQuery q = geometry->Query(x);
        ASSERT_TRUE(std::isfinite(q.distance) && AllFinite(q.normal) && AllFinite(q.hessian))
            << "query at " << x.transpose() << " of " << extension << ":\n"
            << bytes;
      }
      ++tally.accepted;
    } catch (const SceneError& e) {
      ASSERT_EQ(e.where(), "fuzz") << e.what();
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

// ---- states.bin ---------------------------------------------------------------

// A state file of `steps` records on an nx × ny mesh, with unit directors.
std::string StateFileBytes(int nx, int ny, int steps) {
  const Mesh mesh = MeshRectangle(0.2, 0.1, {0, 0}, nx, ny, 0.0);
  const TempFile file(".bin", "");
  {
    StateFileWriter writer(file.path(), mesh);
    for (int s = 0; s < steps; ++s) {
      StoredStep step;
      step.stage = s / 2;
      step.step = s + 1;
      step.lambda = 0.25 * (s + 1);
      step.positions = mesh.positions;
      step.positions.col(2).array() -= 0.01 * s;
      step.directors.resize(mesh.NodeCount(), 3);
      for (int n = 0; n < mesh.NodeCount(); ++n)
        step.directors.row(n) = Eigen::Vector3d(0.1 * s, -0.05 * n, 1.0).normalized();
      writer.Append(step);
    }
  }
  return ReadBytes(file.path());
}

// Every number finite, every quad's nodes in the mesh, every record the
// mesh's size; and the rotations a result rebuilds from the directors
// (StateOf) finite too.
void ExpectSoundStates(const StateFile& states, const std::string& what) {
  const Mesh& mesh = states.mesh;
  ASSERT_TRUE(AllFinite(mesh.positions)) << what;
  if (mesh.ElementCount() > 0) {
    ASSERT_GE(mesh.quads.minCoeff(), 0) << what;
    ASSERT_LT(mesh.quads.maxCoeff(), mesh.NodeCount()) << what;
  }
  for (const StoredStep& s : states.steps) {
    ASSERT_TRUE(std::isfinite(s.lambda)) << what;
    ASSERT_EQ(s.positions.rows(), mesh.NodeCount()) << what;
    ASSERT_EQ(s.directors.rows(), mesh.NodeCount()) << what;
    ASSERT_TRUE(AllFinite(s.positions) && AllFinite(s.directors)) << what;
    for (int n = 0; n < s.directors.rows(); ++n)
      ASSERT_TRUE(AllFinite(RotationFromDirector(s.directors.row(n).transpose())))
          << what << ", node " << n << " director " << s.directors.row(n);
  }
}

std::string Hex(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string text;
  for (std::size_t i = 0; i < std::min<std::size_t>(bytes.size(), 256); ++i) {
    text += digits[static_cast<unsigned char>(bytes[i]) >> 4];
    text += digits[static_cast<unsigned char>(bytes[i]) & 15];
    text += i % 32 == 31 ? '\n' : ' ';
  }
  return text + (bytes.size() > 256 ? "..." : "") + " (" + std::to_string(bytes.size()) + " bytes)";
}

TEST(ReaderFuzzStates, MutatedStateFilesGiveStatesOrANamedError) {
  // 2 × 2 (even quad count) and 3 × 1 (odd: a padding word), with and without records.
  const std::vector<std::string> seeds = {
      StateFileBytes(2, 2, 3), StateFileBytes(3, 1, 2), StateFileBytes(1, 1, 0)};
  Mutator mutator(424242, {"\x00\x01\xff\x7f\x80", {"DRAPESTA", std::string(8, '\0')}, true});
  FuzzTally tally{"states.bin"};
  const int inputs = FuzzInputs();
  for (int i = 0; i < inputs; ++i) {
    const std::string bytes = mutator.Make(seeds);
    const TempFile file(".bin", bytes);
    try {
      ExpectSoundStates(ReadStateFile(file.path()), Hex(bytes));
      ++tally.accepted;
    } catch (const std::runtime_error& e) {
      ASSERT_NE(std::string(e.what()).find(file.path().string()), std::string::npos) << e.what();
      ++tally.rejected;
    }
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(tally.accepted, 0);
  EXPECT_GT(tally.rejected, 0);
}

// ---- regressions: one per defect the fuzzing found ------------------------------

::testing::AssertionResult Contains(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << message << "' does not contain '" << part << "'";
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

std::string MeshMessage(const std::string& name, const std::string& content) {
  const TempFile file(fs::path(name).extension().string(), content);
  try {
    const auto geometry = MakeTriangleMeshGeometry(file.path(), "obstacles[0].mesh.file");
    const DistanceQuery q = geometry->Query(Eigen::Vector3d(0.1, 0.1, 0.1));
    ADD_FAILURE() << "no SceneError; distance " << q.distance;
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Coordinates this large are finite, but the cross products and the volume
// made of them are not: the mesh passed every check and the distance was NaN.
TEST(ReaderFuzzRegression, MeshRefusesCoordinatesTooLargeToComputeWith) {
  // Corners of a cube 3e308 wide: every edge vector is 0 or ±inf, every
  // cross product NaN, so no triangle looked degenerate.
  const std::string obj =
      "v 1.5e308 1.5e308 1.5e308\nv 1.5e308 -1.5e308 -1.5e308\n"
      "v -1.5e308 1.5e308 -1.5e308\nv -1.5e308 -1.5e308 1.5e308\n"
      "f 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n";
  const std::string message = MeshMessage("big.obj", obj);
  EXPECT_TRUE(Contains(message, "obstacles[0].mesh.file: mesh '"));
  EXPECT_TRUE(Contains(message, "line 1: coordinate '1.5e308' is too large"));
  std::string stl = AsciiStl(Tetrahedron());
  stl.replace(stl.find("vertex 1 0 0"), 12, "vertex 1 -2e150 0");
  EXPECT_TRUE(Contains(MeshMessage("big.stl", stl), "coordinate '-2e150' is too large"));
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

std::string StateMessage(const std::string& bytes) {
  const TempFile file(".bin", bytes);
  try {
    ReadStateFile(file.path());
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(Contains(e.what(), "state file '" + file.path().string() + "': "));
    return e.what();
  }
  ADD_FAILURE() << "no error for\n" << Hex(bytes);
  return "";
}

template <class T>
std::string Patched(std::string bytes, std::size_t offset, T value) {
  std::memcpy(bytes.data() + offset, &value, sizeof value);
  return bytes;
}

// 2 × 2 quads: 9 nodes (bytes 24-239), 4 quads (240-303), records of
// 16 + 48 · 9 = 448 bytes from byte 304.
TEST(ReaderFuzzRegression, StateFileRefusesWhatItCannotHold) {
  const std::string good = StateFileBytes(2, 2, 3);
  ASSERT_EQ(good.size(), 304u + 3 * 448);
  // A node count of 2^31 or more was a negative matrix size; a large one an
  // allocation of gigabytes the file cannot fill.
  EXPECT_TRUE(Contains(StateMessage(Patched<std::uint32_t>(good, 12, 0xffffffffu)),
                       "truncated mesh: the header gives 4294967295 nodes and 4 elements"));
  EXPECT_TRUE(Contains(StateMessage(Patched<std::uint32_t>(good, 16, 100000000u)),
                       "truncated mesh: the header gives 9 nodes and 100000000 elements"));
  // Quads whose nodes are not in the mesh were passed on to index with.
  EXPECT_TRUE(Contains(StateMessage(Patched<std::int32_t>(good, 240 + 16 * 2 + 4, 9)),
                       "quad 2 has node 9, outside the mesh's 9 nodes (byte 276)"));
  EXPECT_TRUE(Contains(StateMessage(Patched<std::int32_t>(good, 240, -1)),
                       "quad 0 has node -1, outside the mesh's 9 nodes (byte 240)"));
  // Numbers that are not finite, and directors that are not unit vectors
  // (the rotation rebuilt from one overflowed).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 24 + 24 * 5 + 8, nan)),
                       "node 5 of the mesh: its position is not a finite number (byte 144)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 448 + 8, nan)),
                       "record 1 (stage 0, step 2): the load factor is not a finite number "
                       "(byte 760)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 16 + 24 * 3, -HUGE_VAL)),
                       "record 0 (stage 0, step 1): node 3's position is not a finite number "
                       "(byte 392)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 2 * 448 + 16 + 24 * 9 + 24 * 8, nan)),
                       "record 2 (stage 1, step 3): node 8's director is not a finite number "
                       "(byte 1624)"));
  EXPECT_TRUE(Contains(StateMessage(Patched(good, 304 + 16 + 24 * 9 + 16, 3.0)),
                       "record 0 (stage 0, step 1): node 0's director is not a unit vector "
                       "(length 3) (byte 536)"));
  // A record cut off is still no error: the whole ones before it are kept.
  const TempFile cut(".bin", good.substr(0, good.size() - 7));
  EXPECT_EQ(ReadStateFile(cut.path()).steps.size(), 2u);
}

}  // namespace
}  // namespace drape
