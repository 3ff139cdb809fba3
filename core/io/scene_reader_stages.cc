// Reading a scene's stages and the paths its moves follow, then checking
// what the stages name (grippers, obstacles, loads) in the order they run.
#include "core/io/scene_parser.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace drape {
namespace {

// "the grippers are 'a', 'b'", "the only gripper is 'a'", "this scene has no
// grippers": the names a reference may take, for a message.
std::string NamesThereAre(const std::vector<std::string>& names, const std::string& kind) {
  if (names.empty()) return "this scene has no " + kind + "s";
  if (names.size() == 1) return "the only " + kind + " is '" + names[0] + "'";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
  return "the " + kind + "s are " + list;
}

}  // namespace

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
      i->Fail("must lie in (0, 1], found " + i->value().dump());
  }
  if (auto ctl = c.Find("control"))
    s.control = static_cast<StepControl>(ctl->Choice({"arc_length", "load"}));
  if (auto r = c.Find("release"))
    for (const auto& item : r->Items()) s.release.push_back(item.String());
  if (auto m = c.Find("moves")) {
    if (s.kind != StageKind::kMove)
      m->Fail("only a stage of kind 'move' has moves; this stage is of kind '" +
              c["kind"].String() + "'");
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
  std::vector<std::string> gripper_names;
  for (const auto& g : scene.grippers) gripper_names.push_back(g.name);
  std::vector<std::string> obstacle_names;
  for (const auto& o : scene.obstacles) obstacle_names.push_back(o.name);
  for (size_t i = 0; i < scene.stages.size(); ++i) {
    const Stage& stage = scene.stages[i];
    const JsonCursor& c = stages[i];
    if (stage.kind == StageKind::kGravity && !(scene.material.areal_weight > 0)) {
      // The weight as typed: the scene's own key, or the library material's.
      const JsonCursor material = root["material"];
      std::string found;
      for (const char* key : {"areal_weight", "areal_density"})
        if (material.Has(key))
          found = std::string("material.") + key + " is " + AsTyped(material[key].value());
      if (found.empty() && material.Has("library"))
        found = "library material " + Quoted(material["library"].String()) + " weighs nothing";
      c["kind"].Fail("a gravity stage needs a positive material.areal_weight" +
                     (found.empty() ? std::string() : "; " + found));
    }
    if (stage.kind == StageKind::kLoad && scene.loads.empty())
      c["kind"].Fail("a load stage needs at least one entry in 'loads'");
    auto releases = stage.release.empty() ? std::vector<JsonCursor>{} : c["release"].Items();
    for (size_t r = 0; r < stage.release.size(); ++r) {
      const std::string& name = stage.release[r];
      if (!gripper_exists(name))
        releases[r].Fail("no gripper is named '" + name + "'; " +
                         NamesThereAre(gripper_names, "gripper"));
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
          obstacle.Fail("no obstacle is named '" + name + "'; " +
                        NamesThereAre(obstacle_names, "obstacle"));
        if (!moved_obstacles.insert(name).second)
          obstacle.Fail("obstacle '" + name + "' is moved twice in one stage");
        continue;
      }
      const std::string& name = stage.moves[m].gripper;
      auto gripper = moves[m]["gripper"];
      if (!gripper_exists(name))
        gripper.Fail("no gripper is named '" + name + "'; " +
                     NamesThereAre(gripper_names, "gripper"));
      if (released.count(name))
        gripper.Fail("gripper '" + name + "' was released in " + released[name]);
      if (!moved.insert(name).second)
        gripper.Fail("gripper '" + name + "' is moved twice in one stage");
    }
  }
}

}  // namespace drape
