// A strip hung over a round rod, built in code for the rod-hang and capstan
// tests: the flat strip (length L along x, width b, n × 1 elements, ν = 0)
// lies centred on the top of a rod whose axis is along y, its underside
// touching it. Nothing but contact holds it. A gravity stage wraps it over
// the rod; with `pull`, a load stage then pulls the right end down.
//
// `hold_middle` clamps the strip's cross-section over the rod's top during
// the gravity stage and lets it go in a following hold stage. A thin strip
// flops from flat to hanging at λ of order 1e-4, balanced on one node line
// over the rod: left free, that start fails (see rod_hang_test.cc). Held, it
// hangs from the clamp like two cantilevers, wraps onto the rod, and on
// release only the clamp's small share of the weight moves to the rod.
#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "core/model/scene.h"

namespace drape::test {

struct RodHangSpec {
  double length = 0.4;          // L [m]
  double width = 0.01;          // b [m]
  double thickness = 5e-4;      // h [m]
  double youngs_modulus = 2e6;  // E [Pa]
  double areal_weight = 2.0;    // w [N/m²]
  double radius = 0.02;         // R of the rod [m]
  double offset = 0.0;          // x of the strip's centre [m]; 0 hangs it symmetrically
  int elements = 80;            // along the strip
  double friction = 0.0;        // μ
  std::optional<double> pull;   // total downward force on the right edge [N]
  // Clamp the node line at x = 0 (which needs one: even `elements`, no
  // offset) through the gravity stage; a hold stage "drop" releases it.
  bool hold_middle = false;
  double gravity_increment = 0.01;
  double pull_increment = 0.05;
  double tolerance = 1e-6;
  int max_steps = 2000;
};

// z of the rod's axis: its top is the strip's underside, z = −h/2.
inline double RodAxisZ(const RodHangSpec& s) {
  return -s.radius - s.thickness / 2;
}

// EI / (w b) cubed root: the length over which the strip's bending stiffness
// competes with its weight [m].
inline double BendingLength(const RodHangSpec& s) {
  const double bending_rigidity = s.youngs_modulus * std::pow(s.thickness, 3) / 12.0;  // per b
  return std::cbrt(bending_rigidity / s.areal_weight);
}

inline Scene RodHang(const RodHangSpec& s) {
  Scene scene;
  scene.name = "strip hung over a rod";
  scene.fabric.outline = RectangleOutline{{s.length, s.width}, {s.offset, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{s.elements, 1};
  scene.material.thickness = s.thickness;
  scene.material.areal_weight = s.areal_weight;
  scene.material.membrane = IsotropicMembrane{s.youngs_modulus, 0.0};
  scene.material.bending.warp = LinearBending{};
  scene.obstacles.push_back(
      {"rod", CylinderShape{{0.0, 0.0, RodAxisZ(s)}, {0.0, 1.0, 0.0}, s.radius, {}}});
  scene.contact = Contact{};  // penalty "auto"
  scene.contact->friction = s.friction;
  Stage gravity;
  gravity.name = "SW";
  gravity.kind = StageKind::kGravity;
  gravity.initial_increment = s.gravity_increment;
  scene.stages.push_back(gravity);
  if (s.hold_middle) {
    scene.grippers.push_back({"middle",
                              Selection{LineSelection{{0.0, -s.width / 2}, {0.0, s.width / 2}}, {}},
                              Fixity::kClamp});
    Stage drop;
    drop.name = "drop";
    drop.kind = StageKind::kHold;
    drop.release = {"middle"};
    scene.stages.push_back(drop);
  }
  if (s.pull) {
    scene.loads.push_back({"pull",
                           Selection{EdgeSelection{Side::kRight}, {}},
                           {0.0, 0.0, -*s.pull},
                           {0.0, 0.0, 0.0}});
    Stage pull;
    pull.name = "pull";
    pull.kind = StageKind::kLoad;
    pull.initial_increment = s.pull_increment;
    scene.stages.push_back(pull);
  }
  scene.solver.tolerance = s.tolerance;
  // Hung symmetrically over a frictionless rod the strip is a chain over a
  // pulley: unstable to sliding, held only by the stabilisation springs while
  // the weight is small. The tests check the symmetric equilibrium (and the
  // capstan limit with friction) itself, so the path is followed through
  // the sliding bifurcation (solver.branching: fundamental).
  scene.solver.branching = Branching::kFundamental;
  scene.solver.target_iterations = 7;
  scene.solver.max_steps = s.max_steps;
  scene.probes.push_back({"left", {s.offset - s.length / 2, 0.0}});
  scene.probes.push_back({"right", {s.offset + s.length / 2, 0.0}});
  return scene;
}

}  // namespace drape::test
