// What keeps a scene from being lost, without the window
// (ui/widgets/scene_keeper): an autosave only of unsaved edits, recovered
// as unsaved edits on top of their source, and the recent files newest
// first, eight at most, each once.
#include "ui/widgets/scene_keeper.h"

#include <QFileInfo>
#include <QSettings>

#include "gui_test.h"
#include "support/test_paths.h"
#include "ui/widgets/scene_document.h"

namespace drape {
namespace {

TEST_F(Widgets, TheKeeperAutosavesUnsavedEditsAndRecoversThem) {
  SceneKeeper::ForgetAutosave();
  const QString source = QString::fromStdString((test::ScenesDir() / "strip-fold.json").string());
  SceneDocument edited;
  edited.open(source);
  EXPECT_FALSE(SceneKeeper::Autosave(edited).done);  // nothing unsaved
  EXPECT_FALSE(QFileInfo::exists(SceneKeeper::AutosavePath()));
  Scene thicker = edited.scene();
  thicker.material.thickness *= 2;
  edited.apply("thickness", thicker);
  const KeeperOutcome saved = SceneKeeper::Autosave(edited);
  ASSERT_TRUE(saved.done) << saved.message.toStdString();
  ASSERT_TRUE(QFileInfo::exists(SceneKeeper::AutosavePath()));

  SceneDocument after_crash;
  const KeeperOutcome recovered = SceneKeeper::Recover(after_crash);
  ASSERT_TRUE(recovered.done) << recovered.message.toStdString();
  EXPECT_EQ(after_crash.scene(), thicker);
  EXPECT_EQ(after_crash.file(), source);  // saved again where it came from
  EXPECT_TRUE(after_crash.isModified());  // the edits are unsaved again
  after_crash.undoStack()->undo();
  EXPECT_EQ(after_crash.scene().material.thickness, thicker.material.thickness / 2);

  SceneKeeper::ForgetAutosave();
  SceneDocument nothing;
  EXPECT_FALSE(SceneKeeper::Recover(nothing).done);
}

TEST_F(Widgets, TheKeeperListsRecentFilesNewestFirstEachOnce) {
  QSettings().remove("recent");
  for (int i = 0; i < 10; ++i) SceneKeeper::Remember(QString("/tmp/scene_%1.json").arg(i));
  SceneKeeper::Remember("/tmp/scene_4.json");  // again: to the front, not twice
  const QStringList recent = SceneKeeper::RecentFiles();
  ASSERT_EQ(recent.size(), SceneKeeper::kRecentFiles);
  EXPECT_EQ(recent.front().toStdString(), "/tmp/scene_4.json");
  EXPECT_EQ(recent.at(1).toStdString(), "/tmp/scene_9.json");
  EXPECT_EQ(recent.count("/tmp/scene_4.json"), 1);
  EXPECT_FALSE(recent.contains("/tmp/scene_0.json"));  // the oldest went
  QSettings().remove("recent");
}

}  // namespace
}  // namespace drape
