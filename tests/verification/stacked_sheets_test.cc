// Two sheets stacked and pressed by a rigid plate (issue 17): the contact
// pressure self-contact carries between them equals the load over the area.
// The lower sheet, 10 × 10 cm, is held flat (a rigid base); the upper,
// 9 × 9 cm, its nodes above the lower's element centres, starts 1.25 h
// above it. Its load is its weight plus a frictionless rigid plate's uniform
// pressure; it is held in its plane only (x and y at its centre, y at one
// more node), so that the barrier alone carries the load. Equilibrium by
// Newton at the full load (the CCD filter keeps every update outside the
// thickness).
#include <gtest/gtest.h>

#include <cmath>

#include "core/contact/self_contact.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"

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

TEST(StackedSheets, ContactPressureBetweenThemIsTheLoadOverTheArea) {
  const Scene scene = ParseScene(R"({
    "drape_scene": 1,
    "fabric": {"outline": {"rectangle": {"size": ["10 cm", "10 cm"], "center": [0, 0]}},
               "mesh": {"elements": [20, 20]}},
    "material": {"thickness": "0.0469 cm", "areal_weight": "4.019e-3 oz/in^2",
                 "youngs_modulus": "4196 oz/in^2", "poisson_ratio": 0.3},
    "stages": [{"name": "SW", "kind": "gravity"}]
  })");
  Mesh mesh;
  AddSheet(mesh, 20, 0.10, 0.0);                // lower: nodes 0 … 440
  const int upper = mesh.NodeCount();           // upper: from here
  AddSheet(mesh, 18, 0.09, 1.25 * kThickness);  // 19 × 19 nodes
  const ShellModel model = BuildShellModel(scene, mesh);
  const int n_upper = model.NodeCount() - upper;

  DofMap dofs(model.NodeCount());
  for (int i = 0; i < upper; ++i) dofs.FixNode(i, Fixity::kClamp);
  const int centre = upper + 9 * 19 + 9, east = upper + 9 * 19 + 18;
  dofs.FixDof(kDofsPerNode * centre + 0);
  dofs.FixDof(kDofsPerNode * centre + 1);
  dofs.FixDof(kDofsPerNode * east + 1);

  // The plate's pressure: 50 times the sheet's own weight per area.
  const double w = scene.material.areal_weight;
  const double plate = 50 * w;
  const double area = 0.09 * 0.09;
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
  ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged) << out.reason;

  // The force the lower sheet exerts on the upper, node by node: the
  // barrier's gradient on the upper sheet (its weight and the plate's
  // pressure pull down, the barrier pushes up).
  const SelfContactEvaluation e = contact.Evaluate(state.positions, false);
  const double total_load = (w + plate) * area;
  double pushed_up = 0;
  for (int i = upper; i < model.NodeCount(); ++i) pushed_up -= e.gradient(3 * i + 2);
  EXPECT_NEAR(pushed_up / area, w + plate, 0.01 * (w + plate));
  EXPECT_NEAR(e.force, total_load, 0.01 * total_load);  // result.json's layers.force
  // Pressure node by node away from the edges (where the sheet bends onto
  // the base): the barrier's force on each node over its share of the area
  // (one element).
  const double element_area = (0.09 / 18) * (0.09 / 18);
  double worst = 0;
  for (int j = 3; j < 16; ++j)
    for (int i = 3; i < 16; ++i) {
      const int node = upper + j * 19 + i;
      if (node == centre || node == east) continue;
      const double pressure = -e.gradient(3 * node + 2) / element_area;
      worst = std::max(worst, std::abs(pressure / (w + plate) - 1));
    }
  EXPECT_LT(worst, 0.01);
  // The sheets stay outside each other's thickness, inside the barrier's band.
  EXPECT_GT(e.smallest_distance, kThickness);
  EXPECT_LT(e.smallest_distance, 1.5 * kThickness);
  std::printf(
      "  %d upper nodes; gap %.4f h; mean pressure %.5g Pa (load/area %.5g Pa); "
      "worst interior node %.2e\n",
      n_upper,
      e.smallest_distance / kThickness,
      pushed_up / area,
      w + plate,
      worst);
}

}  // namespace
}  // namespace drape
