// The scene reader's parser, shared by the files that read one part of a
// scene each (scene_reader_*.cc): one object per document, so that names
// taken in one part are known in the others. Private to core/io.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "core/io/json_cursor.h"
#include "core/model/scene.h"

namespace drape {

// What the reader's messages show of a value (defined in json_cursor.cc):
// AsTyped, the value as the user wrote it ("5 cm" in its double quotes, 80.5,
// true, null; an array or object by its kind only); FoundValue, the same after
// "found" (a string "5 cm", the number 80.5, true, an array).
std::string AsTyped(const nlohmann::json& v);
std::string FoundValue(const nlohmann::json& v);
// A string that starts with a letter: a word (a keyword mistyped, "atuo"),
// not a quantity.
bool IsWord(const nlohmann::json& v);

// Reads one scene document. Each Read* function takes the cursor of its JSON
// value and returns plain data; cross-references are checked at the end.
class SceneParser {
 public:
  explicit SceneParser(std::filesystem::path base) : base_(std::move(base)) {}

  Scene Read(const JsonCursor& root);
  // A selection outside a scene document (a plan's region), with `scene`'s
  // parts for its `part`.
  Selection ReadSelectionFor(const JsonCursor& c, const Scene& scene);

 private:
  Fabric ReadFabric(const JsonCursor& c);
  // `fabric`: one part, or an array of named parts.
  void ReadFabricParts(const JsonCursor& c, Scene& scene);
  // The part a selection or probe names at `c` ("part"), checked.
  std::optional<std::string> ReadPartName(const JsonCursor& c) const;
  Outline ReadOutline(const JsonCursor& c);
  // A piece of a DXF-AAMA pattern file (relative to the scene's folder).
  PatternOutline ReadPatternOutline(const JsonCursor& c);
  MeshSpec ReadMeshSpec(const JsonCursor& c, const Outline& outline);
  ImperfectionSpec ReadImperfection(const JsonCursor& c);
  Material ReadMaterialOrLibrary(const JsonCursor& c);
  Material ReadMaterial(const JsonCursor& c);
  // material.angle_deg: "grain": the pattern piece's grain line [deg].
  double GrainAngle(const JsonCursor& c) const;
  Bending ReadBending(const JsonCursor& c);
  // The law and, from its "hysteresis" key, its 2HB.
  BendingLaw ReadBendingLaw(const JsonCursor& c, Hysteresis& hysteresis);
  // A bare number is in `moment_unit`'s units; "measured" takes
  // `loop_width`, the loop of the law's Kawabata file.
  Hysteresis ReadHysteresis(const JsonCursor& law,
                            double moment_unit,
                            std::optional<double> loop_width);
  // A curve's points from a Kawabata file (relative to the scene's folder).
  // Returns the file's loop width 2HB, when it has a loop.
  std::optional<double> ReadKawabataPoints(const JsonCursor& c, CurveBending& law);
  Selection ReadSelection(const JsonCursor& c);
  Support ReadSupport(const JsonCursor& c);
  Gripper ReadGripper(const JsonCursor& c);
  PointLoad ReadLoad(const JsonCursor& c);
  Obstacle ReadObstacle(const JsonCursor& c);
  Contact ReadContact(const JsonCursor& c);
  Stage ReadStage(const JsonCursor& c);
  Path ReadPath(const JsonCursor& c);
  SolverSettings ReadSolver(const JsonCursor& c);
  Probe ReadProbe(const JsonCursor& c);

  std::string ReadName(const JsonCursor& c, const std::string& group);
  std::string ReadFileReference(const JsonCursor& c);
  double ReadAngleDeg(const JsonCursor& c);
  void CheckStages(const JsonCursor& root, const Scene& scene);

  // Names already taken, per namespace, with the path that took them.
  std::map<std::string, std::map<std::string, std::string>> names_;
  std::filesystem::path base_;
  // The fabric's parts, once read: "grain" reads their grain lines, and
  // selections and probes name them.
  std::vector<const Fabric*> parts_;
};

}  // namespace drape
