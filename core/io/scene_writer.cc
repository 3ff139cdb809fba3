#include "core/io/scene_writer.h"

#include "core/model/overloaded.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace drape {
namespace {

using json = nlohmann::ordered_json;

json ToJson(const Outline& outline) {
  return std::visit(Overloaded{
                        [](const RectangleOutline& r) {
                          return json{{"rectangle", {{"size", r.size}, {"center", r.center}}}};
                        },
                        [](const DiskOutline& d) {
                          return json{{"disk", {{"radius", d.radius}, {"center", d.center}}}};
                        },
                        [](const PolygonOutline& p) {
                          return json{{"polygon", p.vertices}};
                        },
                        [](const PatternOutline& p) {
                          json pattern{{"file", p.file}, {"piece", p.piece}};
                          const PiecePlacement& at = p.placement;
                          if (at.at != PiecePoint{0, 0}) pattern["at"] = at.at;
                          if (at.rotation_deg != 0) pattern["rotation_deg"] = at.rotation_deg;
                          if (at.flip) pattern["flip"] = true;
                          return json{{"pattern", pattern}};
                        },
                    },
                    outline);
}

json ToJson(const Fabric& f) {
  json j{{"outline", ToJson(f.outline)}, {"mesh", json::object()}};
  if (!f.name.empty()) j["name"] = f.name;
  if (f.mesh.elements) j["mesh"]["elements"] = *f.mesh.elements;
  if (f.mesh.size) j["mesh"]["size"] = *f.mesh.size;
  j["elevation"] = f.elevation;
  if (f.imperfection) {
    const auto& i = *f.imperfection;
    json imp{{"amplitude", i.amplitude}, {"seed", i.seed}, {"pattern", ToString(i.pattern)}};
    if (i.wavelength) imp["wavelength"] = *i.wavelength;
    j["imperfection"] = imp;
  }
  return j;
}

json ToJson(const BendingLaw& law) {
  return std::visit(Overloaded{
                        [](const LinearBending& l) {
                          json j{{"model", "linear"}};
                          if (l.rigidity) j["rigidity"] = *l.rigidity;
                          return j;
                        },
                        [](const PolynomialBending& p) {
                          return json{{"model", "polynomial"},
                                      {"coefficients", p.coefficients},
                                      {"moment_unit", "N*m/m"},
                                      {"curvature_unit", "1/m"},
                                      {"valid_to", p.valid_to}};
                        },
                        [](const CurveBending& c) {
                          json j{{"model", "curve"}};
                          if (c.file.empty()) {
                            j["points"] = c.points;
                            j["moment_unit"] = "N*m/m";
                            j["curvature_unit"] = "1/m";
                          } else {
                            j["file"] = c.file;
                            if (c.branch != "average") j["branch"] = c.branch;
                            if (!c.curvature_column.empty() || !c.moment_column.empty())
                              j["columns"] = {c.curvature_column, c.moment_column};
                          }
                          return j;
                        },
                    },
                    law);
}

json ToJson(const BendingLaw& law, const Hysteresis& hysteresis) {
  json j = ToJson(law);
  if (hysteresis.measured)
    j["hysteresis"] = "measured";
  else if (hysteresis.width > 0)
    j["hysteresis"] = hysteresis.width;  // N·m/m, as the law's moment_unit (SI) says
  return j;
}

json ToJson(const Material& m) {
  json j{{"thickness", m.thickness},
         {"areal_weight", m.areal_weight},
         {"angle_deg", m.angle_from_grain ? json("grain") : json(m.angle_deg)}};
  std::visit(Overloaded{
                 [&](const IsotropicMembrane& i) {
                   j["youngs_modulus"] = i.youngs_modulus;
                   j["poisson_ratio"] = i.poisson_ratio;
                 },
                 [&](const OrthotropicMembrane& o) {
                   j["membrane"] = {{"E1", o.e1}, {"E2", o.e2}, {"nu12", o.nu12}, {"G12", o.g12}};
                 },
             },
             m.membrane);
  const Bending& b = m.bending;
  if (b.weft)
    j["bending"] = {{"warp", ToJson(b.warp, b.warp_hysteresis)},
                    {"weft", ToJson(*b.weft, b.weft_hysteresis)}};
  else
    j["bending"] = ToJson(b.warp, b.warp_hysteresis);
  return j;
}

json ToJson(const Selection& s) {
  json j = std::visit(Overloaded{
                          [](const PointSelection& p) {
                            return json{{"point", p.at}};
                          },
                          [](const LineSelection& l) {
                            return json{{"line", {l.from, l.to}}};
                          },
                          [](const BoxSelection& b) {
                            return json{{"box", {b.min, b.max}}};
                          },
                          [](const CircleSelection& c) {
                            return json{{"circle", {{"center", c.center}, {"radius", c.radius}}}};
                          },
                          [](const CornersSelection&) {
                            return json{{"corners", true}};
                          },
                          [](const EdgeSelection& e) {
                            return json{{"edge", ToString(e.side)}};
                          },
                          [](const NodesSelection& n) {
                            return json{{"nodes", n.nodes}};
                          },
                          [](const PatternMarkSelection& m) {
                            return json{{PatternMarkKey(m.mark), m.index}};
                          },
                      },
                      s.shape);
  if (s.tolerance) j["tolerance"] = *s.tolerance;
  if (s.part) j["part"] = *s.part;
  return j;
}

json ToJson(const ObstacleShape& shape) {
  return std::visit(
      Overloaded{
          [](const PlaneShape& p) {
            return json{{"plane", {{"point", p.point}, {"normal", p.normal}}}};
          },
          [](const BoxShape& b) {
            return json{{"box", {{"min", b.min}, {"max", b.max}, {"edge_radius", b.edge_radius}}}};
          },
          [](const CylinderShape& c) {
            json cyl{{"point", c.point}, {"axis", c.axis}, {"radius", c.radius}};
            if (c.length) cyl["length"] = *c.length;
            return json{{"cylinder", cyl}};
          },
          [](const SphereShape& s) {
            return json{{"sphere", {{"center", s.center}, {"radius", s.radius}}}};
          },
          [](const MeshShape& m) {
            json mesh{{"file", m.file}};
            if (m.scale != Vec3{1, 1, 1}) {
              if (m.scale[0] == m.scale[1] && m.scale[1] == m.scale[2])
                mesh["scale"] = m.scale[0];
              else
                mesh["scale"] = m.scale;
            }
            if (m.rotation_deg != 0) mesh["rotation_deg"] = m.rotation_deg;
            if (m.at != Vec3{0, 0, 0}) mesh["at"] = m.at;
            return json{{"mesh", mesh}};
          },
      },
      shape);
}

json ToJson(const Path& path) {
  return std::visit(
      Overloaded{
          [](const LinePath& l) {
            return json{{"line", {{"by", l.by}}}};
          },
          [](const ArcPath& a) {
            return json{
                {"arc", {{"center", a.center}, {"axis", a.axis}, {"angle_deg", a.angle_deg}}}};
          },
          [](const KeyframesPath& k) {
            return json{{"keyframes",
                         {{"points", k.points}, {"interpolation", ToString(k.interpolation)}}}};
          },
      },
      path);
}

json ToJson(const Stage& s) {
  json j{{"name", s.name},
         {"kind", ToString(s.kind)},
         {"initial_increment", s.initial_increment},
         {"control", ToString(s.control)}};
  if (!s.release.empty()) j["release"] = s.release;
  if (!s.moves.empty()) {
    j["moves"] = json::array();
    for (const auto& m : s.moves)
      j["moves"].push_back(m.obstacle.empty()
                               ? json{{"gripper", m.gripper}, {"path", ToJson(m.path)}}
                               : json{{"obstacle", m.obstacle}, {"path", ToJson(m.path)}});
  }
  return j;
}

json ToJson(const SolverSettings& s) {
  json j;
  if (s.preset) j["preset"] = ToString(*s.preset);
  // Written beside a preset even when 1: it overrides the preset's on reading.
  if (s.preset || s.mesh_scale != 1) j["mesh_scale"] = s.mesh_scale;
  j.update(json{{"tolerance", s.tolerance},
                {"displacement_tolerance", s.displacement_tolerance},
                {"target_iterations", s.target_iterations},
                {"acceleration", s.acceleration},
                {"max_steps", s.max_steps},
                {"max_iterations", s.max_iterations},
                {"max_step_cuts", s.max_step_cuts},
                {"max_turns", s.max_turns},
                {"branching", ToString(s.branching)}});
  if (s.psi) j["psi"] = *s.psi;
  if (s.sequencing != kAutoSequencing) j["sequencing"] = s.sequencing;
  if (s.max_wall_s) j["max_wall_s"] = *s.max_wall_s;
  if (s.error_estimate) j["error_estimate"] = true;
  return j;
}

}  // namespace

nlohmann::ordered_json SceneToJson(const Scene& scene) {
  json j;
  j["drape_scene"] = kSceneFormatVersion;
  j["name"] = scene.name;
  if (!scene.description.empty()) j["description"] = scene.description;
  if (scene.other_parts.empty()) {
    j["fabric"] = ToJson(scene.fabric);
  } else {
    j["fabric"] = json::array();
    for (const Fabric* part : FabricParts(scene)) j["fabric"].push_back(ToJson(*part));
  }
  j["material"] = ToJson(scene.material);
  j["supports"] = json::array();
  for (const auto& s : scene.supports)
    j["supports"].push_back(
        {{"name", s.name}, {"select", ToJson(s.select)}, {"fix", ToString(s.fix)}});
  j["grippers"] = json::array();
  for (const auto& g : scene.grippers)
    j["grippers"].push_back(
        {{"name", g.name}, {"select", ToJson(g.select)}, {"hold", ToString(g.hold)}});
  j["loads"] = json::array();
  for (const auto& l : scene.loads)
    j["loads"].push_back(
        {{"name", l.name}, {"select", ToJson(l.select)}, {"force", l.force}, {"moment", l.moment}});
  j["obstacles"] = json::array();
  for (const auto& o : scene.obstacles) {
    json obstacle{{"name", o.name}};
    obstacle.update(ToJson(o.shape));
    j["obstacles"].push_back(obstacle);
  }
  if (scene.contact) {
    json contact{{"friction", scene.contact->friction}};
    contact["self"] = scene.contact->self;
    if (scene.contact->thickness) contact["thickness"] = *scene.contact->thickness;
    if (scene.contact->friction_slip) contact["friction_slip"] = *scene.contact->friction_slip;
    if (scene.contact->law == ContactLaw::kBarrier) {
      contact["law"] = "barrier";
      if (scene.contact->barrier_distance)
        contact["barrier_distance"] = *scene.contact->barrier_distance;
    } else if (scene.contact->penalty) {
      contact["penalty"] = *scene.contact->penalty;
    } else {
      contact["penalty"] = "auto";
    }
    j["contact"] = contact;
  }
  j["gravity"] = {{"direction", scene.gravity_direction}};
  j["stages"] = json::array();
  for (const auto& s : scene.stages) j["stages"].push_back(ToJson(s));
  j["solver"] = ToJson(scene.solver);
  j["probes"] = json::array();
  for (const auto& p : scene.probes) {
    j["probes"].push_back({{"name", p.name}, {"at", p.at}});
    if (p.part) j["probes"].back()["part"] = *p.part;
  }
  return j;
}

namespace {

bool IsFlat(const json& array) {
  for (const auto& item : array)
    if (item.is_structured() && !(item.is_array() && item.size() <= 3 && IsFlat(item)))
      return false;
  return array.size() <= 12;
}

// Scalars and short numeric arrays on one line: [0.2, 0.02], [[0, 0], [1, 1]].
void FormatInline(const json& value, std::string& out) {
  if (value.is_array()) {
    out += '[';
    for (size_t i = 0; i < value.size(); ++i) {
      if (i) out += ", ";
      FormatInline(value[i], out);
    }
    out += ']';
  } else {
    out += value.dump();  // scalars, and {} for an empty object
  }
}

void Format(const json& value, int indent, std::string& out) {
  const std::string pad(indent, ' '), inner(indent + 2, ' ');
  if (value.is_object() && !value.empty()) {
    out += "{\n";
    size_t i = 0;
    for (const auto& [key, item] : value.items()) {
      out += inner + json(key).dump() + ": ";
      Format(item, indent + 2, out);
      out += ++i < value.size() ? ",\n" : "\n";
    }
    out += pad + "}";
  } else if (value.is_array() && !value.empty() && !IsFlat(value)) {
    out += "[\n";
    for (size_t i = 0; i < value.size(); ++i) {
      out += inner;
      Format(value[i], indent + 2, out);
      out += i + 1 < value.size() ? ",\n" : "\n";
    }
    out += pad + "]";
  } else {
    FormatInline(value, out);
  }
}

}  // namespace

std::string FormatJson(const nlohmann::ordered_json& document) {
  std::string out;
  Format(document, 0, out);
  return out + "\n";
}

std::string WriteSceneText(const Scene& scene) {
  return FormatJson(SceneToJson(scene));
}

void WriteScene(const Scene& scene, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write scene file '" + file.string() + "'");
  out << WriteSceneText(scene);
  if (!out) throw std::runtime_error("failed while writing scene file '" + file.string() + "'");
}

Scene WithAbsoluteReferences(const Scene& scene, const std::filesystem::path& folder) {
  Scene out = scene;
  auto absolute = [&](std::string& reference) {
    if (!reference.empty() && std::filesystem::path(reference).is_relative())
      reference = std::filesystem::absolute(folder / reference).lexically_normal().string();
  };
  for (BendingLaw* law : {&out.material.bending.warp,
                          out.material.bending.weft ? &*out.material.bending.weft : nullptr})
    if (law)
      if (auto* curve = std::get_if<CurveBending>(law)) absolute(curve->file);
  for (Obstacle& o : out.obstacles)
    if (auto* mesh = std::get_if<MeshShape>(&o.shape)) absolute(mesh->file);
  if (auto* pattern = std::get_if<PatternOutline>(&out.fabric.outline)) absolute(pattern->file);
  for (Fabric& part : out.other_parts)
    if (auto* pattern = std::get_if<PatternOutline>(&part.outline)) absolute(pattern->file);
  return out;
}

}  // namespace drape
