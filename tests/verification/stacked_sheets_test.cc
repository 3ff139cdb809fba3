// Two sheets stacked and pressed by a rigid plate (issue 17): the contact
// pressure self-contact carries between them equals the load over the area,
// whether the two sheets are a mesh made by hand, a scene's two parts, or two
// plies cut from a pattern file (issue 38).
// The lower sheet, 10 × 10 cm, is held flat (a rigid base); the upper,
// 9 × 9 cm, its nodes above the lower's element centres, starts 1.25 h
// above it. Its load is its weight plus a frictionless rigid plate's uniform
// pressure; it is held in its plane only (x and y at its centre, y at one
// more node), so that the barrier alone carries the load. Equilibrium by
// Newton at the full load (the CCD filter keeps every update outside the
// thickness).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "core/contact/self_contact.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/io/dxf_pattern_writer.h"
#include "core/io/scene_reader.h"
#include "support/temp_dir.h"

namespace drape {
namespace {

constexpr double kThickness = 0.469e-3;  // [m]

// n × n quads over a square of side `size` centred on the origin, at z.
void AddSheet(Mesh& mesh, int n, double size, double z) {
  const int first = static_cast<int>(mesh.positions.rows());
  const int elements = static_cast<int>(mesh.quads.rows());
  mesh.positions.conservativeResize(first + (n + 1) * (n + 1), 3);
  mesh.quads.conservativeResize(elements + n * n, 4);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.positions.row(first + j * (n + 1) + i) << size * (double(i) / n - 0.5),
          size * (double(j) / n - 0.5), z;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = first + j * (n + 1) + i;
      mesh.quads.row(elements + j * n + i) << a, a + 1, a + n + 2, a + n + 1;
    }
}

constexpr const char* kMaterial = R"("material": {"thickness": "0.0469 cm",
    "areal_weight": "4.019e-3 oz/in^2", "youngs_modulus": "4196 oz/in^2", "poisson_ratio": 0.3},
    "stages": [{"name": "SW", "kind": "gravity"}])";

// The node of `mesh` nearest (x, y) among nodes [first, last).
int NearestNode(const Mesh& mesh, int first, int last, double x, double y) {
  int best = first;
  for (int i = first; i < last; ++i)
    if ((mesh.positions.row(i).head<2>() - Eigen::RowVector2d(x, y)).norm() <
        (mesh.positions.row(best).head<2>() - Eigen::RowVector2d(x, y)).norm())
      best = i;
  return best;
}

struct PlatePress {
  double pushed_up = 0;          // the barrier's upward force on the upper sheet [N]
  double layers_force = 0;       // result.json's layers.force [N]
  double smallest_distance = 0;  // between the mid-surfaces [m]
  Eigen::VectorXd gradient;      // the barrier's, 3 per node
};

// The lower sheet (nodes before `upper`) held flat; the upper pressed by its
// weight and the plate's pressure `plate` [Pa], held in its plane only (x
// and y at the node nearest its centre, y at the node nearest (4.5 cm, 0)),
// so that the barrier alone carries the load. Equilibrium by Newton at the
// full load (the CCD filter keeps every update outside the thickness).
PlatePress Press(const ShellModel& model, int upper, double w, double plate) {
  DofMap dofs(model.NodeCount());
  for (int i = 0; i < upper; ++i) dofs.FixNode(i, Fixity::kClamp);
  const int centre = NearestNode(model.mesh, upper, model.NodeCount(), 0, 0);
  const int east = NearestNode(model.mesh, upper, model.NodeCount(), 0.045, 0);
  dofs.FixDof(kDofsPerNode * centre + 0);
  dofs.FixDof(kDofsPerNode * centre + 1);
  dofs.FixDof(kDofsPerNode * east + 1);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.DofCount());
  for (int i = upper; i < model.NodeCount(); ++i)
    load.segment<3>(kDofsPerNode * i) =
        (1 + plate / w) * model.weight_load.segment<3>(kDofsPerNode * i);

  SelfContactSettings settings;
  settings.offset = kThickness;
  settings.activation = 0.5 * kThickness;
  settings.exclusion = 0.02;  // within one sheet; the sheets are separate pieces
  // As the solver chooses it: halfway into the band the barrier carries ten
  // times a node's weight.
  const double s_hat =
      2 * settings.offset * settings.activation + settings.activation * settings.activation;
  settings.stiffness = 10 * (model.total_weight.norm() / model.NodeCount()) /
                       (2.39 * s_hat * (settings.offset + 0.5 * settings.activation));
  SelfContact contact(model.mesh, settings);
  EquilibriumSystem system(model, dofs);
  system.SetSelfContact(&contact);

  ShellState state = model.reference;
  NewtonSettings newton;
  newton.tolerance = 1e-10;
  newton.max_iterations = 60;
  const NewtonOutcome out = SolveEquilibrium(
      system, [&](const ShellState&) { return load; }, newton, state, nullptr);
  EXPECT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;

  // The force the lower sheet exerts on the upper, node by node: the
  // barrier's gradient on the upper sheet (its weight and the plate's
  // pressure pull down, the barrier pushes up).
  const SelfContactEvaluation e = contact.Evaluate(state.positions, false);
  PlatePress press;
  for (int i = upper; i < model.NodeCount(); ++i) press.pushed_up -= e.gradient(3 * i + 2);
  press.layers_force = e.force;
  press.smallest_distance = e.smallest_distance;
  press.gradient = e.gradient;
  return press;
}

TEST(StackedSheets, ContactPressureBetweenThemIsTheLoadOverTheArea) {
  const Scene scene = ParseScene(std::string(R"({
    "drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": ["10 cm", "10 cm"], "center": [0, 0]}},
               "mesh": {"elements": [20, 20]}},
    )") + kMaterial + "}");
  Mesh mesh;
  AddSheet(mesh, 20, 0.10, 0.0);                // lower: nodes 0 … 440
  const int upper = mesh.NodeCount();           // upper: from here
  AddSheet(mesh, 18, 0.09, 1.25 * kThickness);  // 19 × 19 nodes
  const ShellModel model = BuildShellModel(scene, mesh);
  const int n_upper = model.NodeCount() - upper;

  // The plate's pressure: 50 times the sheet's own weight per area.
  const double w = scene.material.areal_weight;
  const double plate = 50 * w;
  const double area = 0.09 * 0.09;
  const PlatePress press = Press(model, upper, w, plate);
  const double total_load = (w + plate) * area;
  EXPECT_NEAR(press.pushed_up / area, w + plate, 0.01 * (w + plate));
  EXPECT_NEAR(press.layers_force, total_load, 0.01 * total_load);  // result.json's layers.force
  // Pressure node by node away from the edges (where the sheet bends onto
  // the base): the barrier's force on each node over its share of the area
  // (one element).
  const int centre = upper + 9 * 19 + 9, east = upper + 9 * 19 + 18;
  const double element_area = (0.09 / 18) * (0.09 / 18);
  double worst = 0;
  for (int j = 3; j < 16; ++j)
    for (int i = 3; i < 16; ++i) {
      const int node = upper + j * 19 + i;
      if (node == centre || node == east) continue;
      const double pressure = -press.gradient(3 * node + 2) / element_area;
      worst = std::max(worst, std::abs(pressure / (w + plate) - 1));
    }
  EXPECT_LT(worst, 0.01);
  // The sheets stay outside each other's thickness, inside the barrier's band.
  EXPECT_GT(press.smallest_distance, kThickness);
  EXPECT_LT(press.smallest_distance, 1.5 * kThickness);
  std::printf(
      "  %d upper nodes; gap %.4f h; mean pressure %.5g Pa (load/area %.5g Pa); "
      "worst interior node %.2e\n",
      n_upper,
      press.smallest_distance / kThickness,
      press.pushed_up / area,
      w + plate,
      worst);
}

// The same two sheets as a scene's two parts ("fabric" an array): the scene
// meshes exactly the hand-made mesh, and the plate's pressure between them
// is the load over the area.
TEST(StackedSheets, AScenesTwoPartsAreTheSameTwoSheets) {
  const Scene scene = ParseScene(std::string(R"({
    "drape_scene": 1,
    "fabric": [{"name": "lower", "outline": {"rectangle": {"size": ["10 cm", "10 cm"]}},
                "mesh": {"elements": [20, 20]}},
               {"name": "upper", "outline": {"rectangle": {"size": ["9 cm", "9 cm"]}},
                "mesh": {"elements": [18, 18]}, "elevation": "0.058625 cm"}],
    )") + kMaterial + "}");
  Mesh by_hand;
  AddSheet(by_hand, 20, 0.10, 0.0);
  const int upper = by_hand.NodeCount();
  AddSheet(by_hand, 18, 0.09, 1.25 * kThickness);
  const ShellModel model = BuildShellModel(scene);
  ASSERT_EQ(model.mesh.parts.size(), 2u);
  EXPECT_EQ(model.mesh.parts[1].first_node, upper);
  ASSERT_EQ(model.NodeCount(), by_hand.NodeCount());
  EXPECT_LT((model.mesh.positions - by_hand.positions).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(model.mesh.quads, by_hand.quads);
  const double w = scene.material.areal_weight, plate = 50 * w, area = 0.09 * 0.09;
  const PlatePress press = Press(model, upper, w, plate);
  EXPECT_NEAR(press.pushed_up / area, w + plate, 0.01 * (w + plate));
  EXPECT_NEAR(press.layers_force, (w + plate) * area, 0.01 * (w + plate) * area);
}

// Two plies cut from a pattern file (two pieces of one DXF, meshed by Gmsh,
// unstructured), stacked: the same pressure.
TEST(StackedSheets, TwoPliesCutFromAPatternCarryThePlate) {
  test::TempDir dir("stacked-plies");
  PatternPiece lower, upper;
  lower.name = "LOWER";
  lower.boundary = {{-0.05, -0.05}, {0.05, -0.05}, {0.05, 0.05}, {-0.05, 0.05}};
  upper.name = "UPPER";
  upper.boundary = {{-0.045, -0.045}, {0.045, -0.045}, {0.045, 0.045}, {-0.045, 0.045}};
  WriteDxfPattern(dir / "plies.dxf", {lower, upper});
  std::ofstream(dir / "plies.json") << std::string(R"({
    "drape_scene": 1,
    "fabric": [{"name": "lower", "mesh": {"size": "5 mm"},
                "outline": {"pattern": {"file": "plies.dxf", "piece": "LOWER"}}},
               {"name": "upper", "mesh": {"size": "5 mm"}, "elevation": "0.058625 cm",
                "outline": {"pattern": {"file": "plies.dxf", "piece": "UPPER"}}}],
    )") + kMaterial + "}";
  const Scene scene = ReadScene(dir / "plies.json");
  const ShellModel model = BuildShellModel(scene);
  ASSERT_EQ(model.mesh.parts.size(), 2u);
  const int upper_first = model.mesh.parts[1].first_node;
  for (int i = upper_first; i < model.NodeCount(); ++i)
    ASSERT_DOUBLE_EQ(model.mesh.positions(i, 2), 1.25 * kThickness);
  const double w = scene.material.areal_weight, plate = 50 * w, area = 0.09 * 0.09;
  const PlatePress press = Press(model, upper_first, w, plate);
  EXPECT_NEAR(press.pushed_up / area, w + plate, 0.01 * (w + plate));
  EXPECT_NEAR(press.layers_force, (w + plate) * area, 0.01 * (w + plate) * area);
  EXPECT_GT(press.smallest_distance, kThickness);
  std::printf("  pattern plies: %d + %d nodes; mean pressure %.5g Pa (load/area %.5g Pa)\n",
              upper_first,
              model.NodeCount() - upper_first,
              press.pushed_up / area,
              w + plate);
}

}  // namespace
}  // namespace drape
