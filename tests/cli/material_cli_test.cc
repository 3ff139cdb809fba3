// `drape material fit`: what it prints is a scene's `bending` object.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <variant>

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

}  // namespace
}  // namespace drape
