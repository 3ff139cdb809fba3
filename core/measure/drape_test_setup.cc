#include "core/measure/drape_test_setup.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/model/outline_geometry.h"

namespace drape {
namespace {

std::string Cm(double metres) {
  std::ostringstream s;
  s.precision(4);
  s << metres * 100 << " cm";
  return s.str();
}

const CircleSelection* SupportDisc(const Scene& scene) {
  for (const Support& s : scene.supports)
    if (const auto* c = std::get_if<CircleSelection>(&s.select.shape)) return c;
  return nullptr;
}

// The reference mesh's area in x, y: its quads' shoelace areas.
double FlatArea(const Mesh& mesh) {
  double area = 0;
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    double twice = 0;
    for (int k = 0; k < 4; ++k) {
      const int a = mesh.quads(e, k), b = mesh.quads(e, (k + 1) % 4);
      twice +=
          mesh.positions(a, 0) * mesh.positions(b, 1) - mesh.positions(b, 0) * mesh.positions(a, 1);
    }
    area += 0.5 * std::abs(twice);
  }
  return area;
}

}  // namespace

DrapeTestOptions DrapeTestFor(const Scene& scene,
                              const Mesh& mesh,
                              std::optional<double> support_radius,
                              std::optional<Vec2> centre) {
  if (std::none_of(scene.stages.begin(), scene.stages.end(), [](const Stage& s) {
        return s.kind == StageKind::kGravity;
      }))
    throw DrapeTestError(
        "the scene has no gravity stage: nothing hangs under its weight, so there is no drape to "
        "measure");
  const CircleSelection* disc = SupportDisc(scene);
  if (!support_radius && !disc)
    throw DrapeTestError(
        "no support disc: give the support radius, or hold the specimen with a support that "
        "selects a circle ({\"circle\": {\"center\": [0, 0], \"radius\": \"9 cm\"}})");
  DrapeTestOptions o;
  o.disc_radius = support_radius ? *support_radius : disc->radius;
  const Vec2 c = centre ? *centre : disc ? disc->center : Vec2{0, 0};
  if (!(o.disc_radius > 0) || !std::isfinite(o.disc_radius))
    throw DrapeTestError("the support radius must be a length greater than zero");
  // The disc must lie on the part: its rim, every degree.
  const double tolerance = 1e-6 * OutlineSize(scene.fabric.outline);
  double outside = 0;
  for (int k = 0; k < 360; ++k) {
    const double a = 2 * M_PI * k / 360;
    outside = std::max(outside,
                       DistanceToOutline(scene.fabric.outline,
                                         {c[0] + o.disc_radius * std::cos(a),
                                          c[1] + o.disc_radius * std::sin(a)}));
  }
  if (outside > tolerance)
    throw DrapeTestError("the support disc (radius " + Cm(o.disc_radius) + " about (" + Cm(c[0]) +
                         ", " + Cm(c[1]) + ")) reaches " + Cm(outside) +
                         " outside the part: it must lie inside the specimen");
  o.specimen_area = FlatArea(mesh);
  o.down = Eigen::Vector3d(
      scene.gravity_direction[0], scene.gravity_direction[1], scene.gravity_direction[2]);
  o.centre = Eigen::Vector3d(c[0], c[1], scene.fabric.elevation);
  return o;
}

}  // namespace drape
