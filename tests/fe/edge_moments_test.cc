// Loads' moments about the line of element edges they act on: split from the
// rest of the moment, shared over the edge's segments, and at the flat
// reference the same resultant moment the fixed vector gave.
#include "core/fe/edge_moments.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "core/fe/shell_model.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

// A 4 × 2 strip whose tip edge (3 nodes, 2 segments) carries M = (1, 2, 3)
// mN·m: 2 about the edge's axis y, the rest about x and z.
ShellModel TipMomentModel() {
  test::StripSpec spec;
  Scene scene = test::TipLoadedStrip(spec, {0, 0, 0}, {1e-3, 2e-3, 3e-3});
  scene.fabric.mesh.elements = std::array<int, 2>{4, 2};
  return BuildShellModel(scene);
}

TEST(EdgeMoments, TheMomentAboutAnEdgeIsSharedOverItsSegments) {
  const ShellModel model = TipMomentModel();
  const NodalLoad& load = model.loads.at(0);
  ASSERT_EQ(load.nodes.size(), 3u);
  ASSERT_EQ(load.edge_segments.size(), 2u);
  double about_axis = 0;
  for (const auto& s : load.edge_segments) {
    about_axis += s.moment * s.reference.axis.y();
    EXPECT_NEAR(std::abs(s.reference.axis.y()), 1.0, 1e-15);
  }
  EXPECT_NEAR(about_axis, 2e-3, 1e-18);
  // The rest stays a fixed vector shared over the three nodes.
  EXPECT_LT((load.moment_per_node - Eigen::Vector3d(1e-3, 0, 3e-3) / 3).norm(), 1e-18);
}

TEST(EdgeMoments, AtTheFlatReferenceTheyMakeTheMomentAboutTheEdge) {
  const ShellModel model = TipMomentModel();
  const Eigen::VectorXd f = EdgeMomentForce(model, model.reference);
  Eigen::Vector3d moment = Eigen::Vector3d::Zero(), force = Eigen::Vector3d::Zero();
  for (int i = 0; i < model.NodeCount(); ++i) {
    const Eigen::Matrix3d& r = model.reference.rotations[i];
    force += f.segment<3>(kDofsPerNode * i);
    // Work M·w on w = a g₁ + b g₂: (f_a, f_b) are M's parts along g₁, g₂.
    moment += f(kDofsPerNode * i + 3) * r.col(0) + f(kDofsPerNode * i + 4) * r.col(1);
  }
  EXPECT_LT(force.norm(), 1e-18);
  EXPECT_LT((moment - Eigen::Vector3d(0, 2e-3, 0)).norm(), 1e-18);
}

TEST(EdgeMoments, NodesThatAreNotOneLineOfElementEdgesKeepAFixedVector) {
  const ShellModel model = TipMomentModel();
  const std::vector<int>& edge = model.loads.at(0).nodes;
  const Eigen::Vector3d m(0, 2e-3, 0);
  // One node; the edge's two ends without the node between them; two nodes
  // off one line.
  for (const std::vector<int>& nodes : {std::vector<int>{edge[0]},
                                        std::vector<int>{edge.front(), edge.back()},
                                        std::vector<int>{0, edge[1], edge[2]}}) {
    const NodalLoad load = MakeNodalLoad(model.mesh, model.reference, "m", nodes, {0, 0, 0}, m);
    EXPECT_TRUE(load.edge_segments.empty()) << nodes.size() << " nodes";
    EXPECT_LT((load.moment_per_node * static_cast<double>(nodes.size()) - m).norm(), 1e-18);
  }
}

}  // namespace
}  // namespace drape
