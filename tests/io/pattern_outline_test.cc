// A fabric cut from a pattern file: `fabric.outline.pattern` read from a
// DXF that ezdxf wrote (tests/data/patterns/make_aama_dxf.py), meshed with
// its cut-out, in any unit the file states.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/fabric_mesh.h"
#include "core/model/node_selection.h"
#include "core/model/outline_geometry.h"
#include "core/model/scene_error.h"
#include "support/aama_patterns.h"
#include "support/drape_command.h"
#include "support/edge_chain.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using test::TempDir;

// FRONT as the script draws it [cm]: the cut line's shoelace area minus the
// 5 × 4 cm cut-out.
constexpr double kFrontAreaCm2 = 40 * 30 + 0.5 * 40 * 2 - 5 * 4;

// A scene cutting `piece` from `file` (next to the scene).
std::string PatternScene(const std::string& file,
                         const std::string& piece,
                         const std::string& angle = "0") {
  nlohmann::json scene = {{"drape_scene", 1},
                          {"fabric",
                           {{"outline", {{"pattern", {{"file", file}, {"piece", piece}}}}},
                            {"mesh", {{"size", "1.5 cm"}}}}},
                          {"material",
                           {{"thickness", "0.5 mm"},
                            {"areal_weight", "1.5 N/m^2"},
                            {"youngs_modulus", "10 MPa"},
                            {"poisson_ratio", 0.3},
                            {"angle_deg", nlohmann::json::parse(angle)}}},
                          {"supports", {{{"name", "notch"}, {"select", {{"notch", 2}}}}}},
                          {"stages", {{{"name", "weight"}, {"kind", "gravity"}}}}};
  return scene.dump(2);
}

Scene ReadIn(const TempDir& dir, const std::string& text) {
  const std::filesystem::path file = dir / "scene.json";
  std::ofstream(file) << text;
  return ReadScene(file);
}

std::string SceneErrorOf(const TempDir& dir, const std::string& text) {
  try {
    ReadIn(dir, text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(PatternOutline, MeshesThePieceWithItsCutOutOpen) {
  TempDir dir("pattern-mesh");
  test::MakeAamaPattern(dir / "p.dxf", "mm");
  const Scene scene = ReadIn(dir, PatternScene("p.dxf", "FRONT"));
  EXPECT_NEAR(OutlineArea(scene.fabric.outline), kFrontAreaCm2 * 1e-4, 1e-12);
  const Mesh mesh = MeshFabric(scene.fabric);
  EXPECT_NEAR(std::abs(ProjectedArea(mesh)) / (kFrontAreaCm2 * 1e-4), 1.0, 1e-3);
  // No element covers the cut-out's inside (10…15 × 10…14 cm).
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centroid += mesh.positions.row(mesh.quads(e, k)).transpose() / 4;
    const bool in_hole =
        centroid.x() > 0.10 && centroid.x() < 0.15 && centroid.y() > 0.10 && centroid.y() < 0.14;
    EXPECT_FALSE(in_hole) << "element " << e << " covers the cut-out";
  }
}

TEST(PatternOutline, InchesAndMillimetresGiveTheSameMesh) {
  TempDir dir("pattern-units");
  test::MakeAamaPattern(dir / "mm.dxf", "mm");
  test::MakeAamaPattern(dir / "in.dxf", "in");
  const Mesh mm = MeshFabric(ReadIn(dir, PatternScene("mm.dxf", "FRONT")).fabric);
  const Mesh in = MeshFabric(ReadIn(dir, PatternScene("in.dxf", "FRONT")).fabric);
  ASSERT_EQ(mm.NodeCount(), in.NodeCount());
  ASSERT_EQ(mm.ElementCount(), in.ElementCount());
  EXPECT_LT((mm.positions - in.positions).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(mm.quads, in.quads);
}

TEST(PatternOutline, NotchPicksTheNodeNearestIt) {
  TempDir dir("pattern-notch");
  test::MakeAamaPattern(dir / "p.dxf", "mm");
  const Scene scene = ReadIn(dir, PatternScene("p.dxf", "FRONT"));
  const Mesh mesh = MeshFabric(scene.fabric);
  const std::vector<int> nodes = SelectNodes(scene.supports[0].select, mesh, scene.fabric.outline);
  ASSERT_EQ(nodes.size(), 1u);
  // Notch 2 is at (40, 15) cm: the nearest node by brute force.
  int nearest = 0;
  for (int i = 1; i < mesh.NodeCount(); ++i)
    if ((mesh.positions.row(i).head<2>() - Eigen::RowVector2d(0.40, 0.15)).norm() <
        (mesh.positions.row(nearest).head<2>() - Eigen::RowVector2d(0.40, 0.15)).norm())
      nearest = i;
  EXPECT_EQ(nodes[0], nearest);
}

TEST(PatternOutline, MarksAreNodesAndTheFoldLineIsAChainOfEdges) {
  TempDir dir("pattern-marks");
  test::MakeAamaPattern(dir / "p.dxf", "in");
  nlohmann::json doc = nlohmann::json::parse(PatternScene("p.dxf", "FRONT"));
  doc["supports"][0]["select"] = {{"internal_line", 1}};
  const Scene scene = ReadIn(dir, doc.dump());
  const Mesh mesh = MeshFabric(scene.fabric);
  // The script's notches and drill holes [cm], each now a node.
  for (const auto& p : {Eigen::Vector2d(10, 0),
                        Eigen::Vector2d(40, 15),
                        Eigen::Vector2d(30, 31),
                        Eigen::Vector2d(0, 20),
                        Eigen::Vector2d(25, 20),
                        Eigen::Vector2d(30, 8)})
    EXPECT_LE(test::DistanceToNearestNode(mesh, 1e-2 * p), 1e-9) << p.transpose();
  // The fold line, (20, 0) to the peak (20, 32) cm: a chain of element
  // edges, and {"internal_line": 1} picks exactly its nodes.
  const std::vector<int> chain = test::ExpectEdgeChain(mesh, {0.20, 0}, {0.20, 0.32}, 1e-9);
  std::vector<int> sorted = chain;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(SelectNodes(scene.supports[0].select, mesh, scene.fabric.outline), sorted);
  EXPECT_GE(chain.size(), static_cast<std::size_t>(32 / 1.5));
  // The writer keeps the selection.
  EXPECT_EQ(ReadIn(dir, WriteSceneText(scene)), scene);
}

TEST(PatternOutline, GrainGivesTheWarpDirection) {
  TempDir dir("pattern-grain");
  test::MakeAamaPattern(dir / "p.dxf", "in");
  EXPECT_NEAR(
      ReadIn(dir, PatternScene("p.dxf", "FRONT", "\"grain\"")).material.angle_deg, 30.0, 0.01);
  EXPECT_NEAR(
      ReadIn(dir, PatternScene("p.dxf", "BACK", "\"grain\"")).material.angle_deg, 90.0, 0.01);
}

TEST(PatternOutline, APlacedPieceTakesItsMarksAndGrainAlong) {
  TempDir dir("pattern-placed");
  test::MakeAamaPattern(dir / "p.dxf", "mm");
  nlohmann::json doc = nlohmann::json::parse(PatternScene("p.dxf", "FRONT", "\"grain\""));
  doc["fabric"]["outline"]["pattern"]["at"] = {"1 m", 0};
  doc["fabric"]["outline"]["pattern"]["rotation_deg"] = 90;
  const Scene turned = ReadIn(dir, doc.dump());
  // Grain at 30° turned by 90°; notch 2 at (40, 15) cm to (1 m − 15 cm, 40 cm).
  EXPECT_NEAR(turned.material.angle_deg, 120.0, 0.01);
  const auto& shape = std::get<PatternOutline>(turned.fabric.outline).shape;
  EXPECT_NEAR(shape.notches[1][0], 0.85, 1e-12);
  EXPECT_NEAR(shape.notches[1][1], 0.40, 1e-12);
  EXPECT_NEAR(OutlineArea(turned.fabric.outline), kFrontAreaCm2 * 1e-4, 1e-12);
  // Turned over: the grain's x component changes sign, 30° → 150°.
  doc["fabric"]["outline"]["pattern"].erase("at");
  doc["fabric"]["outline"]["pattern"].erase("rotation_deg");
  doc["fabric"]["outline"]["pattern"]["flip"] = true;
  const Scene flipped = ReadIn(dir, doc.dump());
  EXPECT_NEAR(flipped.material.angle_deg, 150.0, 0.01);
  EXPECT_NEAR(std::get<PatternOutline>(flipped.fabric.outline).shape.notches[1][0], -0.40, 1e-12);
  // The scene writer keeps the placement and "grain".
  EXPECT_EQ(ReadIn(dir, WriteSceneText(turned)), turned);
  EXPECT_EQ(ReadIn(dir, WriteSceneText(flipped)), flipped);
}

TEST(PatternOutline, ErrorsNameTheKey) {
  TempDir dir("pattern-errors");
  test::MakeAamaPattern(dir / "p.dxf", "mm");
  test::MakeAamaPattern(dir / "no-grain.dxf", "mm", "no-grain");
  test::MakeAamaPattern(dir / "open.dxf", "mm", "open");
  std::string e = SceneErrorOf(dir, PatternScene("p.dxf", "SLEEVE"));
  EXPECT_NE(e.find("fabric.outline.pattern.piece: p.dxf: no piece 'SLEEVE'; the file has "
                   "'FRONT', 'BACK'"),
            std::string::npos)
      << e;
  e = SceneErrorOf(dir, PatternScene("open.dxf", "FRONT"));
  EXPECT_NE(e.find("fabric.outline.pattern.file: "), std::string::npos) << e;
  EXPECT_NE(e.find("the cut line (layer 1) is open"), std::string::npos) << e;
  e = SceneErrorOf(dir, PatternScene("no-grain.dxf", "FRONT", "\"grain\""));
  EXPECT_NE(e.find("material.angle_deg: piece 'FRONT' of no-grain.dxf has no grain line (layer 7)"),
            std::string::npos)
      << e;
  // "grain" needs a pattern piece to take it from.
  nlohmann::json rectangle = nlohmann::json::parse(PatternScene("p.dxf", "FRONT", "\"grain\""));
  rectangle["fabric"] = {{"outline", {{"rectangle", {{"size", {"10 cm", "10 cm"}}}}}},
                         {"mesh", {{"elements", {4, 4}}}}};
  rectangle["supports"] = nlohmann::json::array();
  e = SceneErrorOf(dir, rectangle.dump());
  EXPECT_NE(e.find("material.angle_deg: \"grain\" takes the warp from a pattern piece's grain "
                   "line; this fabric's outline is not a pattern piece"),
            std::string::npos)
      << e;
  // A notch the piece does not have.
  nlohmann::json many = nlohmann::json::parse(PatternScene("p.dxf", "FRONT"));
  many["supports"][0]["select"] = {{"notch", 5}};
  const Scene scene = ReadIn(dir, many.dump());
  const Mesh mesh = MeshFabric(scene.fabric);
  try {
    SelectNodes(scene.supports[0].select, mesh, scene.fabric.outline);
    ADD_FAILURE() << "no error for notch 5 of 4";
  } catch (const SelectionError& error) {
    EXPECT_STREQ(error.what(), "notch 5 does not exist; piece 'FRONT' has 4 notches (1 to 4)");
  }
  // BACK has no internal line.
  nlohmann::json back = nlohmann::json::parse(PatternScene("p.dxf", "BACK"));
  back["supports"][0]["select"] = {{"internal_line", 1}};
  const Scene back_scene = ReadIn(dir, back.dump());
  try {
    SelectNodes(
        back_scene.supports[0].select, MeshFabric(back_scene.fabric), back_scene.fabric.outline);
    ADD_FAILURE() << "no error for an internal line BACK lacks";
  } catch (const SelectionError& error) {
    EXPECT_STREQ(error.what(), "internal line 1 does not exist; piece 'BACK' has 0 internal lines");
  }
}

}  // namespace
}  // namespace drape
