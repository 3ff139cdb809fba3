// `drape material fit`: what it prints is a scene's `bending` object;
// `drape material list`: the library a scene can name;
// `drape material show`: a library entry's figures in textile units, read
// back from the material a scene builds of it.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <variant>

#include <unistd.h>

#include "core/io/scene_reader.h"
#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using nlohmann::json;

const std::string kCottonCsv =
    (test::SourceDir() / "resources/materials/kawabata/cotton-twill-warp.csv").string();

TEST(MaterialFitCli, JsonIsASceneBendingObject) {
  const test::CommandResult r =
      test::RunDrape("material fit '" + kCottonCsv + "' --json", test::Captured::kStdout);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json bending = json::parse(r.output);
  EXPECT_EQ(bending["model"], "polynomial");
  ASSERT_EQ(bending["coefficients"].size(), 5u);
  // The file is synthetic from the paper's fit (its hysteresis averages out).
  const double paper[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(bending["coefficients"][i].get<double>(), paper[i], 1e-9);
  EXPECT_EQ(bending["valid_to"], "2.5 1/cm");
  EXPECT_EQ(bending["range"], json::array({-2.5, 2.5}));

  // Pasted into a scene (without the fit's report keys), the reader takes it.
  json scene = json::parse(std::ifstream(test::ScenesDir() / "rod-drape-nonlinear.json"));
  json law = bending;
  law.erase("rms_error");
  law.erase("range");
  scene["material"]["bending"] = law;
  const Scene read = SceneFromJson(scene, test::ScenesDir());
  const auto& polynomial = std::get<PolynomialBending>(read.material.bending.warp);
  EXPECT_NEAR(polynomial.coefficients[0], 1.33387 * 9.80665e-3 / 100, 1e-12);
  EXPECT_NEAR(polynomial.valid_to, 250.0, 1e-9);
}

TEST(MaterialFitCli, ReportNamesUnitsAndRange) {
  const test::CommandResult r = test::RunDrape("material fit '" + kCottonCsv + "' --degree 3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("51 points, K from -2.5 to 2.5 1/cm"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gf*cm/cm"), std::string::npos);
  EXPECT_NE(r.output.find("c3 = "), std::string::npos);
  EXPECT_EQ(r.output.find("c4 = "), std::string::npos);
  EXPECT_NE(r.output.find("rms error"), std::string::npos);
}

TEST(MaterialFitCli, BadFileExitsOneWithTheLine) {
  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "drape-fit-bad.csv";
  std::ofstream(bad) << "curvature (1/cm),moment (gf*cm/cm)\n0,0\n0.1,0.13\n0.2,x\n";
  const test::CommandResult r = test::RunDrape("material fit '" + bad.string() + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("drape material fit: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("line 4"), std::string::npos) << r.output;
  std::filesystem::remove(bad);

  const test::CommandResult degree =
      test::RunDrape("material fit '" + kCottonCsv + "' --degree 12");
  EXPECT_NE(degree.exit_code, 0);
}

TEST(MaterialFitCli, SplineJsonIsASceneCurveThroughThePapersLaw) {
  const test::CommandResult r =
      test::RunDrape("material fit '" + kCottonCsv + "' --model spline --knots 10 --json",
                     test::Captured::kStdout);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json bending = json::parse(r.output);
  EXPECT_EQ(bending["model"], "curve");
  ASSERT_EQ(bending["points"].size(), 10u);
  // Knot 4 is K = 1 1/cm, where the paper's law gives Σ cₖ and the file's
  // 0.1-spaced points are that law; a local quadratic over ±0.375 1/cm
  // misses only its K⁴, K⁵ terms there (measured: 1.3e-4 gf·cm/cm).
  EXPECT_DOUBLE_EQ(bending["points"][3][0].get<double>(), 1.0);
  EXPECT_NEAR(
      bending["points"][3][1].get<double>(), 1.33387 - 2.23070 + 2.36510 - 1.08471 + 0.17876, 1e-3);
  json scene = json::parse(std::ifstream(test::ScenesDir() / "rod-drape-nonlinear.json"));
  json law = bending;
  law.erase("rms_error");
  law.erase("range");
  scene["material"]["bending"] = law;
  const Scene read = SceneFromJson(scene, test::ScenesDir());
  EXPECT_EQ(std::get<CurveBending>(read.material.bending.warp).points.size(), 10u);
}

TEST(MaterialFitCli, WarnsOfAFitThatSoftensInsideItsRange) {
  // M = K − 0.3 K³: dM/dK = 1 − 0.9 K² < 0 beyond K = 1/√0.9 = 1.0541 1/cm.
  const std::filesystem::path soft = std::filesystem::temp_directory_path() / "drape-soft.csv";
  {
    std::ofstream out(soft);
    out << "curvature (1/cm),moment (gf*cm/cm)\n";
    for (int i = 0; i <= 25; ++i)
      out << 0.1 * i << "," << 0.1 * i - 0.3 * std::pow(0.1 * i, 3) << "\n";
  }
  const test::CommandResult r = test::RunDrape("material fit '" + soft.string() + "' --degree 3");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the fitted moment falls with curvature (dM/dK < 0) for K from "
                          "1.054 to 2.5 1/cm"),
            std::string::npos)
      << r.output;
  std::filesystem::remove(soft);
}

// `drape material show NAME --json`, parsed; the exit code is checked.
json ShowJson(const std::string& name) {
  const test::CommandResult r =
      test::RunDrape("material show '" + name + "' --json", test::Captured::kStdout);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return json::parse(r.output);
}

// Within 0.5 % of a published figure.
void ExpectFigure(const json& shown, const char* key, double published) {
  ASSERT_TRUE(shown.contains(key)) << key;
  ASSERT_TRUE(shown[key].is_number()) << key << ": " << shown[key];
  EXPECT_NEAR(shown[key].get<double>(), published, 0.005 * std::abs(published)) << key;
}

// J. W. Eischen, S. Deng, T. G. Clapp, "Finite-element modeling and control of
// flexible fabric parts", IEEE CG&A, Oct. 1996, section "Fabric material
// response": cotton twill, h = 0.0489 cm, w = 0.02665 gmf/cm^2, Kawabata
// B = 0.589 gmf cm^2/cm (warp), I = 9.744e-6 cm^4 per 1 cm strip, and the
// effective modulus E = B/I it uses as the membrane, with nu = 0.3.
TEST(MaterialShowCli, CottonTwillLinearGivesBackEischenDengClapp1996) {
  const double h_cm = 0.0489, w_gf_per_cm2 = 0.02665, b = 0.589, inertia_cm4 = 9.744e-6;
  const double nu = 0.3;
  const double e = b / inertia_cm4;  // gf/cm^2, the paper's 60450
  const json shown = ShowJson("cotton-twill-linear");
  ExpectFigure(shown, "thickness_mm", h_cm * 10);
  ExpectFigure(shown, "weight_g_per_m2", w_gf_per_cm2 * 1e4);  // 1 gf/cm^2 of weight = 1e4 g/m^2
  ExpectFigure(shown, "bending_rigidity_warp_gf_cm2_per_cm", b);
  ExpectFigure(shown, "bending_rigidity_weft_gf_cm2_per_cm", b);  // one law, every direction
  ExpectFigure(shown, "tensile_stiffness_warp_gf_per_cm", e * h_cm);
  ExpectFigure(shown, "tensile_stiffness_weft_gf_per_cm", e * h_cm);
  ExpectFigure(shown, "emt_warp_percent_at_500_gf_per_cm", 500 / (e * h_cm) * 100);
  // An isotropic membrane: G = E/2(1 + nu), per width, per degree.
  ExpectFigure(
      shown, "shear_rigidity_gf_per_cm_deg", e / (2 * (1 + nu)) * h_cm * std::numbers::pi / 180);
  ExpectFigure(shown, "poisson_ratio", nu);
  EXPECT_EQ(shown["membrane"], "isotropic");
  EXPECT_EQ(shown["bending_law_warp"], "linear");
  EXPECT_NE(shown["source"].get<std::string>().find("Eischen"), std::string::npos);
}

// The nonlinear twill's B is its fitted law's mean slope over K = 0.5..1.5
// 1/cm, M(1.5) - M(0.5) of the paper's fifth-order fit (gmf cm/cm, K in 1/cm).
TEST(MaterialShowCli, ANonlinearLawShowsItsKawabataSlope) {
  const double c[] = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
  auto moment = [&](double k) {
    double m = 0, power = 1;
    for (double ci : c) m += ci * (power *= k);
    return m;
  };
  const json shown = ShowJson("cotton-twill");
  EXPECT_EQ(shown["bending_law_warp"], "polynomial");
  ExpectFigure(shown, "bending_rigidity_warp_gf_cm2_per_cm", moment(1.5) - moment(0.5));
}

TEST(MaterialShowCli, EveryShippedEntryShowsFiniteFigures) {
  const test::CommandResult list = test::RunDrape("material list --json", test::Captured::kStdout);
  ASSERT_EQ(list.exit_code, 0) << list.output;
  for (const auto& entry : json::parse(list.output)) {
    const std::string name = entry["library"].get<std::string>();
    const json shown = ShowJson(name);
    for (const auto& [key, value] : shown.items()) {
      EXPECT_FALSE(value.is_null()) << name << ": " << key;
      if (value.is_number()) {
        EXPECT_TRUE(std::isfinite(value.get<double>())) << name << ": " << key;
      }
    }
  }
}

TEST(MaterialShowCli, TextNamesTheTextileUnits) {
  const test::CommandResult r = test::RunDrape("material show cotton-twill-linear");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* unit : {"mm", "g/m^2", "gf*cm^2/cm", "gf/(cm*deg)", "gf/cm", "EMT at 500 gf/cm"})
    EXPECT_NE(r.output.find(unit), std::string::npos) << unit << " in\n" << r.output;
  EXPECT_EQ(r.output.find("nan"), std::string::npos) << r.output;
}

// An entry's bending hysteresis is kept and shown as KES prints 2HB.
TEST(MaterialShowCli, AnEntryKeepsItsBendingHysteresis) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("drape-2hb-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const json entry = {{"drape_material", 1},
                      {"name", "cotton broadcloth"},
                      {"source", "Matsudaira et al. 2015, Table 1, as reprinted"},
                      {"description", "test entry"},
                      {"material",
                       {{"thickness", "0.497 mm"},
                        {"areal_density", "123.8 g/m^2"},
                        {"youngs_modulus", "20 MPa"},
                        {"poisson_ratio", 0.2},
                        {"bending",
                         {{"model", "linear"},
                          {"rigidity", "0.118 gf*cm^2/cm"},
                          {"hysteresis", "0.124 gf*cm/cm"}}}}}};
  std::ofstream(dir / "broadcloth.json") << entry.dump();
  const test::CommandResult r =
      test::RunCommand("DRAPE_MATERIALS='" + dir.string() + "' '" + std::string(test::DrapeCli()) +
                           "' material show broadcloth --json",
                       test::Captured::kStdout);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json shown = json::parse(r.output);
  ExpectFigure(shown, "bending_hysteresis_warp_gf_cm_per_cm", 0.124);
  ExpectFigure(shown, "bending_hysteresis_weft_gf_cm_per_cm", 0.124);  // one law, every way
  ExpectFigure(shown, "bending_rigidity_warp_gf_cm2_per_cm", 0.118);
  EXPECT_EQ(ShowJson("cotton-twill")["bending_hysteresis_warp_gf_cm_per_cm"], 0.0);
  fs::remove_all(dir);
}

TEST(MaterialShowCli, AnUnknownNameListsTheLibraryAndExitsOne) {
  const test::CommandResult r =
      test::RunDrape("material show no-such-fabric --json", test::Captured::kStderr);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("drape material show: no library material 'no-such-fabric'"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("cotton-twill-linear"), std::string::npos) << r.output;
  const test::CommandResult out =
      test::RunDrape("material show no-such-fabric --json", test::Captured::kStdout);
  EXPECT_EQ(out.output, "") << "nothing on stdout for a failure";
}

TEST(MaterialListCli, ListsTheShippedLibraryWithSources) {
  const test::CommandResult r = test::RunDrape("material list --json", test::Captured::kStdout);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const json list = json::parse(r.output);
  ASSERT_GE(list.size(), 3u);
  bool cotton = false;
  for (const auto& entry : list) {
    EXPECT_FALSE(entry["source"].get<std::string>().empty()) << entry.dump();
    cotton = cotton || entry["library"] == "cotton-twill";
  }
  EXPECT_TRUE(cotton) << r.output;
}

// Laid out as `cmake --install` does (bin/, share/drape/resources/), the
// program finds the library next to itself, not in the source tree; and
// $DRAPE_RESOURCES comes first.
TEST(MaterialListCli, AnInstalledProgramFindsItsOwnLibrary) {
  namespace fs = std::filesystem;
  const fs::path prefix = fs::temp_directory_path() / ("drape-install-" + std::to_string(getpid()));
  fs::remove_all(prefix);
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share/drape/resources/materials");
  fs::create_directories(prefix / "elsewhere/materials");
  fs::copy_file(test::DrapeCli(), prefix / "bin/drape");
  const fs::path material = test::SourceDir() / "resources/materials/cotton-twill-linear.json";
  fs::copy_file(material, prefix / "share/drape/resources/materials/installed-twill.json");
  fs::copy_file(material, prefix / "elsewhere/materials/elsewhere-twill.json");
  const std::string run = "cd '" + prefix.string() + "' && '" + (prefix / "bin/drape").string() +
                          "' material list --json";

  auto libraries = [](const test::CommandResult& r) {
    std::map<std::string, std::string> found;  // name → file
    for (const auto& entry : json::parse(r.output))
      found[entry["library"].get<std::string>()] = entry["file"].get<std::string>();
    return found;
  };
  const test::CommandResult installed = test::RunCommand(run, test::Captured::kStdout);
  ASSERT_EQ(installed.exit_code, 0) << installed.output;
  auto found = libraries(installed);
  ASSERT_TRUE(found.count("installed-twill")) << installed.output;
  EXPECT_EQ(found["installed-twill"].rfind((prefix / "share/drape/resources").string(), 0), 0u);
  EXPECT_FALSE(found.count("cotton-twill")) << "the source tree's library was used";

  const test::CommandResult chosen =
      test::RunCommand("DRAPE_RESOURCES='" + (prefix / "elsewhere").string() +
                           "' && export DRAPE_RESOURCES && " + run,
                       test::Captured::kStdout);
  ASSERT_EQ(chosen.exit_code, 0) << chosen.output;
  found = libraries(chosen);
  EXPECT_TRUE(found.count("elsewhere-twill")) << chosen.output;
  EXPECT_FALSE(found.count("installed-twill")) << chosen.output;
  fs::remove_all(prefix);
}

}  // namespace
}  // namespace drape
