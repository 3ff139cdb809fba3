// Each change of the scene says which of its top-level parts changed (the
// scene file's keys), undo and redo as the edit did.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <optional>
#include <string>

#include <QSignalSpy>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include "core/io/scene_writer.h"
#include "support/test_paths.h"
#include "ui/widgets/scene_document.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

using Part = SceneDocument::Part;
using Parts = SceneDocument::Parts;

QString StripFold() {
  return QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
}

// Every part, each with a change of that part alone.
const std::map<Part, std::function<void(Scene&)>>& ChangeOfEachPart() {
  static const std::map<Part, std::function<void(Scene&)>> changes = {
      {Part::kName, [](Scene& s) { s.name += " again"; }},
      {Part::kDescription, [](Scene& s) { s.description += " again"; }},
      {Part::kFabric, [](Scene& s) { s.fabric.elevation += 0.01; }},
      {Part::kMaterial, [](Scene& s) { s.material.thickness *= 2; }},
      {Part::kSupports,
       [](Scene& s) {
         s.supports.push_back({"pin", {CornersSelection{}, std::nullopt}});
       }},
      {Part::kGrippers,
       [](Scene& s) {
         s.grippers.push_back({"hand", {CornersSelection{}, std::nullopt}});
       }},
      {Part::kLoads,
       [](Scene& s) {
         s.loads.push_back({"push", {CornersSelection{}, std::nullopt}});
       }},
      {Part::kObstacles,
       [](Scene& s) {
         s.obstacles.push_back({"ball", SphereShape{}});
       }},
      {Part::kContact,
       [](Scene& s) {
         Contact c = s.contact.value_or(Contact{});
         c.friction += 0.1;
         s.contact = c;
       }},
      {Part::kGravity,
       [](Scene& s) {
         s.gravity_direction = {0, 0, 1};
       }},
      {Part::kStages,
       [](Scene& s) {
         Stage settle;
         settle.name = "settle";
         s.stages.push_back(settle);
       }},
      {Part::kSolver, [](Scene& s) { s.solver.tolerance *= 2; }},
      {Part::kProbes, [](Scene& s) { s.probes.push_back({"tip"}); }},
  };
  return changes;
}

TEST_F(Widgets, EachPartOfTheSceneIsToldApartAndNamedByItsKey) {
  SceneDocument doc;
  doc.open(StripFold());
  const Scene& original = doc.scene();
  EXPECT_EQ(SceneDocument::differences(original, original), Parts());
  Parts all;
  for (const auto& [part, change] : ChangeOfEachPart()) {
    Scene changed = original;
    change(changed);
    EXPECT_EQ(SceneDocument::differences(original, changed), Parts(part))
        << SceneDocument::key(part);
    EXPECT_EQ(SceneDocument::differences(changed, original), Parts(part))
        << SceneDocument::key(part);
    // The name is the scene file's key of the part.
    EXPECT_TRUE(SceneToJson(changed).contains(SceneDocument::key(part)))
        << SceneDocument::key(part);
    all |= part;
  }
  EXPECT_EQ(all, SceneDocument::kAllParts);  // no part left untold
}

TEST_F(Widgets, EditsUndoAndRedoSayTheSamePartsAndOpeningSaysAll) {
  SceneDocument doc;
  QSignalSpy parts(&doc, &SceneDocument::partsChanged);
  QSignalSpy changed(&doc, &SceneDocument::changed);
  doc.open(StripFold());
  ASSERT_EQ(parts.count(), 1);
  EXPECT_EQ(parts.takeLast().at(0).value<Parts>(), SceneDocument::kAllParts);
  Scene after = doc.scene();
  after.material.thickness *= 2;
  after.probes.push_back({"middle", {0, 0}});
  QString problem;
  ASSERT_TRUE(doc.tryApply("thicker, probed", after, &problem)) << problem.toStdString();
  const Parts edited = Part::kMaterial | Part::kProbes;
  ASSERT_EQ(parts.count(), 1);
  EXPECT_EQ(parts.takeLast().at(0).value<Parts>(), edited);
  doc.undoStack()->undo();
  ASSERT_EQ(parts.count(), 1);
  EXPECT_EQ(parts.takeLast().at(0).value<Parts>(), edited);
  doc.undoStack()->redo();
  ASSERT_EQ(parts.count(), 1);
  EXPECT_EQ(parts.takeLast().at(0).value<Parts>(), edited);
  EXPECT_EQ(changed.count(), 4);  // "anything changed" goes on as before
}

}  // namespace
}  // namespace drape
