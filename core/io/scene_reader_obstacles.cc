// Reading a scene's obstacles (planes, boxes, cylinders, spheres, triangle
// meshes from files) and how the fabric touches them and itself.
#include "core/io/scene_parser.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/model/string_format.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

// A mesh's scale: one factor for every axis, or [sx, sy, sz]. Each factor
// positive (a negative one would mirror the form inside out) and within
// 1e-6..1e6 (a file in millimetres needs 0.001).
Vec3 ReadMeshScale(const JsonCursor& c) {
  std::vector<JsonCursor> factors;
  if (c.value().is_array())
    factors = c.Items(3);
  else
    factors = {c};
  Vec3 scale{};
  for (std::size_t k = 0; k < factors.size(); ++k) {
    const double f = factors[k].Number();
    if (!(f >= 1e-6 && f <= 1e6))
      factors[k].Fail(
          "a scale factor must be between 1e-6 and 1e6 (a positive number; a negative one "
          "would turn the mesh inside out), found " +
          factors[k].value().dump());
    scale[k] = f;
  }
  if (factors.size() == 1) scale = {scale[0], scale[0], scale[0]};
  return scale;
}

// `si` metres in the unit `typed` was written in ("2 cm" beside "3 cm"); in
// metres when `typed` is a bare number.
std::string LengthInUnitOf(double si, const nlohmann::json& typed) {
  if (typed.is_string()) {
    const std::string& text = typed.get_ref<const std::string&>();
    const auto begin = text.find_first_not_of(" \t\r\n");
    const auto unit_begin =
        begin == std::string::npos ? begin : text.find_first_not_of("0123456789.eE+-", begin);
    if (unit_begin != std::string::npos) {
      const std::string unit_text = text.substr(unit_begin);
      const auto first = unit_text.find_first_not_of(" \t\r\n");
      const auto last = unit_text.find_last_not_of(" \t\r\n");
      try {
        const Unit unit = ParseUnit(unit_text);
        if (unit.dimension == dim::kLength && first != std::string::npos)
          return Format(
              "%g %s", si / unit.si_factor, unit_text.substr(first, last - first + 1).c_str());
      } catch (const UnitError&) {
        // Cannot happen for a value already read as a length; fall back to metres.
      }
    }
  }
  return Format("%g m", si);
}

}  // namespace

Obstacle SceneParser::ReadObstacle(const JsonCursor& c) {
  c.ExpectObject({"name", "plane", "box", "cylinder", "sphere", "mesh"});
  Obstacle o;
  o.name = ReadName(c, "obstacle");
  switch (c.OneOf({"plane", "box", "cylinder", "sphere", "mesh"})) {
    case 0: {
      auto p = c["plane"];
      p.ExpectObject({"point", "normal"});
      o.shape = PlaneShape{p["point"].QuantityVec3(dim::kLength), p["normal"].Direction()};
      break;
    }
    case 1: {
      auto b = c["box"];
      b.ExpectObject({"min", "max", "edge_radius"});
      BoxShape box{b["min"].QuantityVec3(dim::kLength), b["max"].QuantityVec3(dim::kLength), 0};
      double smallest = 1e300;
      for (int k = 0; k < 3; ++k) {
        if (!(box.max[k] > box.min[k])) {
          const std::string index = "[" + std::to_string(k) + "]";
          b["max"].Fail("each coordinate of 'max' must exceed that of 'min', found max" + index +
                        " = " + b["max"].value()[k].dump() + " and min" + index + " = " +
                        b["min"].value()[k].dump());
        }
        smallest = std::min(smallest, box.max[k] - box.min[k]);
      }
      if (auto r = b.Find("edge_radius")) {
        box.edge_radius = r->NonNegativeQuantity(dim::kLength);
        if (box.edge_radius >= 0.5 * smallest)
          r->Fail("must be smaller than half the box's smallest side (" +
                  LengthInUnitOf(0.5 * smallest, r->value()) + "), found " + AsTyped(r->value()));
      }
      o.shape = box;
      break;
    }
    case 2: {
      auto cy = c["cylinder"];
      cy.ExpectObject({"point", "axis", "radius", "length"});
      CylinderShape cyl;
      cyl.point = cy["point"].QuantityVec3(dim::kLength);
      cyl.axis = cy["axis"].Direction();
      cyl.radius = cy["radius"].PositiveQuantity(dim::kLength);
      if (auto l = cy.Find("length")) cyl.length = l->PositiveQuantity(dim::kLength);
      o.shape = cyl;
      break;
    }
    case 3: {
      auto s = c["sphere"];
      s.ExpectObject({"center", "radius"});
      o.shape = SphereShape{s["center"].QuantityVec3(dim::kLength),
                            s["radius"].PositiveQuantity(dim::kLength)};
      break;
    }
    default: {
      auto m = c["mesh"];
      m.ExpectObject({"file", "scale", "rotation_deg", "at"});
      MeshShape mesh{ReadFileReference(m["file"]), {}};
      if (auto s = m.Find("scale")) mesh.scale = ReadMeshScale(*s);
      if (auto r = m.Find("rotation_deg")) mesh.rotation_deg = ReadAngleDeg(*r);
      if (auto at = m.Find("at")) mesh.at = at->QuantityVec3(dim::kLength);
      const fs::path file(mesh.file);
      mesh.resolved_path =
          (file.is_absolute() ? file : fs::absolute(base_ / file)).lexically_normal().string();
      o.shape = mesh;
    }
  }
  return o;
}

Contact SceneParser::ReadContact(const JsonCursor& c) {
  c.ExpectObject(
      {"law", "penalty", "barrier_distance", "friction", "friction_slip", "self", "thickness"});
  Contact contact;
  if (auto l = c.Find("law"))
    contact.law = static_cast<ContactLaw>(l->Choice({"penalty", "barrier"}));
  if (auto p = c.Find("penalty")) {
    if (contact.law == ContactLaw::kBarrier)
      p->Fail(
          "a penalty belongs to contact.law \"penalty\"; this contact is a barrier "
          "(its distance is contact.barrier_distance)");
    if (p->value().is_string() && p->value().get<std::string>() == "auto")
      contact.penalty = std::nullopt;
    else if (IsWord(p->value()) || !(p->value().is_string() || p->value().is_number()))
      p->Fail("expected \"auto\" or a " + DimensionName(dim::kPenaltyPerArea) + ", found " +
              AsTyped(p->value()));
    else
      contact.penalty = p->PositiveQuantity(dim::kPenaltyPerArea);
  }
  if (auto f = c.Find("friction")) {
    contact.friction = f->Number();
    if (!std::isfinite(contact.friction)) f->Fail("a friction coefficient must be a finite number");
    if (contact.friction < 0)
      f->Fail("a friction coefficient must not be negative, found " + f->value().dump());
  }
  if (auto d = c.Find("barrier_distance")) {
    if (contact.law != ContactLaw::kBarrier)
      d->Fail("a barrier distance belongs to contact.law \"barrier\" (this contact is a penalty)");
    contact.barrier_distance = d->PositiveQuantity(dim::kLength);
  }
  if (auto e = c.Find("friction_slip")) contact.friction_slip = e->PositiveQuantity(dim::kLength);
  if (auto s = c.Find("self")) contact.self = s->Boolean();
  if (auto t = c.Find("thickness")) contact.thickness = t->PositiveQuantity(dim::kLength);
  return contact;
}

}  // namespace drape
