// Reading a scene's material: its own or a library's with the scene's keys
// over it, and the bending laws (linear, polynomial, or a curve given point by
// point or measured in a Kawabata file).
#include "core/io/scene_parser.h"

#include <cmath>
#include <map>

#include "core/io/kawabata_reader.h"
#include "core/io/material_library.h"
#include "core/model/scene_error.h"
#include "core/model/string_format.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

constexpr double kStandardGravity = 9.80665;  // m/s², for areal_density

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
      nu.Fail(
          Format("must lie in [0, %.4g) for a stable orthotropic law with these E1 and E2 "
                 "(the bound is √(E1/E2)), found %s",
                 std::sqrt(o.e1 / o.e2),
                 nu.value().dump().c_str()));
    m.membrane = o;
  } else {
    IsotropicMembrane iso;
    iso.youngs_modulus = c["youngs_modulus"].PositiveQuantity(dim::kPressure);
    auto nu = c["poisson_ratio"];
    iso.poisson_ratio = nu.Number();
    if (iso.poisson_ratio < 0 || iso.poisson_ratio >= 0.5)
      nu.Fail(
          "must lie in [0, 0.5) (an isotropic sheet with ν = 0.5 cannot change its area), "
          "found " +
          nu.value().dump());
    m.membrane = iso;
  }
  m.bending.warp = LinearBending{};
  if (auto b = c.Find("bending")) m.bending = ReadBending(*b);
  if (auto a = c.Find("angle_deg")) {
    if (a->value().is_string() && a->String() == "grain") {
      m.angle_deg = GrainAngle(*a);
      m.angle_from_grain = true;
    } else if (IsWord(a->value()) || !(a->value().is_string() || a->value().is_number())) {
      a->Fail(
          "expected \"grain\" or an angle (a number of degrees, or a \"number unit\" string "
          "such as \"0.5 rad\"), found " +
          AsTyped(a->value()));
    } else {
      m.angle_deg = ReadAngleDeg(*a);
    }
  }
  return m;
}

// One material has one warp: with several parts, each is a pattern piece
// and their grain lines agree.
double SceneParser::GrainAngle(const JsonCursor& c) const {
  std::optional<double> angle;
  std::string first;
  for (const Fabric* part : parts_) {
    const auto* pattern = std::get_if<PatternOutline>(&part->outline);
    if (!pattern)
      c.Fail("\"grain\" takes the warp from a pattern piece's grain line; " +
             (parts_.size() > 1 ? "part '" + part->name + "'" : std::string("this fabric")) +
             "'s outline is not a pattern piece");
    if (!pattern->shape.grain)
      c.Fail("piece '" + pattern->piece + "' of " + pattern->file + " has no grain line (layer 7)");
    const double a = GrainAngleDeg(pattern->shape);
    if (angle && std::abs(std::remainder(a - *angle, 360.0)) > 1e-9)
      c.Fail(
          Format("the parts' grain lines differ ('%s' %g deg, '%s' %g deg) and the parts "
                 "share one material: give angle_deg",
                 first.c_str(),
                 *angle,
                 part->name.c_str(),
                 a));
    if (!angle) first = part->name;
    angle = a;
  }
  return *angle;
}

Bending SceneParser::ReadBending(const JsonCursor& c) {
  Bending bending;
  if (c.Has("warp") || c.Has("weft")) {
    c.ExpectObject({"warp", "weft"});
    bending.warp = ReadBendingLaw(c["warp"], bending.warp_hysteresis);
    bending.weft = ReadBendingLaw(c["weft"], bending.weft_hysteresis);
    return bending;
  }
  bending.warp = ReadBendingLaw(c, bending.warp_hysteresis);
  return bending;
}

namespace {

// The SI factor of the unit named at `key` (SI when absent), which must be
// of dimension `d`; `expected` says what such a unit is, for the message.
double UnitFactorAt(const JsonCursor& c, const char* key, Dimension d, const char* expected) {
  auto u = c.Find(key);
  if (!u) return 1.0;  // SI
  try {
    Unit unit = ParseUnit(u->String());
    if (!(unit.dimension == d))
      u->Fail(std::string("expected ") + expected + ", found " + u->value().dump());
    return unit.si_factor;
  } catch (const UnitError& e) {
    u->Fail(e.what());
  }
}

PolynomialBending ReadPolynomialBending(const JsonCursor& c,
                                        double moment_unit,
                                        double curvature_unit) {
  c.ExpectObject(
      {"model", "coefficients", "moment_unit", "curvature_unit", "valid_to", "hysteresis"});
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
    coefficients.Fail(
        "the linear coefficient c1 (the initial bending rigidity) must be positive, found " +
        coefficients.Items()[0].value().dump());
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
    if (!(law.points[i][0] > law.points[i - 1][0])) {
      const auto items = points.Items();
      items[i].Fail("curvatures must increase from point to point, found " +
                    items[i].value()[0].dump() + " after " + items[i - 1].value()[0].dump());
    }
}

}  // namespace

std::optional<double> SceneParser::ReadKawabataPoints(const JsonCursor& c, CurveBending& law) {
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
  // (docs/format.md); a bad file is a scene error at this key, with its own
  // line number.
  const fs::path file(law.file);
  try {
    const KawabataCurve curve = ReadKawabata(file.is_absolute() ? file : base_ / file, options);
    for (size_t i = 0; i < curve.curvature.size(); ++i)
      law.points.push_back({curve.curvature[i], curve.moment[i]});
    return curve.hysteresis_width;
  } catch (const KawabataError& e) {
    c["file"].Fail(e.what());
  }
}

BendingLaw SceneParser::ReadBendingLaw(const JsonCursor& c, Hysteresis& hysteresis) {
  if (!c.value().is_object())
    c.Fail("expected an object with a 'model', found " + FoundValue(c.value()));
  int model = c["model"].Choice({"linear", "polynomial", "curve"});
  if (model == 0) {
    c.ExpectObject({"model", "rigidity", "hysteresis"});
    LinearBending law;
    if (auto r = c.Find("rigidity")) law.rigidity = r->PositiveQuantity(dim::kBendingRigidity);
    hysteresis = ReadHysteresis(c, 1.0, std::nullopt);
    return law;
  }
  const double moment_unit = UnitFactorAt(c,
                                          "moment_unit",
                                          dim::kMomentPerWidth,
                                          "a unit of moment per width, such as gf*cm/cm or N*m/m");
  const double curvature_unit = UnitFactorAt(
      c, "curvature_unit", dim::kCurvature, "a unit of curvature, such as 1/cm or 1/m");
  if (model == 1) {
    PolynomialBending law = ReadPolynomialBending(c, moment_unit, curvature_unit);
    hysteresis = ReadHysteresis(c, moment_unit, std::nullopt);
    return law;
  }

  c.ExpectObject({"model",
                  "points",
                  "file",
                  "moment_unit",
                  "curvature_unit",
                  "branch",
                  "columns",
                  "hysteresis"});
  CurveBending law;
  std::optional<double> loop_width;
  if (c.OneOf({"points", "file"}) == 0)
    ReadCurvePoints(c, moment_unit, curvature_unit, law);
  else
    loop_width = ReadKawabataPoints(c, law);
  hysteresis = ReadHysteresis(c, moment_unit, loop_width);
  return law;
}

Hysteresis SceneParser::ReadHysteresis(const JsonCursor& law,
                                       double moment_unit,
                                       std::optional<double> loop_width) {
  auto h = law.Find("hysteresis");
  if (!h) return {};
  Hysteresis hysteresis;
  if (h->value().is_string() && h->String() == "measured") {
    if (!law.Has("file"))
      h->Fail("\"measured\" takes 2HB from a Kawabata file's loop; this law has no 'file'");
    if (!loop_width)
      h->Fail(
          "the Kawabata file has no loop to measure 2HB on: its loading and unloading "
          "branches do not both reach |K| = 1 1/cm");
    return {*loop_width, true};
  }
  if (IsWord(h->value()) || !(h->value().is_string() || h->value().is_number()))
    h->Fail(
        "expected \"measured\" or 2HB, a moment per width (a number in the law's moment_unit, "
        "or a \"number unit\" string such as \"0.1 gf*cm/cm\"), found " +
        AsTyped(h->value()));
  // 2HB, the loop's width; a bare number is in the law's moment_unit.
  hysteresis.width =
      h->value().is_number() ? h->Number() * moment_unit : h->Quantity(dim::kMomentPerWidth);
  if (!(hysteresis.width >= 0))
    h->Fail("2HB, the width of the moment-curvature loop, must not be negative, found " +
            AsTyped(h->value()));
  return hysteresis;
}

}  // namespace drape
