#include "core/plan/plan_file.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/io/json_cursor.h"
#include "core/io/scene_key.h"
#include "core/io/scene_reader.h"
#include "core/io/selection_reader.h"
#include "core/io/text_file.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

constexpr int kPlanFormatVersion = 1;
// More parameters than a derivative-free search can handle in a few hundred
// runs: BOBYQA alone needs 2n + 1 runs to build its first model.
constexpr size_t kMaxParameters = 20;

// "2 cm" → "cm"; a bare number has no unit.
std::string UnitOf(const json& value) {
  if (!value.is_string()) return "";
  const std::string text = value.get<std::string>();
  size_t at = 0;
  while (at < text.size() &&
         std::string_view("0123456789+-.eE ").find(text[at]) != std::string::npos) {
    // An exponent's e is part of the number only before a digit or sign.
    if ((text[at] == 'e' || text[at] == 'E') &&
        (at + 1 >= text.size() ||
         std::string_view("0123456789+-").find(text[at + 1]) == std::string::npos))
      break;
    ++at;
  }
  return text.substr(at);
}

// A bound, the start or the scene's value: a number or a quantity string.
Quantity QuantityAt(const JsonCursor& c) {
  if (c.value().is_number()) return {c.Number(), dim::kNone};
  if (!c.value().is_string()) c.Fail("expected a number or a quantity such as \"2 cm\"");
  try {
    return ParseQuantity(c.value().get<std::string>());
  } catch (const UnitError& e) {
    c.Fail(e.what());
  }
}

// The value as the scene reader is given it: a plain number, or the
// quantity in the unit the plan's bounds were written in.
json SceneValue(const PlanParameter& p, double value) {
  if (p.dimension == dim::kNone) return value;
  const double factor = ParseUnit(p.unit.empty() ? "m" : p.unit).si_factor;
  char text[64];
  std::snprintf(text, sizeof text, "%.17g %s", value / factor, p.unit.c_str());
  return text;
}

// The value as a person reads it: six digits, in the plan's unit.
std::string Shown(const PlanParameter& p, double value) {
  char text[64];
  if (p.unit.empty())
    std::snprintf(text, sizeof text, "%.6g", value);
  else
    std::snprintf(
        text, sizeof text, "%.6g %s", value / ParseUnit(p.unit).si_factor, p.unit.c_str());
  return text;
}

PlanParameter ReadParameter(const JsonCursor& c, const ordered_json& scene) {
  c.ExpectObject({"key", "min", "max", "start"});
  PlanParameter p;
  p.key = c["key"].String();
  const JsonCursor min = c["min"], max = c["max"];
  Quantity lo = QuantityAt(min), hi = QuantityAt(max);
  // A bare number is SI (docs/format.md §2.6): it has the other bound's dimension.
  if (min.value().is_number()) lo.dimension = hi.dimension;
  if (max.value().is_number()) hi.dimension = lo.dimension;
  if (!(lo.dimension == hi.dimension))
    max.Fail("has dimension " + DimensionName(hi.dimension) + ", but min has " +
             DimensionName(lo.dimension));
  if (!(lo.value_si < hi.value_si)) max.Fail("must be greater than min");
  p.min = lo.value_si;
  p.max = hi.value_si;
  p.dimension = lo.dimension;
  p.unit = UnitOf(min.value());
  if (p.unit.empty()) p.unit = UnitOf(max.value());
  if (p.dimension != dim::kNone && p.unit.empty())
    p.unit = p.dimension == dim::kLength ? "m" : p.dimension == dim::kAngle ? "rad" : "";
  Quantity start;
  if (auto s = c.Find("start")) {
    start = QuantityAt(*s);
    if (!(start.dimension == p.dimension))
      s->Fail("has dimension " + DimensionName(start.dimension) + ", but min and max have " +
              DimensionName(p.dimension));
  } else {
    const ordered_json value = SceneKeyValue(scene, p.key, c["key"].path());
    if (value.is_null())
      c["key"].Fail("the scene has no value at '" + p.key + "'; give the parameter a \"start\"");
    const json plain = json::parse(value.dump());
    start = QuantityAt(JsonCursor(plain, c["key"].path()));
    // A bare number in the scene is SI (docs/format.md §2.6).
    if (start.dimension == dim::kNone) start.dimension = p.dimension;
    if (!(start.dimension == p.dimension))
      c["key"].Fail("the scene's value " + value.dump() + " has dimension " +
                    DimensionName(start.dimension) + ", but min and max have " +
                    DimensionName(p.dimension));
  }
  p.start = start.value_si;
  if (p.start < p.min || p.start > p.max)
    c.Fail("the start " + Shown(p, p.start) + " lies outside [" + Shown(p, p.min) + ", " +
           Shown(p, p.max) + "]");
  return p;
}

ProbeTarget ReadProbeTarget(const JsonCursor& c, const Scene& scene) {
  c.ExpectObject({"probe", "target", "weight"});
  ProbeTarget t;
  t.probe = c["probe"].String();
  bool known = false;
  std::string names;
  for (const Probe& p : scene.probes) {
    known = known || p.name == t.probe;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  if (!known)
    c["probe"].Fail("the scene has no probe '" + t.probe + "'" +
                    (names.empty() ? " (it has none)" : " (it has " + names + ")"));
  t.target = c["target"].QuantityVec3(dim::kLength);
  if (auto w = c.Find("weight")) t.weight = w->Number();
  if (t.weight <= 0) c["weight"].Fail("must be greater than zero");
  return t;
}

void CheckObstacleName(const JsonCursor& c, const Scene& scene) {
  const std::string name = c.String();
  std::string names;
  for (const Obstacle& o : scene.obstacles) {
    if (o.name == name) return;
    names += (names.empty() ? "" : ", ") + o.name;
  }
  c.Fail("the scene has no obstacle '" + name + "'" +
         (names.empty() ? " (it has none)" : " (it has " + names + ")"));
}

FlatTerm ReadFlat(const JsonCursor& c, const Scene& scene) {
  c.ExpectObject({"select", "side", "on", "layer", "share", "weight"});
  FlatTerm f;
  if (c.OneOf({"select", "side"}) == 0) {
    f.select = ReadSelection(c["select"].value(), c["select"].path(), scene);
  } else {
    const JsonCursor side = c["side"];
    side.ExpectObject({"line", "toward"});
    const auto ends = side["line"].Items(2);
    SideOfLine s{ends[0].QuantityVec2(dim::kLength),
                 ends[1].QuantityVec2(dim::kLength),
                 side["toward"].QuantityVec2(dim::kLength)};
    if (s.from == s.to) side["line"].Fail("the line's two points must differ");
    const double cross = (s.to[0] - s.from[0]) * (s.toward[1] - s.from[1]) -
                         (s.to[1] - s.from[1]) * (s.toward[0] - s.from[0]);
    if (cross == 0) side["toward"].Fail("lies on the line: it must name a side of it");
    f.side = s;
  }
  CheckObstacleName(c["on"], scene);
  f.on = c["on"].String();
  if (auto l = c.Find("layer")) {
    f.layer = l->Integer();
    if (f.layer < 1) l->Fail("expected a layer number ≥ 1 (1: on the obstacle)");
  }
  if (auto s = c.Find("share")) {
    f.share = s->Number();
    if (f.share <= 0 || f.share > 1) s->Fail("expected a share in (0, 1]");
  }
  if (auto w = c.Find("weight")) {
    f.weight = w->Number();
    if (f.weight <= 0) w->Fail("must be greater than zero");
  }
  return f;
}

PlanObjective ReadObjective(const JsonCursor& c, const Scene& scene) {
  c.ExpectObject({"probes", "flat", "path_length"});
  PlanObjective o;
  if (auto probes = c.Find("probes"))
    for (const JsonCursor& p : probes->Items()) o.probes.push_back(ReadProbeTarget(p, scene));
  if (auto flat = c.Find("flat")) o.flat = ReadFlat(*flat, scene);
  if (auto length = c.Find("path_length")) {
    o.path_length_weight = length->Number();
    if (o.path_length_weight < 0) length->Fail("must not be negative");
  }
  if (o.probes.empty() && !o.flat && o.path_length_weight == 0)
    c.Fail("nothing to optimise: give probes with targets, a flat region or a path_length weight");
  return o;
}

PlanConstraints ReadConstraints(const JsonCursor& c, const Scene& scene) {
  c.ExpectObject({"stable", "layers", "grippers_outside", "max_gripper_force", "no_slip"});
  PlanConstraints k;
  if (auto s = c.Find("stable")) k.stable = s->Boolean();
  if (auto s = c.Find("layers")) k.layers = s->Boolean();
  if (auto s = c.Find("grippers_outside")) k.grippers_outside = s->Boolean();
  if (auto f = c.Find("max_gripper_force")) k.max_gripper_force = f->PositiveQuantity(dim::kForce);
  if (auto s = c.Find("no_slip")) {
    CheckObstacleName(*s, scene);
    k.no_slip = s->String();
    if (!scene.contact || scene.contact->friction <= 0)
      s->Fail(
          "the scene's contact has no friction (contact.friction = 0): nothing holds the "
          "fabric, so it cannot be told not to slip");
  }
  return k;
}

PlanSearch ReadSearch(const JsonCursor& c, size_t parameters) {
  c.ExpectObject({"algorithm", "max_evaluations", "tolerance"});
  PlanSearch s;
  if (auto a = c.Find("algorithm"))
    s.algorithm =
        a->Choice({"bobyqa", "cobyla"}) == 0 ? PlanAlgorithm::kBobyqa : PlanAlgorithm::kCobyla;
  if (auto m = c.Find("max_evaluations")) {
    s.max_evaluations = m->Integer();
    // BOBYQA's first model interpolates 2n + 1 points.
    const int least = static_cast<int>(2 * parameters + 2);
    if (s.max_evaluations < least)
      m->Fail("expected at least " + std::to_string(least) + " (2 × " + std::to_string(parameters) +
              " parameters + 2: the search's first model)");
  }
  if (auto t = c.Find("tolerance")) s.tolerance = t->PositiveQuantity(dim::kLength);
  return s;
}

void CheckSceneAt(const Plan& plan, const std::vector<double>& x, const std::string& what) {
  try {
    ParseScene(PlanSceneText(plan, x), plan.scene_file.parent_path());
  } catch (const SceneError& e) {
    throw SceneError("", what + " (" + DescribePoint(plan, x) + "): " + e.what());
  }
}

}  // namespace

std::vector<double> StartOf(const Plan& plan) {
  std::vector<double> x;
  for (const PlanParameter& p : plan.parameters) x.push_back(p.start);
  return x;
}

std::string DescribePoint(const Plan& plan, const std::vector<double>& x) {
  std::string text;
  for (size_t i = 0; i < plan.parameters.size() && i < x.size(); ++i) {
    const std::string shown = Shown(plan.parameters[i], x[i]);
    text += (i ? ", " : "") + plan.parameters[i].key + " = " + shown;
  }
  return text;
}

std::string PlanSceneText(const Plan& plan, const std::vector<double>& x) {
  ordered_json scene = ordered_json::parse(plan.scene_text);
  for (size_t i = 0; i < plan.parameters.size(); ++i)
    SetSceneKey(scene, plan.parameters[i].key, SceneValue(plan.parameters[i], x.at(i)), "");
  MakeFilesAbsolute(scene, plan.scene_file.parent_path());
  return scene.dump(2);
}

Plan ReadPlan(const fs::path& file) {
  Plan plan;
  plan.file = fs::absolute(file).lexically_normal();
  json document;
  try {
    document = json::parse(ReadTextFile(plan.file, "plan file"));
  } catch (const json::parse_error& e) {
    throw SceneError("", "not valid JSON: " + std::string(e.what()));
  }
  const JsonCursor root(document, "");
  root.ExpectObject({"drape_plan",
                     "scene",
                     "parameters",
                     "objective",
                     "constraints",
                     "optimizer",
                     "time_limit_s",
                     "description"});
  if (root["drape_plan"].Integer() != kPlanFormatVersion)
    root["drape_plan"].Fail("this program reads plan format 1");
  const JsonCursor scene_key = root["scene"];
  plan.scene_file = (plan.file.parent_path() / scene_key.String()).lexically_normal();
  ordered_json scene;
  try {
    plan.scene_text = ReadTextFile(plan.scene_file, "scene file");
    scene = ordered_json::parse(plan.scene_text);
    plan.scene = ParseScene(plan.scene_text, plan.scene_file.parent_path());
  } catch (const SceneError& e) {
    scene_key.Fail(e.what());
  } catch (const json::parse_error& e) {
    scene_key.Fail(plan.scene_file.string() + " is not valid JSON: " + e.what());
  }
  const auto parameters = root["parameters"].Items();
  if (parameters.empty()) root["parameters"].Fail("expected at least one parameter");
  if (parameters.size() > kMaxParameters)
    root["parameters"].Fail("at most " + std::to_string(kMaxParameters) +
                            " parameters: a derivative-free search needs ever more runs");
  for (const JsonCursor& p : parameters) {
    plan.parameters.push_back(ReadParameter(p, scene));
    for (size_t i = 0; i + 1 < plan.parameters.size(); ++i)
      if (plan.parameters[i].key == plan.parameters.back().key)
        p["key"].Fail("'" + plan.parameters.back().key + "' is already parameter " +
                      std::to_string(i + 1));
  }
  plan.objective = ReadObjective(root["objective"], plan.scene);
  if (auto c = root.Find("constraints")) plan.constraints = ReadConstraints(*c, plan.scene);
  if (auto c = root.Find("optimizer")) plan.search = ReadSearch(*c, plan.parameters.size());
  if (auto limit = root.Find("time_limit_s")) {
    plan.time_limit_s = limit->Number();
    if (*plan.time_limit_s <= 0) limit->Fail("expected a number of seconds > 0");
  }
  // The scene must take the start and each bound of each key.
  CheckSceneAt(plan, StartOf(plan), "the start");
  for (size_t i = 0; i < plan.parameters.size(); ++i) {
    for (double bound : {plan.parameters[i].min, plan.parameters[i].max}) {
      std::vector<double> x = StartOf(plan);
      x[i] = bound;
      CheckSceneAt(plan, x, "parameters[" + std::to_string(i) + "] at its bound");
    }
  }
  return plan;
}

}  // namespace drape
