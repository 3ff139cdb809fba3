// Scenes of a straight strip clamped at its left end (x = 0), built in code
// for verification tests: length L along x, width b, n × 1 elements, ν = 0 so
// that plate and beam theory agree, EI = E b h³ / 12.
#pragma once

#include <cmath>
#include <numbers>

#include "core/model/scene.h"

namespace drape::test {

struct StripSpec {
  double length = 0.2;          // L [m]
  double width = 0.01;          // b [m]
  double thickness = 5e-4;      // h [m]
  double youngs_modulus = 1e6;  // E [Pa]
  int elements = 40;
};

// The default strip on `elements` elements.
inline StripSpec StripOf(int elements) {
  return {.elements = elements};
}

inline double StripBendingStiffness(const StripSpec& s) {  // EI [N·m²]
  return s.youngs_modulus * s.width * std::pow(s.thickness, 3) / 12.0;
}

// The clamped–free strip's first Euler load P_E = π²EI/4L² [N].
inline double CantileverEulerLoad(const StripSpec& s) {
  return std::numbers::pi * std::numbers::pi * StripBendingStiffness(s) / (4 * s.length * s.length);
}

// A cantilever strip with a clamped root, no loads, no stages yet.
inline Scene CantileverStrip(const StripSpec& s) {
  Scene scene;
  scene.name = "cantilever strip";
  scene.fabric.outline = RectangleOutline{{s.length, s.width}, {s.length / 2, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{s.elements, 1};
  scene.material.thickness = s.thickness;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{s.youngs_modulus, 0.0};
  scene.material.bending.warp = LinearBending{};
  scene.supports.push_back({"root", Selection{EdgeSelection{Side::kLeft}, {}}, Fixity::kClamp});
  scene.probes.push_back({"tip", {s.length, 0.0}});
  scene.probes.push_back({"root", {0.0, 0.0}});
  return scene;
}

// The strip with a `load` stage ramping a total tip force and moment on the
// right edge from 0 to 1.
inline Scene TipLoadedStrip(const StripSpec& s,
                            const Vec3& force,
                            const Vec3& moment,
                            double initial_increment = 0.05) {
  Scene scene = CantileverStrip(s);
  scene.loads.push_back({"tip", Selection{EdgeSelection{Side::kRight}, {}}, force, moment});
  Stage stage;
  stage.name = "load";
  stage.kind = StageKind::kLoad;
  stage.initial_increment = initial_increment;
  stage.control = StepControl::kLoad;
  scene.stages.push_back(stage);
  return scene;
}

// The strip under its own weight w = α EI / (b L³) so that α = wbL³/EI.
inline Scene HeavyStrip(const StripSpec& s, double alpha, double initial_increment = 0.05) {
  Scene scene = CantileverStrip(s);
  scene.material.areal_weight =
      alpha * StripBendingStiffness(s) / (s.width * std::pow(s.length, 3));
  Stage stage;
  stage.name = "SW";
  stage.kind = StageKind::kGravity;
  stage.initial_increment = initial_increment;
  stage.control = StepControl::kLoad;
  scene.stages.push_back(stage);
  return scene;
}

}  // namespace drape::test
