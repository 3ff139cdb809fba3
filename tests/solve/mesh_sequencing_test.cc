// Mesh sequencing's parts (core/solve/mesh_sequencing.h): which scenes it
// refuses and why, and the interpolation of a coarse state onto a fine mesh,
// against fields it must reproduce exactly (bilinear displacements, a
// uniform director).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "core/fe/shell_model.h"
#include "core/mechanics/director.h"
#include "core/model/scene_error.h"
#include "core/solve/mesh_sequencing.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

Scene Sheet(int nx, int ny) {
  test::StripSpec spec;
  spec.width = 0.1;
  Scene scene = test::HeavyStrip(spec, 4.0);
  scene.fabric.mesh.elements = std::array<int, 2>{nx, ny};
  return scene;
}

std::string Refusal(const Scene& scene, int factor) {
  try {
    CheckSequencing(scene, factor);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshSequencing, RefusesWhatItCannotSolveNamingTheKey) {
  EXPECT_EQ(Refusal(Sheet(8, 4), 2), "");
  EXPECT_EQ(Refusal(Sheet(8, 4), 1), "");  // off
  EXPECT_NE(Refusal(Sheet(8, 3), 2).find("solver.sequencing"), std::string::npos);
  EXPECT_NE(Refusal(Sheet(8, 4), 4).find("at least 2 each way"), std::string::npos);
  Scene two = Sheet(8, 4);
  two.stages.push_back(two.stages[0]);
  two.stages[1].name = "again";
  EXPECT_NE(Refusal(two, 2).find("2 stages"), std::string::npos);
  Scene moved = Sheet(8, 4);
  moved.stages[0].kind = StageKind::kMove;
  EXPECT_NE(Refusal(moved, 2).find("depends on the path"), std::string::npos);
}

TEST(MeshSequencing, CoarsenedSceneDividesTheMesh) {
  Scene scene = Sheet(12, 6);
  scene.solver.sequencing = 3;
  const Scene coarse = CoarsenedScene(scene, 3);
  EXPECT_EQ(*coarse.fabric.mesh.elements, (std::array<int, 2>{4, 2}));
  EXPECT_EQ(coarse.solver.sequencing, 1);
  EXPECT_EQ(coarse.stages, scene.stages);
}

// A displacement bilinear in (X, Y) and a uniform director are in the
// coarse interpolation space: every fine node gets them exactly, except
// the nodes the clamp holds, which keep their reference state.
TEST(MeshSequencing, ProlongationReproducesBilinearFieldsAndKeepsHeldNodes) {
  const Scene fine_scene = Sheet(12, 6);
  const ShellModel fine = BuildShellModel(fine_scene);
  const ShellModel coarse = BuildShellModel(CoarsenedScene(fine_scene, 3));
  auto u = [](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(
        0.1 * x.y() + 0.02, -0.3 * x.x() * x.y(), 0.5 * x.x() - 0.7 * x.x() * x.y());
  };
  const Eigen::Vector3d t = Eigen::Vector3d(0.3, -0.4, 0.5).normalized();
  ShellState state = coarse.reference;
  for (int i = 0; i < coarse.NodeCount(); ++i) {
    state.positions.row(i) += u(coarse.reference.positions.row(i).transpose()).transpose();
    state.rotations[i] = RotationFromDirector(t);
  }
  const ShellState out = Prolongate(coarse, state, fine);
  ASSERT_EQ(out.NodeCount(), fine.NodeCount());
  std::vector<bool> held(fine.NodeCount(), false);
  for (int node : fine.supports.at(0).nodes) held[node] = true;
  for (int i = 0; i < fine.NodeCount(); ++i) {
    const Eigen::Vector3d x = fine.reference.positions.row(i).transpose();
    const Eigen::Vector3d expected_position = held[i] ? x : Eigen::Vector3d(x + u(x));
    const Eigen::Vector3d expected_director = held[i] ? fine.reference.Director(i) : t;
    EXPECT_LT((out.positions.row(i).transpose() - expected_position).norm(), 1e-14) << i;
    EXPECT_LT((out.Director(i) - expected_director).norm(), 1e-14) << i;
  }
}

// Bending hysteresis's history goes with the state: each fine element takes
// the slip of the coarse element under its centre, that element's Gauss
// points' mean per friction family. Here a coarse element's slip is its own
// centre (x, y) and the family plus a tenth of the Gauss point's number, so
// the expected value is the centre of the coarse cell the fine centre lies in.
TEST(MeshSequencing, ProlongationCarriesTheBendingSlipOfTheCoarseElementBelow) {
  const Scene fine_scene = Sheet(12, 6);
  const ShellModel fine = BuildShellModel(fine_scene);
  const ShellModel coarse = BuildShellModel(CoarsenedScene(fine_scene, 3));  // 4 × 2
  auto centre = [](const ShellModel& m, int e) {
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int k = 0; k < 4; ++k) c += 0.25 * m.mesh.positions.row(m.mesh.quads(e, k)).head<2>();
    return c;
  };
  ShellState state = coarse.reference;
  for (int e = 0; e < coarse.mesh.ElementCount(); ++e) {
    ElementSlip slip;
    for (int p = 0; p < 4; ++p)
      for (int f = 0; f < 2; ++f) slip.col(2 * p + f) << centre(coarse, e), f + 0.1 * p;
    state.bending_slip.push_back(slip);
  }
  const ShellState out = Prolongate(coarse, state, fine);
  ASSERT_EQ(out.bending_slip.size(), static_cast<size_t>(fine.mesh.ElementCount()));
  const Eigen::Vector2d lo = fine.mesh.positions.leftCols<2>().colwise().minCoeff();
  const Eigen::Vector2d hi = fine.mesh.positions.leftCols<2>().colwise().maxCoeff();
  const Eigen::Vector2d cell = (hi - lo).cwiseQuotient(Eigen::Vector2d(4, 2));
  for (int e = 0; e < fine.mesh.ElementCount(); ++e) {
    const Eigen::Vector2d c = centre(fine, e);
    const Eigen::Vector2d below(
        lo.x() + (std::floor((c.x() - lo.x()) / cell.x()) + 0.5) * cell.x(),
        lo.y() + (std::floor((c.y() - lo.y()) / cell.y()) + 0.5) * cell.y());
    for (int p = 0; p < 4; ++p)
      for (int f = 0; f < 2; ++f) {
        const Eigen::Vector3d expected(below.x(), below.y(), f + 0.15);
        EXPECT_LT((out.bending_slip[e].col(2 * p + f) - expected).norm(), 1e-12)
            << "element " << e << ", Gauss point " << p << ", family " << f;
      }
  }
  state.bending_slip.clear();
  EXPECT_TRUE(Prolongate(coarse, state, fine).bending_slip.empty());
}

}  // namespace
}  // namespace drape
