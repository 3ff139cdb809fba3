// The scene being edited: its file, every edit as an undoable command
// (QUndoStack) holding the scene before and after, save and open. Editors
// change the scene only through apply(), so every edit undoes.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>

#include "core/model/scene.h"

namespace drape {

class SceneDocument : public QObject {
  Q_OBJECT
 public:
  explicit SceneDocument(QObject* parent = nullptr);

  const Scene& scene() const { return scene_; }
  const QString& file() const { return file_; }
  QUndoStack* undoStack() { return &undo_; }
  bool isModified() const { return !undo_.isClean(); }

  // Reads a scene file (throws SceneError / std::runtime_error); clears undo.
  void open(const QString& file);
  // A new, unsaved scene from a template file (Save then asks where).
  void openTemplate(const QString& file);
  // Writes the scene; throws std::runtime_error naming the file. Saved into
  // another folder, file references (Kawabata data, obstacle meshes) are
  // written as absolute paths, so the scene still finds them.
  void saveAs(const QString& file);
  // An edit named `what` ("thickness 0.5 mm"): undoable; nothing happens
  // when `after` equals the scene.
  void apply(const QString& what, const Scene& after);

 signals:
  void changed();  // after open, an edit, undo or redo

 private:
  friend class SceneEdit;
  void set(const Scene& scene);

  Scene scene_;
  QString file_;
  QString origin_;  // the folder the scene's relative references are in
  QUndoStack undo_;
};

}  // namespace drape
