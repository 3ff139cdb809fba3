#include "ui/widgets/scene_document.h"

#include <QUndoCommand>

#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"

namespace drape {

// One edit: the whole scene before and after (scenes are small next to
// their meshes and states, and this cannot get an inverse wrong).
class SceneEdit : public QUndoCommand {
 public:
  SceneEdit(SceneDocument* document, const QString& what, Scene before, Scene after)
      : QUndoCommand(what),
        document_(document),
        before_(std::move(before)),
        after_(std::move(after)) {}
  void redo() override { document_->set(after_); }
  void undo() override { document_->set(before_); }

 private:
  SceneDocument* document_;
  Scene before_, after_;
};

SceneDocument::SceneDocument(QObject* parent) : QObject(parent) {}

void SceneDocument::open(const QString& file) {
  Scene scene = ReadScene(file.toStdString());
  scene_ = std::move(scene);
  file_ = file;
  undo_.clear();
  undo_.setClean();
  emit changed();
}

void SceneDocument::saveAs(const QString& file) {
  WriteScene(scene_, file.toStdString());
  file_ = file;
  undo_.setClean();
}

void SceneDocument::apply(const QString& what, const Scene& after) {
  if (after == scene_) return;
  undo_.push(new SceneEdit(this, what, scene_, after));
}

void SceneDocument::set(const Scene& scene) {
  scene_ = scene;
  emit changed();
}

}  // namespace drape
