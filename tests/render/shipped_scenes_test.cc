// Every shipped scene, run and exported as a user would (the `drape` binary):
// it converges on a state a real part could rest in (no negative pivot), or
// its description and its result say why not; and no number anywhere in
// what it writes is NaN or infinite — result.json, states.bin, and the CSV,
// OBJ and VTU exports of every step.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/io/state_file.h"
#include "support/drape_command.h"
#include "support/finite_outputs.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::CollectNulls;
using test::NonFiniteTokens;

int NonFiniteVtu(const fs::path& file, std::string* what) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  int bad = 0;
  auto check = [&](vtkDataArray* a, const std::string& name) {
    if (!a) return;
    for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
      for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        if (!std::isfinite(a->GetComponent(t, c)) && bad++ == 0) *what = name;
  };
  if (grid->GetNumberOfPoints() == 0) {
    *what = "no points";
    return 1;
  }
  check(grid->GetPoints()->GetData(), "points");
  for (int i = 0; i < grid->GetPointData()->GetNumberOfArrays(); ++i)
    check(grid->GetPointData()->GetArray(i), grid->GetPointData()->GetArrayName(i));
  for (int i = 0; i < grid->GetCellData()->GetNumberOfArrays(); ++i)
    check(grid->GetCellData()->GetArray(i), grid->GetCellData()->GetArrayName(i));
  return bad;
}

// Speed work must not move the answers: each probe's final position within
// 1e-4 of the part's length of what the engine computed before it
// (tests/data/shipped_probes.json names the commit). A symmetric scene whose
// snaps may land in either of two mirror-image states (its `mirror`) may
// match the mirror image of those values instead.
void ExpectProbesAsBefore(const std::string& scene, const nlohmann::json& probes) {
  std::ifstream in(test::SourceDir() / "tests" / "data" / "shipped_probes.json");
  const nlohmann::json reference = nlohmann::json::parse(in);
  ASSERT_TRUE(reference["scenes"].contains(scene))
      << "tests/data/shipped_probes.json has no values for " << scene
      << ": add them from a run of the engine it should agree with";
  const nlohmann::json& before = reference["scenes"][scene];
  const double allowed = 1e-4 * before["length"].get<double>();
  ASSERT_EQ(probes.size(), before["probes"].size());
  // The largest distance of a probe from its value before, and which.
  auto farthest = [&](const nlohmann::json* mirror) {
    std::pair<double, std::string> worst{0.0, ""};
    for (auto it = before["probes"].begin(); it != before["probes"].end(); ++it) {
      if (!probes.contains(it.key())) return std::pair{HUGE_VAL, it.key() + " (missing)"};
      std::string source = it.key();
      if (mirror && mirror->contains("probes") && (*mirror)["probes"].contains(it.key()))
        source = (*mirror)["probes"][it.key()].get<std::string>();
      const nlohmann::json& was = before["probes"][source];
      double distance2 = 0;
      for (int k = 0; k < 3; ++k) {
        double expected = was[k].get<double>();
        if (mirror) {
          expected = 0;
          for (int m = 0; m < 3; ++m)
            expected += (*mirror)["matrix"][k][m].get<double>() * was[m].get<double>();
        }
        const double d = probes[it.key()][k].get<double>() - expected;
        distance2 += d * d;
      }
      worst = std::max(worst, std::pair{std::sqrt(distance2), it.key()});
    }
    return worst;
  };
  const auto direct = farthest(nullptr);
  if (direct.first <= allowed) return;
  ASSERT_TRUE(before.contains("mirror"))
      << "probe '" << direct.second << "' moved " << direct.first << " m (allowed " << allowed
      << ") from where commit " << reference["commit"].get<std::string>() << " put it";
  const auto mirrored = farthest(&before["mirror"]);
  EXPECT_LE(mirrored.first, allowed)
      << "probe '" << direct.second << "' moved " << direct.first << " m, and '" << mirrored.second
      << "' " << mirrored.first << " m from the mirror image, from where commit "
      << reference["commit"].get<std::string>() << " put them";
}

class ShippedScene : public ::testing::TestWithParam<fs::path> {};

TEST_P(ShippedScene, EndsStableOrSaysWhyAndWritesOnlyFiniteNumbers) {
  const fs::path scene = GetParam();
  // Per process: two checkouts' tests may run at once.
  const test::TempDir folder("shipped-" + scene.stem().string());
  const fs::path& dir = folder.path();
  const test::CommandResult run =
      test::RunDrape("run '" + scene.string() + "' -o '" + dir.string() + "' --quiet");
  ASSERT_TRUE(fs::exists(dir / "result.json")) << run.output;

  std::ifstream in(dir / "result.json");
  const nlohmann::json result = nlohmann::json::parse(in);
  EXPECT_EQ(result["status"], "converged") << result["message"];
  ASSERT_FALSE(result["steps"].empty());
  const int pivots = result["steps"].back()["negative_pivots"];
  if (pivots != 0) {
    std::ifstream scene_in(scene);
    const std::string description = nlohmann::json::parse(scene_in).value("description", "");
    EXPECT_NE(description.find("ends unstable"), std::string::npos)
        << "the last state has " << pivots
        << " negative pivots and the description does not say why";
    bool warned = false;
    for (const auto& w : result["warnings"])
      warned |= w.get<std::string>().find("unstable equilibrium") != std::string::npos;
    EXPECT_TRUE(warned) << "the result does not warn of its " << pivots << " negative pivots";
  }

  ExpectProbesAsBefore(scene.stem().string(), result["final"]["probes"]);

  std::vector<std::string> nulls;
  CollectNulls(result, "", nulls);
  EXPECT_TRUE(nulls.empty()) << "result.json: " << nulls.size() << " non-finite numbers, first at "
                             << nulls.front();

  const StateFile states = ReadStateFile(dir / "states.bin");
  ASSERT_FALSE(states.steps.empty());
  for (const StoredStep& s : states.steps) {
    EXPECT_TRUE(s.positions.allFinite()) << "states.bin, step " << s.step;
    EXPECT_TRUE(s.directors.allFinite()) << "states.bin, step " << s.step;
  }

  for (const char* format : {"csv", "obj", "vtu"}) {
    const fs::path out = dir / format;
    const test::CommandResult exported = test::RunDrape("export '" + dir.string() + "' -o '" +
                                                        out.string() + "' --format " + format);
    ASSERT_EQ(exported.exit_code, 0) << exported.output;
    int files = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
      const fs::path& f = entry.path();
      std::string first;
      if (f.extension() == ".csv" || f.extension() == ".obj") {
        ++files;
        EXPECT_EQ(NonFiniteTokens(f, &first), 0) << f << ": " << first;
      } else if (f.extension() == ".vtu") {
        ++files;
        EXPECT_EQ(NonFiniteVtu(f, &first), 0) << f << ": " << first;
      }
    }
    EXPECT_GE(files, static_cast<int>(states.steps.size())) << format;
  }
}

std::string SceneName(const ::testing::TestParamInfo<fs::path>& info) {
  std::string name = info.param.stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// The shipped scenes that take a minute or more run in the slow tier, each
// by a test of its own that checks the same (tests/verification).
std::vector<fs::path> QuickScenes() {
  std::vector<fs::path> quick;
  for (const fs::path& scene : test::ExampleScenes())
    if (scene.stem() != "skirt-on-form") quick.push_back(scene);
  return quick;
}

INSTANTIATE_TEST_SUITE_P(Resources, ShippedScene, ::testing::ValuesIn(QuickScenes()), SceneName);

}  // namespace
}  // namespace drape
