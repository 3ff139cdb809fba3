// What keeps a workbench's scene from being lost: the autosave of unsaved
// edits (recovered after a crash as unsaved edits again) and the list of
// recently opened files. QSettings and the application's data folder, no
// window.
#pragma once

#include <QString>
#include <QStringList>

namespace drape {

class SceneDocument;

struct KeeperOutcome {
  bool done = false;
  QString message;  // what happened, or why not
};

class SceneKeeper {
 public:
  static constexpr int kRecentFiles = 8;

  // The application's data folder / autosave.json (made when missing).
  static QString AutosavePath();
  // Writes the document's scene there when it has unsaved edits, and
  // remembers the file it came from (relative references resolve there).
  static KeeperOutcome Autosave(const SceneDocument& document);
  // Opens the autosaved scene in `document`: the source file first, then
  // the autosave as one undoable edit, so the edits are unsaved again.
  static KeeperOutcome Recover(SceneDocument& document);
  // After a clean close there is nothing to recover.
  static void ForgetAutosave();

  // Newest first, absolute paths, at most kRecentFiles.
  static QStringList RecentFiles();
  static void Remember(const QString& file);
};

}  // namespace drape
