#include "core/io/scene_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/scene_writer.h"
#include "core/model/scene_error.h"
#include "support/minimal_scene.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using nlohmann::json;

constexpr double kGf = 9.80665e-3;                 // N, gram-force
constexpr double kOzf = 0.028349523125 * 9.80665;  // N, ounce-force (avoirdupois)
constexpr double kInch = 0.0254;                   // m

json Minimal() {
  return test::MinimalSceneJson();
}

// The message of the SceneError that parsing `doc` throws.
std::string ErrorOf(const json& doc) {
  try {
    SceneFromJson(doc);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SceneReader, SequencingMustDivideTheMeshOfOneWeightStage) {
  json doc = Minimal();
  doc["fabric"]["mesh"]["elements"] = {8, 4};
  doc["solver"]["sequencing"] = 2;
  EXPECT_EQ(SceneFromJson(doc).solver.sequencing, 2);
  doc["solver"]["sequencing"] = 0;
  EXPECT_EQ(ErrorOf(doc), "solver.sequencing: must be at least 1, found 0");
  doc["solver"]["sequencing"] = 3;
  EXPECT_EQ(ErrorOf(doc),
            "solver.sequencing: 3 must divide the mesh's 8 × 4 elements and leave at least 2 "
            "each way");
  doc["solver"]["sequencing"] = "auto";
  EXPECT_EQ(SceneFromJson(doc).solver.sequencing, kAutoSequencing);
  doc["solver"]["sequencing"] = "often";
  EXPECT_EQ(ErrorOf(doc),
            "solver.sequencing: must be \"auto\" or an integer ≥ 1 (1: off), found \"often\"");
  // Absent: auto, which the writer leaves out; off (1) is written.
  doc["solver"].erase("sequencing");
  EXPECT_EQ(SceneFromJson(doc).solver.sequencing, kAutoSequencing);
  EXPECT_FALSE(SceneToJson(SceneFromJson(doc))["solver"].contains("sequencing"));
  doc["solver"]["sequencing"] = 1;
  EXPECT_EQ(SceneFromJson(SceneToJson(SceneFromJson(doc))).solver.sequencing, 1);
}

TEST(SceneReader, APresetIsABaseTheSolverKeysBesideItOverride) {
  json doc = Minimal();
  EXPECT_FALSE(SceneFromJson(doc).solver.preset.has_value());
  EXPECT_EQ(SceneFromJson(doc).solver.mesh_scale, 1.0);
  doc["solver"] = {{"preset", "accurate"}};
  SolverSettings accurate = SceneFromJson(doc).solver;
  ASSERT_TRUE(accurate.preset.has_value());
  EXPECT_EQ(*accurate.preset, SolverPreset::kAccurate);
  EXPECT_EQ(accurate.tolerance, 1e-7);
  EXPECT_EQ(accurate.target_iterations, 6);
  EXPECT_EQ(accurate.mesh_scale, 2.0);
  // Keys beside the preset win, whatever their order in the file.
  doc["solver"] = {{"tolerance", 1e-6}, {"preset", "draft"}, {"mesh_scale", 1}};
  SolverSettings draft = SceneFromJson(doc).solver;
  EXPECT_EQ(*draft.preset, SolverPreset::kDraft);
  EXPECT_EQ(draft.tolerance, 1e-6);
  EXPECT_EQ(draft.target_iterations, 6);
  EXPECT_EQ(draft.mesh_scale, 1.0);
  // Written and read again: the same settings, the preset's name kept.
  EXPECT_EQ(SceneFromJson(SceneToJson(SceneFromJson(doc))).solver, draft);
  doc["solver"] = {{"preset", "accurate"}};
  EXPECT_EQ(SceneFromJson(SceneToJson(SceneFromJson(doc))).solver, accurate);
  doc["solver"] = {{"preset", "fast"}};
  EXPECT_EQ(ErrorOf(doc),
            "solver.preset: 'fast' is not a preset; one of draft, balanced, accurate");
  doc["solver"] = {{"mesh_scale", 20}};
  EXPECT_EQ(ErrorOf(doc), "solver.mesh_scale: must lie in [0.1, 10], found 20");
  // Sequencing is checked on the mesh that is solved: 8 x 4 at half is 4 x 2.
  doc["fabric"]["mesh"]["elements"] = {8, 4};
  doc["solver"] = {{"sequencing", 2}};
  EXPECT_EQ(SceneFromJson(doc).solver.sequencing, 2);
  doc["solver"] = {{"sequencing", 2}, {"preset", "draft"}};
  EXPECT_EQ(ErrorOf(doc),
            "solver.sequencing: 2 must divide the mesh's 4 × 2 elements and leave at least 2 "
            "each way (the mesh solved: fabric.mesh at solver.mesh_scale 0.5)");
}

TEST(SceneReader, WallClockLimitIsSecondsAboveZero) {
  json doc = Minimal();
  EXPECT_FALSE(SceneFromJson(doc).solver.max_wall_s.has_value());
  doc["solver"]["max_wall_s"] = 90.5;
  EXPECT_EQ(SceneFromJson(doc).solver.max_wall_s, 90.5);
  const Scene limited = SceneFromJson(doc);  // written and read back unchanged
  EXPECT_EQ(SceneFromJson(json::parse(SceneToJson(limited).dump())), limited);
  doc["solver"]["max_wall_s"] = 0;
  EXPECT_EQ(ErrorOf(doc), "solver.max_wall_s: must be a number of seconds > 0, found 0");
  doc["solver"]["max_wall_s"] = "1 min";
  EXPECT_NE(ErrorOf(doc).find("solver.max_wall_s"), std::string::npos) << ErrorOf(doc);
}

TEST(SceneReader, SelfContactAndItsThickness) {
  json doc = Minimal();
  EXPECT_FALSE(SceneFromJson(doc).contact.has_value());
  doc["contact"] = {{"self", true}, {"thickness", "0.4 mm"}};
  const Scene scene = SceneFromJson(doc);
  ASSERT_TRUE(scene.contact.has_value());
  EXPECT_TRUE(scene.contact->self);
  EXPECT_DOUBLE_EQ(*scene.contact->thickness, 4e-4);
  EXPECT_EQ(SceneFromJson(json::parse(SceneToJson(scene).dump())), scene);
  doc["contact"]["thickness"] = "-1 mm";
  EXPECT_NE(ErrorOf(doc).find("contact.thickness"), std::string::npos) << ErrorOf(doc);
  doc["contact"] = {{"self", "yes"}};
  EXPECT_NE(ErrorOf(doc).find("contact.self"), std::string::npos) << ErrorOf(doc);
}

TEST(SceneReader, ReadsEveryExampleScene) {
  for (const auto& file : test::ExampleScenes()) {
    SCOPED_TRACE(file.string());
    Scene scene = ReadScene(file);
    EXPECT_FALSE(scene.name.empty());
    // Each says where it comes from and how to run it.
    EXPECT_GT(scene.description.size(), 100u);
    EXPECT_NE(scene.description.find("Run: drape run resources/scenes/" + file.filename().string()),
              std::string::npos);
    EXPECT_FALSE(scene.stages.empty());
  }
}

TEST(SceneReader, SaveThenLoadGivesAnEqualScene) {
  for (const auto& file : test::ExampleScenes()) {
    SCOPED_TRACE(file.string());
    Scene scene = ReadScene(file);
    Scene again = ParseScene(WriteSceneText(scene), test::ScenesDir());
    EXPECT_TRUE(scene == again);
    // And the resolved text is a fixed point.
    EXPECT_EQ(WriteSceneText(again), WriteSceneText(scene));
  }
}

TEST(SceneReader, ResolvesPaperUnitsToSI) {
  Scene rod = ReadScene(test::ScenesDir() / "rod-drape-nonlinear.json");
  // 0.02665 gf/cm² = 0.02665 × 9.80665e-3 N / 1e-4 m² = 2.61347 N/m² (issue 3's example).
  EXPECT_NEAR(rod.material.areal_weight, 2.6134722, 1e-6);
  EXPECT_DOUBLE_EQ(rod.material.thickness, 0.0489e-2);
  const auto& poly = std::get<PolynomialBending>(rod.material.bending.warp);
  ASSERT_EQ(poly.coefficients.size(), 5u);
  // The SI law must give the same moment as the paper's law in its units:
  // K = 1.7 1/cm → M = Σ cₖ 1.7ᵏ gf·cm/cm.
  const double paper[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  double k_cm = 1.7, m_paper = 0, m_si = 0;
  for (int i = 0; i < 5; ++i) {
    m_paper += paper[i] * std::pow(k_cm, i + 1);
    m_si += poly.coefficients[i] * std::pow(k_cm * 100.0, i + 1);
  }
  EXPECT_NEAR(m_si, m_paper * kGf, 1e-12);  // gf·cm/cm = gf = 9.80665e-3 N
  EXPECT_DOUBLE_EQ(poly.valid_to, 250.0);

  Scene strip = ReadScene(test::ScenesDir() / "strip-fold.json");
  const auto& e = std::get<IsotropicMembrane>(strip.material.membrane);
  EXPECT_NEAR(e.youngs_modulus, 4196 * kOzf / (kInch * kInch), 1e-6);
  EXPECT_NEAR(strip.material.areal_weight, 4.019e-3 * kOzf / (kInch * kInch), 1e-12);
  EXPECT_EQ(strip.fabric.mesh.elements, (std::array<int, 2>{80, 2}));
  ASSERT_EQ(strip.stages.size(), 3u);
  EXPECT_DOUBLE_EQ(strip.stages[0].initial_increment, 2.70782672e-6);
  const auto& arc = std::get<ArcPath>(strip.stages[1].moves[0].path);
  EXPECT_DOUBLE_EQ(arc.angle_deg, 180.0);
  EXPECT_EQ(strip.solver.target_iterations, 10);
}

TEST(SceneReader, DefaultsAreDocumented) {
  Scene s = SceneFromJson(Minimal());
  EXPECT_EQ(s.gravity_direction, (Vec3{0, 0, -1}));
  EXPECT_DOUBLE_EQ(s.solver.tolerance, 1e-5);
  EXPECT_EQ(s.solver.target_iterations, 7);
  EXPECT_TRUE(s.solver.acceleration);
  EXPECT_EQ(s.stages[0].control, StepControl::kArcLength);
  EXPECT_TRUE(std::holds_alternative<LinearBending>(s.material.bending.warp));
  EXPECT_FALSE(std::get<LinearBending>(s.material.bending.warp).rigidity.has_value());
  EXPECT_EQ(std::get<RectangleOutline>(s.fabric.outline).center, (Vec2{0, 0}));
}

TEST(SceneReader, AcceptsArealDensityAsMassTimesStandardGravity) {
  json doc = Minimal();
  doc["material"].erase("areal_weight");
  doc["material"]["areal_density"] = "150 g/m^2";
  EXPECT_NEAR(SceneFromJson(doc).material.areal_weight, 0.150 * 9.80665, 1e-12);
}

TEST(SceneReader, NormalisesDirectionsButKeepsUnitOnesExactly) {
  json doc = Minimal();
  doc["gravity"] = {{"direction", {3, 0, -4}}};
  EXPECT_EQ(SceneFromJson(doc).gravity_direction, (Vec3{0.6, 0, -0.8}));
  double s = std::sqrt(0.5);
  doc["gravity"] = {{"direction", {s, 0, -s}}};
  EXPECT_EQ(SceneFromJson(doc).gravity_direction, (Vec3{s, 0, -s}));
}

TEST(SceneReader, AngleInRadiansUnderDegKeyIsConverted) {
  json doc = Minimal();
  doc["material"]["angle_deg"] = "0.5 rad";
  EXPECT_NEAR(SceneFromJson(doc).material.angle_deg, 0.5 * 180 / M_PI, 1e-12);
  doc["material"]["angle_deg"] = 45;
  EXPECT_DOUBLE_EQ(SceneFromJson(doc).material.angle_deg, 45);
}

TEST(SceneReader, UnknownKeySuggestsTheNearestValidKey) {
  json doc = Minimal();
  doc["fabric"]["mesh"] = {{"element", {8, 1}}};
  EXPECT_EQ(ErrorOf(doc), "fabric.mesh.element: unknown key; did you mean 'elements'?");
  doc = Minimal();
  doc["material"]["thicknes"] = 1;
  EXPECT_EQ(ErrorOf(doc), "material.thicknes: unknown key; did you mean 'thickness'?");
}

TEST(SceneReader, UnitOfTheWrongDimensionNamesKeyAndDimension) {
  json doc = Minimal();
  doc["material"]["youngs_modulus"] = "3 cm";
  std::string message = ErrorOf(doc);
  EXPECT_EQ(message.rfind("material.youngs_modulus: ", 0), 0u) << message;
  EXPECT_NE(message.find("force/area"), std::string::npos) << message;
}

TEST(SceneReader, DuplicateJsonKeyIsAnErrorNotSilentlyOverwritten) {
  std::string text = R"({"drape_scene": 1, "fabric": {"outline": {}, "outline": {}}})";
  try {
    ParseScene(text);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where(), "fabric.outline");
    EXPECT_NE(std::string(e.what()).find("twice"), std::string::npos);
  }
}

TEST(SceneReader, NotJsonGivesLineAndColumn) {
  std::string text = "{\n  \"drape_scene\": 1,\n  \"name\": oops\n}\n";
  try {
    ParseScene(text);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.where().rfind("line 3, column ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos);
  }
}

TEST(SceneReader, MissingFileIsAClearError) {
  try {
    ReadScene("/nonexistent/scene.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json"), std::string::npos);
  }
}

TEST(SceneReader, FileReferencesMustExist) {
  json doc = Minimal();
  doc["material"]["bending"] = {{"model", "curve"}, {"file", "no-such-kawabata.csv"}};
  std::string message = ErrorOf(doc);
  EXPECT_EQ(message.rfind("material.bending.file: cannot read 'no-such-kawabata.csv'", 0), 0u)
      << message;
}

// A Kawabata file in a curve law is read with the scene: its averaged
// points are the law's, in SI; a bad file is an error at the key, carrying
// the file's own line number.
TEST(SceneReader, CurveLawReadsItsKawabataFile) {
  json doc = Minimal();
  doc["material"]["bending"] = {{"model", "curve"},
                                {"file", "../materials/kawabata/cotton-twill-warp.csv"}};
  const Scene scene = SceneFromJson(doc, test::ScenesDir());
  const auto& law = std::get<CurveBending>(scene.material.bending.warp);
  ASSERT_EQ(law.points.size(), 51u);  // −2.5 … 2.5 1/cm in steps of 0.1
  // The paper's fit at K = 1 1/cm: Σ cₖ = 0.56232 gf·cm/cm (the file is
  // synthetic from it, with ±0.02 hysteresis averaged out).
  const auto& at_one = law.points[35];
  EXPECT_NEAR(at_one[0], 100.0, 1e-9);
  EXPECT_NEAR(at_one[1], (1.33387 - 2.23070 + 2.36510 - 1.08471 + 0.17876) * 9.80665e-3, 1e-12);

  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "drape-bad-kes.csv";
  std::ofstream(bad) << "curvature (1/cm),moment (gf*cm/cm)\n0,0\n0.1,abc\n";
  doc["material"]["bending"]["file"] = bad.string();
  const std::string message = ErrorOf(doc);
  EXPECT_EQ(message.rfind("material.bending.file: ", 0), 0u) << message;
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
  std::filesystem::remove(bad);
}

// Bending hysteresis: 2HB as a quantity, as a bare number in the law's
// moment_unit, or "measured" from a Kawabata file's loop; per direction;
// kept through a save; bad values named at the key.
TEST(SceneReader, BendingHysteresisIsReadPerLaw) {
  json doc = Minimal();
  doc["material"]["bending"] = {
      {"model", "linear"}, {"rigidity", "0.118 gf*cm^2/cm"}, {"hysteresis", "0.124 gf*cm/cm"}};
  const Scene linear = SceneFromJson(doc);
  EXPECT_NEAR(linear.material.bending.warp_hysteresis.width, 0.124 * kGf, 1e-15);
  EXPECT_FALSE(linear.material.bending.warp_hysteresis.measured);
  EXPECT_EQ(ParseScene(WriteSceneText(linear)).material, linear.material);

  doc["material"]["bending"] = {{"model", "curve"},
                                {"file", "../materials/kawabata/cotton-twill-warp.csv"},
                                {"hysteresis", "measured"}};
  const Scene measured = SceneFromJson(doc, test::ScenesDir());
  EXPECT_NEAR(measured.material.bending.warp_hysteresis.width, 0.04 * kGf, 1e-12);
  EXPECT_TRUE(measured.material.bending.warp_hysteresis.measured);
  EXPECT_EQ(ParseScene(WriteSceneText(measured), test::ScenesDir()).material, measured.material);

  const json polynomial = {{"model", "polynomial"},
                           {"coefficients", {1.33387}},
                           {"moment_unit", "gf*cm/cm"},
                           {"curvature_unit", "1/cm"},
                           {"valid_to", "2.5 1/cm"},
                           {"hysteresis", 0.05}};
  doc["material"]["bending"] = {{"warp", polynomial}, {"weft", {{"model", "linear"}}}};
  const Scene warp_only = SceneFromJson(doc);
  EXPECT_NEAR(warp_only.material.bending.warp_hysteresis.width, 0.05 * kGf, 1e-15);
  EXPECT_EQ(warp_only.material.bending.weft_hysteresis.width, 0.0);

  doc["material"]["bending"] = {{"model", "linear"}, {"hysteresis", "-0.1 gf*cm/cm"}};
  EXPECT_EQ(ErrorOf(doc).rfind("material.bending.hysteresis: 2HB", 0), 0u) << ErrorOf(doc);
  doc["material"]["bending"]["hysteresis"] = "0.1 gf*cm^2/cm";
  EXPECT_EQ(ErrorOf(doc).rfind("material.bending.hysteresis: ", 0), 0u) << ErrorOf(doc);
  doc["material"]["bending"]["hysteresis"] = "measured";
  EXPECT_EQ(ErrorOf(doc),
            "material.bending.hysteresis: \"measured\" takes 2HB from a Kawabata file's loop; "
            "this law has no 'file'");
}

// The branch and the columns of a Kawabata file are the scene's choice, and
// survive a save.
TEST(SceneReader, CurveLawPicksBranchAndColumns) {
  json doc = Minimal();
  doc["material"]["bending"] = {{"model", "curve"},
                                {"file", "../materials/kawabata/cotton-twill-warp.csv"},
                                {"branch", "loading"}};
  const Scene loading = SceneFromJson(doc, test::ScenesDir());
  const auto& law = std::get<CurveBending>(loading.material.bending.warp);
  // The synthetic file loads 0.02 gf·cm/cm above the paper's law.
  EXPECT_NEAR(law.points[35][1],
              (1.33387 - 2.23070 + 2.36510 - 1.08471 + 0.17876 + 0.02) * 9.80665e-3,
              1e-12);
  EXPECT_EQ(ParseScene(WriteSceneText(loading), test::ScenesDir()).material, loading.material);

  const std::filesystem::path three = std::filesystem::temp_directory_path() / "drape-3col.csv";
  std::ofstream(three) << "time (s),M (gf*cm/cm),K (1/cm)\n0,0,0\n1,0.5,1\n2,0.8,2\n3,1.0,3\n";
  doc["material"]["bending"] = {
      {"model", "curve"}, {"file", three.string()}, {"columns", {"K", "M"}}};
  const Scene picked = SceneFromJson(doc);
  const auto& points = std::get<CurveBending>(picked.material.bending.warp).points;
  ASSERT_EQ(points.size(), 4u);
  EXPECT_NEAR(points[2][0], 200.0, 1e-12);
  EXPECT_NEAR(points[2][1], 0.8 * kGf, 1e-15);
  EXPECT_EQ(ParseScene(WriteSceneText(picked)).material, picked.material);
  doc["material"]["bending"]["columns"] = {"K", "torque"};
  EXPECT_EQ(ErrorOf(doc).rfind("material.bending.file: ", 0), 0u) << ErrorOf(doc);
  std::filesystem::remove(three);

  doc["material"]["bending"] = {
      {"model", "curve"}, {"points", {{1, 1}, {2, 3}}}, {"branch", "loading"}};
  EXPECT_EQ(ErrorOf(doc), "material.bending.branch: applies only to a Kawabata 'file'");
}

TEST(SceneReader, ReleasedGripperCannotMoveLater) {
  json doc = Minimal();
  doc["grippers"] = json::array({{{"name", "g"}, {"select", {{"edge", "right"}}}}});
  doc["stages"] = json::parse(R"([
    {"name": "up", "kind": "move", "moves": [{"gripper": "g", "path": {"line": {"by": [0, 0, 0.01]}}}]},
    {"name": "drop", "kind": "hold", "release": ["g"]},
    {"name": "again", "kind": "move", "moves": [{"gripper": "g", "path": {"line": {"by": [0, 0, 0.01]}}}]}
  ])");
  EXPECT_EQ(ErrorOf(doc), "stages[2].moves[0].gripper: gripper 'g' was released in stage 'drop'");
}

// A mesh obstacle's placement: a scale (one factor or three), a turn about
// the vertical and where its origin goes, each in the user's units; written
// back the same; a scale that would mirror or vanish the form names its key
// and the value.
TEST(SceneReader, MeshObstacleIsScaledTurnedAndPlaced) {
  json doc = Minimal();
  const std::string form = (test::SourceDir() / "resources/forms/dress-form.obj").string();
  doc["obstacles"] = json::parse(R"([{"name": "form", "mesh": {"scale": [1.1, 1.1, 1.2],
      "rotation_deg": "0.5 rad", "at": ["10 cm", 0, "-5 mm"]}}])");
  doc["obstacles"][0]["mesh"]["file"] = form;
  const Scene scene = SceneFromJson(doc);
  const auto& mesh = std::get<MeshShape>(scene.obstacles[0].shape);
  EXPECT_EQ(mesh.scale, (Vec3{1.1, 1.1, 1.2}));
  EXPECT_NEAR(mesh.rotation_deg, 0.5 * 180 / M_PI, 1e-12);
  EXPECT_EQ(mesh.at, (Vec3{0.1, 0, -0.005}));
  EXPECT_EQ(ParseScene(WriteSceneText(scene)).obstacles, scene.obstacles);

  doc["obstacles"][0]["mesh"]["scale"] = 2;
  EXPECT_EQ(std::get<MeshShape>(SceneFromJson(doc).obstacles[0].shape).scale, (Vec3{2, 2, 2}));
  doc["obstacles"][0]["mesh"]["scale"] = -2;
  EXPECT_EQ(ErrorOf(doc),
            "obstacles[0].mesh.scale: a scale factor must be between 1e-6 and 1e6 (a positive "
            "number; a negative one would turn the mesh inside out), found -2");
  doc["obstacles"][0]["mesh"]["scale"] = {1, 0, 1};
  EXPECT_EQ(ErrorOf(doc).rfind("obstacles[0].mesh.scale[1]: a scale factor must be", 0), 0u);
  doc["obstacles"][0]["mesh"]["scale"] = {1, 2};
  EXPECT_EQ(ErrorOf(doc).rfind("obstacles[0].mesh.scale: expected 3 values", 0), 0u)
      << ErrorOf(doc);
}

}  // namespace
}  // namespace drape
