// The scene as a tree: fabric, material, supports, grippers, loads, obstacles,
// stages with their moves, probes and solver, each with a one-line summary.
// Choosing an item says which part of the scene to edit; the main window
// shows its editor.
#pragma once

#include <QTreeWidget>

namespace drape {

class SceneDocument;

class ModelTree : public QTreeWidget {
  Q_OBJECT
 public:
  enum class Part {
    kFabric,
    kMaterial,
    kSupports,
    kGrippers,
    kObstacles,
    kStages,
    kProbes,
    kSolver,
    kLoads  // (shown after the grippers)
  };

  explicit ModelTree(SceneDocument* document, QWidget* parent = nullptr);

  // The item for `part` (index -1: its heading; `move` a stage's move).
  QTreeWidgetItem* item(Part part, int index = -1, int move = -1) const;

 public slots:
  void refresh();

 signals:
  void chosen(drape::ModelTree::Part part, int index, int move);
  void opened(drape::ModelTree::Part part, int index, int move);  // double click

 private:
  SceneDocument* document_;
};

}  // namespace drape
