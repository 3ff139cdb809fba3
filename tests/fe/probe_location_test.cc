// Points located on unstructured meshes: a probe's (element, ξ, η) must map
// back onto the point itself, wherever it lies in the part — the bilinear
// map's own inverse, checked by the forward map.
#include <gtest/gtest.h>

#include <cmath>

#include "core/fe/shell_model.h"
#include "core/model/mesh.h"

namespace drape {
namespace {

TEST(ProbeLocation, EveryPointOfAPolygonMapsBackOntoItself) {
  // The FRONT panel of the pattern tests, with its cut-out, meshed by Gmsh.
  const std::vector<Eigen::Vector2d> outline{{0, 0}, {0.4, 0}, {0.4, 0.3}, {0.2, 0.32}, {0, 0.3}};
  const std::vector<Eigen::Vector2d> hole{{0.1, 0.1}, {0.15, 0.1}, {0.15, 0.14}, {0.1, 0.14}};
  ShellModel model;
  model.mesh = MeshPolygon(outline, 0.015, 0.0, {.holes = {hole}});
  ShellState state;
  state.positions = model.mesh.positions;
  int checked = 0;
  for (double x = 0.013; x < 0.4; x += 0.027)
    for (double y = 0.011; y < 0.3; y += 0.023) {
      if (x > 0.1 && x < 0.15 && y > 0.1 && y < 0.14) continue;  // the cut-out
      const ProbePoint p = LocateProbe(model.mesh, Probe{"p", {x, y}});
      const Eigen::Vector3d at = ProbePosition(model, p, state);
      EXPECT_NEAR(at.x(), x, 1e-9) << "(" << x << ", " << y << ") in element " << p.element;
      EXPECT_NEAR(at.y(), y, 1e-9) << "(" << x << ", " << y << ") in element " << p.element;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace drape
