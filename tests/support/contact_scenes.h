// Scenes of a square sheet held only by contact, built in code for the
// contact tests: no supports, no grippers, one gravity stage.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "core/model/scene.h"

namespace drape::test {

struct SheetSpec {
  double size = 0.1;            // side [m], centred on the origin
  int elements = 10;            // per side
  double thickness = 5e-4;      // h [m]
  double youngs_modulus = 1e6;  // E [Pa]
  double poisson_ratio = 0.3;
  double areal_weight = 2.0;       // w [N/m²]
  std::optional<double> penalty;   // k [N/m³]; absent: "auto"
  double initial_increment = 0.1;  // Δλ₀ of the gravity stage
  double tolerance = 1e-10;        // ‖R‖/‖R₀‖
};

// The flat sheet at z = 0, its own weight the only load, no obstacles yet.
inline Scene FreeSheet(const SheetSpec& s) {
  Scene scene;
  scene.name = "sheet held by contact";
  scene.fabric.outline = RectangleOutline{{s.size, s.size}, {0.0, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{s.elements, s.elements};
  scene.material.thickness = s.thickness;
  scene.material.areal_weight = s.areal_weight;
  scene.material.membrane = IsotropicMembrane{s.youngs_modulus, s.poisson_ratio};
  scene.material.bending.warp = LinearBending{};
  scene.contact = Contact{};
  scene.contact->penalty = s.penalty;
  Stage stage;
  stage.name = "SW";
  stage.kind = StageKind::kGravity;
  stage.initial_increment = s.initial_increment;
  scene.stages.push_back(stage);
  scene.solver.tolerance = s.tolerance;
  return scene;
}

// The sheet lying on a frictionless table whose surface is the sheet's
// underside: the plane z = −h/2, so every node starts with g = 0.
inline Scene SheetOnTable(const SheetSpec& s) {
  Scene scene = FreeSheet(s);
  scene.obstacles.push_back({"table", PlaneShape{{0.0, 0.0, -s.thickness / 2}, {0.0, 0.0, 1.0}}});
  return scene;
}

// The sheet centred h/2 above the top of a frictionless sphere of `radius`:
// the centre node starts touching (g = 0), every other node clear of it.
//
// Centred on a frictionless sphere the sheet is unstable to sliding off (its
// weight's potential falls as it slides; only the stabilisation springs hold
// it, and they stop doing so as the weight grows): the tests check the
// symmetric equilibrium itself, so the path is followed through those
// bifurcations (solver.branching: fundamental).
inline Scene SheetOverSphere(const SheetSpec& s, double radius) {
  Scene scene = FreeSheet(s);
  scene.solver.branching = Branching::kFundamental;
  scene.obstacles.push_back({"ball", SphereShape{{0.0, 0.0, -radius - s.thickness / 2}, radius}});
  return scene;
}

}  // namespace drape::test
