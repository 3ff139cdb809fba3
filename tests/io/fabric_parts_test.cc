// A fabric of several parts ("fabric" an array): read and written back,
// meshed part after part, selections and probes in the part they name (or
// the only part that has them), and each mistake named at its key.
#include <gtest/gtest.h>

#include <string>

#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/fabric_mesh.h"
#include "core/model/node_selection.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

// Two 10 × 10 cm plies, 4 × 4 elements, the upper 1 mm above the lower,
// and a 6 × 4 cm strip beside them; `extra` adds to the scene.
std::string Plies(const std::string& extra = "") {
  return R"({"drape_scene": 1,
    "fabric": [
      {"name": "lower", "outline": {"rectangle": {"size": ["10 cm", "10 cm"]}},
       "mesh": {"elements": [4, 4]}},
      {"name": "upper", "outline": {"rectangle": {"size": ["10 cm", "10 cm"]}},
       "mesh": {"elements": [4, 4]}, "elevation": "1 mm"},
      {"name": "strip", "outline": {"rectangle": {"size": ["6 cm", "4 cm"], "center": ["20 cm", 0]}},
       "mesh": {"elements": [3, 2]}}],
    "material": {"thickness": "0.5 mm", "areal_weight": "1.5 N/m^2",
                 "youngs_modulus": "5 MPa", "poisson_ratio": 0.3},
    "stages": [{"name": "weight", "kind": "gravity"}])" +
         extra + "}";
}

std::string ErrorOf(const std::string& text) {
  try {
    BuildShellModel(ParseScene(text));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(FabricParts, AreReadMeshedInOrderAndWrittenBack) {
  const Scene scene = ParseScene(Plies());
  ASSERT_EQ(scene.other_parts.size(), 2u);
  EXPECT_EQ(scene.fabric.name, "lower");
  EXPECT_EQ(scene.other_parts[0].elevation, 1e-3);
  EXPECT_EQ(ParseScene(WriteSceneText(scene)), scene);
  const Mesh mesh = MeshFabricParts(scene);
  ASSERT_EQ(mesh.parts.size(), 3u);
  EXPECT_EQ(mesh.NodeCount(), 25 + 25 + 12);
  EXPECT_EQ(mesh.ElementCount(), 16 + 16 + 6);
  EXPECT_EQ(mesh.parts[1].first_node, 25);
  EXPECT_EQ(mesh.parts[2].first_element, 32);
  // Each part's nodes at its elevation, and each quad within its part.
  for (int i = 25; i < 50; ++i) EXPECT_EQ(mesh.positions(i, 2), 1e-3);
  for (int e = 16; e < 32; ++e)
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(mesh.quads(e, k), 25);
      EXPECT_LT(mesh.quads(e, k), 50);
    }
  const ShellModel model = BuildShellModel(scene);
  // The weight is every part's: 2 × 100 + 24 cm² at 1.5 N/m².
  EXPECT_NEAR(-model.total_weight.z(), 1.5 * 224e-4, 1e-15);
}

TEST(FabricParts, SelectionsAndProbesFindTheirPart) {
  const Scene scene = ParseScene(Plies(R"(,
    "supports": [{"name": "left edges", "select": {"edge": "left"}},
                 {"name": "upper middle", "select": {"point": [0, 0], "part": "upper"}},
                 {"name": "strip corner", "select": {"point": ["23 cm", "2 cm"]}}],
    "probes": [{"name": "top", "at": ["5 cm", "5 cm"], "part": "upper"},
               {"name": "strip", "at": ["20 cm", 0]}])"));
  const ShellModel model = BuildShellModel(scene);
  // An edge without a part: the left edge of each part (5 + 5 + 3 nodes).
  EXPECT_EQ(model.supports[0].nodes,
            (std::vector<int>{0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 54, 58}));
  EXPECT_EQ(model.supports[1].nodes, (std::vector<int>{25 + 12}));
  EXPECT_EQ(model.supports[2].nodes, (std::vector<int>{61}));
  // The probes: the upper's last element, and the strip's middle element.
  EXPECT_GE(model.probes[0].element, 16);
  EXPECT_LT(model.probes[0].element, 32);
  const Eigen::Vector3d top = ProbePosition(model, model.probes[0], model.reference);
  EXPECT_LT((top - Eigen::Vector3d(0.05, 0.05, 1e-3)).norm(), 1e-15);
  const Eigen::Vector3d strip = ProbePosition(model, model.probes[1], model.reference);
  EXPECT_LT((strip - Eigen::Vector3d(0.20, 0, 0)).norm(), 1e-15);
}

TEST(FabricParts, MistakesAreNamedAtTheirKey) {
  EXPECT_NE(ErrorOf(Plies(R"(, "supports": [{"name": "s", "select": {"point": [0, 0]}}])"))
                .find("supports[0].select: it picks a node in each of the parts 'lower' and "
                      "'upper', which lie over each other there; name one with \"part\""),
            std::string::npos)
      << ErrorOf(Plies(R"(, "supports": [{"name": "s", "select": {"point": [0, 0]}}])"));
  EXPECT_NE(
      ErrorOf(Plies(R"(, "probes": [{"name": "p", "at": [0, 0]}])"))
          .find("probes[0]: probe 'p' at (0, 0) m lies on the parts 'lower' and 'upper', over "
                "each other there; name one with \"part\""),
      std::string::npos);
  EXPECT_NE(ErrorOf(Plies(R"(, "probes": [{"name": "p", "at": [0, 0], "part": "strip"}])"))
                .find("probes[0].at: probe 'p' at (0, 0) m lies outside part 'strip'"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf(Plies(R"(, "supports": [{"name": "s", "select": {"edge": "left", "part": "top"}}])"))
          .find("supports[0].select.part: no fabric part is named 'top'; the parts are "
                "'lower', 'upper', 'strip'"),
      std::string::npos);
  // A part without a name, two with one name.
  std::string unnamed = Plies();
  unnamed.replace(unnamed.find(R"("name": "strip", )"), 17, "");
  EXPECT_NE(ErrorOf(unnamed).find("fabric[2]: missing required key 'name'"), std::string::npos)
      << ErrorOf(unnamed);
  std::string twice = Plies();
  twice.replace(twice.find(R"("name": "strip")"), 15, R"("name": "upper")");
  EXPECT_NE(ErrorOf(twice).find("fabric[2].name: 'upper' is already the name of fabric[1]"),
            std::string::npos)
      << ErrorOf(twice);
  // "part" names a part only where there are several.
  EXPECT_NE(ErrorOf(R"({"drape_scene": 1,
      "fabric": {"outline": {"rectangle": {"size": ["10 cm", "10 cm"]}}, "mesh": {"elements": [2, 2]}},
      "material": {"thickness": "0.5 mm", "areal_weight": "1.5 N/m^2", "youngs_modulus": "5 MPa",
                   "poisson_ratio": 0.3},
      "supports": [{"name": "s", "select": {"corners": true, "part": "lower"}}],
      "stages": [{"name": "weight", "kind": "gravity"}]})")
                .find("supports[0].select.part: 'lower' names a part, but this fabric is one "
                      "part: leave out 'part'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Plies(R"(, "solver": {"sequencing": 2})")).find("solver.sequencing: "),
            std::string::npos);
}

}  // namespace
}  // namespace drape
