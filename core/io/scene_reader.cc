#include "core/io/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/io/kawabata_reader.h"
#include "core/io/material_library.h"
#include "core/io/scene_parser.h"
#include "core/model/scene_error.h"
#include "core/model/sequencing_check.h"
#include "core/model/solver_preset.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr double kStandardGravity = 9.80665;  // m/s², for areal_density

template <typename T, typename F>
std::vector<T> ReadList(const std::optional<JsonCursor>& c, F read) {
  std::vector<T> out;
  if (!c) return out;
  for (const auto& item : c->Items()) out.push_back(read(item));
  return out;
}

}  // namespace

std::string SceneParser::ReadName(const JsonCursor& c, const std::string& group) {
  auto name_cursor = c["name"];
  std::string name = name_cursor.String();
  if (name.empty()) name_cursor.Fail("a name must not be empty");
  auto& taken = names_[group];
  if (auto it = taken.find(name); it != taken.end())
    name_cursor.Fail("'" + name + "' is already the name of " + it->second);
  taken[name] = c.path();
  return name;
}

std::string SceneParser::ReadFileReference(const JsonCursor& c) {
  std::string file = c.String();
  if (file.empty()) c.Fail("a file name must not be empty");
  fs::path full = fs::path(file).is_absolute() ? fs::path(file) : base_ / file;
  std::error_code ec;
  if (!fs::is_regular_file(full, ec))
    c.Fail("cannot read '" + file + "' (looked for " + full.lexically_normal().string() + ")");
  return file;
}

double SceneParser::ReadAngleDeg(const JsonCursor& c) {
  // A bare number under a `_deg` key is in degrees; "3.14159 rad" is converted.
  if (c.value().is_number()) return c.Number();
  return c.Quantity(dim::kAngle) * 180.0 / M_PI;
}

Scene SceneParser::Read(const JsonCursor& root) {
  root.ExpectObject({"drape_scene",
                     "name",
                     "description",
                     "fabric",
                     "material",
                     "supports",
                     "grippers",
                     "loads",
                     "obstacles",
                     "contact",
                     "gravity",
                     "stages",
                     "solver",
                     "probes"});
  auto version = root["drape_scene"];
  if (version.Integer() != kSceneFormatVersion)
    version.Fail("unsupported scene format version " + std::to_string(version.Integer()) +
                 "; this program reads version " + std::to_string(kSceneFormatVersion));

  Scene scene;
  if (auto c = root.Find("name")) scene.name = c->String();
  if (auto c = root.Find("description")) scene.description = c->String();
  scene.fabric = ReadFabric(root["fabric"]);
  scene.material = ReadMaterialOrLibrary(root["material"]);
  scene.supports =
      ReadList<Support>(root.Find("supports"), [&](auto& c) { return ReadSupport(c); });
  scene.grippers =
      ReadList<Gripper>(root.Find("grippers"), [&](auto& c) { return ReadGripper(c); });
  scene.loads = ReadList<PointLoad>(root.Find("loads"), [&](auto& c) { return ReadLoad(c); });
  scene.obstacles =
      ReadList<Obstacle>(root.Find("obstacles"), [&](auto& c) { return ReadObstacle(c); });
  if (auto c = root.Find("contact")) scene.contact = ReadContact(*c);
  if (auto c = root.Find("gravity")) {
    c->ExpectObject({"direction"});
    scene.gravity_direction = (*c)["direction"].Direction();
  }
  auto stages = root["stages"];
  scene.stages = ReadList<Stage>(stages, [&](auto& c) { return ReadStage(c); });
  if (scene.stages.empty()) stages.Fail("a scene needs at least one stage");
  if (auto c = root.Find("solver")) scene.solver = ReadSolver(*c);
  scene.probes = ReadList<Probe>(root.Find("probes"), [&](auto& c) { return ReadProbe(c); });
  CheckStages(root, scene);
  try {
    CheckSequencing(SceneOnSolvedMesh(scene), scene.solver.sequencing);
  } catch (const SceneError& e) {
    if (scene.solver.mesh_scale == 1) throw;
    char scale[32];
    std::snprintf(scale, sizeof scale, "%g", scene.solver.mesh_scale);
    throw SceneError(
        e.where(),
        e.message() + " (the mesh solved: fabric.mesh at solver.mesh_scale " + scale + ")");
  }
  return scene;
}

// ---- fabric -----------------------------------------------------------------

Fabric SceneParser::ReadFabric(const JsonCursor& c) {
  c.ExpectObject({"outline", "mesh", "elevation", "imperfection"});
  Fabric fabric;
  fabric.outline = ReadOutline(c["outline"]);
  fabric.mesh = ReadMeshSpec(c["mesh"], fabric.outline);
  if (auto e = c.Find("elevation")) fabric.elevation = e->Quantity(dim::kLength);
  if (auto i = c.Find("imperfection")) fabric.imperfection = ReadImperfection(*i);
  return fabric;
}

Outline SceneParser::ReadOutline(const JsonCursor& c) {
  c.ExpectObject({"rectangle", "disk", "polygon"});
  switch (c.OneOf({"rectangle", "disk", "polygon"})) {
    case 0: {
      auto r = c["rectangle"];
      r.ExpectObject({"size", "center"});
      RectangleOutline out;
      auto size = r["size"].Items(2);
      out.size = {size[0].PositiveQuantity(dim::kLength), size[1].PositiveQuantity(dim::kLength)};
      if (auto center = r.Find("center")) out.center = center->QuantityVec2(dim::kLength);
      return out;
    }
    case 1: {
      auto d = c["disk"];
      d.ExpectObject({"radius", "center"});
      DiskOutline out;
      out.radius = d["radius"].PositiveQuantity(dim::kLength);
      if (auto center = d.Find("center")) out.center = center->QuantityVec2(dim::kLength);
      return out;
    }
    default: {
      auto p = c["polygon"];
      PolygonOutline out;
      for (const auto& v : p.Items()) out.vertices.push_back(v.QuantityVec2(dim::kLength));
      if (out.vertices.size() < 3)
        p.Fail("a polygon needs at least 3 vertices, found " + std::to_string(out.vertices.size()));
      return out;
    }
  }
}

MeshSpec SceneParser::ReadMeshSpec(const JsonCursor& c, const Outline& outline) {
  c.ExpectObject({"elements", "size"});
  MeshSpec spec;
  if (c.OneOf({"elements", "size"}) == 0) {
    auto e = c["elements"];
    if (!std::holds_alternative<RectangleOutline>(outline))
      e.Fail("element counts are for rectangle outlines; give 'size' (a target element edge)");
    auto items = e.Items(2);
    std::array<int, 2> n{items[0].Integer(), items[1].Integer()};
    for (int k = 0; k < 2; ++k)
      if (n[k] < 1) items[k].Fail("must be at least 1, got " + std::to_string(n[k]));
    if (static_cast<double>(n[0]) * n[1] > 4e6)
      e.Fail("more than 4 million elements (" + std::to_string(n[0]) + " x " +
             std::to_string(n[1]) + ")");
    spec.elements = n;
  } else {
    spec.size = c["size"].PositiveQuantity(dim::kLength);
  }
  return spec;
}

ImperfectionSpec SceneParser::ReadImperfection(const JsonCursor& c) {
  c.ExpectObject({"amplitude", "seed", "pattern", "wavelength"});
  ImperfectionSpec spec;
  spec.amplitude = c["amplitude"].NonNegativeQuantity(dim::kLength);
  if (auto s = c.Find("seed")) {
    // nlohmann stores every non-negative integer literal as unsigned.
    if (!s->value().is_number_unsigned()) s->Fail("expected a non-negative integer");
    spec.seed = s->value().get<std::uint64_t>();
  }
  if (auto p = c.Find("pattern"))
    spec.pattern = p->Choice({"smooth", "nodal"}) == 0 ? ImperfectionPattern::kSmooth
                                                       : ImperfectionPattern::kNodal;
  if (auto w = c.Find("wavelength")) spec.wavelength = w->PositiveQuantity(dim::kLength);
  return spec;
}

// ---- material -----------------------------------------------------------------

namespace {

// Keys a scene may give next to "library", and which library keys each one
// replaces (a modulus replaces the library's orthotropic membrane, …).
const std::map<std::string, std::vector<std::string>>& LibraryOverrides() {
  static const std::map<std::string, std::vector<std::string>> overrides = {
      {"thickness", {}},
      {"areal_weight", {"areal_density"}},
      {"areal_density", {"areal_weight"}},
      {"youngs_modulus", {"membrane"}},
      {"poisson_ratio", {"membrane"}},
      {"membrane", {"youngs_modulus", "poisson_ratio"}},
      {"bending", {}},
      {"angle_deg", {}},
  };
  return overrides;
}

// Swaps the directory relative file names resolve against, for a scope.
class BaseDirectory {
 public:
  BaseDirectory(fs::path& base, fs::path value) : base_(base), saved_(base) {
    base_ = std::move(value);
  }
  ~BaseDirectory() { base_ = saved_; }

 private:
  fs::path& base_;
  fs::path saved_;
};

}  // namespace

// "material": {"library": "cotton-twill", …}: the library's material with the
// scene's keys over it. The library entry must be valid on its own (its
// errors name its file); its Kawabata file is resolved next to it and kept
// as an absolute path, so that a scene written back reads the same data.
Material SceneParser::ReadMaterialOrLibrary(const JsonCursor& c) {
  if (!c.value().is_object() || !c.Has("library")) return ReadMaterial(c);
  auto library = c["library"];
  const std::string name = library.String();
  const std::vector<fs::path> dirs = MaterialLibraryDirs(base_);
  const std::optional<fs::path> file = FindLibraryMaterial(name, dirs);
  if (!file) {
    const std::vector<std::string> names = LibraryMaterialNames(dirs);
    std::string message = "no library material " + Quoted(name);
    // A likely typo first: the closest name within two edits.
    for (const auto& n : names)
      if (EditDistance(name, n) <= 2) {
        message += "; did you mean " + Quoted(n) + "?";
        library.Fail(message);
      }
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    message += known.empty() ? "; no library found (looked in " + dirs.front().string() + " …)"
                             : "; the library has: " + known;
    library.Fail(message);
  }
  const LibraryMaterial entry = ReadLibraryMaterial(*file);
  const fs::path library_dir = file->parent_path();
  Material own;
  {
    BaseDirectory in_library(base_, library_dir);
    try {
      own = ReadMaterial(JsonCursor(*entry.material, ""));
    } catch (const SceneError& e) {
      throw SceneError(file->string() + ": material" + (e.where().empty() ? "" : "." + e.where()),
                       e.message());
    }
  }
  nlohmann::json merged = *entry.material;
  for (const auto& [key, value] : c.value().items()) {
    if (key == "library") continue;
    const auto it = LibraryOverrides().find(key);
    if (it == LibraryOverrides().end()) continue;  // ReadMaterial names it below
    for (const auto& replaced : it->second) merged.erase(replaced);
  }
  for (const auto& [key, value] : c.value().items())
    if (key != "library") merged[key] = value;
  const bool own_bending = !c.Has("bending");
  Material m;
  {
    BaseDirectory bending_files(base_, own_bending ? library_dir : base_);
    m = ReadMaterial(JsonCursor(merged, c.path()));
  }
  if (own_bending) {
    auto absolute = [&](BendingLaw& law) {
      if (auto* curve = std::get_if<CurveBending>(&law); curve && !curve->file.empty())
        if (fs::path(curve->file).is_relative())
          curve->file = fs::absolute(library_dir / curve->file).lexically_normal().string();
    };
    absolute(m.bending.warp);
    if (m.bending.weft) absolute(*m.bending.weft);
  }
  return m;
}

Material SceneParser::ReadMaterial(const JsonCursor& c) {
  c.ExpectObject({"library",
                  "thickness",
                  "areal_weight",
                  "areal_density",
                  "youngs_modulus",
                  "poisson_ratio",
                  "membrane",
                  "bending",
                  "angle_deg"});
  Material m;
  m.thickness = c["thickness"].PositiveQuantity(dim::kLength);
  if (c.OneOf({"areal_weight", "areal_density"}) == 0)
    m.areal_weight = c["areal_weight"].NonNegativeQuantity(dim::kPressure);
  else
    m.areal_weight = c["areal_density"].NonNegativeQuantity(dim::kArealDensity) * kStandardGravity;

  if (auto mem = c.Find("membrane")) {
    for (auto key : {"youngs_modulus", "poisson_ratio"})
      if (c.Has(key))
        c[key].Fail("give either 'youngs_modulus'/'poisson_ratio' or 'membrane', not both");
    mem->ExpectObject({"E1", "E2", "nu12", "G12"});
    OrthotropicMembrane o;
    o.e1 = (*mem)["E1"].PositiveQuantity(dim::kPressure);
    o.e2 = (*mem)["E2"].PositiveQuantity(dim::kPressure);
    o.g12 = (*mem)["G12"].PositiveQuantity(dim::kPressure);
    auto nu = (*mem)["nu12"];
    o.nu12 = nu.Number();
    // Positive-definite plane stress needs ν12·ν21 < 1 with ν21 = ν12 E2/E1.
    if (o.nu12 < 0 || o.nu12 * o.nu12 * o.e2 / o.e1 >= 1)
      nu.Fail("must lie in [0, sqrt(E1/E2)) for a stable orthotropic law, got " +
              std::to_string(o.nu12));
    m.membrane = o;
  } else {
    IsotropicMembrane iso;
    iso.youngs_modulus = c["youngs_modulus"].PositiveQuantity(dim::kPressure);
    auto nu = c["poisson_ratio"];
    iso.poisson_ratio = nu.Number();
    if (iso.poisson_ratio < 0 || iso.poisson_ratio >= 0.5)
      nu.Fail("must lie in [0, 0.5), got " + std::to_string(iso.poisson_ratio));
    m.membrane = iso;
  }
  m.bending.warp = LinearBending{};
  if (auto b = c.Find("bending")) m.bending = ReadBending(*b);
  if (auto a = c.Find("angle_deg")) m.angle_deg = ReadAngleDeg(*a);
  return m;
}

Bending SceneParser::ReadBending(const JsonCursor& c) {
  if (c.Has("warp") || c.Has("weft")) {
    c.ExpectObject({"warp", "weft"});
    return Bending{ReadBendingLaw(c["warp"]), ReadBendingLaw(c["weft"])};
  }
  return Bending{ReadBendingLaw(c), std::nullopt};
}

namespace {

// The SI factor of the unit named at `key` (SI when absent), which must be
// of dimension `d`.
double UnitFactorAt(const JsonCursor& c, const char* key, Dimension d) {
  auto u = c.Find(key);
  if (!u) return 1.0;  // SI
  try {
    Unit unit = ParseUnit(u->String());
    if (!(unit.dimension == d))
      u->Fail(Quoted(u->String()) + " is not a unit of " + DimensionName(d));
    return unit.si_factor;
  } catch (const UnitError& e) {
    u->Fail(e.what());
  }
}

PolynomialBending ReadPolynomialBending(const JsonCursor& c,
                                        double moment_unit,
                                        double curvature_unit) {
  c.ExpectObject({"model", "coefficients", "moment_unit", "curvature_unit", "valid_to"});
  PolynomialBending law;
  auto coefficients = c["coefficients"];
  // M = mu Σ cₖ (K/cu)ᵏ in SI, with mu and cu the SI factors of the units.
  double scale = moment_unit;
  for (const auto& item : coefficients.Items()) {
    scale /= curvature_unit;
    law.coefficients.push_back(item.Number() * scale);
  }
  if (law.coefficients.empty()) coefficients.Fail("needs at least one coefficient");
  if (!(law.coefficients[0] > 0))
    coefficients.Fail("the linear coefficient c1 (the initial bending rigidity) must be positive");
  law.valid_to = c["valid_to"].PositiveQuantity(dim::kCurvature);
  return law;
}

// A curve given point by point: curvatures increasing, at least two.
void ReadCurvePoints(const JsonCursor& c,
                     double moment_unit,
                     double curvature_unit,
                     CurveBending& law) {
  for (auto key : {"branch", "columns"})
    if (c.Has(key)) c[key].Fail("applies only to a Kawabata 'file'");
  auto points = c["points"];
  for (const auto& p : points.Items()) {
    auto km = p.Items(2);
    law.points.push_back({km[0].Number() * curvature_unit, km[1].Number() * moment_unit});
  }
  if (law.points.size() < 2)
    points.Fail("a curve needs at least 2 points, found " + std::to_string(law.points.size()));
  for (size_t i = 1; i < law.points.size(); ++i)
    if (!(law.points[i][0] > law.points[i - 1][0]))
      points.Items()[i].Fail("curvatures must increase from point to point");
}

}  // namespace

void SceneParser::ReadKawabataPoints(const JsonCursor& c, CurveBending& law) {
  law.file = ReadFileReference(c["file"]);
  KawabataOptions options;
  if (auto b = c.Find("branch")) {
    const int branch = b->Choice({"average", "loading", "unloading"});
    law.branch = b->String();
    options.branch = branch == 0   ? KawabataBranch::kAverage
                     : branch == 1 ? KawabataBranch::kLoading
                                   : KawabataBranch::kUnloading;
  }
  if (auto columns = c.Find("columns")) {
    auto names = columns->Items(2);
    law.curvature_column = options.curvature_column = names[0].String();
    law.moment_column = options.moment_column = names[1].String();
  }
  // The measured points, by default averaged over loading and unloading
  // (FORMAT.md); a bad file is a scene error at this key, with its own
  // line number.
  const fs::path file(law.file);
  try {
    const KawabataCurve curve = ReadKawabata(file.is_absolute() ? file : base_ / file, options);
    for (size_t i = 0; i < curve.curvature.size(); ++i)
      law.points.push_back({curve.curvature[i], curve.moment[i]});
  } catch (const KawabataError& e) {
    c["file"].Fail(e.what());
  }
}

BendingLaw SceneParser::ReadBendingLaw(const JsonCursor& c) {
  if (!c.value().is_object()) c.Fail("expected an object with a 'model'");
  int model = c["model"].Choice({"linear", "polynomial", "curve"});
  if (model == 0) {
    c.ExpectObject({"model", "rigidity"});
    LinearBending law;
    if (auto r = c.Find("rigidity")) law.rigidity = r->PositiveQuantity(dim::kBendingRigidity);
    return law;
  }
  const double moment_unit = UnitFactorAt(c, "moment_unit", dim::kMomentPerWidth);
  const double curvature_unit = UnitFactorAt(c, "curvature_unit", dim::kCurvature);
  if (model == 1) return ReadPolynomialBending(c, moment_unit, curvature_unit);

  c.ExpectObject({"model", "points", "file", "moment_unit", "curvature_unit", "branch", "columns"});
  CurveBending law;
  if (c.OneOf({"points", "file"}) == 0)
    ReadCurvePoints(c, moment_unit, curvature_unit, law);
  else
    ReadKawabataPoints(c, law);
  return law;
}

// ---- selections and what uses them -------------------------------------------

Selection SceneParser::ReadSelection(const JsonCursor& c) {
  c.ExpectObject({"point", "line", "box", "corners", "edge", "nodes", "tolerance"});
  Selection s;
  switch (c.OneOf({"point", "line", "box", "corners", "edge", "nodes"})) {
    case 0:
      s.shape = PointSelection{c["point"].QuantityVec2(dim::kLength)};
      break;
    case 1: {
      auto ends = c["line"].Items(2);
      LineSelection line{ends[0].QuantityVec2(dim::kLength), ends[1].QuantityVec2(dim::kLength)};
      if (line.from == line.to) c["line"].Fail("the two ends of a line must differ");
      s.shape = line;
      break;
    }
    case 2: {
      auto corners = c["box"].Items(2);
      BoxSelection box{corners[0].QuantityVec2(dim::kLength),
                       corners[1].QuantityVec2(dim::kLength)};
      if (box.min[0] > box.max[0] || box.min[1] > box.max[1])
        c["box"].Fail("expected [[xmin, ymin], [xmax, ymax]] with min <= max");
      s.shape = box;
      break;
    }
    case 3:
      if (!c["corners"].Boolean()) c["corners"].Fail("write \"corners\": true to select corners");
      s.shape = CornersSelection{};
      break;
    case 4: {
      int side = c["edge"].Choice({"left", "right", "bottom", "top", "boundary"});
      s.shape = EdgeSelection{static_cast<Side>(side)};
      break;
    }
    default: {
      auto nodes = c["nodes"];
      NodesSelection n;
      for (const auto& item : nodes.Items()) {
        int index = item.Integer();
        if (index < 0) item.Fail("node indices start at 0");
        n.nodes.push_back(index);
      }
      if (n.nodes.empty()) nodes.Fail("an empty node list selects nothing");
      s.shape = n;
    }
  }
  if (auto t = c.Find("tolerance")) s.tolerance = t->PositiveQuantity(dim::kLength);
  return s;
}

Support SceneParser::ReadSupport(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "fix"});
  Support s;
  s.name = ReadName(c, "support or gripper");
  s.select = ReadSelection(c["select"]);
  if (auto f = c.Find("fix")) s.fix = static_cast<Fixity>(f->Choice({"position", "clamp"}));
  return s;
}

Gripper SceneParser::ReadGripper(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "hold"});
  Gripper g;
  g.name = ReadName(c, "support or gripper");
  g.select = ReadSelection(c["select"]);
  if (auto h = c.Find("hold")) g.hold = static_cast<Fixity>(h->Choice({"position", "clamp"}));
  return g;
}

PointLoad SceneParser::ReadLoad(const JsonCursor& c) {
  c.ExpectObject({"name", "select", "force", "moment"});
  PointLoad load;
  load.name = ReadName(c, "load");
  load.select = ReadSelection(c["select"]);
  if (!c.Has("force") && !c.Has("moment")) c.Fail("a load needs a 'force', a 'moment' or both");
  if (auto f = c.Find("force")) load.force = f->QuantityVec3(dim::kForce);
  if (auto m = c.Find("moment")) load.moment = m->QuantityVec3(dim::kMoment);
  return load;
}

// ---- obstacles ----------------------------------------------------------------

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
        if (!(box.max[k] > box.min[k]))
          b["max"].Fail(
              "each coordinate of 'max' must exceed that of 'min' (a box of zero or "
              "negative size)");
        smallest = std::min(smallest, box.max[k] - box.min[k]);
      }
      if (auto r = b.Find("edge_radius")) {
        box.edge_radius = r->NonNegativeQuantity(dim::kLength);
        if (box.edge_radius >= 0.5 * smallest)
          r->Fail("must be smaller than half the box's smallest side");
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
      m.ExpectObject({"file"});
      MeshShape mesh{ReadFileReference(m["file"]), {}};
      const fs::path file(mesh.file);
      mesh.resolved_path =
          (file.is_absolute() ? file : fs::absolute(base_ / file)).lexically_normal().string();
      o.shape = mesh;
    }
  }
  return o;
}

Contact SceneParser::ReadContact(const JsonCursor& c) {
  c.ExpectObject({"penalty", "friction", "self", "thickness"});
  Contact contact;
  if (auto p = c.Find("penalty")) {
    if (p->value().is_string() && p->value().get<std::string>() == "auto")
      contact.penalty = std::nullopt;
    else
      contact.penalty = p->PositiveQuantity(dim::kPenaltyPerArea);
  }
  if (auto f = c.Find("friction")) {
    contact.friction = f->Number();
    if (contact.friction < 0) f->Fail("a friction coefficient must not be negative");
  }
  if (auto s = c.Find("self")) contact.self = s->Boolean();
  if (auto t = c.Find("thickness")) contact.thickness = t->PositiveQuantity(dim::kLength);
  return contact;
}

// ---- stages -------------------------------------------------------------------

Path SceneParser::ReadPath(const JsonCursor& c) {
  c.ExpectObject({"line", "arc", "keyframes"});
  switch (c.OneOf({"line", "arc", "keyframes"})) {
    case 0: {
      auto l = c["line"];
      l.ExpectObject({"by"});
      return LinePath{l["by"].QuantityVec3(dim::kLength)};
    }
    case 1: {
      auto a = c["arc"];
      a.ExpectObject({"center", "axis", "angle_deg"});
      ArcPath arc{a["center"].QuantityVec3(dim::kLength), a["axis"].Direction(), 0};
      auto angle = a["angle_deg"];
      arc.angle_deg = ReadAngleDeg(angle);
      if (arc.angle_deg == 0) angle.Fail("an arc of zero angle does not move");
      return arc;
    }
    default: {
      auto k = c["keyframes"];
      k.ExpectObject({"points", "interpolation"});
      KeyframesPath path;
      auto points = k["points"];
      for (const auto& p : points.Items()) path.points.push_back(p.QuantityVec3(dim::kLength));
      if (path.points.empty()) points.Fail("needs at least one point");
      if (auto i = k.Find("interpolation"))
        path.interpolation = static_cast<Interpolation>(i->Choice({"linear", "smooth"}));
      return path;
    }
  }
}

Stage SceneParser::ReadStage(const JsonCursor& c) {
  c.ExpectObject({"name", "kind", "initial_increment", "control", "release", "moves"});
  Stage s;
  s.name = ReadName(c, "stage");
  s.kind = static_cast<StageKind>(c["kind"].Choice({"gravity", "load", "move", "hold"}));
  if (auto i = c.Find("initial_increment")) {
    s.initial_increment = i->Number();
    if (!(s.initial_increment > 0 && s.initial_increment <= 1))
      i->Fail("must lie in (0, 1], got " + std::to_string(s.initial_increment));
  }
  if (auto ctl = c.Find("control"))
    s.control = static_cast<StepControl>(ctl->Choice({"arc_length", "load"}));
  if (auto r = c.Find("release"))
    for (const auto& item : r->Items()) s.release.push_back(item.String());
  if (auto m = c.Find("moves")) {
    if (s.kind != StageKind::kMove) m->Fail("only a stage of kind 'move' has moves");
    for (const auto& item : m->Items()) {
      item.ExpectObject({"gripper", "obstacle", "path"});
      Move move;
      if (item.OneOf({"gripper", "obstacle"}) == 0)
        move.gripper = item["gripper"].String();
      else
        move.obstacle = item["obstacle"].String();
      move.path = ReadPath(item["path"]);
      s.moves.push_back(std::move(move));
    }
  }
  if (s.kind == StageKind::kMove && s.moves.empty())
    c.Fail("a 'move' stage needs at least one entry in 'moves'");
  return s;
}

// Stages refer to grippers and loads by name; check those references in order.
void SceneParser::CheckStages(const JsonCursor& root, const Scene& scene) {
  std::map<std::string, std::string> released;  // gripper → stage that released it
  auto stages = root["stages"].Items();
  auto gripper_exists = [&](const std::string& name) {
    for (const auto& g : scene.grippers)
      if (g.name == name) return true;
    return false;
  };
  for (size_t i = 0; i < scene.stages.size(); ++i) {
    const Stage& stage = scene.stages[i];
    const JsonCursor& c = stages[i];
    if (stage.kind == StageKind::kGravity && !(scene.material.areal_weight > 0))
      c["kind"].Fail("a gravity stage needs a positive material.areal_weight");
    if (stage.kind == StageKind::kLoad && scene.loads.empty())
      c["kind"].Fail("a load stage needs at least one entry in 'loads'");
    auto releases = stage.release.empty() ? std::vector<JsonCursor>{} : c["release"].Items();
    for (size_t r = 0; r < stage.release.size(); ++r) {
      const std::string& name = stage.release[r];
      if (!gripper_exists(name)) releases[r].Fail("no gripper is named '" + name + "'");
      if (released.count(name))
        releases[r].Fail("gripper '" + name + "' was already released in " + released[name]);
      released[name] = "stage '" + stage.name + "'";
    }
    if (stage.moves.empty()) continue;
    auto moves = c["moves"].Items();
    std::set<std::string> moved;
    std::set<std::string> moved_obstacles;
    for (size_t m = 0; m < stage.moves.size(); ++m) {
      if (!stage.moves[m].obstacle.empty()) {
        const std::string& name = stage.moves[m].obstacle;
        auto obstacle = moves[m]["obstacle"];
        if (std::none_of(scene.obstacles.begin(), scene.obstacles.end(), [&](const Obstacle& o) {
              return o.name == name;
            }))
          obstacle.Fail("no obstacle is named '" + name + "'");
        if (!moved_obstacles.insert(name).second)
          obstacle.Fail("obstacle '" + name + "' is moved twice in one stage");
        continue;
      }
      const std::string& name = stage.moves[m].gripper;
      auto gripper = moves[m]["gripper"];
      if (!gripper_exists(name)) gripper.Fail("no gripper is named '" + name + "'");
      if (released.count(name))
        gripper.Fail("gripper '" + name + "' was released in " + released[name]);
      if (!moved.insert(name).second)
        gripper.Fail("gripper '" + name + "' is moved twice in one stage");
    }
  }
}

SolverSettings SceneParser::ReadSolver(const JsonCursor& c) {
  c.ExpectObject({"preset",
                  "mesh_scale",
                  "tolerance",
                  "displacement_tolerance",
                  "target_iterations",
                  "acceleration",
                  "max_steps",
                  "max_iterations",
                  "max_step_cuts",
                  "psi",
                  "branching",
                  "sequencing",
                  "max_wall_s",
                  "error_estimate"});
  SolverSettings s;
  // The preset first: the keys beside it override its values.
  if (auto p = c.Find("preset")) {
    const std::string name = p->String();
    std::optional<SolverPreset> preset = PresetNamed(name);
    if (!preset) {
      std::string names;
      for (const auto& d : PresetDefinitions())
        names += std::string(names.empty() ? "" : ", ") + d.name;
      p->Fail("'" + name + "' is not a preset; one of " + names);
    }
    s = WithPreset(s, *preset);
  }
  if (auto m = c.Find("mesh_scale")) {
    s.mesh_scale = m->Number();
    if (!(s.mesh_scale >= 0.1 && s.mesh_scale <= 10))
      m->Fail("must lie in [0.1, 10], got " + std::to_string(s.mesh_scale));
  }
  auto fraction = [&](const char* key, double& out) {
    if (auto v = c.Find(key)) {
      out = v->Number();
      if (!(out > 0 && out < 1)) v->Fail("must lie in (0, 1), got " + std::to_string(out));
    }
  };
  auto count = [&](const char* key, int& out, int minimum) {
    if (auto v = c.Find(key)) {
      out = v->Integer();
      if (out < minimum)
        v->Fail("must be at least " + std::to_string(minimum) + ", got " + std::to_string(out));
    }
  };
  fraction("tolerance", s.tolerance);
  fraction("displacement_tolerance", s.displacement_tolerance);
  count("target_iterations", s.target_iterations, 1);
  count("max_steps", s.max_steps, 1);
  count("max_iterations", s.max_iterations, 1);
  count("max_step_cuts", s.max_step_cuts, 0);
  count("sequencing", s.sequencing, 1);
  if (auto a = c.Find("acceleration")) s.acceleration = a->Boolean();
  if (auto e = c.Find("error_estimate")) s.error_estimate = e->Boolean();
  if (auto p = c.Find("psi")) s.psi = p->PositiveQuantity(dim::kLength);
  if (auto w = c.Find("max_wall_s")) {
    s.max_wall_s = w->Number();
    if (!(*s.max_wall_s > 0) || !std::isfinite(*s.max_wall_s))
      w->Fail("must be a number of seconds > 0, got " + std::to_string(*s.max_wall_s));
  }
  if (auto b = c.Find("branching"))
    s.branching = static_cast<Branching>(b->Choice({"stable", "fundamental"}));
  return s;
}

Probe SceneParser::ReadProbe(const JsonCursor& c) {
  c.ExpectObject({"name", "at"});
  Probe p;
  p.name = ReadName(c, "probe");
  p.at = c["at"].QuantityVec2(dim::kLength);
  return p;
}

namespace {

// Tracks the path of the value being parsed so a repeated key can be named:
// nlohmann/json would silently keep the last of two equal keys.
class DuplicateKeyCheck {
 public:
  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        CountArrayElement();
        frames_.push_back({event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        break;
      case json::parse_event_t::key: {
        Frame& top = frames_.back();
        std::string key = parsed.get<std::string>();
        if (!top.keys.insert(key).second) {
          std::string where = Path();
          throw SceneError(where.empty() ? key : where + "." + key,
                           "key appears twice in the same object");
        }
        top.key = key;
        break;
      }
      case json::parse_event_t::value:
        CountArrayElement();
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool array;
    int next_index;
    std::string key;
    std::set<std::string> keys;
  };
  void CountArrayElement() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next_index;
  }
  std::string Path() const {
    std::string p;
    for (size_t i = 0; i + 1 < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.array) {
        // Appended: GCC 12 -O3 warns falsely (-Wrestrict) on "[" + std::to_string(…).
        p += '[';
        p += std::to_string(f.next_index - 1);
        p += ']';
      } else {
        p += (p.empty() ? "" : ".") + f.key;
      }
    }
    return p;
  }
  std::vector<Frame> frames_;
};

// "line 3, column 5" for a byte offset (1-based, as nlohmann reports it).
std::string LineColumn(std::string_view text, size_t byte) {
  size_t line = 1, column = 0;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 0;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(std::max<size_t>(column, 1));
}

}  // namespace

Scene SceneFromJson(const json& document, const fs::path& base_directory) {
  SceneParser parser(base_directory);
  return parser.Read(JsonCursor(document, ""));
}

Scene ParseScene(std::string_view text, const fs::path& base_directory) {
  json document;
  try {
    document = json::parse(text.begin(), text.end(), DuplicateKeyCheck());
  } catch (const json::parse_error& e) {
    // nlohmann's text is "[json.exception.parse_error.101] parse error at line L, column C:
    // <detail>"; keep the detail and give the position our way.
    std::string detail = e.what();
    if (auto colon = detail.find(": "); colon != std::string::npos)
      detail = detail.substr(colon + 2);
    throw SceneError(LineColumn(text, e.byte), "not valid JSON: " + detail);
  } catch (const json::exception& e) {
    // Found by fuzzing: a number too large for a double ("1e906") is an
    // out_of_range error, with no position.
    std::string detail = e.what();
    if (auto bracket = detail.find("] "); bracket != std::string::npos)
      detail = detail.substr(bracket + 2);
    throw SceneError("", "not valid JSON: " + detail);
  }
  return SceneFromJson(document, base_directory);
}

Scene ReadScene(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || fs::is_directory(file, ec))
    throw SceneError("", "cannot open scene file '" + file.string() + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return ParseScene(buffer.str(), file.parent_path().empty() ? fs::path(".") : file.parent_path());
}

}  // namespace drape
