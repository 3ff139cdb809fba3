// The workbench's scene as a document: open, new from a template, save,
// the autosave every minute and its recovery, the recent files, the
// question about unsaved changes on close, and each change of the
// document's scene accepted (modelled: the view shows it) or taken back
// (the engine cannot model it: undone with its message). The model is the
// document's (SceneDocument::model()), built once per change.
#pragma once

#include <QObject>
#include <QString>
#include <QStringList>

class QMenu;
class QTimer;
class QWidget;

namespace drape {

class SceneDocument;
struct Scene;

class DocumentController : public QObject {
  Q_OBJECT
 public:
  // `window` is the parent of dialogs and gets the scene's title.
  DocumentController(SceneDocument* document, QWidget* window, QObject* parent = nullptr);

  // While the document is locked (a run works on it) these refuse.
  bool open(const QString& file);
  bool newFromTemplate(const QString& file);
  // To `file`, or where the scene came from; false with a message.
  bool save(const QString& file = {});

  bool autosave();
  bool recoverAutosave();
  QStringList recentFiles() const;
  // Filled with the recent files (each opens its scene), kept up to date.
  void setRecentMenu(QMenu* menu);

  // Before the window closes: false when the user cancels (or saving the
  // unsaved changes failed); then, once closed, the autosave goes.
  bool mayClose();
  void closed();

 signals:
  // The document's scene and model are the accepted ones now; `renumbered`:
  // its nodes are not those of the scene accepted before (or none was);
  // `edited`: an edit, undo or redo (not an open, a template or a recovery).
  void accepted(bool renumbered, bool edited);
  // A scene was opened from `file` (for a template: the template's file).
  void opened(const QString& file);
  void message(const QString& text);

 private:
  void OnChanged();
  void WarnOfNodeNumbers(const Scene& scene);
  void Remember(const QString& file);
  void RebuildRecentMenu();

  SceneDocument* document_;
  QWidget* window_;
  QMenu* recent_menu_ = nullptr;
  QTimer* autosave_timer_ = nullptr;
  int node_count_ = -1;   // of the scene accepted last; -1: none yet
  bool opening_ = false;  // the document's changes come from open, not edits
};

}  // namespace drape
