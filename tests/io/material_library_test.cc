// Scenes that name a library material: lookup, overrides, errors, and the
// library that ships in resources/materials.
#include "core/io/material_library.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/scene_error.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kGf = 9.80665e-3;  // N

// A scene folder with a materials/ library next to the scenes.
class LibraryDir {
 public:
  LibraryDir()
      : root_(fs::temp_directory_path() / ("drape-library-" + std::to_string(::getpid()))) {
    fs::remove_all(root_);
    fs::create_directories(root_ / "scenes");
    fs::create_directories(root_ / "materials" / "kawabata");
  }
  ~LibraryDir() { fs::remove_all(root_); }
  fs::path Scenes() const { return root_ / "scenes"; }
  fs::path Materials() const { return root_ / "materials"; }
  void Write(const fs::path& file, const std::string& text) const { std::ofstream(file) << text; }

 private:
  fs::path root_;
};

json Entry(json material) {
  return {{"drape_material", 1},
          {"name", "Test twill"},
          {"source", "made up for the test"},
          {"description", "an orthotropic twill with a measured warp curve"},
          {"material", std::move(material)}};
}

json TwillMaterial() {
  return json::parse(R"({
    "thickness": "0.5 mm", "areal_density": "200 g/m^2",
    "membrane": {"E1": "2 MPa", "E2": "1 MPa", "nu12": 0.2, "G12": "0.05 MPa"},
    "bending": {"warp": {"model": "curve", "file": "kawabata/twill-warp.csv"},
                "weft": {"model": "linear", "rigidity": "0.3 gf*cm^2/cm"}}
  })");
}

json SceneWith(json material) {
  json doc = json::parse(R"({
    "drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": ["20 cm", "2 cm"]}}, "mesh": {"elements": [8, 1]}},
    "supports": [{"name": "root", "select": {"edge": "left"}, "fix": "clamp"}],
    "stages": [{"name": "SW", "kind": "gravity"}]
  })");
  doc["material"] = std::move(material);
  return doc;
}

std::string ErrorOf(const json& doc, const fs::path& base) {
  try {
    SceneFromJson(doc, base);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

class MaterialLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_.Write(dir_.Materials() / "test-twill.json", Entry(TwillMaterial()).dump());
    dir_.Write(dir_.Materials() / "kawabata" / "twill-warp.csv",
               "curvature (1/cm),moment (gf*cm/cm)\n0,0\n0.5,0.4\n1.0,0.7\n1.5,0.95\n2.0,1.2\n");
  }
  LibraryDir dir_;
};

TEST_F(MaterialLibrary, ANamedMaterialIsTheLibraryEntry) {
  const Scene scene = SceneFromJson(SceneWith({{"library", "test-twill"}}), dir_.Scenes());
  const Material& m = scene.material;
  EXPECT_DOUBLE_EQ(m.thickness, 0.5e-3);
  EXPECT_DOUBLE_EQ(m.areal_weight, 0.2 * 9.80665);
  const auto& membrane = std::get<OrthotropicMembrane>(m.membrane);
  EXPECT_DOUBLE_EQ(membrane.e1, 2e6);
  EXPECT_DOUBLE_EQ(membrane.g12, 0.05e6);
  // The warp's Kawabata file is found next to the library entry and kept as
  // an absolute path, so the scene can be saved anywhere and read again.
  const auto& warp = std::get<CurveBending>(m.bending.warp);
  ASSERT_EQ(warp.points.size(), 5u);
  EXPECT_NEAR(warp.points[2][1], 0.7 * kGf, 1e-15);
  EXPECT_TRUE(fs::path(warp.file).is_absolute()) << warp.file;
  const auto& weft = std::get<LinearBending>(*m.bending.weft);
  EXPECT_NEAR(*weft.rigidity, 0.3 * kGf * 1e-2, 1e-15);
  const Scene again = ParseScene(WriteSceneText(scene), fs::temp_directory_path());
  EXPECT_EQ(again.material, scene.material);
}

TEST_F(MaterialLibrary, SceneKeysOverrideTheEntry) {
  const Scene scene = SceneFromJson(
      SceneWith({{"library", "test-twill"}, {"thickness", "0.8 mm"}, {"angle_deg", 45}}),
      dir_.Scenes());
  EXPECT_DOUBLE_EQ(scene.material.thickness, 0.8e-3);
  EXPECT_DOUBLE_EQ(scene.material.angle_deg, 45.0);
  EXPECT_TRUE(std::holds_alternative<OrthotropicMembrane>(scene.material.membrane));
  // An isotropic modulus replaces the entry's orthotropic membrane.
  const Scene iso = SceneFromJson(
      SceneWith({{"library", "test-twill"}, {"youngs_modulus", "3 MPa"}, {"poisson_ratio", 0.25}}),
      dir_.Scenes());
  const auto& m = std::get<IsotropicMembrane>(iso.material.membrane);
  EXPECT_DOUBLE_EQ(m.youngs_modulus, 3e6);
  // A scene's own bending replaces the entry's, and its files are the scene's.
  const Scene linear = SceneFromJson(
      SceneWith({{"library", "test-twill"}, {"bending", {{"model", "linear"}}}}), dir_.Scenes());
  EXPECT_TRUE(std::holds_alternative<LinearBending>(linear.material.bending.warp));
  EXPECT_FALSE(linear.material.bending.weft);
}

TEST_F(MaterialLibrary, UnknownNameSuggestsTheNearestOrListsTheLibrary) {
  std::string message = ErrorOf(SceneWith({{"library", "test-twil"}}), dir_.Scenes());
  EXPECT_EQ(message.rfind("material.library: no library material 'test-twil'; did you mean "
                          "'test-twill'?",
                          0),
            0u)
      << message;
  message = ErrorOf(SceneWith({{"library", "velvet-of-mars"}}), dir_.Scenes());
  EXPECT_NE(message.find("the library has: "), std::string::npos) << message;
  EXPECT_NE(message.find("test-twill"), std::string::npos) << message;
  // A name, not a path.
  message = ErrorOf(SceneWith({{"library", "../materials/test-twill"}}), dir_.Scenes());
  EXPECT_EQ(message.rfind("material.library: no library material", 0), 0u) << message;
}

TEST_F(MaterialLibrary, ABadEntryIsAnErrorInItsOwnFile) {
  json bad = TwillMaterial();
  bad["thickness"] = "-1 mm";
  dir_.Write(dir_.Materials() / "bad.json", Entry(bad).dump());
  const fs::path file = (dir_.Materials() / "bad.json").lexically_normal();
  std::string message = ErrorOf(SceneWith({{"library", "bad"}}), dir_.Scenes());
  EXPECT_EQ(message.rfind(file.string() + ": material.thickness: ", 0), 0u) << message;

  dir_.Write(dir_.Materials() / "old.json", R"({"drape_material": 7, "material": {}})");
  message = ErrorOf(SceneWith({{"library", "old"}}), dir_.Scenes());
  EXPECT_NE(message.find("unsupported material format version 7"), std::string::npos) << message;

  dir_.Write(dir_.Materials() / "broken.json", "{\"drape_material\": 1,");
  message = ErrorOf(SceneWith({{"library", "broken"}}), dir_.Scenes());
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;

  // A bad override is the scene's error, at its key.
  message = ErrorOf(SceneWith({{"library", "test-twill"}, {"thicknes", "1 mm"}}), dir_.Scenes());
  EXPECT_EQ(message.rfind("material.thicknes: unknown key; did you mean 'thickness'?", 0), 0u)
      << message;
}

TEST_F(MaterialLibrary, EnvironmentDirectoriesComeFirst) {
  const fs::path elsewhere = dir_.Scenes() / "my-materials";
  fs::create_directories(elsewhere);
  json mine = TwillMaterial();
  mine["thickness"] = "0.3 mm";
  mine["bending"] = {{"model", "linear"}};
  dir_.Write(elsewhere / "test-twill.json", Entry(mine).dump());
  ::setenv("DRAPE_MATERIALS", ("/no/such/dir:" + elsewhere.string()).c_str(), 1);
  const Scene scene = SceneFromJson(SceneWith({{"library", "test-twill"}}), dir_.Scenes());
  ::unsetenv("DRAPE_MATERIALS");
  EXPECT_DOUBLE_EQ(scene.material.thickness, 0.3e-3);
}

// Every entry that ships parses, names its source, and builds a model.
TEST(ShippedMaterialLibrary, EveryEntryReadsAndBuildsAModel) {
  const fs::path dir = test::SourceDir() / "resources" / "materials";
  const std::vector<std::string> names = LibraryMaterialNames({dir});
  EXPECT_GE(names.size(), 3u);
  for (const auto& name : names) {
    SCOPED_TRACE(name);
    const LibraryMaterial entry = ReadLibraryMaterial(dir / (name + ".json"));
    EXPECT_FALSE(entry.source.empty());
    const Scene scene = SceneFromJson(SceneWith({{"library", name}}), test::ScenesDir());
    EXPECT_GT(scene.material.thickness, 0);
    EXPECT_GT(scene.material.areal_weight, 0);
    const ShellModel model = BuildShellModel(scene);
    EXPECT_GT(model.section.bending(0, 0), 0);
  }
}

}  // namespace
}  // namespace drape
