#include "ui/widgets/document_controller.h"

#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QScopedValueRollback>
#include <QTimer>
#include <QUndoStack>
#include <QWidget>

#include <variant>

#include "ui/widgets/error_box.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_keeper.h"

namespace drape {

DocumentController::DocumentController(SceneDocument* document, QWidget* window, QObject* parent)
    : QObject(parent), document_(document), window_(window) {
  connect(document_, &SceneDocument::changed, this, &DocumentController::OnChanged);
  autosave_timer_ = new QTimer(this);
  autosave_timer_->setInterval(60 * 1000);
  connect(autosave_timer_, &QTimer::timeout, this, &DocumentController::autosave);
  autosave_timer_->start();
}

bool DocumentController::open(const QString& file) {
  if (document_->isLocked()) return false;
  try {
    // The document models it before taking it: a scene that cannot be
    // modelled is refused with the reader's or the engine's message.
    const QScopedValueRollback opening(opening_, true);
    document_->open(file);
  } catch (const std::exception& e) {
    ShowError(window_, "Cannot open the scene", QString::fromStdString(e.what()));
    emit message(QString::fromStdString(e.what()));
    return false;
  }
  window_->setWindowTitle(QFileInfo(file).fileName() + " — Drape Studio");
  Remember(file);
  emit opened(file);
  return document_->model() != nullptr;
}

bool DocumentController::newFromTemplate(const QString& file) {
  if (document_->isLocked()) return false;
  try {
    const QScopedValueRollback opening(opening_, true);
    document_->openTemplate(file);
  } catch (const std::exception& e) {
    ShowError(window_, "Cannot open the template", QString::fromStdString(e.what()));
    return false;
  }
  window_->setWindowTitle("untitled (" + QFileInfo(file).completeBaseName() + ") — Drape Studio");
  emit opened(file);
  return document_->model() != nullptr;
}

bool DocumentController::save(const QString& file) {
  try {
    document_->saveAs(file.isEmpty() ? document_->file() : file);
    emit message("saved " + document_->file());
    window_->setWindowTitle(QFileInfo(document_->file()).fileName() + " — Drape Studio");
    return true;
  } catch (const std::exception& e) {
    ShowError(window_, "Cannot save the scene", QString::fromStdString(e.what()));
    return false;
  }
}

bool DocumentController::autosave() {
  if (!document_->model()) return false;
  const KeeperOutcome saved = SceneKeeper::Autosave(*document_);
  if (!saved.done && document_->isModified()) emit message(saved.message);
  return saved.done;
}

bool DocumentController::recoverAutosave() {
  if (document_->isLocked() || !QFileInfo::exists(SceneKeeper::AutosavePath())) return false;
  opening_ = true;
  const KeeperOutcome recovered = SceneKeeper::Recover(*document_);
  opening_ = false;
  if (recovered.done) {
    emit message(recovered.message);
    emit opened(document_->file());
  } else {
    ShowError(window_, "Cannot recover the autosaved scene", recovered.message);
  }
  return recovered.done;
}

QStringList DocumentController::recentFiles() const {
  return SceneKeeper::RecentFiles();
}

void DocumentController::setRecentMenu(QMenu* menu) {
  recent_menu_ = menu;
  RebuildRecentMenu();
}

void DocumentController::Remember(const QString& file) {
  SceneKeeper::Remember(file);
  RebuildRecentMenu();
}

void DocumentController::RebuildRecentMenu() {
  if (!recent_menu_) return;
  recent_menu_->clear();
  for (const QString& file : recentFiles())
    recent_menu_->addAction(QFileInfo(file).fileName(), this, [this, file] { open(file); })
        ->setToolTip(file);
  recent_menu_->setEnabled(!recent_menu_->isEmpty());
}

bool DocumentController::mayClose() {
  if (!document_->isModified()) return true;
  const auto answer =
      QMessageBox::question(window_,
                            "Unsaved changes",
                            "Save the changes to the scene before closing?",
                            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  return answer == QMessageBox::Discard || (answer == QMessageBox::Save && save());
}

void DocumentController::closed() {
  SceneKeeper::ForgetAutosave();  // a clean close: nothing to recover
}

// The scene changed (opened, edited, undone): the view is to show it with
// the document's model; the steps of an earlier run no longer belong to
// it. An edit the engine cannot model is taken back with its message.
void DocumentController::OnChanged() {
  if (document_->isLocked()) return;  // cannot happen: edits are off during a run
  const auto& model = document_->model();
  if (!model) {
    const QString problem = document_->modelProblem();
    emit message(problem);
    // Asked once the edit is on the stack (an edit's signal comes while
    // QUndoStack::push runs, before canUndo() counts it).
    QTimer::singleShot(0, this, [this, problem] {
      if (document_->model() || !document_->undoStack()->canUndo()) return;
      ShowError(window_, "Edit refused", problem);
      document_->undoStack()->undo();
    });
    return;
  }
  const bool renumbered = model->NodeCount() != node_count_;
  if (renumbered && node_count_ >= 0) WarnOfNodeNumbers(document_->scene());
  node_count_ = model->NodeCount();
  emit accepted(renumbered, !opening_);
  emit message(QString("%1: %2 nodes, %3 elements")
                   .arg(QString::fromStdString(document_->scene().name))
                   .arg(model->NodeCount())
                   .arg(model->mesh.ElementCount()));
}

// Selections by node number hold on the mesh they were picked on: after
// the mesh changed they may hold other places of the part.
void DocumentController::WarnOfNodeNumbers(const Scene& scene) {
  QStringList names;
  auto check = [&](const std::string& name, const Selection& s) {
    if (std::holds_alternative<NodesSelection>(s.shape)) names << QString::fromStdString(name);
  };
  for (const Support& s : scene.supports) check(s.name, s.select);
  for (const Gripper& g : scene.grippers) check(g.name, g.select);
  for (const PointLoad& l : scene.loads) check(l.name, l.select);
  if (!names.isEmpty())
    ShowError(window_,
              "Check the held nodes",
              "The mesh changed; " + names.join(", ") +
                  " hold nodes by their numbers, which are other places on the new mesh. "
                  "Pick them again or hold them by a rule.");
}

}  // namespace drape
