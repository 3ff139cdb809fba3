// Each change of the scene says which of its top-level parts changed (the
// scene file's keys), undo and redo as the edit did, and each editor of the
// workbench redraws only for the parts it shows: an edit of the material
// leaves the supports, grippers, obstacles and stages alone.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <nlohmann/json.hpp>

#include "core/io/scene_writer.h"
#include "support/test_paths.h"
#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/stages_panel.h"
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

class EditorRefreshes : public Widgets {
 protected:
  void SetUp() override {
    Widgets::SetUp();
    if (IsSkipped()) return;
    window_ = std::make_unique<MainWindow>();
    ASSERT_TRUE(window_->openScene(StripFold()));
    PropertyPanel* properties = window_->properties();
    editors_ = {{"fabric", properties->fabric()},
                {"imperfection", properties->fabric()->imperfection()},
                {"material", properties->material()},
                {"solver", properties->solver()},
                {"supports", window_->supports()},
                {"grippers", window_->grippers()},
                {"loads", window_->loads()},
                {"obstacles", window_->obstacles()},
                {"stages", window_->stages()},
                {"moves", window_->stages()->moves()},
                {"probes", window_->probes()},
                {"tree", window_->tree()}};
    for (const auto& [name, editor] : editors_)
      ASSERT_NE(ScenePartWatch::of(editor), nullptr) << name << " does not follow the scene";
  }
  void TearDown() override { window_.reset(); }

  // How many times each editor redrew from the scene since the last call.
  std::map<std::string, int> Refreshes() {
    std::map<std::string, int> since;
    for (const auto& [name, editor] : editors_) {
      const int now = ScenePartWatch::of(editor)->refreshes();
      since[name] = now - counted_[name];
      counted_[name] = now;
    }
    return since;
  }
  // Only `redrawn` redrew, once each.
  void ExpectOnly(const std::set<std::string>& redrawn, const std::string& after) {
    for (const auto& [name, count] : Refreshes())
      EXPECT_EQ(count, redrawn.count(name) ? 1 : 0) << name << " after " << after;
  }

  std::unique_ptr<MainWindow> window_;
  std::map<std::string, QObject*> editors_;
  std::map<std::string, int> counted_;
};

TEST_F(EditorRefreshes, AMaterialEditRedrawsTheMaterialEditorAndTheTreeOnly) {
  Refreshes();
  QLineEdit* thickness = window_->properties()->thickness()->edit();
  thickness->setText("0.6 mm");
  emit thickness->editingFinished();
  ASSERT_NEAR(window_->document()->scene().material.thickness, 0.6e-3, 1e-15);
  ExpectOnly({"material", "tree"}, "the thickness was typed");
  window_->document()->undoStack()->undo();
  ExpectOnly({"material", "tree"}, "its undo");
  // Redrawn, not merely counted: the field shows the scene's thickness again.
  EXPECT_NE(thickness->text().toStdString(), "0.6 mm");
  window_->document()->undoStack()->redo();
  ExpectOnly({"material", "tree"}, "its redo");
  EXPECT_EQ(thickness->text().toStdString(), "0.6 mm");
}

TEST_F(EditorRefreshes, OpeningASceneRedrawsEveryEditor) {
  Refreshes();
  ASSERT_TRUE(window_->openScene(StripFold()));
  std::set<std::string> all;
  for (const auto& [name, editor] : editors_) all.insert(name);
  ExpectOnly(all, "opening");
}

// Each editor hears of the parts it shows, and of no others: a move chooses
// what it carries from the grippers and the obstacles; the obstacles' panel
// shows the contact too, which the tree does not.
TEST_F(EditorRefreshes, EachEditorRedrawsForThePartsItShows) {
  Refreshes();
  ASSERT_TRUE(window_->properties()->setOutline("rectangle", "40 cm, 2 cm"))
      << window_->properties()->fabricMessage().toStdString();
  ExpectOnly({"fabric", "imperfection", "tree"}, "the outline was typed");
  ASSERT_TRUE(window_->grippers()->add("point", 0, -0.05, 0))
      << window_->grippers()->message().toStdString();
  ExpectOnly({"grippers", "moves", "tree"}, "a gripper was added");
  ASSERT_TRUE(window_->supports()->add("point", 0, 0.05, 0))
      << window_->supports()->message().toStdString();
  ExpectOnly({"supports", "tree"}, "a support was added");
  ASSERT_TRUE(window_->loads()->add("point", "0, 0, -1 gf", "0, 0, 0", 0.1, 0))
      << window_->loads()->message().toStdString();
  ExpectOnly({"loads", "tree"}, "a load was added");
  ASSERT_TRUE(window_->obstacles()->add("sphere")) << window_->obstacles()->message().toStdString();
  ExpectOnly({"obstacles", "moves", "tree"}, "an obstacle was added");
  ASSERT_TRUE(window_->obstacles()->setContact("auto", "0.3"))
      << window_->obstacles()->message().toStdString();
  ExpectOnly({"obstacles"}, "the friction was typed");
  ASSERT_TRUE(window_->probes()->add(0.01, 0)) << window_->probes()->message().toStdString();
  ExpectOnly({"probes", "tree"}, "a probe was added");
  window_->properties()->timeLimit()->setValue(60);
  emit window_->properties()->timeLimit()->editingFinished();
  ExpectOnly({"solver", "tree"}, "the time limit was typed");
  ASSERT_TRUE(window_->stages()->addStage("gravity")) << window_->stages()->message().toStdString();
  ExpectOnly({"stages", "moves", "tree"}, "a stage was added");
}

}  // namespace
}  // namespace drape
