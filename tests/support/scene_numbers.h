// Every number a Scene holds (core/model/scene.h), named by where it sits, so
// that a test can ask of a scene the reader accepted that none is NaN or
// infinite. Every double of a Scene is a length, a modulus, a factor or an
// angle that the model computes with: none may be non-finite (an absent
// optional is no number).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/model/scene.h"

namespace drape::test {

class SceneNumbers {
 public:
  // The names of the numbers of `scene` that are not finite.
  static std::vector<std::string> NonFinite(const Scene& scene) {
    SceneNumbers n;
    n.Visit(scene);
    return n.bad_;
  }
  // How many numbers NonFinite looked at (a check that the visit reaches them).
  static int Count(const Scene& scene) {
    SceneNumbers n;
    n.Visit(scene);
    return n.count_;
  }

 private:
  void Number(const std::string& at, double x) {
    ++count_;
    if (!std::isfinite(x)) bad_.push_back(at + " = " + std::to_string(x));
  }
  void Number(const std::string& at, const std::optional<double>& x) {
    if (x) Number(at, *x);
  }
  template <std::size_t N>
  void Numbers(const std::string& at, const std::array<double, N>& v) {
    for (std::size_t k = 0; k < N; ++k) Number(at + "[" + std::to_string(k) + "]", v[k]);
  }
  static std::string Item(const std::string& at, std::size_t i) {
    return at + "[" + std::to_string(i) + "]";
  }

  void Visit(const Selection& s, const std::string& at) {
    if (const auto* p = std::get_if<PointSelection>(&s.shape)) Numbers(at + ".point", p->at);
    if (const auto* l = std::get_if<LineSelection>(&s.shape)) {
      Numbers(at + ".line.from", l->from);
      Numbers(at + ".line.to", l->to);
    }
    if (const auto* b = std::get_if<BoxSelection>(&s.shape)) {
      Numbers(at + ".box.min", b->min);
      Numbers(at + ".box.max", b->max);
    }
    if (const auto* c = std::get_if<CircleSelection>(&s.shape)) {
      Numbers(at + ".circle.center", c->center);
      Number(at + ".circle.radius", c->radius);
    }
    Number(at + ".tolerance", s.tolerance);
  }

  void Visit(const BendingLaw& law, const std::string& at) {
    if (const auto* l = std::get_if<LinearBending>(&law)) Number(at + ".rigidity", l->rigidity);
    if (const auto* p = std::get_if<PolynomialBending>(&law)) {
      for (std::size_t i = 0; i < p->coefficients.size(); ++i)
        Number(Item(at + ".coefficients", i), p->coefficients[i]);
      Number(at + ".valid_to", p->valid_to);
    }
    if (const auto* c = std::get_if<CurveBending>(&law))
      for (std::size_t i = 0; i < c->points.size(); ++i)
        Numbers(Item(at + ".points", i), c->points[i]);
  }

  void Visit(const Path& path, const std::string& at) {
    if (const auto* l = std::get_if<LinePath>(&path)) Numbers(at + ".line.by", l->by);
    if (const auto* a = std::get_if<ArcPath>(&path)) {
      Numbers(at + ".arc.center", a->center);
      Numbers(at + ".arc.axis", a->axis);
      Number(at + ".arc.angle_deg", a->angle_deg);
    }
    if (const auto* k = std::get_if<KeyframesPath>(&path))
      for (std::size_t i = 0; i < k->points.size(); ++i)
        Numbers(Item(at + ".keyframes.points", i), k->points[i]);
  }

  void Visit(const ObstacleShape& shape, const std::string& at) {
    if (const auto* p = std::get_if<PlaneShape>(&shape)) {
      Numbers(at + ".plane.point", p->point);
      Numbers(at + ".plane.normal", p->normal);
    }
    if (const auto* b = std::get_if<BoxShape>(&shape)) {
      Numbers(at + ".box.min", b->min);
      Numbers(at + ".box.max", b->max);
      Number(at + ".box.edge_radius", b->edge_radius);
    }
    if (const auto* c = std::get_if<CylinderShape>(&shape)) {
      Numbers(at + ".cylinder.point", c->point);
      Numbers(at + ".cylinder.axis", c->axis);
      Number(at + ".cylinder.radius", c->radius);
      Number(at + ".cylinder.length", c->length);
    }
    if (const auto* s = std::get_if<SphereShape>(&shape)) {
      Numbers(at + ".sphere.center", s->center);
      Number(at + ".sphere.radius", s->radius);
    }
  }

  void Visit(const Scene& scene) {
    const Fabric& f = scene.fabric;
    if (const auto* r = std::get_if<RectangleOutline>(&f.outline)) {
      Numbers("fabric.outline.rectangle.size", r->size);
      Numbers("fabric.outline.rectangle.center", r->center);
    }
    if (const auto* d = std::get_if<DiskOutline>(&f.outline)) {
      Number("fabric.outline.disk.radius", d->radius);
      Numbers("fabric.outline.disk.center", d->center);
    }
    if (const auto* p = std::get_if<PolygonOutline>(&f.outline))
      for (std::size_t i = 0; i < p->vertices.size(); ++i)
        Numbers(Item("fabric.outline.polygon", i), p->vertices[i]);
    Number("fabric.mesh.size", f.mesh.size);
    Number("fabric.elevation", f.elevation);
    if (f.imperfection) {
      Number("fabric.imperfection.amplitude", f.imperfection->amplitude);
      Number("fabric.imperfection.wavelength", f.imperfection->wavelength);
    }

    const Material& m = scene.material;
    Number("material.thickness", m.thickness);
    Number("material.areal_weight", m.areal_weight);
    if (const auto* i = std::get_if<IsotropicMembrane>(&m.membrane)) {
      Number("material.youngs_modulus", i->youngs_modulus);
      Number("material.poisson_ratio", i->poisson_ratio);
    }
    if (const auto* o = std::get_if<OrthotropicMembrane>(&m.membrane)) {
      Number("material.membrane.E1", o->e1);
      Number("material.membrane.E2", o->e2);
      Number("material.membrane.nu12", o->nu12);
      Number("material.membrane.G12", o->g12);
    }
    Visit(m.bending.warp, "material.bending.warp");
    if (m.bending.weft) Visit(*m.bending.weft, "material.bending.weft");
    Number("material.angle_deg", m.angle_deg);

    for (std::size_t i = 0; i < scene.supports.size(); ++i)
      Visit(scene.supports[i].select, Item("supports", i) + ".select");
    for (std::size_t i = 0; i < scene.grippers.size(); ++i)
      Visit(scene.grippers[i].select, Item("grippers", i) + ".select");
    for (std::size_t i = 0; i < scene.loads.size(); ++i) {
      const PointLoad& l = scene.loads[i];
      Visit(l.select, Item("loads", i) + ".select");
      Numbers(Item("loads", i) + ".force", l.force);
      Numbers(Item("loads", i) + ".moment", l.moment);
    }
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
      Visit(scene.obstacles[i].shape, Item("obstacles", i));
    if (scene.contact) {
      Number("contact.penalty", scene.contact->penalty);
      Number("contact.friction", scene.contact->friction);
      Number("contact.thickness", scene.contact->thickness);
    }
    Numbers("gravity", scene.gravity_direction);
    for (std::size_t i = 0; i < scene.stages.size(); ++i) {
      const Stage& s = scene.stages[i];
      Number(Item("stages", i) + ".initial_increment", s.initial_increment);
      for (std::size_t k = 0; k < s.moves.size(); ++k)
        Visit(s.moves[k].path, Item(Item("stages", i) + ".moves", k));
    }
    const SolverSettings& s = scene.solver;
    Number("solver.mesh_scale", s.mesh_scale);
    Number("solver.tolerance", s.tolerance);
    Number("solver.displacement_tolerance", s.displacement_tolerance);
    Number("solver.psi", s.psi);
    Number("solver.max_wall_s", s.max_wall_s);
    for (std::size_t i = 0; i < scene.probes.size(); ++i)
      Numbers(Item("probes", i) + ".at", scene.probes[i].at);
  }

  std::vector<std::string> bad_;
  int count_ = 0;
};

}  // namespace drape::test
