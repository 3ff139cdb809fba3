// The count of the mesh the engine made for the scene (Gmsh's for curved
// outlines) and the mesh a preset solves on, or why the engine could not
// model the scene: read from the document's model, never meshed here.
#pragma once

#include <QLabel>

#include <memory>

#include "core/fe/shell_model.h"

namespace drape {

class SceneDocument;

class MeshSummary : public QLabel {
  Q_OBJECT
 public:
  explicit MeshSummary(SceneDocument* document, QWidget* parent = nullptr);

  // The model counted: the document's.
  const std::shared_ptr<const ShellModel>& model() const { return model_; }

 public slots:
  void refresh();

 private:
  SceneDocument* document_;
  std::shared_ptr<const ShellModel> model_;
};

}  // namespace drape
