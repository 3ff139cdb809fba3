// `drape export RESULT --format trajectory`: the 20-element strip fold's
// gripper (resources/scenes/strip-convergence-20.json),
// checked step by step against what the run stored of the gripped end
// (states.bin: the left edge's nodes and their directors) and against the
// arc's length at the stated speed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "core/io/state_file.h"
#include "support/csv_file.h"
#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::Column;

TEST(TrajectoryCli, TheGrippersPoseTimeAndForceAreTheRunsOwn) {
  const fs::path dir = fs::temp_directory_path() / ("drape-trajectory-" + std::to_string(getpid()));
  fs::remove_all(dir);
  const test::CommandResult run =
      test::RunDrape("run '" + (test::ScenesDir() / "strip-convergence-20.json").string() +
                     "' -o '" + (dir / "result").string() + "' --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const test::CommandResult exported =
      test::RunDrape("export '" + (dir / "result").string() + "' -o '" + (dir / "out").string() +
                     "' --format trajectory --speed '5 cm/s'");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;

  const auto rows = test::ReadCsv(dir / "out" / "trajectory.csv");
  const StateFile states = ReadStateFile(dir / "result" / "states.bin");
  const auto result = nlohmann::json::parse(test::ReadText(dir / "result" / "result.json"));
  ASSERT_EQ(rows.size(), states.steps.size() + 1);
  const auto& h = rows[0];
  // The gripped end: the nodes of the left edge, x = −10 cm.
  std::vector<int> end;
  for (int n = 0; n < states.mesh.NodeCount(); ++n)
    if (std::abs(states.mesh.positions(n, 0) + 0.1) < 1e-9) end.push_back(n);
  ASSERT_EQ(end.size(), 2u);  // 20 × 1 elements: two nodes across
  const double c = 0.036675e-2, radius = std::hypot(0.1, c), speed = 0.05;
  for (size_t i = 0; i < states.steps.size(); ++i) {
    const auto& row = rows[i + 1];
    const StoredStep& s = states.steps[i];
    EXPECT_EQ(std::stoi(row[Column(h, "step")]), s.step);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int n : end) centroid += s.positions.row(n).transpose() / 2.0;
    const Eigen::Vector3d at(std::stod(row[Column(h, "end_x_m")]),
                             std::stod(row[Column(h, "end_y_m")]),
                             std::stod(row[Column(h, "end_z_m")]));
    EXPECT_LT((at - centroid).norm(), 1e-9) << "step " << s.step;
    // The clamp turns the directors with the gripper: q rotates the
    // reference normal onto the stored director.
    const Eigen::Quaterniond q(std::stod(row[Column(h, "end_qw")]),
                               std::stod(row[Column(h, "end_qx")]),
                               std::stod(row[Column(h, "end_qy")]),
                               std::stod(row[Column(h, "end_qz")]));
    EXPECT_NEAR(q.norm(), 1, 1e-9);
    EXPECT_LT((q * Eigen::Vector3d::UnitZ() - s.directors.row(end[1]).transpose()).norm(), 1e-9)
        << "step " << s.step;
    const auto& force = result["steps"][i]["reactions"]["end"];
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::stod(row[Column(h, std::string("end_f") + "xyz"[k] + "_N")]),
                  force[k].get<double>(),
                  1e-11 + 1e-9 * std::abs(force[k].get<double>()));
    // Time: none in SW, then the arc π r λ at 5 cm/s.
    const double lambda = std::stod(row[Column(h, "lambda")]);
    const double expected = s.stage == 0 ? 0 : M_PI * radius * lambda / speed;
    EXPECT_NEAR(std::stod(row[Column(h, "time_s")]), expected, 1e-5 * (1 + expected));
    EXPECT_EQ(row[Column(h, "end_held")], "1");
  }
  // At the end the gripper has turned 180° about y: q = (0, 0, ±1, 0).
  EXPECT_NEAR(std::abs(std::stod(rows.back()[Column(h, "end_qy")])), 1, 1e-9);

  const test::CommandResult bad =
      test::RunDrape("export '" + (dir / "result").string() + "' -o '" + (dir / "out").string() +
                     "' --format trajectory --speed '0 cm/s'");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.output, "drape export: --speed: must be greater than zero, found 0 cm/s\n");
  const test::CommandResult unit =
      test::RunDrape("export '" + (dir / "result").string() + "' -o '" + (dir / "out").string() +
                     "' --format trajectory --speed '5 cm'");
  EXPECT_EQ(unit.exit_code, 1);
  EXPECT_EQ(unit.output.rfind("drape export: --speed: ", 0), 0u) << unit.output;
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace drape
