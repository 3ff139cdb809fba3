#include "ui/widgets/mesh_summary.h"

#include "ui/widgets/scene_document.h"

namespace drape {

MeshSummary::MeshSummary(SceneDocument* document, QWidget* parent)
    : QLabel(parent), document_(document) {
  setWordWrap(true);  // the solved mesh of a preset makes it long
  // The document builds a new model for every change of the scene, of any
  // part: holding the one it shares keeps no stale model alive.
  connect(document_, &SceneDocument::changed, this, &MeshSummary::refresh);
  refresh();
}

void MeshSummary::refresh() {
  model_ = document_->model();
  if (!model_) {
    setText(document_->modelProblem());
    return;
  }
  const Mesh& mesh = model_->mesh;
  QString info = QString("%1 nodes, %2 elements, %3 DOFs")
                     .arg(mesh.NodeCount())
                     .arg(mesh.ElementCount())
                     .arg(5 * mesh.NodeCount());
  const SolverSettings& solver = document_->scene().solver;
  if (solver.mesh_scale != 1)
    info = QString("solved on %1: %2 × the element counts above (%3)")
               .arg(info)
               .arg(solver.mesh_scale)
               .arg(solver.preset ? QString("accuracy ") + ToString(*solver.preset)
                                  : QString("solver.mesh_scale"));
  setText(info);
}

}  // namespace drape
