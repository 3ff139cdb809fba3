// Reading a scene: the entry points, the document's top level and what
// every part reads with (names, file references, angles). The parts have a
// file each (scene_reader_*.cc) sharing one SceneParser (scene_parser.h), so
// that Read can check, once all are read, what they say of each other.
#include "core/io/scene_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "core/io/scene_parser.h"
#include "core/model/scene_error.h"
#include "core/model/sequencing_check.h"
#include "core/model/solver_preset.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

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
  if (!c.value().is_string())
    c.Fail(
        "expected an angle (a number of degrees, or a \"number unit\" string such as "
        "\"0.5 rad\"), found " +
        FoundValue(c.value()));
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
  ReadFabricParts(root["fabric"], scene);
  parts_ = FabricParts(scene);
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
  parts_.clear();
  try {
    CheckSequencing(SceneOnSolvedMesh(scene), scene.solver.sequencing);
  } catch (const SceneError& e) {
    if (scene.solver.mesh_scale == 1) throw;
    // The scale as typed; from a preset, as the preset gives it.
    std::string scale;
    if (auto solver = root.Find("solver"); solver && solver->Has("mesh_scale")) {
      scale = AsTyped((*solver)["mesh_scale"].value());
    } else {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%g", scene.solver.mesh_scale);
      scale = buffer;
    }
    throw SceneError(
        e.where(),
        e.message() + " (the mesh solved: fabric.mesh at solver.mesh_scale " + scale + ")");
  }
  return scene;
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
